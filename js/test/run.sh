#!/usr/bin/env bash
# The JavaScript package's tests (node's test runner), as the meson test 'js' runs them:
#   js/test/run.sh [PEAR_CLI]   the native CLI to compare triangles with (else those tests skip)
# Exits 77 (meson: SKIP) without node or without js/pear.wasm (js/build.sh builds it).
set -euo pipefail
js="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
command -v node >/dev/null || { echo "skipped: node not found"; exit 77; }
[[ -f $js/pear.wasm ]] || { echo "skipped: js/pear.wasm not built (js/build.sh)"; exit 77; }
export PEAR_CLI=${1:+$(realpath "$1")}
cd "$js"
# --expose-gc: the test that no call allocates on the JavaScript side collects garbage first.
exec node --expose-gc --test test/*.test.js
