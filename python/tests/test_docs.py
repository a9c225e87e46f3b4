"""The Python code blocks of README.md and docs/python.md, run exactly as written.

Convention: the line before each ```python fence is a mark, either <!-- test: run --> (the
block is a program: this test writes it to a file and runs it with this interpreter in a
fresh folder holding the data it reads) or <!-- test: skip (why) --> (a signature, a
fragment). An unmarked Python block fails the first test, so none is forgotten.
"""
import os
import pathlib
import re
import signal
import subprocess
import sys

import pytest

from polygons import child_environment, counties_frame

REPO = pathlib.Path(__file__).resolve().parents[2]
DOCUMENTS = ("README.md", "docs/python.md")
RUN = "<!-- test: run -->"
SKIP = re.compile(r"<!-- test: skip \(.+\) -->")
TIMEOUT = 240  # seconds: a recipe that hangs (the Dask one did) fails instead


def python_blocks(document):
    """(line number, mark, code) of every ```python block; mark: the line before the fence."""
    lines = (REPO / document).read_text().split("\n")
    blocks = []
    for n, line in enumerate(lines):
        if line.strip() == "```python":
            end = lines.index("```", n + 1) if "```" in lines[n + 1:] else len(lines)
            mark = lines[n - 1].strip() if n > 0 else ""
            blocks.append((n + 1, mark, "\n".join(lines[n + 1:end]) + "\n"))
    return blocks


RUNNABLE = [pytest.param(code, id=f"{document}:{line}")
            for document in DOCUMENTS for line, mark, code in python_blocks(document)
            if mark == RUN]


def test_every_python_block_is_marked():
    unmarked = [f"{document}:{line}" for document in DOCUMENTS
                for line, mark, _ in python_blocks(document)
                if mark != RUN and not SKIP.fullmatch(mark)]
    assert not unmarked, f"mark each with {RUN} or <!-- test: skip (why) -->: {unmarked}"
    assert len(RUNNABLE) >= 3


def write_counties(folder):
    """counties.gpkg, the Dask recipe's input: the shared corpus' counties, through geopandas
    (GDAL's GeoPackage driver, by fiona). Returns the frame written."""
    frame = counties_frame()
    frame.to_file(folder / "counties.gpkg", driver="GPKG")
    return frame


def check_output(code, stdout, written):
    """What a block that reads data prints, checked against that data."""
    if "counties.gpkg" not in code:
        return
    import pear
    line = re.search(r"(\d+) of (\d+) counties", stdout)
    assert line, f"no 'N of M counties' line in what the recipe printed:\n{stdout}"
    ok, total = map(int, line.groups())
    statuses = pear.triangulate_many(written["counties.gpkg"].geometry).geometry_status
    assert total == len(written["counties.gpkg"])
    assert ok == (statuses == pear.Status.ok).sum()


def run_python(script, folder):
    """(stdout, stderr, exit status) of this interpreter running script in folder, as a user
    would. A run past TIMEOUT fails the test; its process group (Dask's workers with it) is
    killed, so nothing is left running."""
    process = subprocess.Popen([sys.executable, script], cwd=folder, env=child_environment(),
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               start_new_session=True)
    try:
        stdout, stderr = process.communicate(timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        stdout, stderr = process.communicate()
        pytest.fail(f"{script} hung for {TIMEOUT} s:\n{stdout}\n{stderr[-4000:]}")
    return stdout, stderr, process.returncode


@pytest.mark.parametrize("code", RUNNABLE)
def test_block_runs_as_written(code, tmp_path):
    for module in ("shapely", "geopandas", "dask", "distributed"):
        if re.search(rf"\b{module}\b", code):
            pytest.importorskip(module)  # an optional dependency the block uses
    written = {}
    if "counties.gpkg" in code:
        written["counties.gpkg"] = write_counties(tmp_path)
    (tmp_path / "recipe.py").write_text(code)
    stdout, stderr, status = run_python("recipe.py", tmp_path)
    assert status == 0, f"exit status {status}:\n{stdout}\n{stderr[-4000:]}"
    check_output(code, stdout, written)
