"""pear: polygon triangulation (parallel ear clipping) for numpy, shapely and geopandas.

    import numpy as np, pear
    square_with_hole = np.array([[0, 0], [10, 0], [10, 10], [0, 10],
                                 [4, 4], [4, 6], [6, 6], [6, 4]], dtype=float)
    triangles = pear.triangulate(square_with_hole, [4])   # (8, 3) uint32 indices
    assert pear.validate(square_with_hole, triangles, [4]).valid

One polygon: triangulate(coords, ring_ends) or triangulate(shapely_polygon); with its points
too, triangulate_points(shapely_polygon), and as shapely Polygons,
shapely_triangles(*triangulate_points(shapely_polygon)). Many:
triangulate_many(coords, ring_offsets, polygon_offsets) or triangulate_many(geometries or WKB),
in parallel with the GIL released. GeoSeries and Dask: pear.geopandas. Reference:
docs/python.md.
"""
from ._pear import (Diagnostic, QualityStatistics, ValidationReport, incircle, orient2d, quality,
                    release_cached_engines, triangulate, triangulate_points, validate)
from ._many import BatchResult, triangulate_many
from ._shapely import shapely_triangles
from ._types import InvalidInputError, NotSimpleError, PearError, Status, WKBError

__version__ = "0.1.0"
#: The names the algorithm keyword takes ("auto" is "automatic").
ALGORITHMS = ("automatic", "sequential", "partition_and_cut", "mark_and_cut",
              "divide_and_conquer")
#: The names the heuristic keyword takes.
HEURISTICS = ("top", "fast")

__all__ = ["ALGORITHMS", "BatchResult", "Diagnostic", "HEURISTICS", "InvalidInputError",
           "NotSimpleError", "PearError", "QualityStatistics", "Status", "ValidationReport",
           "WKBError", "incircle", "orient2d", "quality", "release_cached_engines",
           "shapely_triangles", "triangulate", "triangulate_many", "triangulate_points",
           "validate"]
