#!/usr/bin/env bash
# Two builds of pear on one many-core machine (issue 27): pear_threads of each, alternating per
# input (a, b, a, b), so that what changed between two commits is measured on the same host at
# the same hour; lent machines differ by 1.5x in one thread's speed from one day to the next.
#
#   bash ab_threads.sh INPUTS A B OUT
#   INPUTS: a folder of .json.gz (or .json.xz) polygons, e.g. the inputs/ of bench/threads.sh
#   --pack; A, B: folders each with a pear_threads and the lib/ it needs (copy a build's
#   bench/profile/pear_threads, src/libpear*.so.0 and what `ldd` lists beyond glibc).
#   Writes OUT/ab.json (every record with its build and batch) and prints, per input and
#   configuration, the median over the batches of each build and their ratio (A over B).
#   CONFIGS (default top,auto_t2,auto_t16,cdt,auto_t2_cdt,auto_t16_cdt), THREADS (1,2,16),
#   BATCHES (2), BUDGET (240 s: no batch starts after it).
set -u
inputs=${1:?usage: ab_threads.sh INPUTS A B OUT}; a=${2:?}; b=${3:?}; out=${4:?}
configs=${CONFIGS:-top,auto_t2,auto_t16,cdt,auto_t2_cdt,auto_t16_cdt}
mkdir -p "$out/parts"
python3 "$(dirname "$0")/unpack_inputs.py" "$inputs"
start=$SECONDS
for file in "$inputs"/*.json.gz; do
  name=$(basename "$file" .json.gz)
  for batch in $(seq "${BATCHES:-2}"); do
    for build in "$a" "$b"; do
      (( SECONDS - start > ${BUDGET:-240} )) && { echo "budget: stopped at $name" >&2; break 3; }
      tag=$([[ $build = "$a" ]] && echo a || echo b)
      LD_LIBRARY_PATH=$build/lib "$build/pear_threads" --threads "${THREADS:-1,2,16}" \
        --rounds 3 --configs "$configs" "$file" > "$out/parts/${tag}_${batch}_$name.json"
      echo "$name $tag batch $batch: rc $?, load $(cut -d' ' -f1 /proc/loadavg)" >&2
    done
  done
done
python3 - "$out" "$a" "$b" <<'PY'
import glob, json, os, statistics, sys
out, builds = sys.argv[1], {"a": sys.argv[2], "b": sys.argv[3]}
records, cells = [], {}
for path in sorted(glob.glob(os.path.join(out, "parts", "*.json"))):
    tag, batch, name = os.path.basename(path)[:-5].split("_", 2)
    for r in json.load(open(path)):
        if "median_ms" in r:
            records.append(dict(r, build=builds[tag], batch=int(batch)))
            cells.setdefault((r["input"], r["config"]), {}).setdefault(tag, []).append(r["median_ms"])
json.dump(records, open(os.path.join(out, "ab.json"), "w"), indent=0)
for (inp, config), t in cells.items():
    if "a" in t and "b" in t:
        ma, mb = statistics.median(t["a"]), statistics.median(t["b"])
        print(f"{inp:24} {config:14} {ma:9.1f} {mb:9.1f} ms  a/b {ma / mb:.2f}x")
PY
rm -rf "$out/parts"
