#!/usr/bin/env bash
# The main job: build pear (library + CLI), triangulate a bundled real polygon (Mozambique,
# Natural Earth 1:10m, with its lakes), print the stats and write a picture to pear-demo.svg.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
scripts/setup.sh minimal
# PEAR_DEMO_BUILD: an existing build folder whose CLI to use (CI's build-test) instead of
# build-release. build-release is a unity build (a few sources compiled as one): the first
# build in 40% less time.
build=${PEAR_DEMO_BUILD:-build-release}
[[ -f $build/build.ninja ]] ||
  meson setup "$build" --buildtype=release --unity on -Dtests=disabled -Dbench=disabled \
    -Dfuzz=disabled >/dev/null
ninja -C "$build" tools/pear/pear >/dev/null
"./$build/tools/pear/pear" triangulate corpus/countries/mozambique_000.json --stats --validate -o pear-demo.svg
echo "picture: $(pwd)/pear-demo.svg"
