"""triangulate_many over shapely 1.8 geometries read through their GEOS handles: the same
arrays, results and errors as through their WKB (pear._many._read_geos_handles = False), for
every geometry shapely makes. Skips with shapely 2 or a module built without geos_c.h."""
import numpy as np
import pytest

import pear
import polygons
from polygons import SQUARE_WITH_HOLE, counties_frame

geometry = pytest.importorskip("shapely.geometry")
wkt = pytest.importorskip("shapely.wkt")
if not pear._many._reads_geos_handles():
    pytest.skip("no GEOS reader: shapely 2, or the module was built without geos_c.h",
                allow_module_level=True)

SQUARE = geometry.Polygon(SQUARE_WITH_HOLE[:4], [SQUARE_WITH_HOLE[4:]])
TRIANGLE = geometry.Polygon([(20, 0), (30, 0), (30, 10)])


def read_by_geos(data):
    """The module's reading of data, None where it leaves it to WKB."""
    return pear._pear.read_geos(data)


def through_wkb(data, **options):
    return polygons.through_wkb(pear, "_read_geos_handles", data, **options)


def assert_same(data):
    return polygons.assert_reads_as_wkb(pear, "_read_geos_handles", data)


def test_every_polygonal_form_reads_as_its_wkb():
    forms = [SQUARE, None, geometry.MultiPolygon([SQUARE, TRIANGLE]), geometry.Polygon(),
             wkt.loads("POLYGON EMPTY"), wkt.loads("MULTIPOLYGON EMPTY"),
             wkt.loads("GEOMETRYCOLLECTION EMPTY"),
             wkt.loads("MULTIPOLYGON (EMPTY, ((0 0, 1 0, 1 1, 0 0)))"),
             wkt.loads("POLYGON Z ((0 0 1, 1 0 2, 1 1 3, 0 0 1))"),
             wkt.loads("POLYGON ((0 0, 1 1, 1 0, 0 1, 0 0))"),  # a bowtie: not_simple
             wkt.loads("POLYGON ((0 0, 1 0, 0 0))")]            # too few points: invalid
    assert read_by_geos(forms) is not None  # no element sent the batch to WKB
    result = assert_same(forms)
    assert result.geometry_offsets.tolist() == [0, 1, 1, 3, 3, 3, 3, 3, 4, 5, 6, 7]
    assert [len(t) for t in result.geometry_triangles()][:3] == [8, 0, 9]


def test_the_counties_read_as_their_wkb():
    shapes = list(counties_frame().geometry)
    assert read_by_geos(shapes) is not None
    result = assert_same(shapes)
    assert len(result.geometry_offsets) == len(shapes) + 1 and len(result.triangles) > 0


@pytest.mark.parametrize("other", [
    "POINT (1 2)", "LINESTRING (0 0, 1 1)", "MULTIPOINT (0 0, 1 1)",
    "GEOMETRYCOLLECTION (POINT (1 2))", "LINEARRING (0 0, 1 0, 1 1, 0 0)"])
def test_other_geometries_raise_what_their_wkb_raises(other):
    data = [SQUARE, wkt.loads(other)]
    assert read_by_geos(data) is None
    with pytest.raises(pear.WKBError) as by_wkb:
        through_wkb(data)
    with pytest.raises(pear.WKBError) as by_geos:
        pear.triangulate_many(data)
    assert str(by_geos.value) == str(by_wkb.value) and "geometry 1" in str(by_geos.value)


class LooksLikeShapely:
    """Not a shapely geometry, with what one has: a wkb property and a _geom that is no GEOS
    geometry. Must be read through its WKB, never as an address."""
    _geom = 12345

    @property
    def wkb(self):
        return SQUARE.wkb


def test_an_object_that_is_not_shapely_goes_through_wkb():
    data = [SQUARE, LooksLikeShapely()]
    assert read_by_geos(data) is None
    result = pear.triangulate_many(data)
    assert result.ok and np.array_equal(result.geometry_triangles()[1],
                                        pear.triangulate(SQUARE))


class GeometryOfAnother(geometry.Polygon):
    """A shapely Polygon whose _geom is another's (as shapely's proxies override _geom): the
    reader must ask _geom, not read __geom__, which it does for types that keep shapely's."""

    @property
    def _geom(self):
        return TRIANGLE._geom


def test_a_type_that_overrides_geom_is_read_through_it():
    other = GeometryOfAnother(SQUARE_WITH_HOLE[:4])
    result = pear.triangulate_many([SQUARE, other, TRIANGLE])
    assert result.geometry_offsets.tolist() == [0, 1, 2, 3]
    assert np.array_equal(result.coordinates[result.geometry_point_offsets()[1]:
                                             result.geometry_point_offsets()[2]],
                          np.asarray(TRIANGLE.exterior.coords))


def test_other_values_still_raise_type_error():
    with pytest.raises(TypeError, match="geometry 1 is not WKB"):
        pear.triangulate_many([SQUARE, "POLYGON ((0 0, 1 0, 1 1))"])


def test_a_generator_and_an_object_array_read_alike():
    shapes = [SQUARE, None, TRIANGLE]
    as_array = np.empty(3, dtype=object)
    as_array[:] = shapes
    expected = pear.triangulate_many(shapes)
    for data in (as_array, (s for s in shapes)):
        assert np.array_equal(pear.triangulate_many(data).triangles, expected.triangles)
