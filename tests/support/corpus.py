"""The corpora for the Python tests, as tests/support/corpus.hpp is for the C++ ones.

The shared corpus is PEAR_SHARED_CORPUS, else ../shared/corpus beside the source tree; the bundled
one PEAR_CORPUS, else the source tree's corpus/. Each folder's MANIFEST.tsv is read by its header.
A test whose data is absent raises unittest.SkipTest through require() (or with MISSING_TOOL for
a missing program); main() runs the tests and exits 77 (meson's SKIP) when every test that ran
was skipped that way.
"""
import dataclasses
import os
import pathlib
import sys
import unittest

REPO = pathlib.Path(__file__).resolve().parents[2]
MISSING_DATA = "missing data: "
MISSING_TOOL = "missing tool: "  # a renderer or module a test needs; skips like missing data
DEFECTS = ("GEOS:", "NOT SIMPLE", "DEGENERATE")


def shared_root():
    return pathlib.Path(os.environ.get("PEAR_SHARED_CORPUS") or REPO.parent / "shared" / "corpus")


def bundled_root():
    return pathlib.Path(os.environ.get("PEAR_CORPUS") or REPO / "corpus")


@dataclasses.dataclass
class File:
    """One MANIFEST.tsv row; valid: the row records no defect (GEOS verdict, NOT SIMPLE, ...)."""
    folder: str
    file: str
    path: pathlib.Path
    vertices: int
    holes: int
    source: str
    licence: str
    valid: bool


def read_folder(root, name):
    """The folder's files in MANIFEST order; skips the calling test when it cannot be read."""
    manifest = pathlib.Path(root) / name / "MANIFEST.tsv"
    require(manifest)
    lines = [line for line in manifest.read_text().split("\n") if line]
    header = lines[0].split("\t")
    files = []
    for line in lines[1:]:
        row = dict(zip(header, line.split("\t")))
        files.append(File(name, row["file"], manifest.parent / row["file"],
                          int(row.get("vertices", 0)), int(row.get("holes", 0)),
                          row.get("source", ""), row.get("license/attribution", ""),
                          not any(defect in line for defect in DEFECTS)))
    return files


def require(*paths):
    """Skips the calling test, marked as missing data, unless every path exists."""
    for path in paths:
        if not os.path.exists(path):
            raise unittest.SkipTest(MISSING_DATA + str(path))


def main():
    """unittest.main, but exit status 77 when every test that ran skipped for missing data."""
    result = unittest.main(verbosity=2, exit=False).result
    missing = [test for test, reason in result.skipped
               if reason.startswith((MISSING_DATA, MISSING_TOOL))]
    if result.wasSuccessful() and result.testsRun > 0 and len(missing) == result.testsRun:
        sys.exit(77)
    sys.exit(0 if result.wasSuccessful() else 1)
