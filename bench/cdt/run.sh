#!/bin/sh
# Runs bench_cdt (5 repetitions, medians) and writes docs/results/<date>-cdt.json and its table
# of median times and ratios against CGAL (table.py) next to it.
#   bench/cdt/run.sh [build-dir] [extra benchmark flags...]
# PEAR_BENCH_LARGE=1 adds the Australia and Eurasia coastlines. Record where it ran: only ratios
# within one run mean anything.
set -eu
build=${1:-build}
[ $# -gt 0 ] && shift
root=$(cd "$(dirname "$0")/../.." && pwd)
binary="$root/$build/bench/cdt/bench_cdt"
if [ ! -x "$binary" ]; then
  echo "$binary not built: meson setup $build -Dbench=enabled && ninja -C $build" >&2
  exit 2
fi
mkdir -p "$root/docs/results"
out="$root/docs/results/$(date +%Y-%m-%d)-cdt.json"
"$binary" --benchmark_repetitions=5 --benchmark_report_aggregates_only=true \
  --benchmark_out_format=json --benchmark_out="$out" "$@"
python3 "$root/bench/cdt/table.py" "$out" > "${out%.json}.md"
echo "wrote $out and ${out%.json}.md"
