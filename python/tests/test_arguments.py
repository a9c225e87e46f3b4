"""How every entry point reads its arguments (docs/python.md, "How arguments are read"): no
silent coercion. Numbers that are not real, indices that are not integers, counts out of range,
an argument given twice, None and empty geometries raise the documented exception, naming the
argument (issue 30, item 7)."""
from fractions import Fraction

import numpy as np
import pytest

import pear
from polygons import SQUARE_WITH_HOLE

geometry = pytest.importorskip("shapely.geometry")

SQUARE = SQUARE_WITH_HOLE[:4]
TWO = [[0, 1, 2], [0, 2, 3]]  # the square's triangles

# Each entry point that takes coordinates, as a function of them.
COORDINATE_TAKERS = {
    "triangulate": lambda c: pear.triangulate(c),
    "triangulate_many": lambda c: pear.triangulate_many(c, [0, 4], [0, 1]),
    "validate": lambda c: pear.validate(c, TWO),
    "quality": lambda c: pear.quality(c, TWO),
    "orient2d": lambda c: pear.orient2d(c, [0, 0], [1, 0]),
}
NAMES = {"validate": "polygon", "orient2d": "a"}


@pytest.mark.parametrize("taker", COORDINATE_TAKERS)
@pytest.mark.parametrize("coords, kind", [
    (SQUARE + 1j, "complex128"), ([[0, 0], [1, 0], [1, 1j], [0, 1]], "complex128"),
    ([["0", "0"], ["1", "0"], ["1", "1"], ["0", "1"]], "<U1"),
    (SQUARE.astype(bool), "bool"), ([[0, 0], [1, 0], [1, Fraction(1)], [0, 1]], "object"),
])
def test_coordinates_that_are_not_real_numbers_raise_type_error(taker, coords, kind):
    # complex: numpy's cast drops the imaginary part; strings: it parses them.
    name = NAMES.get(taker, "coords")
    with pytest.raises(TypeError, match=f"{name} must be real numbers .*not {kind}"):
        COORDINATE_TAKERS[taker](coords)


@pytest.mark.parametrize("taker", COORDINATE_TAKERS)
@pytest.mark.parametrize("value", [None, 5, 2.5])
def test_none_or_a_scalar_for_coordinates_raises_type_error(taker, value):
    name = NAMES.get(taker, "coords")
    with pytest.raises(TypeError, match=f"{name} must be an array-like of numbers, not "
                                        f"{type(value).__name__}"):
        COORDINATE_TAKERS[taker](value)


def test_integer_coordinates_are_converted_and_ragged_ones_are_a_shape_error():
    assert np.array_equal(pear.triangulate(SQUARE.astype(np.int32)), pear.triangulate(SQUARE))
    with pytest.raises(ValueError, match="coords is not an array"):
        pear.triangulate([[0, 0], [1, 0, 2], [1, 1]])


HOLED = SQUARE_WITH_HOLE


@pytest.mark.parametrize("ring_ends", [[4.7], [4.0], np.array([4.0]), [True]])
@pytest.mark.parametrize("taker", ["triangulate", "validate"])
def test_ring_ends_that_are_not_integers_raise_type_error(taker, ring_ends):
    call = {"triangulate": lambda: pear.triangulate(HOLED, ring_ends),
            "validate": lambda: pear.validate(HOLED, pear.triangulate(HOLED, [4]), ring_ends)}
    with pytest.raises(TypeError, match="ring_ends must be integers, not (float64|bool)"):
        call[taker]()


@pytest.mark.parametrize("ring_ends, shown", [
    (np.array([2**63], np.uint64), "9223372036854775808"), ([2**70], str(2**70))])
def test_ring_ends_beyond_int64_name_the_entry(ring_ends, shown):
    with pytest.raises(ValueError, match=rf"ring_ends\[0\] = {shown} does not fit in int64"):
        pear.triangulate(HOLED, ring_ends)


def test_empty_ring_ends_of_any_dtype_are_one_ring_and_a_scalar_is_a_type_error():
    assert np.array_equal(pear.triangulate(SQUARE, []), pear.triangulate(SQUARE))
    assert np.array_equal(pear.triangulate(SQUARE, np.array([], float)), pear.triangulate(SQUARE))
    with pytest.raises(TypeError, match="ring_ends must be an array-like of integers, not int"):
        pear.triangulate(HOLED, 4)


@pytest.mark.parametrize("argument", ["ring_offsets", "polygon_offsets", "geometry_offsets"])
def test_batch_offsets_that_are_not_integers_raise_type_error(argument):
    coords = np.vstack([SQUARE, SQUARE])
    offsets = {"ring_offsets": [0, 4, 8], "polygon_offsets": [0, 1, 2],
               "geometry_offsets": [0, 2]}
    assert pear.triangulate_many(coords, **offsets).ok
    offsets[argument] = [0.0, 4.5, 8.0][:len(offsets[argument])]  # was truncated to 4
    with pytest.raises(TypeError, match=f"{argument} must be integers, not float64"):
        pear.triangulate_many(coords, **offsets)


def test_batch_offsets_beyond_int64_raise_value_error():
    with pytest.raises(ValueError, match=r"ring_offsets\[1\] = 9223372036854775808"):
        pear.triangulate_many(SQUARE, np.array([0, 2**63], np.uint64), [0, 1])


@pytest.mark.parametrize("taker", ["validate", "quality"])
def test_triangles_that_are_not_integers_raise_type_error(taker):
    call = {"validate": pear.validate, "quality": pear.quality}[taker]
    assert call(SQUARE, TWO)  # a report with triangles == 2
    with pytest.raises(TypeError, match="triangles must be integers, not float64"):
        call(SQUARE, [[0.5, 1, 2], [0, 2, 3]])


OPTION_TAKERS = {
    "triangulate": lambda **o: pear.triangulate(SQUARE, **o),
    "triangulate_many": lambda **o: pear.triangulate_many(SQUARE, [0, 4], [0, 1], **o),
}


@pytest.mark.parametrize("taker", OPTION_TAKERS)
@pytest.mark.parametrize("name", ["threads", "partitions"])
@pytest.mark.parametrize("value", [2**70, 2**63, -1, -2**70, 100000])
def test_counts_out_of_range_raise_value_error(taker, name, value):
    with pytest.raises(ValueError, match=f"{name} {value} is not between 0"):
        OPTION_TAKERS[taker](**{name: value})


@pytest.mark.parametrize("taker", OPTION_TAKERS)
@pytest.mark.parametrize("name, value, expected", [
    ("threads", 2.0, "an int"), ("threads", "2", "an int"), ("partitions", True, "an int"),
    ("delaunay", "no", "a bool"), ("check_simplicity", 0, "a bool"),
    ("algorithm", 3, "a str"), ("heuristic", b"top", "a str")])
def test_options_of_the_wrong_type_raise_type_error(taker, name, value, expected):
    with pytest.raises(TypeError, match=f"{name} must be {expected}, not {type(value).__name__}"):
        OPTION_TAKERS[taker](**{name: value})


@pytest.mark.parametrize("taker", OPTION_TAKERS)
def test_numpy_integers_and_bools_are_options(taker):
    assert OPTION_TAKERS[taker](threads=np.int64(1), delaunay=np.bool_(True)) is not None


def test_validate_counts_and_flags_follow_the_same_rules():
    with pytest.raises(ValueError, match=f"max_messages {2**70} is not between 0"):
        pear.validate(SQUARE, TWO, max_messages=2**70)
    with pytest.raises(ValueError, match="max_messages -1"):
        pear.validate(SQUARE, TWO, max_messages=-1)
    with pytest.raises(TypeError, match="check_delaunay must be a bool, not int"):
        pear.validate(SQUARE, TWO, check_delaunay=1)
    assert pear.validate(SQUARE, TWO, max_messages=np.uint8(3), check_delaunay=np.bool_(1))


@pytest.mark.parametrize("call, name", [
    (lambda: pear.triangulate(SQUARE, coords=SQUARE * 2), "coords"),
    (lambda: pear.triangulate(HOLED, [4], ring_ends=[4]), "ring_ends"),
    (lambda: pear.triangulate(SQUARE, None, ring_ends=None), "ring_ends")])
def test_an_argument_given_twice_raises_type_error(call, name):
    with pytest.raises(TypeError, match=f"got multiple values for argument '{name}'"):
        call()


def test_triangulate_many_of_none_or_a_scalar_raises_type_error():
    for data in (None, 5):
        with pytest.raises(TypeError, match=f"data must be .*not {type(data).__name__}"):
            pear.triangulate_many(data)


@pytest.mark.parametrize("empty", [geometry.Polygon(), geometry.MultiPolygon()])
@pytest.mark.parametrize("strict", [True, False])
def test_an_empty_geometry_is_empty_coordinates(empty, strict):
    with pytest.raises(pear.InvalidInputError) as from_coords:
        pear.triangulate(np.zeros((0, 2)), strict=strict)
    with pytest.raises(pear.InvalidInputError) as from_geometry:
        pear.triangulate(empty, strict=strict)
    assert from_geometry.value.issue == from_coords.value.issue == "empty_input"
    assert str(from_geometry.value) == str(from_coords.value)
    report = pear.validate(empty, np.zeros((0, 3), np.uint32))
    expected = pear.validate(np.zeros((0, 2)), np.zeros((0, 3), np.uint32))
    assert not report.valid and report.messages == expected.messages
