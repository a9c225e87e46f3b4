#!/usr/bin/env python3
"""Checks that every #include in src/ respects the floors of docs/architecture.md.

A folder may include its own headers, the public headers (pear/...), and the internal
headers of the folders listed for it below. Exit status 1, naming file, line and header,
when an include goes anywhere else (upward, or sideways between algorithms).

usage: scripts/check_layers.py [REPO_ROOT]
"""
import pathlib
import re
import sys

# Top to bottom. Each folder may use the folders listed (and nothing above it).
ALLOWED = {
    "io": {"geometry"},
    "generate": {"geometry", "predicates"},
    # The pipeline alone reaches the scheduler (threads_on.cpp), the stages through core/tasks.
    "pipeline": {"clean", "earclip", "parallel", "cdt", "simplicity", "core", "geometry",
                 "scheduler", "predicates"},
    "clean": {"core", "geometry", "predicates"},
    # The algorithms side by side: the parallel variants reach the sequential engine through
    # core/cycle_clipper.hpp, which the pipeline hands them.
    "parallel": {"core", "geometry", "predicates"},
    "earclip": {"core", "geometry", "predicates"},
    "simplicity": {"core", "geometry", "predicates"},
    "cdt": {"core", "geometry", "predicates"},
    "validate": {"geometry", "predicates"},
    "core": {"geometry", "predicates"},
    "geometry": {"predicates"},
    "scheduler": set(),
    "predicates": set(),
}

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')


def folder_of(header: str, own: str) -> str:
    """The src/ folder a quoted include refers to: 'x/y.hpp' is folder x, 'y.hpp' our own."""
    parts = pathlib.PurePosixPath(header).parts
    if parts[0] == "..":
        return "<relative>"
    return parts[0] if len(parts) > 1 else own


def main() -> int:
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    src = root / "src"
    problems = []
    folders = sorted(p.name for p in src.iterdir() if p.is_dir())
    for folder in folders:
        if folder not in ALLOWED:
            problems.append(f"src/{folder}: a folder docs/architecture.md does not place")
            continue
        for path in sorted((src / folder).glob("*.[ch]pp")):
            for number, line in enumerate(path.read_text().splitlines(), 1):
                match = INCLUDE.match(line)
                if not match or match.group(1).startswith("pear/"):
                    continue
                target = folder_of(match.group(1), folder)
                if target != folder and target not in ALLOWED[folder]:
                    problems.append(f"{path.relative_to(root)}:{number}: includes "
                                    f"\"{match.group(1)}\" ({target}), not allowed for {folder}")
    for problem in problems:
        print(problem)
    if not problems:
        print(f"layers: {len(folders)} folders, every include in place")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
