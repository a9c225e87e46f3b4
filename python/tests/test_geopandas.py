"""pear.geopandas: GeoSeries and GeoDataFrames in, per-row triangles and triangle polygons out,
and the county folder on a real Dask cluster (two worker processes) as in one process."""
import numpy as np
import pytest

import pear
from polygons import BOWTIE, SQUARE_WITH_HOLE, counties_frame, exact_check

geopandas = pytest.importorskip("geopandas")
pear_geopandas = pytest.importorskip("pear.geopandas")
from shapely.geometry import MultiPolygon, Polygon  # noqa: E402 (after geopandas)

SQUARE = Polygon(SQUARE_WITH_HOLE[:4], [SQUARE_WITH_HOLE[4:]])
MULTI = MultiPolygon([SQUARE, Polygon([(20, 0), (30, 0), (30, 10)])])


def frame():
    return geopandas.GeoDataFrame(
        {"name": ["square", "missing", "multi", "bowtie"]},
        geometry=[SQUARE, None, MULTI, Polygon(BOWTIE)], index=[10, 11, 12, 13], crs="EPSG:3857")


def coordinates(geometry):
    """A geometry's coordinates in shapely's order (what per-row indices point into)."""
    parts = getattr(geometry, "geoms", [geometry])
    rings = [r for part in parts for r in [part.exterior, *part.interiors]]
    return np.vstack([np.asarray(r.coords) for r in rings]) if rings else np.zeros((0, 2))


def test_triangulate_rows():
    data = frame()
    rows = pear_geopandas.triangulate(data)
    assert list(rows.index) == [10, 11, 12, 13] and list(rows.columns) == ["triangles", "status"]
    assert list(rows.status) == ["ok", "ok", "ok", "not_simple"]
    assert [len(t) for t in rows.triangles] == [8, 0, 9, 1]
    square = coordinates(SQUARE)
    assert exact_check(square, [0, 5, 10], rows.triangles[10]) == []
    for label, geometry in data.geometry.items():
        if geometry is not None:
            points = coordinates(geometry)
            assert rows.triangles[label].max() < len(points)
            # The triangles' area, in the row's own coordinates, is the geometry's.
            a, b, c = (points[rows.triangles[label][:, k]] for k in range(3))
            area = np.sum(np.cross(b - a, c - a)) / 2
            if rows.status[label] == "ok":
                assert area == pytest.approx(geometry.area)
    # The same for a GeoSeries, a named column, and WKB bytes in a plain DataFrame.
    for same in (pear_geopandas.triangulate(data.geometry),
                 pear_geopandas.triangulate(data.rename_geometry("shape"), geometry="shape"),
                 pear_geopandas.triangulate(
                     geopandas.pd.DataFrame({"wkb": data.geometry.to_wkb()}), geometry="wkb")):
        assert all(np.array_equal(x, y) for x, y in zip(same.triangles, rows.triangles))
        assert list(same.status) == list(rows.status)


def test_triangle_polygons():
    data = frame()
    pieces = pear_geopandas.triangle_polygons(data)
    assert isinstance(pieces, geopandas.GeoDataFrame) and pieces.crs == data.crs
    assert list(pieces.source) == [10] * 8 + [12] * 9 + [13]
    assert list(pieces.index) == list(pieces.source)
    for label in (10, 12):
        assert pieces[pieces.source == label].area.sum() == pytest.approx(data.geometry[label].area)
        assert all(p.exterior.is_ccw for p in pieces[pieces.source == label].geometry)


def test_empty_and_wrong_inputs():
    empty = frame().iloc[:0]
    assert len(pear_geopandas.triangulate(empty)) == 0
    assert list(pear_geopandas.triangulate(empty).columns) == ["triangles", "status"]
    assert len(pear_geopandas.triangle_polygons(empty)) == 0
    with pytest.raises(KeyError, match="geometry="):
        pear_geopandas.triangulate(geopandas.pd.DataFrame({"a": [1]}))
    with pytest.raises(TypeError):
        pear_geopandas.triangulate([SQUARE])


@pytest.mark.parametrize("function", ["triangulate", "triangle_polygons"])
def test_options_follow_triangulate_many(function):
    # Issue 30, item 7: the same rules as pear.triangulate_many, not a silent conversion.
    call = getattr(pear_geopandas, function)
    with pytest.raises(ValueError, match=f"threads {2**70} is not between 0"):
        call(frame(), threads=2**70)
    with pytest.raises(TypeError, match="threads must be an int, not float"):
        call(frame(), threads=1.5)
    with pytest.raises(TypeError, match="delaunay must be a bool, not str"):
        call(frame(), delaunay="no")


def test_counties_on_a_dask_cluster_equal_one_process():
    """map_partitions over 2 worker processes gives what one call in this process gives."""
    dd = pytest.importorskip("dask.dataframe")
    distributed = pytest.importorskip("distributed")
    data = counties_frame()
    expected = pear_geopandas.triangulate(data)
    expected_pieces = pear_geopandas.triangle_polygons(data)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None, scheduler_port=0) as cluster, \
            distributed.Client(cluster) as client:
        parts = dd.from_pandas(data, npartitions=8)
        rows = parts.map_partitions(pear_geopandas.triangulate, threads=1,
                                    meta=pear_geopandas.triangulate(parts._meta))
        pieces = parts.map_partitions(pear_geopandas.triangle_polygons, threads=1,
                                      meta=pear_geopandas.triangle_polygons(parts._meta))
        rows, pieces = client.compute([rows, pieces], sync=True)
        workers = client.run(lambda: __import__("os").getpid())
    assert len(set(workers.values())) == 2
    assert list(rows.index) == list(expected.index)
    assert all(np.array_equal(x, y) for x, y in zip(rows.triangles, expected.triangles))
    assert list(rows.status) == list(expected.status)
    assert (rows.status == "ok").sum() >= 2598
    assert len(pieces) == len(expected_pieces) == sum(len(t) for t in expected.triangles)
    assert list(pieces.source) == list(expected_pieces.source)
    assert all(a.equals_exact(b, 0) for a, b in zip(pieces.geometry, expected_pieces.geometry))
