#!/usr/bin/env bash
# One command for every benchmark and experiment of issue 8: builds, runs the timing suite
# (bench_triangulate: pear's algorithms x threads x CDT against CGAL, GEOS, GLU) and the paper's
# other experiments (paper_experiments: ears, work/span profile, quality, flips), writes
# docs/results/DATE-MODE-*.json with the machine described, renders docs/figures/*.svg|png and
# writes docs/benchmarks.md.
#
#   bench/run.sh [quick|full] [--build DIR] [--commit REV] [--build-only|--report-only]
#   bench/run.sh scaling [--eurasia] [--build DIR] [--commit REV]
#
# quick: a few minutes; a subset of sizes and variants, one repetition, still the largest
#        coastline (Eurasia, 1.5M vertices) for the headline ratios.
# full:  every family at 1k..4M, every real input, threads 1, 2, 4, 8, three repetitions (hours).
# scaling: only the work/span profile of every variant at 2, 4, 8 and 16 partitions, on one
#        thread, rendered as docs/scaling.md (the one scaling table the docs quote): the coasts
#        (Eurasia, 1.5M vertices, only with --eurasia: about 2 minutes more; Antarctica is not
#        simple), the synthetic files (Koch-8, star, comb, spiral, holes grid) and the random
#        families at 100k; 5 rounds (PEAR_BENCH_PROFILE_RUNS), the bases again before every
#        fourth variant. About 15
#        minutes on 2 cores, 25 with Eurasia.
# --commit REV: measure that commit, exported with `git archive` into DIR/snapshot (a shared
#        working tree with other people's unfinished edits need not compile); default: the
#        working tree as it is.
# --build-only: stop after building. --report-only: skip building and running; re-render from
#        the JSON of today's MODE run.
# Needs: Meson, Ninja, Google Benchmark; peers and zlib when found; python3-matplotlib.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mode=quick
build=build-bench
commit=""
report_only=0
build_only=0
eurasia=0
while [[ $# -gt 0 ]]; do
  case $1 in
    quick | full | scaling) mode=$1 ;;
    --eurasia) eurasia=1 ;;
    --build) build=$2; shift ;;
    --commit) commit=$2; shift ;;
    --report-only) report_only=1 ;;
    --build-only) build_only=1 ;;
    *)
      echo "usage: $0 [quick|full|scaling] [--eurasia] [--build DIR] [--commit REV]" \
        "[--build-only|--report-only]" >&2
      exit 2
      ;;
  esac
  shift
done
[[ $build = /* ]] || build="$root/$build"
results="$root/docs/results"
stem="$results/$(date -u +%Y-%m-%d)-$mode"
mkdir -p "$results"
export PEAR_BENCH_CORPUS=${PEAR_BENCH_CORPUS:-$root/../shared/corpus}
# Debian's matplotlib lives in the system Python, which a pyenv or venv python3 may hide.
python=${PYTHON:-python3}
"$python" -c 'import matplotlib' 2>/dev/null || python=/usr/bin/python3

# Source to build: the working tree, or a snapshot of one commit (files copied only when they
# changed, so the snapshot's build stays incremental).
source_dir=$root
if [[ -n $commit ]]; then
  source_dir="$build/snapshot/src"
  export_dir="$build/snapshot/export"
  rm -rf "$export_dir" && mkdir -p "$export_dir" "$source_dir"
  git -C "$root" archive "$commit" | tar -x -C "$export_dir"
  (cd "$export_dir" && find . -type f) | while read -r file; do
    cmp -s "$export_dir/$file" "$source_dir/$file" ||
      { mkdir -p "$(dirname "$source_dir/$file")" && cp "$export_dir/$file" "$source_dir/$file"; }
  done
  (cd "$source_dir" && find . -type f) | while read -r file; do
    [[ -e $export_dir/$file ]] || rm "$source_dir/$file"
  done
  build="$build/snapshot/build"
fi
described_commit=$(git -C "$root" rev-parse --short "${commit:-HEAD}")
[[ -z $commit && -n $(git -C "$root" status --porcelain -- src include) ]] &&
  described_commit="$described_commit+uncommitted"

if [[ $mode = scaling ]]; then
  [[ -f $build/build.ninja ]] ||
    meson setup "$build" "$source_dir" --buildtype=release -Dbench=enabled -Dtests=disabled \
      -Dcli=disabled -Dfuzz=disabled
  ninja -C "$build" -j2 bench/paper/paper_experiments
  [[ $build_only -eq 1 ]] && exit 0
  coasts=south_america,greenland,australia,baffin_island,new_guinea,borneo
  [[ $eurasia -eq 1 ]] && coasts="eurasia,$coasts"
  "$python" "$root/bench/report/machine.py" "$mode" "$described_commit" > "$stem-machine.json"
  # PEAR_BENCH_PATHS=':' names no other real file: the countries are below 10k vertices.
  PEAR_BENCH_COASTS=$coasts PEAR_BENCH_FAMILIES=random,random-holes PEAR_BENCH_SIZES=100000 \
    PEAR_BENCH_PATHS=: PEAR_BENCH_PROFILE_RUNS=${PEAR_BENCH_PROFILE_RUNS:-5} \
    "$build/bench/paper/paper_experiments" profile > "$stem-profile.json.new"
  mv "$stem-profile.json.new" "$stem-profile.json"
  "$python" "$root/bench/report/machine.py" --finish "$stem-machine.json"
  command="bash bench/run.sh scaling"
  [[ $eurasia -eq 1 ]] && command="$command --eurasia"
  "$python" "$root/bench/report/scaling.py" "$stem" --docs "$root/docs" --command "$command"
  echo "wrote $stem-profile.json and $root/docs/scaling.md"
  exit 0
fi

if [[ $report_only -eq 0 ]]; then
  [[ -f $build/build.ninja ]] ||
    meson setup "$build" "$source_dir" --buildtype=release -Dbench=enabled -Dtests=disabled \
      -Dcli=disabled -Dfuzz=disabled
  ninja -C "$build" -j2 bench/triangulate/bench_triangulate bench/paper/paper_experiments
  [[ $build_only -eq 1 ]] && exit 0

  # What each mode runs. The regular expression picks triangulators (bench_triangulate's
  # benchmarks are named triangulate/INPUT/TRIANGULATOR).
  peers='cgal_cdt|geos_ear|geos_cdt|glu'
  if [[ $mode = quick ]]; then
    export PEAR_BENCH_SIZES=${PEAR_BENCH_SIZES:-10000,100000}
    export PEAR_BENCH_COASTS=${PEAR_BENCH_COASTS:-borneo,australia,eurasia}
    export PEAR_BENCH_MAX_SECONDS=${PEAR_BENCH_MAX_SECONDS:-8}
    filter="triangulate/.*/(pear_(top|fast|cdt)|pear_(pc|mc|dc)_t[12]|pear_auto_t2|pear_pc_t2_cdt|$peers)/real_time$"
    bench_flags=(--benchmark_repetitions=1 --benchmark_min_time=0.05)
    quality_max=20000
    profile_max=250000
    export PEAR_BENCH_PROFILE_RUNS=${PEAR_BENCH_PROFILE_RUNS:-5}
  else
    export PEAR_BENCH_MAX_SECONDS=${PEAR_BENCH_MAX_SECONDS:-30}
    filter="triangulate/.*"
    bench_flags=(--benchmark_repetitions=3 --benchmark_min_time=0.2
      --benchmark_report_aggregates_only=true)
    quality_max=2000000
    profile_max=2000000
  fi

  "$python" "$root/bench/report/machine.py" "$mode" "$described_commit" > "$stem-machine.json"
  "$build/bench/triangulate/bench_triangulate" --benchmark_filter="$filter" "${bench_flags[@]}" \
    --benchmark_out_format=json --benchmark_out="$stem-triangulate.json"
  experiments="$build/bench/paper/paper_experiments"
  "$experiments" ears > "$stem-ears.json"
  "$experiments" quality "$quality_max" > "$stem-quality.json"
  "$experiments" profile "$profile_max" > "$stem-profile.json"
  "$python" "$root/bench/report/machine.py" --finish "$stem-machine.json"
fi

"$python" "$root/bench/report/report.py" "$stem" --docs "$root/docs"
echo "wrote $stem-*.json, $root/docs/figures/ and $root/docs/benchmarks.md"
