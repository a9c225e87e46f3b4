"""Polygons for the Python tests, and checks that do not trust pear: exact areas (Python
integers), orientations and the expected triangle count, computed here from the input alone."""
import gzip
import json
import os
import pathlib
import subprocess

import numpy as np

import corpus  # tests/support, through conftest.py

SQUARE_WITH_HOLE = np.array([[0, 0], [10, 0], [10, 10], [0, 10],
                             [4, 4], [4, 6], [6, 6], [6, 4]], dtype=np.float64)
BOWTIE = np.array([[0, 0], [2, 2], [2, 0], [0, 2]], dtype=np.float64)


class Polygon:
    """One polygon of a corpus file: coords (N, 2) without closing points, ring offsets."""

    def __init__(self, name, rings, valid=True):
        self.name = name
        self.valid = valid  # its MANIFEST row records no defect (GEOS, NOT SIMPLE, ...)
        rings = [ring[:-1] if len(ring) > 1 and ring[0] == ring[-1] else ring for ring in rings]
        self.coords = np.array([p[:2] for ring in rings for p in ring], dtype=np.float64)
        self.coords = self.coords.reshape(-1, 2)
        self.offsets = np.cumsum([0] + [len(ring) for ring in rings]).astype(np.int64)

    @property
    def ring_ends(self):
        """mapbox_earcut's form: each ring's end."""
        return self.offsets[1:].astype(np.uint32)

    def rings(self):
        return [self.coords[a:b] for a, b in zip(self.offsets[:-1], self.offsets[1:])]


def read_geojson(path, valid=True):
    """The polygons of a GeoJSON file (Polygon, MultiPolygon, Feature, FeatureCollection)."""
    opener = gzip.open if str(path).endswith(".gz") else open
    with opener(path, "rt") as f:
        document = json.load(f)
    out = []

    def visit(g):
        kind = g.get("type")
        if kind == "FeatureCollection":
            for feature in g["features"]:
                visit(feature)
        elif kind == "Feature":
            if g.get("geometry"):
                visit(g["geometry"])
        elif kind == "Polygon":
            out.append(g["coordinates"])
        elif kind == "MultiPolygon":
            out.extend(g["coordinates"])
    visit(document)
    name = pathlib.Path(path).name
    return [Polygon(f"{name}:{i}", rings, valid) for i, rings in enumerate(out) if rings]


def folder(name, limit=None, only=None):
    """The polygons of a folder of the shared corpus, its first `limit` files or the file named
    `only` (skips the test when it is absent)."""
    files = corpus.read_folder(corpus.shared_root(), name)[:limit]
    if only is not None:
        files = [f for f in files if f.file == only]
        corpus.require(*(f.path for f in files))
    return [p for f in files for p in read_geojson(f.path, f.valid)]


def child_environment(**extra):
    """os.environ for a child Python that imports the pear this process imported (first on its
    PYTHONPATH, made absolute: the child may run in another folder), plus `extra`."""
    import pear
    search = [str(pathlib.Path(pear.__file__).resolve().parents[1]),
              os.environ.get("PYTHONPATH", "")]
    return {**os.environ, "PYTHONPATH": os.pathsep.join(filter(None, search)), **extra}


def counties_frame():
    """The shared corpus' counties as a GeoDataFrame (column file, EPSG:4326); skips the test
    when they are absent."""
    import geopandas
    from shapely.geometry import shape
    files = corpus.read_folder(corpus.shared_root(), "counties")
    corpus.require(*(f.path for f in files))
    geometries = [shape(json.loads(f.path.read_text())) for f in files]
    return geopandas.GeoDataFrame({"file": [f.file for f in files]}, geometry=geometries,
                                  crs="EPSG:4326")


def scaled_integers(coords):
    """The coordinates as Python integers, all scaled by one power of two: exact."""
    ratios = [x.as_integer_ratio() for x in np.asarray(coords, dtype=np.float64).ravel().tolist()]
    scale = max((d for _, d in ratios), default=1)
    flat = [n * (scale // d) for n, d in ratios]
    return list(zip(flat[0::2], flat[1::2]))


def cleaned_rings(points, offsets):
    """Each ring's points without repeated consecutive ones and the closing one (pear's
    cleaning); rings of fewer than 3 points or zero area are dropped as pear drops holes."""
    rings = []
    for r, (a, b) in enumerate(zip(offsets[:-1], offsets[1:])):
        ring = []
        for p in points[a:b]:
            if not ring or ring[-1] != p:
                ring.append(p)
        while len(ring) > 1 and ring[-1] == ring[0]:
            ring.pop()
        if r == 0 or (len(ring) >= 3 and twice_area(ring) != 0):
            rings.append(ring)
    return rings


def twice_area(ring):
    return sum(ring[i - 1][0] * ring[i][1] - ring[i][0] * ring[i - 1][1] for i in range(len(ring)))


def exact_check(coords, offsets, triangles, count=True):
    """What the input says a triangulation must be, checked against triangles without pear:
    every triangle strictly counterclockwise, the exact area (twice, in scaled integers) equal
    to the polygon's, and (with no repeated points, and `count`) n + 2h - 2 triangles. Returns
    a list of the failures, empty when all hold. `count` False for a polygon pear repaired
    (a vertex inside an edge adds a point, a spike's tip leaves): pear.validate counts those."""
    points = scaled_integers(coords)
    rings = cleaned_rings(points, list(offsets))
    polygon = abs(twice_area(rings[0])) - sum(abs(twice_area(ring)) for ring in rings[1:])
    failures, total = [], 0
    for a, b, c in np.asarray(triangles, dtype=np.int64).tolist():
        (ax, ay), (bx, by), (cx, cy) = points[a], points[b], points[c]
        cross = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax)
        if cross <= 0:
            failures.append(f"triangle {a, b, c} is not counterclockwise")
        total += cross
    if total != polygon:
        failures.append(f"area {total} != polygon's {polygon}")
    kept = [p for ring in rings for p in ring]
    if count and len(set(kept)) == len(kept):
        expected = len(kept) + 2 * (len(rings) - 1) - 2
        if len(triangles) != expected:
            failures.append(f"{len(triangles)} triangles, not n + 2h - 2 = {expected}")
    return failures


def cli_stats(path, *options):
    """The built pear CLI's --stats lines for path (PEAR_CLI, set by meson), keyed by file name
    and polygon index; None when the CLI is not known."""
    cli = os.environ.get("PEAR_CLI")
    if not cli:
        return None
    run = subprocess.run([cli, "triangulate", str(path), "--stats", "--keep-small-rings",
                          *options], capture_output=True, text=True, timeout=600)
    lines = [json.loads(line) for line in run.stdout.splitlines() if line.strip()]
    return {(pathlib.Path(s["file"]).name, s["index"]): s for s in lines}


BATCH_ARRAYS = ("coordinates", "ring_offsets", "polygon_offsets", "geometry_offsets",
                "triangles", "triangle_offsets", "status", "diagnostic_issue")


def through_wkb(pear, switch, data, **options):
    """triangulate_many(data) with pear._many's `switch` off: geometries read as WKB."""
    setattr(pear._many, switch, False)
    try:
        return pear.triangulate_many(data, **options)
    finally:
        setattr(pear._many, switch, True)


def assert_reads_as_wkb(pear, switch, data):
    """triangulate_many(data) gives the same arrays as through WKB; returns its result."""
    direct, by_wkb = pear.triangulate_many(data), through_wkb(pear, switch, data)
    for name in BATCH_ARRAYS:
        assert np.array_equal(getattr(direct, name), getattr(by_wkb, name)), name
    return direct
