"""The shared corpus through the Python package: the same statuses and triangle counts as the
C++ CLI, exact areas and counts checked without pear, agreement with mapbox_earcut wherever its
output is valid, and every algorithm on the larger polygons. Skips without ../shared/corpus."""
import functools

import numpy as np
import pytest

import corpus
import pear
from polygons import cli_stats, exact_check, folder

FOLDERS = ["counties", "countries", "glyphs", "earcut"]


@functools.lru_cache(maxsize=None)
def polygons_of(name):
    return folder(name)


def repaired(diagnostics):
    """pear split an edge at a vertex inside it, or dissolved a spike: the count changes."""
    return any(d.issue in ("t_junction_split", "spike_dissolved") for d in diagnostics)


def batch_of(polygons, **options):
    """All polygons in one triangulate_many call; returns the result and each one's first point."""
    coords = np.vstack([p.coords for p in polygons])
    starts = np.cumsum([0] + [len(p.coords) for p in polygons])
    rings = np.concatenate([[0]] + [p.offsets[1:] + s for p, s in zip(polygons, starts)])
    first_ring = np.cumsum([0] + [len(p.offsets) - 1 for p in polygons])
    return pear.triangulate_many(coords, rings, first_ring, **options), starts


@pytest.mark.parametrize("name", FOLDERS)
def test_folder_matches_the_cli_and_exact_checks(name):
    polygons = polygons_of(name)
    result, starts = batch_of(polygons)
    stats = cli_stats(corpus.shared_root() / name)
    checked = 0
    for p, polygon in enumerate(polygons):
        triangles = result.polygon_triangles(p) - starts[p]
        status = pear.Status(result.status[p])
        if stats is not None:
            file, index = polygon.name.rsplit(":", 1)
            cli = stats[(file, int(index))]
            assert (status.name, len(triangles)) == (cli["status"], cli["triangles"]), polygon.name
        if polygon.valid:  # GEOS found no defect: pear must triangulate it
            assert status is pear.Status.ok, polygon.name
        if status is pear.Status.ok:
            count = not repaired(result.diagnostics(p))
            assert exact_check(polygon.coords, polygon.offsets, triangles, count) == [], polygon.name
            assert pear.validate(polygon.coords, triangles, polygon.offsets).valid, polygon.name
            checked += 1
    assert checked >= sum(p.valid for p in polygons) > 0


def test_per_polygon_calls_equal_the_batch():
    polygons = polygons_of("counties")
    result, starts = batch_of(polygons, threads=2)
    for p, polygon in enumerate(polygons):
        triangles, status = pear.triangulate(polygon.coords, polygon.offsets, strict=False) \
            if result.status[p] != pear.Status.invalid_input else (None, None)
        if triangles is not None:
            assert status == result.status[p]
            assert np.array_equal(triangles, result.polygon_triangles(p) - starts[p])


def earcut_comparison(polygon):
    """How pear's and mapbox_earcut's triangulations of polygon compare: a pair of pear's
    status and one of "both valid", "earcut invalid", "pear invalid" (when earcut's output
    is valid, pear's is not), "count differs", "area differs", "invalid input"."""
    earcut = pytest.importorskip("mapbox_earcut")
    theirs = earcut.triangulate_float64(polygon.coords, polygon.ring_ends).reshape(-1, 3)
    try:
        ours, status = pear.triangulate(polygon.coords, polygon.offsets, strict=False)
    except pear.InvalidInputError:
        return pear.Status.invalid_input, "invalid input"
    if not pear.validate(polygon.coords, theirs, polygon.offsets).valid:
        assert status is not pear.Status.ok or pear.validate(polygon.coords, ours,
                                                             polygon.offsets).valid
        return status, "earcut invalid"
    if not pear.validate(polygon.coords, ours, polygon.offsets).valid:
        return status, "pear invalid"
    if len(ours) != len(theirs):
        return status, "count differs"
    # Both valid: their exact areas equal the polygon's, checked without pear (the count too
    # unless pear repaired the polygon: then pear.validate counted).
    single, _ = batch_of([polygon])
    count = not repaired(single.diagnostics(0))
    assert exact_check(polygon.coords, polygon.offsets, ours, count) == []
    assert exact_check(polygon.coords, polygon.offsets, theirs, count) == []
    return status, "both valid"


@pytest.mark.parametrize("name", FOLDERS)
def test_same_count_and_area_as_mapbox_earcut_where_its_output_is_valid(name):
    """Where earcut's triangulation is valid (pear's validator) and pear finds the polygon
    simple, pear's has the same number of triangles and the same exact area; where earcut's
    is not valid, pear's is (or pear says the polygon is not simple). Where pear finds the
    polygon not simple, GEOS flagged it too (its MANIFEST row)."""
    outcomes = {}
    for polygon in polygons_of(name):
        status, outcome = earcut_comparison(polygon)
        outcomes.setdefault((status.name, outcome), []).append(polygon.name)
        if status is pear.Status.ok:
            assert outcome in ("both valid", "earcut invalid"), (polygon.name, outcome)
        else:
            assert not polygon.valid, polygon.name
    print(name, {key: len(names) for key, names in sorted(outcomes.items())})
    assert outcomes.get(("ok", "both valid"))


@pytest.mark.parametrize("algorithm", ["sequential", "partition_and_cut", "mark_and_cut",
                                       "divide_and_conquer"])
@pytest.mark.parametrize("heuristic", ["top", "fast"])
def test_every_algorithm_on_the_larger_polygons(algorithm, heuristic):
    large = [p for p in polygons_of("countries") + polygons_of("glyphs") if len(p.coords) >= 2000]
    large += folder("coast", only="borneo_gshhg_full.json.gz")  # 53,410 vertices
    assert large
    result, starts = batch_of(large, algorithm=algorithm, heuristic=heuristic, threads=2)
    for p, polygon in enumerate(large):
        triangles = result.polygon_triangles(p) - starts[p]
        if result.status[p] == pear.Status.ok:
            count = not repaired(result.diagnostics(p))
            assert exact_check(polygon.coords, polygon.offsets, triangles, count) == [], polygon.name


def test_delaunay_on_the_glyphs():
    polygons = polygons_of("glyphs")
    result, starts = batch_of(polygons, delaunay=True, threads=2)
    assert result.ok and result.delaunay_flips > 0
    for p, polygon in enumerate(polygons):
        triangles = result.polygon_triangles(p) - starts[p]
        assert pear.validate(polygon.coords, triangles, polygon.offsets,
                             check_delaunay=True).valid, polygon.name
