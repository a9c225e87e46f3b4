#!/usr/bin/env python3
"""Checks that two builds of pear give the same triangles on the bundled corpus.

For the -Dthreads=disabled build against a threaded one: with the same options the
single-threaded build must triangulate exactly as the threaded build does with --threads 1
(and --partitions fixed, so that the parallel variants cut alike). Every polygon of corpus/
(countries, earcut, glyphs), every algorithm, with and without the CDT; the triangles are
compared as the CLI writes them (OBJ, every index).

usage: scripts/compare_builds.py PEAR_THREADED PEAR_OTHER
"""
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
ALGORITHMS = ["auto", "sequential", "partition-and-cut", "mark-and-cut", "divide-and-conquer"]


def triangles(pear, folder, out, extra):
    """The OBJ text of every polygon of `folder`, by file name."""
    out.mkdir(parents=True, exist_ok=True)
    subprocess.run([pear, "triangulate", str(folder), "-o", f"{out}/", "--format", "obj",
                    *extra], check=False, capture_output=True)
    return {p.name: p.read_text() for p in sorted(out.glob("*.obj"))}


def main() -> int:
    threaded, other = sys.argv[1], sys.argv[2]
    compared, differ = 0, []
    with tempfile.TemporaryDirectory() as tmp:
        for folder in ["countries", "earcut", "glyphs"]:
            for algorithm in ALGORITHMS:
                for cdt in ([], ["--cdt"]):
                    options = ["--algorithm", algorithm, "--partitions", "4", *cdt]
                    name = f"{folder}-{algorithm}{'-cdt' if cdt else ''}"
                    a = triangles(threaded, ROOT / "corpus" / folder, pathlib.Path(tmp) / name / "a",
                                  options + ["--threads", "1"])
                    b = triangles(other, ROOT / "corpus" / folder, pathlib.Path(tmp) / name / "b",
                                  options)
                    if not a or a.keys() != b.keys():
                        differ.append(f"{name}: files {sorted(a)} against {sorted(b)}")
                        continue
                    for file in a:
                        compared += 1
                        if a[file] != b[file]:
                            differ.append(f"{name}: {file}")
    for line in differ:
        print("differs:", line)
    print(f"{compared} triangulations compared, {len(differ)} differ")
    return 1 if differ or compared == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
