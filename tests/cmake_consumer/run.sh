#!/usr/bin/env bash
# Installs pear (library, headers, pkg-config and CMake files) into a staging folder and checks
# it as a CMake user would: find_package(pear CONFIG) takes the version asked for and refuses
# others; tests/cmake_consumer builds against pear::io and runs; every installed public header
# compiles alone under strict warnings (check_headers.sh). The install is staged (DESTDIR)
# away from the prefix pear was configured for, so the package must find its files relative to
# itself. BUILD: pear's build folder, any with install_library on (CI reuses build-test);
# default build-cmake, configured here for /opt/pear with only the libraries. NINJA_JOBS
# limits the build's parallelism.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${BUILD:-$root/build-cmake}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
log="$work/log"

step() {  # step WHAT COMMAND...: runs the command quietly, shows its log when it fails
  if ! "${@:2}" >"$log" 2>&1; then
    cat "$log"
    echo "cmake_consumer: $1 failed" >&2
    exit 1
  fi
}

[[ -f "$build/build.ninja" ]] ||
  step "meson setup" meson setup "$build" "$root" --buildtype=release --prefix=/opt/pear \
    -Dtests=disabled -Dbench=disabled -Dfuzz=disabled -Dpython=disabled -Dcli=disabled
step "ninja" ninja -C "$build" ${NINJA_JOBS:+-j "$NINJA_JOBS"}
step "meson install" meson install -C "$build" --destdir "$work/stage" --no-rebuild
configured_prefix=$(meson introspect "$build" --buildoptions |
  python3 -c 'import json, sys; print(*(o["value"] for o in json.load(sys.stdin) if o["name"] == "prefix"))')
prefix="$work/stage$configured_prefix"
[[ -f "$prefix/include/pear/pear.hpp" ]] ||
  { echo "cmake_consumer: $build installs no pear/pear.hpp (install_library off?)" >&2; exit 1; }

# The version pear's meson.build declares, and requests find_package must accept and refuse.
version=$(meson introspect "$build" --projectinfo |
  python3 -c 'import json, sys; print(json.load(sys.stdin)["version"])')
IFS=. read -r major minor patch <<<"$version"
accepted=("$major.$minor" "$major.$minor...<$((major + 1))")
refused=("$((major + 1)).0" "$major.$minor.$((patch + 1))" "$major.$((minor + 1))...$((major + 1))")

configure() {  # configure DIR VERSION: the consumer configured against the staged tree
  cmake -S "$here" -B "$1" -DCMAKE_PREFIX_PATH="$prefix" -DPEAR_REQUEST="$2" \
    -DCMAKE_BUILD_TYPE=Release
}
step "cmake (pear ${accepted[0]})" configure "$work/b" "${accepted[0]}"
grep -q "pear $version from $prefix/" "$log" ||
  { cat "$log"; echo "cmake_consumer: pear $version was not found in the staged tree" >&2; exit 1; }
step "cmake --build" cmake --build "$work/b"
"$work/b/cmake_consumer"
step "cmake (pear ${accepted[1]})" configure "$work/range" "${accepted[1]}"
for request in "${refused[@]}"; do
  if configure "$work/refused" "$request" >"$log" 2>&1; then
    cat "$log"
    echo "cmake_consumer: find_package(pear $request) accepted pear $version" >&2
    exit 1
  fi
  rm -rf "$work/refused"
done
echo "cmake_consumer: pear $version; ${accepted[*]} accepted, ${refused[*]} refused"
bash "$here/check_headers.sh" "$prefix/include"
