#!/usr/bin/env bash
# Wall time of pear's parallel variants at 1, 2, 4, 8 and 16 threads (issue 27): bench/profile's
# pear_threads on the coasts, the synthetic files and the random families, the configurations of
# each input interleaved in rounds, against the sequential engine, the sequential CDT and CGAL's
# CDT in the same run; then each phase's elapsed time at the largest count. Meant for a machine
# with many cores; on this project's 2-core VMs, 4 threads and more are oversubscribed.
#
#   bench/threads.sh [--build DIR] [--rounds N] [--budget SECONDS]
#   bench/threads.sh --pack DIR      a folder to copy to another x86-64 Linux machine (glibc 2.36
#                                    or newer): the binaries, the libraries they need beyond glibc,
#                                    the inputs and run.sh; `bash DIR/run.sh OUT` there writes
#                                    OUT/threads.json and OUT/machine.json; `bash DIR/contention.sh
#                                    OUT` there, first, what running side by side costs
#                                    (bench/profile/contention.sh)
#   bench/threads.sh --report OUT    docs/results/DATE-threads-*.json from such an OUT, and the
#                                    table (bench/report/threads.py)
#
# Inputs: the shared corpus (PEAR_BENCH_CORPUS, default ../shared/corpus): the coasts but
# Antarctica (not simple), Eurasia last; the synthetic files; random and random-holes at 100k.
# --budget (default 600 s): inputs not started by then are skipped (Eurasia alone ~2 minutes on
# 16 cores). Needs Meson, Ninja, zlib; CGAL (libcgal-dev, GMP, MPFR) for the CGAL column.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=$root/build-bench
rounds=5
budget=600
pack=""
report=""
while [[ $# -gt 0 ]]; do
  case $1 in
    --build) build=$2; shift ;;
    --rounds) rounds=$2; shift ;;
    --budget) budget=$2; shift ;;
    --pack) pack=$2; shift ;;
    --report) report=$2; shift ;;
    *) echo "usage: $0 [--build DIR] [--rounds N] [--budget S] [--pack DIR | --report OUT]" >&2
       exit 2 ;;
  esac
  shift
done
python=${PYTHON:-python3}
"$python" -c 'import json' 2>/dev/null || python=/usr/bin/python3

if [[ -n $report ]]; then
  stem="$root/docs/results/$(date -u +%Y-%m-%dT%H%M)-threads"  # sorts after a day's earlier runs
  cp "$report/threads.json" "$stem.json"
  cp "$report/machine.json" "$stem-machine.json"
  "$python" "$root/bench/report/threads.py" "$stem.json"
  exit 0
fi

[[ -f $build/build.ninja ]] ||
  meson setup "$build" "$root" --buildtype=release -Dbench=enabled -Dtests=disabled \
    -Dcli=disabled -Dfuzz=disabled
ninja -C "$build" bench/profile/pear_threads bench/profile/pear_phases
corpus=${PEAR_BENCH_CORPUS:-$root/../shared/corpus}
coasts="borneo new_guinea australia baffin_island greenland south_america eurasia"
synthetic="koch-8 star-100000 comb-100000 spiral-100000 holes-100x100"

if [[ -z $pack ]]; then
  pack=$(mktemp -d)
  trap 'rm -rf "$pack"' EXIT
  local_run=1
else
  local_run=0
fi
mkdir -p "$pack/lib" "$pack/inputs"
cp "$build/bench/profile/pear_threads" "$build/bench/profile/pear_phases" "$pack/"
cp "$root/bench/profile/contention.sh" "$root/bench/profile/unpack_inputs.py" "$pack/"
# Every library but glibc's own, so that the folder runs where pear was never built.
ldd "$build/bench/profile/pear_threads" | awk '/=> \// {print $3}' | while read -r lib; do
  case $(basename "$lib") in
    libc.so.* | libm.so.* | ld-linux*) ;;
    *) cp -L "$lib" "$pack/lib/" ;;
  esac
done
cp "$root/bench/report/machine.py" "$pack/"
c++ --version | head -1 > "$pack/built_with.txt"
inputs=()
for name in $coasts; do
  file=$(ls "$corpus/coast/${name}"_gshhg_*.json.gz 2>/dev/null | head -1 || true)
  [[ -n $file ]] || continue
  # xz, where there is one: a lent machine takes 64 MiB with the repository (run.sh unpacks).
  if [[ $local_run -eq 0 ]] && command -v xz > /dev/null; then
    gzip -dc "$file" | xz -6 -T0 > "$pack/inputs/$(basename "${file%.gz}").xz"
  else
    cp "$file" "$pack/inputs/"
  fi
  inputs+=("inputs/$(basename "$file")")
done
for name in $synthetic; do
  if [[ -f $corpus/synthetic/$name.json ]]; then
    gzip -c "$corpus/synthetic/$name.json" > "$pack/inputs/$name.json.gz"
    inputs+=("inputs/$name.json.gz")
  fi
done
inputs+=(random:100000 random-holes:100000)
[[ ${#inputs[@]} -gt 2 ]] || echo "corpus $corpus not found: only the random families" >&2
# Eurasia last: the budget may leave it out.
ordered=()
for i in "${inputs[@]}"; do [[ $i = *eurasia* ]] || ordered+=("$i"); done
for i in "${inputs[@]}"; do [[ $i = *eurasia* ]] && ordered+=("$i"); done
cat > "$pack/run.sh" <<EOF
#!/usr/bin/env bash
# Made by bench/threads.sh --pack: bash run.sh OUT [ROUNDS] [BUDGET_SECONDS]
set -u
here=\$(cd "\$(dirname "\$0")" && pwd)
out=\${1:?usage: run.sh OUT [ROUNDS] [BUDGET]}; rounds=\${2:-$rounds}; budget=\${3:-$budget}
mkdir -p "\$out/parts"
export LD_LIBRARY_PATH="\$here/lib"
python3 "\$here/unpack_inputs.py" "\$here/inputs"
python3 "\$here/machine.py" threads "$(git -C "$root" rev-parse --short HEAD)" > "\$out/machine.json"
# The compiler that built the binary (machine.py names the one on this machine, if any).
python3 -c 'import json, sys; m = json.load(open(sys.argv[1])); m["built_with"] = open(sys.argv[2]).read().strip(); json.dump(m, open(sys.argv[1], "w"), indent=1)' "\$out/machine.json" "\$here/built_with.txt"
start=\$SECONDS
for input in ${ordered[*]}; do
  left=\$((budget - (SECONDS - start)))
  if (( left < 30 )); then echo "skipped \$input: budget" >&2; continue; fi
  r=\$rounds; [[ \$input = *eurasia* ]] && r=\$(( rounds < 3 ? rounds : 3 ))
  t0=\$SECONDS
  (cd "\$here" && timeout "\$left" ./pear_threads --rounds "\$r" --phases "\$input") \
    > "\$out/parts/\$(basename "\$input" | tr ':' '-').json"
  echo "\$input: rc \$?, \$((SECONDS - t0)) s, load \$(cut -d' ' -f1-3 /proc/loadavg)" >&2
done
python3 - "\$out" <<'PY'
import glob, json, os, sys
out = sys.argv[1]
records = []
for path in sorted(glob.glob(os.path.join(out, "parts", "*.json"))):
    text = open(path).read().strip()
    try:
        part = json.loads(text)
    except ValueError:  # cut off by the budget: keep the records that are complete
        part, cut = [], text.rfind("},\n{")
        while cut > 0 and not part:
            try:
                part = json.loads(text[:cut + 1] + "]")
            except ValueError:
                cut = text.rfind("},\n{", 0, cut)
    records.extend(r for r in part if "input" in r or not records)
json.dump(records, open(os.path.join(out, "threads.json"), "w"), indent=0)
PY
python3 "\$here/machine.py" --finish "\$out/machine.json"
rm -rf "\$out/parts"
EOF
if [[ $local_run -eq 1 ]]; then
  out=$(mktemp -d)
  bash "$pack/run.sh" "$out" "$rounds" "$budget"
  "$0" --report "$out"
  rm -rf "$out"
else
  echo "packed $(du -sh "$pack" | cut -f1) into $pack: run 'bash $pack/run.sh OUT' there," \
    "then 'bash bench/threads.sh --report OUT' here"
fi
