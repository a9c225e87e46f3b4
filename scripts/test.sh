#!/usr/bin/env bash
# Builds pear with its tests and the Python package and runs them all (meson test; the Python
# tests are the suite 'python', pytest under Debian's python3). The tests that read
# ../shared/corpus run when it is there and skip themselves otherwise (meson: SKIP).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
scripts/setup.sh
[[ -f build-test/build.ninja ]] ||
  meson setup build-test --buildtype=release -Dtests=enabled -Dbench=disabled -Dfuzz=disabled \
    -Dpython=enabled >/dev/null
ninja -C build-test -j"${JOBS:-2}"
meson test -C build-test --print-errorlogs --num-processes "${JOBS:-2}"
