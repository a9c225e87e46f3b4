"""triangulate_many over shapely 2 geometries, read through shapely.to_ragged_array: the same
arrays, results and errors as through their WKB (pear._many._read_ragged_arrays = False), for
every polygonal form. Skips with shapely 1.8 (Debian 12's), which has no to_ragged_array: there
test_geos.py covers the GEOS reader instead."""
import pytest

import pear
import polygons
from polygons import SQUARE_WITH_HOLE, counties_frame

shapely = pytest.importorskip("shapely")
if not hasattr(shapely, "to_ragged_array"):
    pytest.skip(f"shapely {shapely.__version__} has no to_ragged_array (shapely 2 has)",
                allow_module_level=True)
from shapely import wkt  # noqa: E402 (after the skip)

SQUARE = shapely.Polygon(SQUARE_WITH_HOLE[:4], [SQUARE_WITH_HOLE[4:]])
TRIANGLE = shapely.Polygon([(20, 0), (30, 0), (30, 10)])


def through_wkb(data, **options):
    return polygons.through_wkb(pear, "_read_ragged_arrays", data, **options)


def assert_same(data):
    return polygons.assert_reads_as_wkb(pear, "_read_ragged_arrays", data)


def test_every_polygonal_form_reads_as_its_wkb():
    forms = [SQUARE, None, shapely.MultiPolygon([SQUARE, TRIANGLE]), shapely.Polygon(),
             wkt.loads("POLYGON EMPTY"), wkt.loads("MULTIPOLYGON EMPTY"),
             wkt.loads("MULTIPOLYGON (EMPTY, ((0 0, 1 0, 1 1, 0 0)))"),
             wkt.loads("MULTIPOLYGON (((0 0, 1 0, 1 1, 0 0)), EMPTY)"),
             wkt.loads("POLYGON Z ((0 0 1, 1 0 2, 1 1 3, 0 0 1))"),
             wkt.loads("POLYGON ((0 0, 1 1, 1 0, 0 1, 0 0))"),  # a bowtie: not_simple
             wkt.loads("POLYGON ((0 0, 1 0, 0 0))")]            # too few points: invalid
    assert pear._many._ragged_arrays(forms) is not None  # no element sent them to WKB
    result = assert_same(forms)
    assert result.geometry_offsets.tolist() == [0, 1, 1, 3, 3, 3, 3, 4, 5, 6, 7, 8]
    assert [len(t) for t in result.geometry_triangles()][:3] == [8, 0, 9]
    assert result.coordinates.shape[1] == 2  # z dropped, as from WKB


def test_polygons_alone_and_one_of_them():
    for forms in ([SQUARE, TRIANGLE], [TRIANGLE], [None, SQUARE]):
        assert pear._many._ragged_arrays(forms) is not None
        assert_same(forms)


def test_the_counties_read_as_their_wkb():
    shapes = counties_frame().geometry
    assert pear._many._ragged_arrays(shapes) is not None
    result = assert_same(shapes)
    assert len(result.geometry_offsets) == len(shapes) + 1 and len(result.triangles) > 0


@pytest.mark.parametrize("other", ["POINT (1 2)", "GEOMETRYCOLLECTION EMPTY",
                                   "GEOMETRYCOLLECTION (POINT (1 2))"])
def test_what_to_ragged_array_refuses_goes_through_wkb(other):
    data = [SQUARE, wkt.loads(other)]
    assert pear._many._ragged_arrays(data) is None
    if other == "GEOMETRYCOLLECTION EMPTY":  # GEOS' empty Polygon of old: empty, as in WKB
        assert pear.triangulate_many(data).geometry_offsets.tolist() == [0, 1, 1]
        return
    with pytest.raises(pear.WKBError, match="geometry 1"):
        pear.triangulate_many(data)
