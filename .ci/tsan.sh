#!/usr/bin/env bash
# ThreadSanitizer run of the scheduler's tests (deque, executor, task graphs) and of the
# parallel variants' tricky cases (several chains, chunks and parts at 2-8 threads), hole
# bridging in parts (the searches as tasks at 2-8 threads), the walks over runs of consecutive
# nodes (partition-and-cut's start, the cycles after untangling), the parallel CDT's cases
# (flips in breadth-first sets, border rounds, the bucketed adjacency build), cleaning in
# parallel passes and the simplicity check's runs (prepared and walked in tasks).
# Usage: .ci/tsan.sh [build-dir]   (default: build-tsan in the repository root)
# The sanitizer build is separate: only the library and the scheduler tests are compiled.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${1:-$root/build-tsan}"
# gcc 12 gives a clean run here (CXX=clang++ works too; gtest stays uninstrumented either way).
export CXX="${CXX:-g++}"

if [[ ! -f "$build/build.ninja" ]]; then
  meson setup "$build" "$root" --unity on \
    -Db_sanitize=thread -Db_lundef=false -Doptimization=2 -Ddebug=false -Dcpp_args=-g1 \
    -Dbench=disabled -Dcli=disabled -Dtests=enabled -Dfuzz=disabled
fi
ninja -C "$build" -j"${JOBS:-2}" \
  tests/scheduler/scheduler_deque_test \
  tests/scheduler/scheduler_executor_test \
  tests/scheduler/scheduler_graph_test \
  tests/parallel/parallel_variants_test \
  tests/parallel/shared_boundary_test \
  tests/earclip/earclip_bridge_test \
  tests/parallel/divide_conquer_test \
  tests/cdt/cdt_test \
  tests/cdt/cdt_mesh_test \
  tests/pipeline/batch_test \
  tests/pipeline/clean_test \
  tests/simplicity/simplicity_test

# halt_on_error: the first report fails the run (exit code 66), so CI cannot miss one.
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 ${TSAN_OPTIONS:-}"
meson test -C "$build" --suite scheduler --no-rebuild --print-errorlogs
# ManyHolesBridgedInParts (22,000 vertices, 36 runs) is left to the other builds: the bridge
# test below runs the same parallel phases on small polygons (its generated families, too, only
# there: under TSan they take seconds).
"$build/tests/parallel/parallel_variants_test" --gtest_filter='Tricky.*:-Tricky.ManyHolesBridgedInParts'
"$build/tests/parallel/shared_boundary_test"
"$build/tests/earclip/earclip_bridge_test" --gtest_filter='-*GeneratedFamilies'
"$build/tests/parallel/divide_conquer_test" --gtest_filter='DivideAndConquer.*'
"$build/tests/cdt/cdt_test" --gtest_filter='Cdt.*'
"$build/tests/cdt/cdt_mesh_test" --gtest_filter='Families/MeshBuild.*/0'
"$build/tests/pipeline/batch_test" --gtest_filter='Batch.SameAsOneCall*:Batch.OnTheCallersExecutor'
"$build/tests/pipeline/clean_test"
"$build/tests/simplicity/simplicity_test" --gtest_filter='Simplicity.RunsPrepared*:Simplicity.RunPairsInTasks*'
