#!/usr/bin/env bash
# Builds pear with its tests and the Python package and runs them all (meson test; the Python
# tests are the suite 'python', pytest under Debian's python3). The tests that read
# ../shared/corpus run when it is there and skip themselves otherwise (meson: SKIP). The JavaScript
# package's WebAssembly module is built first (js/build.sh; its tests, the suite 'js', skip
# without it), and earcut.js installed for them from npm (js/package-lock.json).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
scripts/setup.sh
# PEAR_UNITY=on (CI sets it) compiles a few sources as one: 40% less build time.
[[ -f build-test/build.ninja ]] ||
  meson setup build-test --buildtype=release ${PEAR_UNITY:+--unity "$PEAR_UNITY"} \
    -Dtests=enabled -Dbench=disabled -Dfuzz=disabled -Dpython=enabled >/dev/null
ninja -C build-test -j"${JOBS:-2}"
bash js/build.sh || [[ $? -eq 77 ]]
if command -v npm >/dev/null && [[ ! -d js/node_modules/earcut ]]; then
  (cd js && npm ci --no-audit --no-fund --loglevel=error)
fi
meson test -C build-test --print-errorlogs --num-processes "${JOBS:-2}"
