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
alone() {  # alone CXX HEADER: the header as the only include of a source
  local source
  source=$(mktemp "$work/alone.XXXXXX.cpp")
  printf '#include <%s>\n' "$2" >"$source"
  "$1" "${flags[@]}" -fsyntax-only "$source" ||
    { echo "check_headers: $2 alone fails under $1" >&2; return 1; }
}
# JOBS at a time (2 by default): one compiler after another took half a minute of CI.
count=0
for cxx in g++ clang++; do
  running=()
  for header in $headers; do
    alone "$cxx" "$header" &
    running+=("$!")
    count=$((count + 1))
    if [[ ${#running[@]} -ge ${JOBS:-2} ]]; then
      wait "${running[0]}" || exit 1
      running=("${running[@]:1}")
    fi
  done
  for pid in "${running[@]}"; do wait "$pid" || exit 1; done
  "$cxx" "${flags[@]}" -c -o "$work/templates.o" "$here/templates.cpp" ||
    { echo "check_headers: the templates fail under $cxx" >&2; exit 1; }
done
echo "check_headers: $count header compilations and the templates clean under g++ and clang++"
