"""pear.triangulate_many: ragged arrays, shapely geometries and WKB in; flat triangles out."""
import struct

import numpy as np
import pytest

import pear
import polygons
from polygons import BOWTIE, SQUARE_WITH_HOLE, exact_check

geometry = pytest.importorskip("shapely.geometry")
wkb = pytest.importorskip("shapely.wkb")

SQUARE = geometry.Polygon(SQUARE_WITH_HOLE[:4], [SQUARE_WITH_HOLE[4:]])
TRIANGLE = geometry.Polygon([(20, 0), (30, 0), (30, 10)])


def ragged(polygons):
    """(coords, ring_offsets, polygon_offsets) of (coords, ring offsets) pairs."""
    coords, rings, starts, base = [], [0], [0], 0
    for points, offsets in polygons:
        coords.append(points)
        rings.extend(base + o for o in offsets[1:])
        starts.append(len(rings) - 1)
        base += len(points)
    return np.vstack(coords), np.array(rings), np.array(starts)


def test_ragged_equals_one_call_per_polygon():
    polygons = [(SQUARE_WITH_HOLE, [0, 4, 8]), (SQUARE_WITH_HOLE[:4] * 3, [0, 4]),
                (BOWTIE, [0, 4]), (np.array([[0, 0], [1, 1], [2, 2.0]]), [0, 3])]
    coords, rings, starts = ragged(polygons)
    result = pear.triangulate_many(coords, rings, starts, threads=2)
    assert len(result) == 4 and result.coordinates is coords
    assert result.status.tolist() == [pear.Status.ok, pear.Status.ok, pear.Status.not_simple,
                                      pear.Status.invalid_input]
    base = 0
    for p, (points, offsets) in enumerate(polygons):
        mine = result.polygon_triangles(p) - base
        if p < 3:
            expected, _ = pear.triangulate(points, offsets, strict=False)
            assert np.array_equal(mine, expected)
        else:
            assert len(mine) == 0
        base += len(points)
    assert exact_check(SQUARE_WITH_HOLE, [0, 4, 8], result.polygon_triangles(0)) == []
    assert [d.issue for d in result.diagnostics(2)] == ["not_simple"]
    assert [d.issue for d in result.diagnostics(3)] == ["outer_ring_too_small"]
    assert "not_simple=1" in repr(result) and not result.ok
    with pytest.raises(pear.NotSimpleError, match="polygon 2"):
        result.check()


def test_ragged_bad_offsets_are_a_status_not_an_exception():
    coords, rings, starts = ragged([(SQUARE_WITH_HOLE, [0, 4, 8])])
    result = pear.triangulate_many(coords, [0, 9, 8], starts)
    assert result.status.tolist() == [pear.Status.invalid_input]
    assert result.diagnostics(0)[0].issue == "invalid_offsets"
    with pytest.raises(TypeError):
        pear.triangulate_many(coords, rings)
    with pytest.raises(ValueError, match="geometry_offsets"):
        pear.triangulate_many(coords, rings, starts, [0, 2])


def test_threads_and_options_do_not_change_equal_inputs():
    coords, rings, starts = ragged([(SQUARE_WITH_HOLE * (k + 1), [0, 4, 8]) for k in range(500)])
    one = pear.triangulate_many(coords, rings, starts, threads=1)
    two = pear.triangulate_many(coords, rings, starts, threads=2)
    assert np.array_equal(one.triangles, two.triangles) and one.ok
    assert np.array_equal(one.triangle_offsets, np.arange(501) * 8)
    cdt = pear.triangulate_many(coords, rings, starts, delaunay=True, heuristic="fast")
    assert cdt.ok and len(cdt.triangles) == 4000


def test_geometries_wkb_and_none():
    multi = geometry.MultiPolygon([SQUARE, TRIANGLE])
    as_array = np.empty(3, dtype=object)
    for i, value in enumerate([SQUARE, None, multi]):
        as_array[i] = value
    for data in ([SQUARE, None, multi], [SQUARE.wkb, None, multi.wkb], as_array,
                 (g for g in [SQUARE, None, multi])):
        result = pear.triangulate_many(data)
        assert result.geometry_offsets.tolist() == [0, 1, 1, 3]
        assert result.geometry_status.tolist() == [0, 0, 0]
        per_geometry = result.geometry_triangles()
        assert [len(t) for t in per_geometry] == [8, 0, 9]
        assert np.array_equal(per_geometry[0], pear.triangulate(SQUARE))
        assert np.array_equal(per_geometry[2], pear.triangulate(multi))
        # The coordinates are shapely's, rings closed.
        first = result.geometry_point_offsets()
        assert np.array_equal(result.coordinates[first[2]:first[3]],
                              np.vstack([np.asarray(SQUARE.exterior.coords),
                                         np.asarray(SQUARE.interiors[0].coords),
                                         np.asarray(TRIANGLE.exterior.coords)]))


def test_empty_inputs():
    for data in ([], [None, None], [geometry.Polygon()]):
        result = pear.triangulate_many(data)
        assert len(result) == 0 and result.triangles.shape == (0, 3)
        assert len(result.geometry_triangles()) == len(data)
    assert pear.triangulate_many(SQUARE).geometry_offsets.tolist() == [0, 1]


def wkb_variants(polygon):
    """shapely's WKB of polygon in each byte order, with Z, and with an SRID (EWKB); and WKB
    built here for what shapely 1.8 does not write: ISO M and ZM, EWKB M and ZM, MultiPolygons
    whose parts differ in byte order."""
    z = geometry.Polygon([(x, y, 7.5) for x, y in polygon.exterior.coords],
                         [[(x, y, -1.0) for x, y in ring.coords] for ring in polygon.interiors])
    yield wkb.dumps(polygon)
    yield wkb.dumps(polygon, big_endian=True)
    yield wkb.dumps(z)
    yield wkb.dumps(z, big_endian=True, srid=4326)
    yield wkb.dumps(polygon, srid=3857)
    yield built_wkb(polygon, ">", 2003, extra=1)                  # ISO M, what ST_AsBinary gives
    yield built_wkb(polygon, "<", 3003, extra=2)                  # ISO ZM
    yield built_wkb(polygon, ">", 0x40000003, extra=1)            # EWKB M
    yield built_wkb(polygon, "<", 0xE0000003, extra=2, srid=4326)  # EWKB ZM with an SRID


def built_wkb(polygon, order, code, extra, srid=None):
    """A WKB Polygon of polygon's rings with `extra` ordinates (99.0) after x and y."""
    out = struct.pack(order + "BI", 0 if order == ">" else 1, code)
    if srid is not None:
        out += struct.pack(order + "I", srid)
    out += struct.pack(order + "I", 1 + len(polygon.interiors))
    for ring in [polygon.exterior, *polygon.interiors]:
        coords = list(ring.coords)
        out += struct.pack(order + "I", len(coords))
        out += b"".join(struct.pack(order + "d" * (2 + extra), x, y, *[99.0] * extra)
                        for x, y in coords)
    return out


def test_multipolygon_parts_in_either_byte_order():
    parts = [built_wkb(SQUARE, ">", 3, 0), built_wkb(TRIANGLE, "<", 1003, 1)]
    value = struct.pack("<BII", 1, 6, 2) + b"".join(parts)
    result = pear.triangulate_many([value])
    assert result.geometry_offsets.tolist() == [0, 2] and result.ok
    expected = pear.triangulate(geometry.MultiPolygon([SQUARE, TRIANGLE]))
    assert np.array_equal(result.geometry_triangles()[0], expected)
    nested = struct.pack("<BII", 1, 6, 1) + value
    with pytest.raises(pear.WKBError, match="part 0 is not a Polygon") as caught:
        pear.triangulate_many([nested])
    assert (caught.value.index, caught.value.offset) == (0, 9)


def test_wkb_forms_read_the_same_coordinates():
    expected = pear.triangulate_many([SQUARE])
    for value in wkb_variants(SQUARE):
        result = pear.triangulate_many([value, bytearray(value)])
        assert np.array_equal(result.coordinates[:10], expected.coordinates), value[:9]
        assert np.array_equal(result.geometry_triangles()[1], expected.triangles)


def test_wkb_round_trips_the_corpus_coordinates():
    """shapely writes, pear reads: the same doubles, bit for bit (big and little endian)."""
    from polygons import folder
    polygons = folder("glyphs", limit=40)
    shapes = [geometry.Polygon(p.rings()[0], p.rings()[1:]) for p in polygons]
    for big_endian in (False, True):
        result = pear.triangulate_many([wkb.dumps(s, big_endian=big_endian) for s in shapes])
        starts = result.geometry_point_offsets()
        for g, shape in enumerate(shapes):
            coords = np.vstack([np.asarray(r.coords) for r in [shape.exterior, *shape.interiors]])
            assert np.array_equal(result.coordinates[starts[g]:starts[g + 1]], coords)
        assert result.ok


@pytest.mark.parametrize("mangle, index, offset, reason", [
    (lambda b: b[:-3], 1, 97, "5 points needs 80 bytes, 77 are left"),
    (lambda b: b + b"\0", 1, 177, "1 bytes follow the end"),
    (lambda b: b[:4], 1, 1, "expected a geometry type"),
    (lambda b: b"\x07" + b[1:], 1, 0, "byte order 7"),
    (lambda b: b[:1] + struct.pack("<I", 2) + b[5:], 1, 1, "type 2 is not a Polygon"),
    (lambda b: b[:5] + struct.pack("<I", 10**6) + b[9:], 1, 5, "rings cannot fit"),
    (lambda b: b[:9] + struct.pack("<I", 10**6) + b[13:], 1, 13, "ring of 1000000 points"),
])
def test_bad_wkb_names_the_geometry_and_the_byte(mangle, index, offset, reason):
    good = wkb.dumps(SQUARE)
    with pytest.raises(pear.WKBError, match=reason) as caught:
        pear.triangulate_many([good, mangle(good), good])
    assert (caught.value.index, caught.value.offset) == (index, offset)
    assert f"geometry {index}, byte {offset}" in str(caught.value)
    assert isinstance(caught.value, ValueError)


def test_not_wkb_raises_type_error():
    with pytest.raises(TypeError, match="geometry 1"):
        pear.triangulate_many([SQUARE.wkb, "POLYGON ((0 0, 1 0, 1 1))"])
    with pytest.raises(ValueError, match="not a Polygon"):
        pear.triangulate_many([geometry.Point(1, 2)])


def test_triangles_as_wkb_read_back():
    triangles = pear.triangulate(SQUARE_WITH_HOLE, [4])
    values = pear._pear.triangles_wkb(SQUARE_WITH_HOLE, triangles)
    shapes = [wkb.loads(v) for v in values]
    assert sum(s.area for s in shapes) == SQUARE.area
    for shape, (a, b, c) in zip(shapes, triangles):
        assert list(shape.exterior.coords) == [tuple(SQUARE_WITH_HOLE[i]) for i in (a, b, c, a)]
    with pytest.raises(ValueError, match="index 8"):
        pear._pear.triangles_wkb(SQUARE_WITH_HOLE, [[0, 1, 8]])


def test_random_and_extreme_offsets_are_statuses():
    """Property (issue 30): whatever int64 offsets the caller hands over, one status per
    polygon, monotone triangle offsets, and a polygon is ok exactly when its offsets are good
    (then its triangles index its own points), else invalid_input naming the offsets."""
    rng = np.random.default_rng(30)
    coords = np.tile([[0, 0], [1, 0], [1, 1], [0, 1.0]], (4, 1))  # 4 squares
    ends = np.array([-2**63, 2**63 - 1, -1, 17, 2**62], dtype=np.int64)
    for _ in range(300):
        rings = np.arange(0, 17, 4, dtype=np.int64)
        polygons = np.arange(5, dtype=np.int64)
        for offsets in (rings, polygons):
            picks = rng.random(len(offsets)) < 0.25
            offsets[picks] = rng.choice(ends, picks.sum())
        result = pear.triangulate_many(coords, rings, polygons, threads=int(rng.integers(1, 3)))
        assert len(result) == 4 and result.triangle_offsets[0] == 0
        assert np.all(np.diff(result.triangle_offsets) >= 0)
        assert result.triangle_offsets[-1] == len(result.triangles)
        for p in range(4):
            r0, r1 = polygons[p], polygons[p + 1]
            good = 0 <= r0 < r1 <= 4 and all(0 <= rings[r] <= 16 for r in range(r0, r1 + 1)) \
                and np.all(np.diff(rings[r0:r1 + 1]) >= 0)
            if not good:
                assert result.status[p] == pear.Status.invalid_input
                assert result.diagnostics(p)[0].issue in ("invalid_offsets", "empty_input")
                assert len(result.polygon_triangles(p)) == 0
            elif result.status[p] == pear.Status.ok:
                mine = result.polygon_triangles(p)
                assert np.all((mine >= rings[r0]) & (mine < rings[r1]))


def test_mangled_wkb_is_an_error_naming_a_byte_inside_or_a_result():
    """Property (issue 30): WKB with bytes overwritten, cut or extended, in bytes or bytearray,
    raises WKBError naming the value and a byte within it, or reads coordinates of 16 bytes
    each at least; never anything else."""
    rng = np.random.default_rng(31)
    values = [SQUARE.wkb, wkb.dumps(SQUARE, big_endian=True), wkb.dumps(
        geometry.MultiPolygon([SQUARE, TRIANGLE]))]
    for _ in range(2000):
        data = bytearray(values[int(rng.integers(len(values)))])
        for _ in range(int(rng.integers(1, 4))):
            at = int(rng.integers(len(data)))
            data[at] = rng.choice([0, 1, 0xFF, int(rng.integers(256))])
        if rng.random() < 0.3:
            data = data[:int(rng.integers(len(data) + 1))]
        value = bytes(data) if rng.random() < 0.5 else data
        try:
            result = pear.triangulate_many([None, value], threads=1)
        except pear.WKBError as error:
            assert error.index == 1 and 0 <= error.offset <= len(value)
            continue
        assert 16 * len(result.coordinates) <= len(value)
        assert len(result.geometry_offsets) == 3


def test_a_geoseries_and_a_series_of_wkb_read_as_their_list():
    """Taken as their arrays (no Python loop over the rows), with None and a non-default
    index: the same arrays as from the list of the same values."""
    geopandas = pytest.importorskip("geopandas")
    shapes = [geometry.Polygon(SQUARE_WITH_HOLE[:4], [SQUARE_WITH_HOLE[4:]]), None,
              geometry.MultiPolygon([geometry.Polygon([(20, 0), (30, 0), (30, 10)]),
                                     geometry.Polygon([(40, 0), (50, 0), (50, 10)])])]
    series = geopandas.GeoSeries(shapes, index=[7, 3, 5])
    values = [None if s is None else s.wkb for s in shapes]
    wkb_series = geopandas.pd.Series(values, index=[1, 2, 0])
    for data, as_list in ((series, shapes), (wkb_series, values)):
        got, want = pear.triangulate_many(data), pear.triangulate_many(as_list)
        assert got.geometry_offsets.tolist() == [0, 1, 1, 3]
        for name in polygons.BATCH_ARRAYS:
            assert np.array_equal(getattr(got, name), getattr(want, name)), name


def circles(count, shift):
    """count 100-gons, shapely Polygons, moved by shift: 10,100 points for count=100."""
    angles = np.linspace(0, 2 * np.pi, 100, endpoint=False)
    ring = np.column_stack([np.cos(angles), np.sin(angles)])
    return [geometry.Polygon(ring * 5 + (12 * k + shift, shift)) for k in range(count)]


@pytest.mark.parametrize("as_wkb", [False, True])
def test_a_freed_results_buffer_serves_the_next_read_and_no_live_one_changes(as_wkb):
    """The coordinates buffer of a result freed is the next batch read's (no fresh pages to
    fault in): never while any array still uses it, and the values are the new ones."""
    first, second = circles(100, 0), circles(100, 1000)
    if as_wkb:
        first, second = [g.wkb for g in first], [g.wkb for g in second]
    a = pear.triangulate_many(first)
    a_coordinates, address = a.coordinates.copy(), a.coordinates.ctypes.data
    view = a.coordinates[:10]  # keeps a's buffer alive after a is gone
    del a
    b = pear.triangulate_many(second)
    assert b.coordinates.ctypes.data != address
    assert np.array_equal(view, a_coordinates[:10])
    del view
    other = np.ones_like(a_coordinates)  # malloc would give it a's memory, were it free
    c = pear.triangulate_many(first)  # a's buffer, kept for the next read
    assert c.coordinates.ctypes.data == address != other.ctypes.data
    assert np.array_equal(c.coordinates, a_coordinates)
    assert b.coordinates[0, 0] > 900 and c.ok and b.ok
