"""Other Python threads changing a call's inputs while pear works on them with the GIL released
(issue 30): pear must read one state of each input, never freed memory or a mix of states.
Each test runs a writer thread against many calls: enough that the bug it pins failed every
run before the fix."""
import sys
import threading

import numpy as np
import pytest

import pear

geometry = pytest.importorskip("shapely.geometry")


class Writer:
    """Calls change() in a loop in another thread while the with-block runs."""

    def __init__(self, change):
        self.change, self.stop = change, threading.Event()
        self.thread = threading.Thread(target=self.run)

    def run(self):
        while not self.stop.is_set():
            self.change()

    def __enter__(self):
        self.interval = sys.getswitchinterval()
        sys.setswitchinterval(1e-6)  # hand the GIL over as often as possible
        self.thread.start()
        return self

    def __exit__(self, *exc):
        self.stop.set()
        self.thread.join()
        sys.setswitchinterval(self.interval)


def line(points, y):
    """A zero-area "polygon" (pear rejects it fast): the test is about reading its WKB."""
    return geometry.Polygon(np.c_[np.arange(points, dtype=float), np.full(points, float(y))])


def test_bytearray_resized_while_its_wkb_is_parsed():
    # Before the fix triangulate_many parsed a bytearray's buffer in place with the GIL
    # released. The writer resizes the value between two WKB polygons, which frees its buffer,
    # and fills a buffer of the freed size with 0xff: the parse read mixed or freed bytes
    # (wrong coordinates, "byte order 255", "geometry type 14191") in about 1 call in 4, and
    # each of 10 runs of this test failed.
    first, second = line(3000, 0), line(2500, 1)
    states = {len(p.exterior.coords): np.array(p.exterior.coords) for p in (first, second)}
    value = bytearray(first.wkb)
    freed = []

    def resize():
        value[:] = second.wkb
        value[:] = first.wkb  # grows: a new buffer, the old one freed
        freed.append(bytearray(b"\xff") * len(first.wkb))
        del freed[:-8]

    with Writer(resize):
        for _ in range(60):
            result = pear.triangulate_many([value] * 100, threads=1)
            points = result.geometry_point_offsets()
            for g in range(100):
                coords = result.coordinates[points[g]:points[g + 1]]
                assert len(coords) in states, f"geometry {g}: {len(coords)} points"
                assert np.array_equal(coords, states[len(coords)]), f"geometry {g}"


def test_offsets_written_while_the_batch_runs():
    # Before the fix triangulate_many read the caller's int64 offsets in place with the GIL
    # released: a polygon's offsets were checked, then read again to copy its points, and the
    # writer's shifted state between the two sent the copy 2^40 points before the array
    # (a segmentation fault in each of 10 runs of this test).
    n = 20000
    coords = np.tile([[0, 0], [1, 0], [1, 1], [0, 1.0]], (n, 1))
    rings = np.arange(0, 4 * n + 1, 4, dtype=np.int64)
    polygons = np.arange(n + 1, dtype=np.int64)
    good, shifted = rings.copy(), rings - 2**40

    def write():
        rings[:] = shifted
        rings[:] = good

    with Writer(write):
        for _ in range(300):
            result = pear.triangulate_many(coords, rings, polygons, threads=1)
            # Whatever mix of the two states the call read: a polygon with good offsets is its
            # own square, one with shifted offsets is invalid_offsets; nothing else.
            ok = result.status == pear.Status.ok
            assert np.all(ok | (result.status == pear.Status.invalid_input))
            assert np.all(np.diff(result.triangle_offsets) == np.where(ok, 2, 0))
            owner = np.repeat(np.arange(n), np.diff(result.triangle_offsets))
            assert np.all(result.triangles // 4 == owner[:, None])
            issues = result.diagnostic_issue[result.diagnostic_offsets[:-1][~ok]]
            if len(issues):  # each bad polygon's first finding: invalid_offsets
                assert result.diagnostics(int(np.argmin(ok)))[0].issue == "invalid_offsets"
                assert np.all(issues == issues[0])
