#!/usr/bin/env bash
# What running beside other threads costs on a many-core machine, apart from pear's own
# partitioning (issue 27): packed by bench/threads.sh --pack DIR, run there as
# `bash DIR/contention.sh OUT` before DIR/run.sh. Writes OUT/contention.log:
#   1. N copies of the sequential engine at once (N = 1, 8, 16; the best of 9 runs of each):
#      shared caches and memory bandwidth, with no task of pear's in between;
#   2. partition-and-cut at 16 partitions on 1, 4, 8 and 16 threads (pear_phases pc16tN), each
#      chain's clip time listed: the same tasks, run alone and side by side;
#   3. the same with malloc told to keep freed memory (no page faults from returned memory);
#   4. 8 threads on 8 distinct physical cores (taskset), where the machine has SMT.
# The inputs: Australia and Greenland from DIR/inputs.
set -u
here=$(cd "$(dirname "$0")" && pwd)
out=${1:?usage: contention.sh OUT}; mkdir -p "$out"
copies=${COPIES:-"1 8 16"}
exec > >(tee "$out/contention.log") 2>&1
date -u; nproc; lscpu | grep -v -e Vulnerab -e '^Flags'; cat /proc/loadavg
python3 "$here/unpack_inputs.py" "$here/inputs"
export LD_LIBRARY_PATH=$here/lib
ph=$here/pear_phases
A=$(ls "$here"/inputs/australia_*.json.gz | head -1)
G=$(ls "$here"/inputs/greenland_*.json.gz | head -1)
tmp=$(mktemp -d)
echo "== 1. N copies of the sequential engine at once (best of 9 runs each, ms)"
for n in $copies; do
  pids=()  # a bare `wait` would also wait for the tee above
  for i in $(seq "$n"); do "$ph" "$A" 9 top > "$tmp/c_${n}_$i.txt" & pids+=($!); done
  wait "${pids[@]}"
  echo "copies $n: $(grep -h 'top: wall' "$tmp"/c_"${n}"_*.txt | awk '{print $3}' | sort -n | tr '\n' ' ')"
done
echo "== 2. 16 partitions at 1, 4, 8, 16 threads"
for f in "$A" "$G"; do
  PEAR_PHASES_TASKS="clip chains" "$ph" "$f" 5 pc16t1 pc16t4 pc16t8 pc16t16 cdt16t1 cdt16t16
done
echo "== 3. the same with freed memory kept by malloc"
GLIBC_TUNABLES=glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=4294967295 \
  PEAR_PHASES_TASKS="clip chains" "$ph" "$A" 5 pc16t1 pc16t16 cdt16t16
if command -v taskset > /dev/null; then
  echo "== 4. 8 threads, one per physical core"
  cpus=$(lscpu -p=CPU,CORE | grep -v '^#' | sort -t, -k2,2n -u | cut -d, -f1 | head -8 | paste -sd,)
  echo "cpus $cpus"
  PEAR_PHASES_TASKS="clip chains" taskset -c "$cpus" "$ph" "$A" 5 pc16t1 pc16t8
fi
cat /proc/loadavg
rm -rf "$tmp"
