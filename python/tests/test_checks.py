"""pear.validate, pear.quality and the exact predicates orient2d and incircle."""
from fractions import Fraction

import numpy as np
import pytest

import pear
from polygons import SQUARE_WITH_HOLE


def exact_orient(a, b, c):
    a, b, c = ([Fraction(v) for v in p] for p in (a, b, c))
    return (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0])


def test_validate_accepts_pear_and_rejects_broken_triangulations():
    triangles = pear.triangulate(SQUARE_WITH_HOLE, [4])
    report = pear.validate(SQUARE_WITH_HOLE, triangles, [4])
    assert report and report.valid and report.triangles == report.expected_triangles == 8
    assert report.area_rel_error == 0 and report.messages == []
    dropped = pear.validate(SQUARE_WITH_HOLE, triangles[1:], [4])
    assert not dropped.valid and dropped.messages
    flipped = triangles.copy()
    flipped[0] = flipped[0, ::-1]
    assert pear.validate(SQUARE_WITH_HOLE, flipped, [4]).bad_orientation == 1
    assert not pear.validate(SQUARE_WITH_HOLE, np.vstack([triangles, triangles[:1]]), [4]).valid
    assert "valid=True" in repr(report)


def test_validate_checks_delaunay_when_asked():
    points = np.array([[0, 0], [4, 0], [4.0, 1], [0, 1]])
    thin = np.array([[0, 1, 2], [0, 2, 3]], dtype=np.uint32)
    assert pear.validate(points, thin).valid
    report = pear.validate(points, thin, check_delaunay=True)
    assert report.valid  # a rectangle's diagonals are both Delaunay (cocircular)
    kite = np.array([[0, 0], [2, -0.2], [4, 0], [2, 3]])
    bad = np.array([[0, 1, 2], [0, 2, 3]], dtype=np.uint32)  # the long diagonal
    assert not pear.validate(kite, bad, check_delaunay=True).valid
    assert pear.validate(kite, pear.triangulate(kite, delaunay=True), check_delaunay=True).valid


def test_validate_rejects_bad_indices():
    with pytest.raises(ValueError, match="index 8"):
        pear.validate(SQUARE_WITH_HOLE, [[0, 1, 8]], [4])
    with pytest.raises(ValueError, match="shape"):
        pear.validate(SQUARE_WITH_HOLE, [0, 1, 2], [4])


def test_quality_of_an_equilateral_triangle():
    points = np.array([[0, 0], [2, 0], [1, np.sqrt(3)]])
    stats = pear.quality(points, [[0, 1, 2]])
    assert stats.triangles == 1
    assert stats.min_angle_avg_deg == pytest.approx(60) and stats.dev60_avg_deg < 1e-6
    assert stats.min_angle_histogram[11] == 1 and sum(stats.min_angle_histogram) == 1


def test_quality_of_a_polygon():
    triangles = pear.triangulate(SQUARE_WITH_HOLE, [4])
    stats = pear.quality(SQUARE_WITH_HOLE, triangles)
    assert stats.triangles == 8 and 0 < stats.min_angle_deg <= stats.min_angle_avg_deg <= 60


def test_orient2d_is_exact_near_collinear_points():
    """Points on a line through doubles' rounding: the float determinant's sign is often wrong;
    orient2d's sign is the exact one (Fraction)."""
    rng = np.random.default_rng(17)
    wrong_float = 0
    for _ in range(2000):
        a = (0.5 + rng.integers(0, 256) * 2.0**-53, 0.5 + rng.integers(0, 256) * 2.0**-53)
        b, c = (12.0, 12.0), (24.0, 24.0)
        exact = exact_orient(a, b, c)
        assert np.sign(pear.orient2d(a, b, c)) == np.sign(float(exact))
        naive = (a[0] - c[0]) * (b[1] - c[1]) - (a[1] - c[1]) * (b[0] - c[0])
        wrong_float += np.sign(naive) != np.sign(float(exact))
    assert wrong_float > 0  # the test does reach the hard cases


def test_predicates_on_arrays():
    a = np.array([[0, 0], [0, 0], [0, 0.0]])
    b = np.array([[1, 0], [1, 0], [1, 0.0]])
    c = np.array([[0, 1], [0, -1], [2, 0.0]])
    assert np.sign(pear.orient2d(a, b, c)).tolist() == [1, -1, 0]
    assert pear.orient2d(a, (1, 0), c).tolist() == pear.orient2d(a, b, c).tolist()
    inside = pear.incircle((0, 0), (1, 0), (0, 1), np.array([[0.5, 0.5], [2, 2], [1, 1.0]]))
    assert np.sign(inside).tolist() == [1, -1, 0]
    with pytest.raises(ValueError, match="same length"):
        pear.orient2d(a, b[:2], c)
    with pytest.raises(ValueError):
        pear.orient2d((0, 0, 0), (1, 0), (0, 1))
