#!/usr/bin/env python3
"""Checks that a -Dthreads=disabled build of libpear includes no thread header.

Reads the header dependencies ninja recorded for libpear's objects in BUILD_DIR and fails,
naming the file and line, when any of them (or a source) includes <thread>, <stop_token>,
<mutex>, <condition_variable> or <future>.

usage: scripts/check_no_threads.py BUILD_DIR
"""
import pathlib
import re
import subprocess
import sys

THREAD_HEADERS = re.compile(r"^\s*#\s*include\s*<(thread|stop_token|mutex|condition_variable|future)>")


def main() -> int:
    build = pathlib.Path(sys.argv[1]).resolve()
    deps = subprocess.run(["ninja", "-C", str(build), "-t", "deps"], capture_output=True,
                          text=True, check=True).stdout
    files, current_is_pear = set(), False
    for line in deps.splitlines():
        if line and not line.startswith(" "):  # "target: #deps N, ..."
            current_is_pear = line.startswith("src/libpear_core.a.p/")
        elif current_is_pear and line.strip():
            path = (build / line.strip()).resolve()
            if path.suffix in (".cpp", ".hpp") and "include/c++" not in str(path):
                files.add(path)
    if not files:
        print(f"{build}: no dependencies of libpear's objects recorded (built?)")
        return 1
    problems = []
    for path in sorted(files):
        for number, text in enumerate(path.read_text().splitlines(), 1):
            if THREAD_HEADERS.match(text):
                problems.append(f"{path}:{number}: {text.strip()}")
    for problem in problems:
        print(problem)
    if not problems:
        print(f"no thread header in the {len(files)} files of libpear in {build}")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
