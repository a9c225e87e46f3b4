#!/usr/bin/env bash
# Fuzzes one target with libFuzzer for a while: fuzz/run.sh TARGET SECONDS [libFuzzer options]
# TARGET: degenerate bridged parallel cdt readers batch wkb. Sets up build-fuzz (clang,
# libFuzzer, ASan, UBSan; FUZZ_BUILD names another) when it is missing and builds only the
# target. The seeds in corpus/fuzz/TARGET are read, never written; an input slower than
# FUZZ_TIMEOUT seconds (30) is reported as a hang; inputs libFuzzer finds go to
# BUILD/fuzz-corpus/TARGET, a crash to BUILD/fuzz-artifacts/TARGET/ (then the exit status is 1).
# Add a crash to corpus/fuzz/TARGET/crash-WHAT to keep it as a regression input.
# Leave src/ alone while it builds: objects compiled from two versions of a header link into a
# binary that crashes on every input (it happened: 966 false crashes).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
target=${1:?usage: fuzz/run.sh TARGET SECONDS [libFuzzer options]}
seconds=${2:?usage: fuzz/run.sh TARGET SECONDS [libFuzzer options]}
shift 2
build=${FUZZ_BUILD:-build-fuzz}
# One set-up and build at a time in the build folder, so that several targets can be started at
# once; meson and ninja name their errors on stdout, shown only when they fail.
mkdir -p "$build"
if ! log=$(flock "$build/.fuzz-build.lock" bash -c '
    [[ -f $1/build.ninja ]] ||
      CC=clang CXX=clang++ meson setup "$1" --unity on -Dfuzz=enabled -Dtests=disabled \
        -Dbench=disabled -Dcli=disabled -Dpython=disabled -Db_sanitize=address,undefined \
        -Db_lundef=false
    ninja -C "$1" -j"$2" "fuzz/fuzz_$3"' _ "$build" "${JOBS:-2}" "$target" 2>&1); then
  printf '%s\n' "$log" >&2
  exit 1
fi
work=$build/fuzz-corpus/$target
artifacts=$build/fuzz-artifacts/$target/
mkdir -p "$work" "$artifacts"
options=(-max_total_time="$seconds" -timeout="${FUZZ_TIMEOUT:-30}" -rss_limit_mb=2048 -max_len=8192
         -print_final_stats=1 -artifact_prefix="$artifacts")
[[ -f fuzz/$target.dict ]] && options+=(-dict="fuzz/$target.dict")
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-halt_on_error=1:print_stacktrace=1}
exec "$build/fuzz/fuzz_$target" "${options[@]}" "$@" "$work" "corpus/fuzz/$target"
