"""pear.triangulate_many: many polygons in one call, and what it returns."""
import numpy as np

from . import _pear
from ._types import Status


class BatchResult:
    """The triangulations of a batch, as flat arrays (triangulate_many returns one).

    coordinates      (N, 2) float64: the points the triangles index (the caller's array for
                     ragged input, (N, 3) when it has z; for WKB and shapely input, every
                     geometry's x and y in shapely's order, rings closed)
    ring_offsets, polygon_offsets, geometry_offsets
                     the layout of those points (int64): ring r is points [ring_offsets[r],
                     ring_offsets[r+1]), polygon p rings [polygon_offsets[p], ...), input
                     geometry g polygons [geometry_offsets[g], ...) (a MultiPolygon has several,
                     an empty or missing geometry none)
    triangles        (M, 3) uint32: counterclockwise triples of indices into coordinates
    triangle_offsets (P + 1) int64: polygon p's triangles are triangles[triangle_offsets[p]:
                     triangle_offsets[p + 1]]
    status           (P,) uint8: each polygon's pear.Status value
    diagnostic_offsets (P + 1) int64, diagnostic_issue (uint8), diagnostic_ring,
    diagnostic_vertex (int64): polygon p's findings (diagnostics(p) makes them objects)
    delaunay_flips   CDT flips over all polygons (delaunay=True)
    """

    def __init__(self, coordinates, ring_offsets, polygon_offsets, geometry_offsets, arrays):
        """arrays: the module's BatchArrays (pear._pear.triangulate_batch's result)."""
        self.coordinates = coordinates
        self.ring_offsets = ring_offsets
        self.polygon_offsets = polygon_offsets
        self.geometry_offsets = geometry_offsets
        for name in ("triangles", "triangle_offsets", "status", "diagnostic_offsets",
                     "diagnostic_issue", "diagnostic_ring", "diagnostic_vertex", "delaunay_flips"):
            setattr(self, name, getattr(arrays, name))

    def __len__(self):
        """The number of polygons (a MultiPolygon counts its parts)."""
        return len(self.status)

    def __repr__(self):
        counts = np.bincount(self.status, minlength=len(Status))
        statuses = ", ".join(f"{s.name}={counts[s]}" for s in Status if counts[s])
        return (f"BatchResult({len(self)} polygons, {len(self.triangles)} triangles"
                f"{', ' if statuses else ''}{statuses})")

    @property
    def ok(self):
        """Whether every polygon has Status.ok."""
        return bool(np.all(self.status == Status.ok))

    def polygon_triangles(self, p):
        """Polygon p's triangles, indices into coordinates."""
        return self.triangles[self.triangle_offsets[p]:self.triangle_offsets[p + 1]]

    def diagnostics(self, p):
        """Polygon p's findings as pear.Diagnostic objects (ring counts within the polygon)."""
        span = range(self.diagnostic_offsets[p], self.diagnostic_offsets[p + 1])
        return [_pear.describe_issue(int(self.diagnostic_issue[d]), int(self.diagnostic_ring[d]),
                                     int(self.diagnostic_vertex[d])) for d in span]

    @property
    def geometry_triangle_offsets(self):
        """(G + 1) int64: geometry g's triangles are triangles[offsets[g]:offsets[g + 1]]."""
        return self.triangle_offsets[self.geometry_offsets]

    @property
    def geometry_status(self):
        """(G,) uint8: each input geometry's worst polygon status (ok for an empty one)."""
        starts = self.geometry_offsets[:-1]
        has_parts = self.geometry_offsets[1:] > starts
        worst = np.zeros(len(starts), dtype=np.uint8)
        if len(self.status):
            worst[has_parts] = np.maximum.reduceat(self.status, starts[has_parts])
        return worst

    def geometry_point_offsets(self):
        """(G + 1) int64: geometry g's points are coordinates[offsets[g]:offsets[g + 1]]."""
        rings = np.take(self.polygon_offsets, self.geometry_offsets, mode="clip")
        return np.take(self.ring_offsets, rings, mode="clip")  # clipped: offsets may be bad

    def local_triangles(self):
        """The triangles with each one's indices counted from its geometry's first point: for
        WKB and shapely input, indices into that geometry's own coordinates."""
        first_point = self.geometry_point_offsets()[:-1]
        per_geometry = np.diff(self.geometry_triangle_offsets)
        shift = np.repeat(first_point, per_geometry).astype(np.uint32)
        return self.triangles - shift[:, None]

    def geometry_triangles(self):
        """A list with each geometry's (k, 3) uint32 triangles, indices into its coordinates."""
        if len(self.geometry_offsets) < 2:
            return []
        return np.split(self.local_triangles(), self.geometry_triangle_offsets[1:-1])

    def check(self):
        """Raises what pear.triangulate would for the first polygon that is not ok."""
        bad = np.flatnonzero(self.status != Status.ok)
        if len(bad) == 0:
            return self
        p = int(bad[0])
        diagnostics = self.diagnostics(p)
        first = next((d for d in diagnostics if d.is_error or d.is_not_simple), None)
        message = f"polygon {p}: {first if first is not None else Status(self.status[p]).name}"
        from ._types import InvalidInputError, NotSimpleError
        if self.status[p] == Status.not_simple:
            raise NotSimpleError(message, self.polygon_triangles(p), diagnostics)
        raise InvalidInputError(message, first.issue if first else "invalid_input",
                                first.ring if first else 0, first.vertex if first else 0,
                                diagnostics)


def _wkb_writer():
    """One shapely geometry to WKB: shapely 1.8's writer made once per batch (half the time of
    .wkb, which makes a writer per geometry), else .wkb. A writer is not shared between calls:
    GEOS writers are not thread-safe. The writer reads a geometry's _geom as a GEOS address,
    so it only gets shapely's own geometries: another object with a wkb gives its .wkb."""
    try:
        from shapely.geometry.base import BaseGeometry
        from shapely.geos import WKBWriter, lgeos  # shapely 1.8
    except ImportError:
        return lambda geometry: geometry.wkb
    write = WKBWriter(lgeos).write
    return lambda geometry: write(geometry) if isinstance(geometry, BaseGeometry) \
        else geometry.wkb


def _vectorised_wkb(geometries):
    """Every geometry's WKB in one call where shapely has one (shapely 2's to_wkb, in C over
    the array), else None: shapely 1.8 writes geometry by geometry."""
    import shapely
    to_wkb = getattr(shapely, "to_wkb", None)
    if to_wkb is None:
        return None
    try:
        return list(to_wkb(np.asarray(geometries, dtype=object)))
    except (TypeError, ValueError):
        return None  # something that is not a geometry: the module names it


def _ragged_arrays(geometries):
    """(coords, ring_offsets, polygon_offsets, geometry_offsets) from shapely 2's
    to_ragged_array (in C over the array: no WKB in between, a quarter less time than to_wkb
    and reading it), laid out as the WKB reader lays them out (x and y, rings closed, an empty
    polygon no polygon); None where shapely has no to_ragged_array (1.8) or refuses the
    geometries (other types, collections, something that is no geometry): WKB takes them."""
    import shapely
    to_ragged_array = getattr(shapely, "to_ragged_array", None)
    if to_ragged_array is None:
        return None
    try:
        kind, coords, offsets = to_ragged_array(np.asarray(geometries, dtype=object),
                                                include_z=False)
    except (TypeError, ValueError):
        return None
    if kind == shapely.GeometryType.POLYGON:
        rings, polygons = offsets
        geometry = np.arange(len(polygons), dtype=np.int64)
    elif kind == shapely.GeometryType.MULTIPOLYGON:
        rings, polygons, geometry = offsets
    else:
        return None
    rings, polygons, geometry = (np.asarray(o, dtype=np.int64) for o in (rings, polygons, geometry))
    # An empty polygon (or None) is a polygon of no rings here, and no polygon in WKB.
    kept = np.diff(polygons) > 0
    kept_before = np.concatenate(([0], np.cumsum(kept)))
    polygons = np.append(polygons[:-1][kept], polygons[-1])
    return np.ascontiguousarray(coords, dtype=np.float64), rings, polygons, kept_before[geometry]


#: Whether shapely 2 geometries are read through to_ragged_array (False: as WKB; the tests
#: compare the two).
_read_ragged_arrays = True

#: Whether shapely 1.8 geometries are read through their GEOS handles (False: as WKB, the
#: path every other input takes; the benchmark and the tests compare the two).
_read_geos_handles = True


def _reads_geos_handles():
    """Whether shapely geometries are read through GEOS here: shapely 1.8 and a module built
    with geos_c.h (the tests and the benchmark ask)."""
    return bool(_pear.has_geos_reader) and _pear.read_geos([]) is not None


def _as_sequence(geometries):
    """geometries as a list or array: one geometry or WKB value becomes a list of one."""
    # hasattr on the type: shapely's wkb is a property, asking a geometry writes its WKB.
    if isinstance(geometries, (bytes, bytearray)) or hasattr(type(geometries), "wkb"):
        return [geometries]
    if isinstance(geometries, (list, np.ndarray)):
        return geometries
    if hasattr(type(geometries), "__array__"):  # a GeoSeries, a pandas Series: their array
        array = np.asarray(geometries, dtype=object)  # (list() cost 1 ms on the counties)
        if array.ndim == 1:
            return array
    try:
        return list(geometries)
    except TypeError:
        raise TypeError("data must be an (N, 2) array with offsets, or a sequence of "
                        f"geometries, WKB values or None, not {type(geometries).__name__}"
                        ) from None


def _read_geometries(geometries):
    """(coords, ring_offsets, polygon_offsets, geometry_offsets) of a sequence of shapely
    geometries, WKB values or None: shapely 1.8's through their GEOS handles where they all
    can be, shapely 2's through to_ragged_array, else from WKB; what is none of these is passed
    on for the module to name."""
    geometries = _as_sequence(geometries)
    # WKB goes to the module as it is (it names any element that is not WKB): a Python test of
    # every element would cost a tenth of a small polygon's triangulation.
    first = next((v for v in geometries if v is not None), None)
    if first is None or isinstance(first, (bytes, bytearray)):
        return _pear.read_wkb(geometries)
    # shapely 1.8: the module finds shapely's libgeos_c itself (None for shapely 2, which has
    # to_ragged_array and to_wkb over arrays, or a module built without geos_c.h).
    if _read_geos_handles and _pear.has_geos_reader:
        flat = _pear.read_geos(geometries)
        if flat is not None:
            return flat
    ragged = _ragged_arrays(geometries) if _read_ragged_arrays else None
    if ragged is not None:
        return ragged
    vectorised = _vectorised_wkb(geometries)
    if vectorised is not None:
        return _pear.read_wkb(vectorised)
    write = _wkb_writer()
    return _pear.read_wkb([write(v) if hasattr(type(v), "wkb") else v for v in geometries])


def triangulate_many(data, ring_offsets=None, polygon_offsets=None, geometry_offsets=None, *,
                     algorithm="automatic", heuristic="top", delaunay=False, threads=0,
                     partitions=0, check_simplicity=True):
    """Triangulates many polygons in one call, in parallel over the polygons on pear's
    scheduler, the GIL released; returns a BatchResult. Never raises for bad geometry: each
    polygon has a status (BatchResult.check() raises as triangulate would).

    data: an (N, 2) float64 array (or (N, 3): z kept, x and y triangulated) with integer
    ring_offsets and polygon_offsets (shapely 2's to_ragged_array layout:
    ``triangulate_many(coords, *offsets)``; geometry_offsets for MultiPolygons); or a sequence
    of shapely Polygons/MultiPolygons (shapely 2's read by to_ragged_array), of WKB bytes
    (Polygon or MultiPolygon, any byte order, ISO or EWKB, Z/M dropped), or of None, a
    GeoSeries among them.
    Options as for triangulate; threads=0 uses every hardware thread.
    """
    options = dict(algorithm=algorithm, heuristic=heuristic, delaunay=delaunay, threads=threads,
                   partitions=partitions, check_simplicity=check_simplicity)
    if ring_offsets is None:
        if polygon_offsets is not None or geometry_offsets is not None:
            raise TypeError("polygon_offsets and geometry_offsets go with ring_offsets")
        coords, ring_offsets, polygon_offsets, geometry_offsets = _read_geometries(data)
    else:
        if polygon_offsets is None:
            raise TypeError("ring_offsets needs polygon_offsets (one polygon: [0, rings])")
        coords = data
        # Integers only, by the module's rules: 4.5 is not truncated to 4 (docs/python.md).
        ring_offsets = _pear.as_offsets(ring_offsets, "ring_offsets")
        polygon_offsets = _pear.as_offsets(polygon_offsets, "polygon_offsets")
        polygons = max(len(polygon_offsets) - 1, 0)
        if geometry_offsets is None:
            geometry_offsets = np.arange(polygons + 1, dtype=np.int64)
        geometry_offsets = _pear.as_offsets(geometry_offsets, "geometry_offsets")
        if (len(geometry_offsets) == 0 or geometry_offsets[0] != 0
                or geometry_offsets[-1] != polygons or np.any(np.diff(geometry_offsets) < 0)):
            raise ValueError(f"geometry_offsets must rise from 0 to the {polygons} polygons")
    arrays = _pear.triangulate_batch(coords, ring_offsets, polygon_offsets, **options)
    if not isinstance(coords, np.ndarray):
        coords = np.asarray(coords, dtype=np.float64)
    return BatchResult(coords, ring_offsets, polygon_offsets, geometry_offsets, arrays)
