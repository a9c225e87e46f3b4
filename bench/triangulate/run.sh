#!/bin/sh
# Runs bench_triangulate and writes docs/results/<date>-triangulate-<mode>.json and its
# Markdown table (table.py) next to it.
#   bench/triangulate/run.sh [quick|full] [build-dir] [extra benchmark flags...]
# quick: 3 repetitions, inputs up to 200k vertices (PEAR_BENCH_MAX_VERTICES overrides);
# full: 5 repetitions, every input (PEAR_BENCH_LARGE=1 adds the 4M sizes).
# Machine note: record where it ran; only ratios within one run are meaningful.
set -eu
mode=${1:-quick}
build=${2:-build}
[ $# -gt 0 ] && shift
[ $# -gt 0 ] && shift
root=$(cd "$(dirname "$0")/../.." && pwd)
case $mode in
  quick)
    repetitions=3
    min_time=0.2
    PEAR_BENCH_MAX_VERTICES=${PEAR_BENCH_MAX_VERTICES:-200000}
    export PEAR_BENCH_MAX_VERTICES
    ;;
  full)
    repetitions=5
    min_time=0.5
    ;;
  *)
    echo "usage: $0 [quick|full] [build-dir] [benchmark flags...]" >&2
    exit 2
    ;;
esac
binary="$root/$build/bench/triangulate/bench_triangulate"
if [ ! -x "$binary" ]; then
  echo "$binary not built: meson setup $build && ninja -C $build" >&2
  exit 2
fi
mkdir -p "$root/docs/results"
out="$root/docs/results/$(date +%Y-%m-%d)-triangulate-$mode.json"
"$binary" --benchmark_repetitions="$repetitions" --benchmark_report_aggregates_only=true \
  --benchmark_min_time="$min_time" --benchmark_out_format=json --benchmark_out="$out" "$@"
python3 "$root/bench/triangulate/table.py" "$out" > "${out%.json}.md"
echo "wrote $out and ${out%.json}.md"
