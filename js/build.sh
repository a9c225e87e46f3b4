#!/usr/bin/env bash
# Builds js/pear.wasm: libpear without threads for wasm32-wasi with Debian's clang 14, lld and
# wasi-libc (js/wasm32-wasi.ini), and the C ABI of js/wasm/exports.cpp.
#   js/build.sh [--small] [BUILD_DIR]   (default BUILD_DIR: build-wasm at the repository root)
# -O2 with link-time optimization by default, the code off the per-polygon path at -Oz
# (src/meson.build); --small: everything at -Os. Then binaryen's wasm-opt -Os, where installed
# (scripts/setup.sh installs it): 10% smaller than none, 0.9% smaller than its -O2 and as fast
# in node (docs/javascript.md, "Size"). docs/javascript.md ("Size") has the figures.
# Exits 77 (a skip to the tests) when the toolchain is not installed (scripts/setup.sh installs it).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
optimization=2
if [[ ${1:-} == --small ]]; then
  optimization=s  # Debian 12's Meson has no optimization=z (-Oz: 316 KB against -Os's 322)
  shift
fi
build=${1:-build-wasm}
for tool in clang++-14 wasm-ld-14 llvm-ar-14; do
  command -v "$tool" >/dev/null || { echo "js/build.sh: $tool not found (scripts/setup.sh)"; exit 77; }
done
for dir in /usr/include/wasm32-wasi /usr/lib/llvm-14/lib/clang/14.0.6/lib/wasi; do
  [[ -d $dir ]] || { echo "js/build.sh: $dir not found (wasi-libc, libc++-14-dev-wasm32, libclang-rt-14-dev-wasm32)"; exit 77; }
done
[[ -f $build/build.ninja ]] ||
  meson setup "$build" --cross-file js/wasm32-wasi.ini --buildtype=release \
    -Doptimization="$optimization" -Db_lto=true -Ddefault_library=static -Dinstall_library=false \
    -Dthreads=disabled -Dtests=disabled -Dbench=disabled -Dfuzz=disabled -Dcli=disabled \
    -Dpython=disabled >/dev/null
ninja -C "$build" -j"${JOBS:-2}" js/pear.wasm
if command -v wasm-opt >/dev/null; then
  # The features of js/wasm32-wasi.ini: --strip-all dropped the section that lists them.
  wasm-opt -Os --enable-simd --enable-nontrapping-float-to-int --enable-bulk-memory \
    --enable-sign-ext "$build/js/pear.wasm" -o js/pear.wasm
else
  echo "js/build.sh: wasm-opt not found (binaryen, scripts/setup.sh): js/pear.wasm not post-optimized"
  cp "$build/js/pear.wasm" js/pear.wasm
fi
echo "js/pear.wasm: $(stat -c %s js/pear.wasm) bytes"
