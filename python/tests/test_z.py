"""(N, 3) coordinates: triangulated on x and y, z kept with the points. The triangles must be
those of the (N, 2) coordinates, and every point's z the input's z at that index."""
import numpy as np
import pytest

import pear
from polygons import SQUARE_WITH_HOLE

# Heights that are no function of x and y, so a mixed-up index shows.
HEIGHTS = np.arange(len(SQUARE_WITH_HOLE), dtype=np.float64) * 7.5 - 3.0
XYZ = np.column_stack([SQUARE_WITH_HOLE, HEIGHTS])


def test_triangulate_xyz_gives_the_xy_triangles():
    assert np.array_equal(pear.triangulate(XYZ, [4]), pear.triangulate(SQUARE_WITH_HOLE, [4]))
    # Not C-contiguous and integer: converted as (N, 2) ones are.
    assert np.array_equal(pear.triangulate(np.asfortranarray(XYZ).astype(np.int64), [4]),
                          pear.triangulate(SQUARE_WITH_HOLE.astype(np.int64), [4]))


def test_triangulate_points_returns_the_z():
    points, triangles = pear.triangulate_points(XYZ, [4])
    assert points.shape == (8, 3) and np.array_equal(points[:, 2], HEIGHTS)
    assert np.array_equal(triangles, pear.triangulate(SQUARE_WITH_HOLE, [4]))


def test_other_widths_are_a_shape_error():
    for bad in (np.zeros((5, 4)), np.zeros((5, 1)), np.zeros(6)):
        with pytest.raises(ValueError, match=r"shape \(N, 2\) or \(N, 3\)"):
            pear.triangulate(bad)
    with pytest.raises(ValueError, match=r"shape \(N, 2\), not \(5, 3\)"):
        pear.validate(np.zeros((5, 3)), np.zeros((0, 3), dtype=np.uint32))


def test_triangulate_many_xyz_keeps_the_callers_array():
    coords = np.vstack([XYZ, XYZ + [20, 0, 100]])
    rings, starts = [0, 4, 8, 12, 16], [0, 2, 4]
    result = pear.triangulate_many(coords, rings, starts)
    flat = pear.triangulate_many(np.ascontiguousarray(coords[:, :2]), rings, starts)
    assert result.ok and np.array_equal(result.triangles, flat.triangles)
    assert result.coordinates is coords


def test_shapely_z_comes_back_with_the_points():
    geometry = pytest.importorskip("shapely.geometry")
    polygon = geometry.Polygon(XYZ[:4], [XYZ[4:]])
    points, triangles = pear.triangulate_points(polygon)
    flat_points, flat_triangles = pear.triangulate_points(
        geometry.Polygon(SQUARE_WITH_HOLE[:4], [SQUARE_WITH_HOLE[4:]]))
    assert points.shape == (10, 3) and np.array_equal(triangles, flat_triangles)
    assert np.array_equal(points[:, :2], flat_points)
    # shapely's own coordinates, z included, rings closed.
    expected = np.vstack([np.asarray(polygon.exterior.coords),
                          np.asarray(polygon.interiors[0].coords)])
    assert np.array_equal(points, expected)
    multi = geometry.MultiPolygon([polygon, geometry.Polygon([(20, 0, 1), (30, 0, 2),
                                                              (30, 10, 3)])])
    points, triangles = pear.triangulate_points(multi)
    assert points.shape == (14, 3) and points[-2:, 2].tolist() == [3, 1]
    assert np.array_equal(triangles, pear.triangulate(multi))
