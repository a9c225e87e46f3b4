"""pear for geopandas and Dask: (Multi)Polygons in, triangles out.

    import geopandas, pear.geopandas
    frame = geopandas.read_file("counties.gpkg")
    rows = pear.geopandas.triangulate(frame)        # per row: triangles (indices), status
    pieces = pear.geopandas.triangle_polygons(frame)  # per triangle: source row, Polygon

The input is a GeoSeries, a GeoDataFrame (its active geometry column), or a pandas Series or
DataFrame column of shapely geometries or WKB bytes (geometry= names the column; missing values
are empty geometries). Both functions are partition functions for
dask.dataframe.map_partitions: pass threads=1 there (Dask runs the partitions in parallel) and
meta=the function applied to the Dask frame's empty meta (frame._meta). Keyword options are
pear.triangulate_many's.
"""
import numpy as np
import pandas

from . import _pear
from ._many import triangulate_many
from ._types import Status


def _values(data, geometry):
    """The geometry values (an object array), the index and the crs of data."""
    if isinstance(data, pandas.DataFrame):
        if geometry is None:
            geometry = getattr(data, "_geometry_column_name", None) or "geometry"
        if geometry not in data.columns:
            raise KeyError(f"no geometry column {geometry!r}: pass geometry=the column's name")
        series = data[geometry]
    elif isinstance(data, pandas.Series):
        series = data
    else:
        raise TypeError("data must be a GeoSeries, GeoDataFrame, pandas Series or DataFrame")
    values = np.array(series.array, dtype=object)
    values[pandas.isna(values)] = None  # NaN in a column of WKB: a missing geometry
    return values, series.index, getattr(series, "crs", None)


def triangulate(data, *, geometry=None, **options):
    """Triangulates every row: a DataFrame with data's index and two columns, triangles (each
    row's (k, 3) uint32 array of indices into the row geometry's coordinates, in shapely's
    order with rings closed: the order of shapely's get_coordinates) and status (the worst
    pear.Status name of the row's polygons; "ok" for an empty row). Never raises for bad
    geometry: look at status."""
    values, index, _ = _values(data, geometry)
    result = triangulate_many(values, **options)
    names = np.array([s.name for s in Status], dtype=object)
    triangles = pandas.Series(result.geometry_triangles(), index=index, dtype=object)
    return pandas.DataFrame({"triangles": triangles, "status": names[result.geometry_status]},
                            index=index)


def triangle_polygons(data, *, geometry=None, **options):
    """Every triangle as a shapely Polygon: a GeoDataFrame with one row per triangle, its
    column source (and index) the label of the row it came from, and data's crs. Rows whose
    status is not ok contribute what pear made of them (nothing for invalid input, the
    best-effort triangles of a polygon that is not simple; triangulate says which)."""
    import geopandas
    values, index, crs = _values(data, geometry)
    result = triangulate_many(values, **options)
    pieces = geopandas.GeoSeries.from_wkb(_pear.triangles_wkb(result.coordinates,
                                                              result.triangles), crs=crs)
    rows = np.repeat(np.arange(len(index)), np.diff(result.geometry_triangle_offsets))
    source = index.take(rows)
    return geopandas.GeoDataFrame({"source": source.to_numpy()}, index=source,
                                  geometry=pieces.values, crs=crs)
