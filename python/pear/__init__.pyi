# Types of the package pear (PEP 561: py.typed marks it typed). The C++ module's part is in
# _pear.pyi, pear.geopandas' in geopandas.pyi; docs/python.md is the reference.
from typing import Any, Iterable, List, Optional, Union

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._pear import Diagnostic as Diagnostic
from ._pear import _Offsets, _Points, _Triangles
from ._pear import QualityStatistics as QualityStatistics
from ._pear import ValidationReport as ValidationReport
from ._pear import incircle as incircle
from ._pear import orient2d as orient2d
from ._pear import quality as quality
from ._pear import release_cached_engines as release_cached_engines
from ._pear import triangulate as triangulate
from ._pear import triangulate_points as triangulate_points
from ._pear import validate as validate
from ._types import InvalidInputError as InvalidInputError
from ._types import NotSimpleError as NotSimpleError
from ._types import PearError as PearError
from ._types import Status as Status
from ._types import WKBError as WKBError

__version__: str
ALGORITHMS: tuple[str, ...]
HEURISTICS: tuple[str, ...]

class BatchResult:
    coordinates: _Points
    ring_offsets: _Offsets
    polygon_offsets: _Offsets
    geometry_offsets: _Offsets
    triangles: _Triangles
    triangle_offsets: _Offsets
    status: NDArray[np.uint8]
    diagnostic_offsets: _Offsets
    diagnostic_issue: NDArray[np.uint8]
    diagnostic_ring: _Offsets
    diagnostic_vertex: _Offsets
    delaunay_flips: int
    def __init__(self, coordinates: _Points, ring_offsets: _Offsets, polygon_offsets: _Offsets,
                 geometry_offsets: _Offsets, arrays: Any) -> None: ...
    def __len__(self) -> int: ...
    @property
    def ok(self) -> bool: ...
    def polygon_triangles(self, p: int) -> _Triangles: ...
    def diagnostics(self, p: int) -> List[Diagnostic]: ...
    @property
    def geometry_triangle_offsets(self) -> _Offsets: ...
    @property
    def geometry_status(self) -> NDArray[np.uint8]: ...
    def geometry_point_offsets(self) -> _Offsets: ...
    def local_triangles(self) -> _Triangles: ...
    def geometry_triangles(self) -> List[_Triangles]: ...
    def check(self) -> BatchResult: ...

# data: an (N, 2) or (N, 3) array with ring_offsets and polygon_offsets, or an iterable of shapely
# geometries, WKB bytes or None (a GeoSeries among them).
def triangulate_many(data: Union[ArrayLike, Iterable[Any]], ring_offsets: Optional[ArrayLike] = None,
                     polygon_offsets: Optional[ArrayLike] = None,
                     geometry_offsets: Optional[ArrayLike] = None, *, algorithm: str = "automatic",
                     heuristic: str = "top", delaunay: bool = False, threads: int = 0,
                     partitions: int = 0, check_simplicity: bool = True) -> BatchResult: ...

# A list of shapely Polygons (shapely.geometry.Polygon).
def shapely_triangles(points: ArrayLike, triangles: ArrayLike) -> List[Any]: ...

__all__ = ["ALGORITHMS", "BatchResult", "Diagnostic", "HEURISTICS", "InvalidInputError",
           "NotSimpleError", "PearError", "QualityStatistics", "Status", "ValidationReport",
           "WKBError", "incircle", "orient2d", "quality", "shapely_triangles", "triangulate",
           "triangulate_many", "triangulate_points", "validate"]
