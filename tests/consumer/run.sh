#!/bin/sh
# Builds tests/consumer against this checkout as a Meson subproject and runs it.
# NINJA_JOBS limits the build's parallelism (ninja's default otherwise).
set -eu
here=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$here/subprojects"
ln -sfn ../../.. "$here/subprojects/pear"  # the repository root, relative to subprojects/
build=$(mktemp -d)
trap 'rm -rf "$build"' EXIT
log="$build/consumer.log"
if ! meson setup "$build" "$here" >"$log" 2>&1 ||
   ! ninja -C "$build" ${NINJA_JOBS:+-j "$NINJA_JOBS"} >>"$log" 2>&1; then
  cat "$log"
  echo "consumer: build failed" >&2
  exit 1
fi
"$build/consumer"
echo "consumer: ok"
