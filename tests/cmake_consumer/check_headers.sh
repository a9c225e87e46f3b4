#!/usr/bin/env bash
# Compiles every public header of an installed pear alone, then templates.cpp (the headers'
# templates instantiated with users' types), with g++ and clang++ under the strict warnings a
# user's build may have: a header must not warn in someone else's project.
# Usage: check_headers.sh INCLUDEDIR...   the installed tree's include/ (or the source tree's
# include/ and the build's include/, which holds the generated pear/config.hpp)
set -euo pipefail
[[ $# -gt 0 ]] || { echo "usage: check_headers.sh INCLUDEDIR..." >&2; exit 2; }
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
flags=(-std=c++20 -Wall -Wextra -Wpedantic -Wsign-conversion -Werror)
for dir in "$@"; do flags+=(-I"$(cd "$dir" && pwd)"); done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
headers=$(for dir in "$@"; do (cd "$dir" && find pear -name '*.hpp'); done | sort -u)
[[ $(wc -w <<<"$headers") -gt 1 ]] || { echo "check_headers: no pear/*.hpp under $*" >&2; exit 1; }
count=0
for cxx in g++ clang++; do
  for header in $headers; do
    printf '#include <%s>\n' "$header" >"$work/alone.cpp"
    "$cxx" "${flags[@]}" -fsyntax-only "$work/alone.cpp" ||
      { echo "check_headers: $header alone fails under $cxx" >&2; exit 1; }
    count=$((count + 1))
  done
  "$cxx" "${flags[@]}" -c -o "$work/templates.o" "$here/templates.cpp" ||
    { echo "check_headers: the templates fail under $cxx" >&2; exit 1; }
done
echo "check_headers: $count header compilations and the templates clean under g++ and clang++"
