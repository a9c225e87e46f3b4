"""pear.triangulate: one polygon, every input form, every status, every algorithm and option."""
import pickle
import threading

import numpy as np
import pytest

import pear
from polygons import BOWTIE, SQUARE_WITH_HOLE, exact_check

ALGORITHMS = ["automatic", "sequential", "partition_and_cut", "mark_and_cut", "divide_and_conquer"]


def star(n, inner=0.4, hole=False):
    """A star of n spikes (2n vertices), with a small square hole at its centre if asked."""
    angles = np.arange(2 * n) * np.pi / n
    radius = np.where(np.arange(2 * n) % 2 == 0, 1.0, inner)
    outer = np.column_stack([radius * np.cos(angles), radius * np.sin(angles)])
    if not hole:
        return outer, None
    square = np.array([[-0.1, -0.1], [-0.1, 0.1], [0.1, 0.1], [0.1, -0.1]])
    return np.vstack([outer, square]), [len(outer)]


def test_square_with_hole_round_trip():
    triangles = pear.triangulate(SQUARE_WITH_HOLE, [4])
    assert triangles.dtype == np.uint32 and triangles.shape == (8, 3)
    # The caller's own array: C order, writable, owning its memory (no view of pear's buffer).
    flags = triangles.flags
    assert flags.c_contiguous and flags.writeable and flags.owndata and triangles.base is None
    assert exact_check(SQUARE_WITH_HOLE, [0, 4, 8], triangles) == []
    assert pear.validate(SQUARE_WITH_HOLE, triangles, [4]).valid


@pytest.mark.parametrize("ring_ends", [[4], [4, 8], [0, 4, 8], np.array([4, 8], np.uint32),
                                       np.array([0, 4, 8], np.int64), np.array([4], np.int32),
                                       (4,)])
def test_ring_ends_forms_agree(ring_ends):
    """Hole indices (earcut.js), ring ends (mapbox_earcut) and ring offsets are one polygon."""
    expected = pear.triangulate(SQUARE_WITH_HOLE, [0, 4, 8])
    assert np.array_equal(pear.triangulate(SQUARE_WITH_HOLE, ring_ends), expected)


@pytest.mark.parametrize("ring_ends, entry", [([5, 4], "ring_ends[1] = 4"),
                                              ([9], "ring_ends[0] = 9"),
                                              ([-1], "ring_ends[0] = -1")])
def test_ring_ends_out_of_order_or_range_name_the_entry(ring_ends, entry):
    with pytest.raises(ValueError, match=entry.replace("[", r"\[").replace("]", r"\]")):
        pear.triangulate(SQUARE_WITH_HOLE, ring_ends)


def test_coordinate_forms_agree():
    """Lists, float32, Fortran order, strided views: converted; the result is the same."""
    expected = pear.triangulate(SQUARE_WITH_HOLE, [4])
    wide = np.zeros((8, 4))
    wide[:, ::2] = SQUARE_WITH_HOLE
    for coords in (SQUARE_WITH_HOLE.tolist(), SQUARE_WITH_HOLE.astype(np.float32),
                   np.asfortranarray(SQUARE_WITH_HOLE), wide[:, ::2],
                   [tuple(p) for p in SQUARE_WITH_HOLE.astype(int).tolist()]):
        assert np.array_equal(pear.triangulate(coords, [4]), expected)


def test_contiguous_float64_is_read_in_place():
    """The array the caller passes is not copied or changed (its buffer is read directly)."""
    coords = SQUARE_WITH_HOLE.copy()
    before = coords.__array_interface__["data"][0]
    pear.triangulate(coords, [4])
    assert coords.__array_interface__["data"][0] == before
    assert np.array_equal(coords, SQUARE_WITH_HOLE)


@pytest.mark.parametrize("coords, error", [(np.zeros((4, 4)), "shape \\(N, 2\\)"),
                                           (np.zeros(8), "shape \\(N, 2\\)")])
def test_wrong_shapes_raise_value_error(coords, error):
    with pytest.raises(ValueError, match=error):
        pear.triangulate(coords)


def test_not_numbers_raise_type_error():
    with pytest.raises(TypeError):
        pear.triangulate("square")
    with pytest.raises(TypeError):
        pear.triangulate(SQUARE_WITH_HOLE, [4], algorithm=3)
    with pytest.raises(TypeError, match="unexpected keyword argument 'holes'"):
        pear.triangulate(SQUARE_WITH_HOLE, holes=[4])
    with pytest.raises(TypeError):
        pear.triangulate()


@pytest.mark.parametrize("name, value", [("algorithm", "ear"), ("heuristic", "slow")])
def test_unknown_option_names_raise_value_error(name, value):
    with pytest.raises(ValueError, match=value):
        pear.triangulate(SQUARE_WITH_HOLE, [4], **{name: value})


def test_threads_out_of_range_raise():
    with pytest.raises(ValueError):
        pear.triangulate(SQUARE_WITH_HOLE, [4], threads=-1)
    with pytest.raises(ValueError, match="limit"):
        pear.triangulate(SQUARE_WITH_HOLE, [4], threads=100000)


@pytest.mark.parametrize("coords, issue, ring, vertex", [
    ([[0, 0], [1, 0], [np.nan, 1]], "non_finite_coordinate", 0, 2),
    ([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0.5], [0.6, np.inf], [0.6, 0.6]],
     "non_finite_coordinate", 1, 1),
    ([[0, 0], [1, 1], [2, 2]], "outer_ring_too_small", 0, 0),
    ([[0, 0], [1e300, 0], [0, 1]], "coordinate_out_of_range", 0, 1),
    (np.zeros((0, 2)), "empty_input", 0, 0),
])
def test_invalid_input_raises_naming_ring_and_vertex(coords, issue, ring, vertex):
    ring_ends = [4] if len(coords) == 7 else None
    with pytest.raises(pear.InvalidInputError) as caught:
        pear.triangulate(np.asarray(coords, dtype=float), ring_ends)
    error = caught.value
    assert isinstance(error, ValueError) and isinstance(error, pear.PearError)
    assert (error.issue, error.ring, error.vertex) == (issue, ring, vertex)
    assert f"ring {ring}, vertex {vertex}" in str(error)
    assert error.diagnostics and error.diagnostics[0].is_error
    # strict=False does not turn invalid input into a result: there is none.
    with pytest.raises(pear.InvalidInputError):
        pear.triangulate(np.asarray(coords, dtype=float), ring_ends, strict=False)


def test_not_simple_raises_with_the_best_effort_triangles():
    with pytest.raises(pear.NotSimpleError) as caught:
        pear.triangulate(BOWTIE)
    error = caught.value
    assert isinstance(error, ValueError) and error.status == pear.Status.not_simple
    assert error.triangles.dtype == np.uint32 and error.triangles.shape[1] == 3
    assert len(error.triangles) >= 1 and error.triangles.max() < 4
    assert [d.issue for d in error.diagnostics] == ["not_simple"]
    assert "ring 0" in str(error)
    triangles, status = pear.triangulate(BOWTIE, strict=False)
    assert status is pear.Status.not_simple and np.array_equal(triangles, error.triangles)


def test_not_simple_names_a_misplaced_hole_not_an_earlier_warning():
    # Hole 1 is dropped (two points: a warning); hole 2 lies outside the outer ring.
    coords = [[0, 0], [10, 0], [10, 10], [0, 10], [1, 1], [2, 2], [20, 2], [20, 4], [22, 4]]
    with pytest.raises(pear.NotSimpleError) as caught:
        pear.triangulate(np.asarray(coords, dtype=float), [4, 6])
    error = caught.value
    assert [d.issue for d in error.diagnostics] == ["hole_dropped_too_small",
                                                    "hole_outside_outer_ring"]
    assert [d.is_not_simple for d in error.diagnostics] == [False, True]
    assert "ring 2, vertex 0: hole lies outside the outer ring" in str(error)
    many = pear.triangulate_many(np.asarray(coords, dtype=float), [0, 4, 6, 9], [0, 3])
    with pytest.raises(pear.NotSimpleError, match="hole lies outside the outer ring"):
        many.check()


def test_large_polygon_engine_is_released_and_taken_again():
    # Past 65,536 points a call takes pear's pooled large engine (no thread keeps one);
    # release_cached_engines frees it, and the next calls, here and in another thread, build
    # a new one and give the same valid triangles.
    n = 70_000
    angles = np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)
    radius = 1.0 + 0.1 * np.sin(37.0 * angles)  # star-shaped about the origin: simple
    coords = np.column_stack([radius * np.cos(angles), radius * np.sin(angles)])
    first = pear.triangulate(coords, partitions=2)
    assert first.shape == (n - 2, 3)
    assert pear.validate(coords, first).valid
    assert pear.release_cached_engines() is None
    np.testing.assert_array_equal(pear.triangulate(coords, partitions=2), first)
    pear.release_cached_engines()
    found = {}
    worker = threading.Thread(target=lambda: found.update(t=pear.triangulate(coords, partitions=2)))
    worker.start()
    worker.join()
    np.testing.assert_array_equal(found["t"], first)


def test_strict_false_returns_ok_with_the_triangles():
    triangles, status = pear.triangulate(SQUARE_WITH_HOLE, [4], strict=False)
    assert status is pear.Status.ok and len(triangles) == 8


def test_check_simplicity_off_accepts_what_it_does_not_see():
    """Without the check the bowtie is not reported as not simple (the documented trade)."""
    triangles, status = pear.triangulate(BOWTIE, strict=False, check_simplicity=False)
    assert triangles.shape[1] == 3
    assert not pear.validate(BOWTIE, triangles).valid or status is pear.Status.not_simple


def test_dropped_hole_is_ok():
    coords = np.vstack([SQUARE_WITH_HOLE[:4], [[5, 5], [5, 5], [5, 5]]])
    triangles = pear.triangulate(coords, [4])
    assert len(triangles) == 2 and exact_check(coords, [0, 4, 7], triangles) == []


def test_exceptions_pickle():
    """Errors cross process boundaries (Dask) with their fields."""
    with pytest.raises(pear.NotSimpleError) as not_simple:
        pear.triangulate(BOWTIE)
    copy = pickle.loads(pickle.dumps(not_simple.value))
    assert str(copy) == str(not_simple.value) and copy.diagnostics == not_simple.value.diagnostics
    assert np.array_equal(copy.triangles, not_simple.value.triangles)
    with pytest.raises(pear.InvalidInputError) as invalid:
        pear.triangulate([[0, 0], [1, 0], [np.nan, 1]])
    copy = pickle.loads(pickle.dumps(invalid.value))
    assert (copy.issue, copy.ring, copy.vertex) == ("non_finite_coordinate", 0, 2)


@pytest.mark.parametrize("algorithm", ALGORITHMS)
@pytest.mark.parametrize("heuristic", ["top", "fast"])
@pytest.mark.parametrize("delaunay", [False, True])
def test_every_algorithm_triangulates_a_star_with_a_hole(algorithm, heuristic, delaunay):
    coords, ring_ends = star(3000, hole=True)
    triangles = pear.triangulate(coords, ring_ends, algorithm=algorithm, heuristic=heuristic,
                                 delaunay=delaunay, threads=2)
    offsets = [0, ring_ends[0], len(coords)]
    assert exact_check(coords, offsets, triangles) == []
    report = pear.validate(coords, triangles, ring_ends, check_delaunay=delaunay)
    assert report.valid, report.messages


def test_auto_is_an_alias_of_automatic():
    coords, _ = star(50)
    assert np.array_equal(pear.triangulate(coords, algorithm="auto"),
                          pear.triangulate(coords, algorithm="automatic"))


def test_threads_do_not_change_the_result():
    coords, ring_ends = star(20000, hole=True)
    one = pear.triangulate(coords, ring_ends, algorithm="partition_and_cut", threads=1,
                           partitions=4)
    two = pear.triangulate(coords, ring_ends, algorithm="partition_and_cut", threads=2,
                           partitions=4)
    assert np.array_equal(one, two)
    with pytest.raises(ValueError, match="partitions"):
        pear.triangulate(coords, ring_ends, partitions=-2)


def test_python_threads_triangulate_at_once():
    """The GIL is released for large polygons; each thread's engine is its own."""
    coords, ring_ends = star(5000, hole=True)
    expected = pear.triangulate(coords, ring_ends)
    results = [None] * 4

    def work(i):
        results[i] = [pear.triangulate(coords, ring_ends) for _ in range(3)]
    threads = [threading.Thread(target=work, args=(i,)) for i in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(np.array_equal(r, expected) for rs in results for r in rs)


def test_shapely_polygon_indices_follow_its_coordinates():
    shapely = pytest.importorskip("shapely.geometry")
    polygon = shapely.Polygon(SQUARE_WITH_HOLE[:4], [SQUARE_WITH_HOLE[4:]])
    triangles = pear.triangulate(polygon)
    coords = np.vstack([np.asarray(polygon.exterior.coords),
                        np.asarray(polygon.interiors[0].coords)])
    assert len(triangles) == 8
    assert exact_check(coords, [0, 5, 10], triangles) == []
    assert pear.validate(polygon, triangles).valid
    with pytest.raises(TypeError):
        pear.triangulate(polygon, [4])


def test_shapely_multipolygon_and_errors():
    geometry = pytest.importorskip("shapely.geometry")
    square = geometry.Polygon([(0, 0), (1, 0), (1, 1), (0, 1)])
    far = geometry.Polygon([(5, 0), (6, 0), (6, 1), (5, 1)])
    triangles = pear.triangulate(geometry.MultiPolygon([square, far]))
    assert sorted(np.unique(triangles).tolist()) == [0, 1, 2, 3, 5, 6, 7, 8]  # closing points unused
    bowtie = geometry.Polygon(BOWTIE)
    with pytest.raises(pear.NotSimpleError, match="polygon 1 of the MultiPolygon"):
        pear.triangulate(geometry.MultiPolygon([square, bowtie]))
    with pytest.raises(ValueError, match="not a Polygon"):
        pear.triangulate(geometry.LineString([(0, 0), (1, 1)]))
    for empty in (geometry.Polygon(), geometry.MultiPolygon()):  # as empty coordinates
        with pytest.raises(pear.InvalidInputError) as raised:
            pear.triangulate(empty, strict=False)
        assert raised.value.issue == "empty_input"


def test_the_readme_example_runs():
    import pathlib
    import re
    readme = (pathlib.Path(__file__).resolve().parents[2] / "README.md").read_text()
    [example] = [b for b in re.findall(r"```python\n(.*?)```", readme, re.S)
                 if b.startswith("import numpy as np, pear")]
    scope = {}
    exec(example, scope)
    assert scope["two"].ok and len(scope["two"].triangles) == 16
    assert len(example.strip().splitlines()) == 5
