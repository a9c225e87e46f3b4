#!/usr/bin/env bash
# Installs what pear's build, tests and tools need on Debian 12 (as root, or through sudo).
# Usage: scripts/setup.sh [minimal]   minimal: only what the library and the CLI need.
set -euo pipefail
packages=(meson ninja-build g++ pkg-config zlib1g-dev python3)
if [[ "${1:-}" != minimal ]]; then
  packages+=(libgtest-dev libgmp-dev libbenchmark-dev libcgal-dev libgeos-dev libtbb-dev
             libglu1-mesa-dev python3-matplotlib
             clang clang-format libclang-rt-14-dev   # clang's libFuzzer and sanitizer runtimes
             cmake                                   # tests/cmake_consumer: find_package(pear)
             # tests/cli/test_svg_render.py: the CLI's SVG drawn by real renderers, read by Pillow
             librsvg2-bin python3-pil
             chromium                                # ~90 MB download, ~20 s to unpack: 'large' only
             libgdal-dev gdal-bin                    # the CLI's GIS formats; ogr2ogr in tests/cli
             # the Python package (python/) and its tests: shapely, geopandas, Dask, earcut
             python3-dev pybind11-dev python3-mesonpy python3-numpy python3-pytest
             python3-shapely python3-geopandas python3-dask python3-distributed
             python3-mapbox-earcut
             python3-mypy                            # stubtest: the type stubs against the module
             # the JavaScript package (js/): its WebAssembly build (binaryen: wasm-opt, 10%
             # smaller) and node for its tests
             clang-14 lld-14 wasi-libc libc++-14-dev-wasm32 libclang-rt-14-dev-wasm32 binaryen
             nodejs)
  # npm fetches earcut.js for the tests; nodejs from nodesource brings its own npm
  command -v npm >/dev/null || packages+=(npm)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0
sudo=""
[[ "$(id -u)" -ne 0 ]] && sudo="sudo"
export DEBIAN_FRONTEND=noninteractive
$sudo apt-get update -qq
$sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
