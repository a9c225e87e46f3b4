#!/usr/bin/env python3
"""What `pear triangulate` carries from its input to its output besides the triangles: each
feature's properties (compared with the input's as parsed JSON), z per vertex (compared with the
input vertex at the same x, y), the SRID as a GeoJSON crs, and geometries that are not polygons
(skipped and named on stderr, the rest still triangulated).

usage: test_attributes.py PATH/TO/pear
"""
import json
import os
import re
import struct
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import corpus  # noqa: E402 (tests/support)
from scratch import ScratchTest  # noqa: E402 (tests/support)

PEAR = None
SOUTH_AFRICA = str(corpus.bundled_root() / "countries" / "south_africa_000.json")

PROPERTIES = [
    {"name": "caf\u00e9 \"quoted\"", "n": 3, "x": -0.5, "big": 1.5e300, "ok": True,
     "nested": {"list": [1, None, {"deep": "v"}]}, "pear": "the user's own"},
    {"name": "line"},
    None,
    {},
]


def pear(*args, stdin=None):
    return subprocess.run([PEAR, *args], input=stdin, capture_output=True, text=True, timeout=120)


def z_of(x, y):
    """The z every test vertex gets: a function of x, y alone, so that a vertex found in the
    output by x, y has one right z whatever polygon or ring it is in."""
    return round(x * 7.25 - y * 3.5 + 100, 6)


def square(x0, size, with_z=True):
    ring = [[x0, 0], [x0 + size, 0], [x0 + size, size], [x0, size], [x0, 0]]
    hole = [[x0 + 1, 1], [x0 + 1, 2], [x0 + 2, 2], [x0 + 2, 1], [x0 + 1, 1]]
    if with_z:
        ring = [[x, y, z_of(x, y)] for x, y in ring]
        hole = [[x, y, z_of(x, y)] for x, y in hole]
    return [ring, hole]


def collection():
    """Four features: a Polygon with a hole, a LineString, a MultiPolygon of two, a null
    geometry; all positions with z."""
    geometries = [
        {"type": "Polygon", "coordinates": square(0, 4)},
        {"type": "LineString", "coordinates": [[0, 0, 1], [1, 1, 1]]},
        {"type": "MultiPolygon", "coordinates": [square(10, 4), square(20, 5)]},
        None,
    ]
    return {"type": "FeatureCollection", "features": [
        {"type": "Feature", "properties": p, "geometry": g} for p, g in zip(PROPERTIES, geometries)]}


class Attributes(ScratchTest):
    def write(self, name, data):
        with open(self.path(name), "wb" if isinstance(data, bytes) else "w") as f:
            f.write(data)
        return self.path(name)

    def triangulate(self, source, out, *options):
        r = pear("triangulate", source, "-o", self.path(out), *options)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(self.path(out)) as f:
            return f.read(), r.stderr

    def assert_z_of_every_vertex(self, positions):
        self.assertGreater(len(positions), 0)
        for x, y, z in positions:
            self.assertEqual(z, z_of(x, y), (x, y))

    def test_properties_survive_and_pear_adds_one_member(self):
        source = self.write("in.geojson", json.dumps(collection()))
        text, stderr = self.triangulate(source, "out.geojson")
        out = json.loads(text)["features"]
        # One output feature per polygon: the Polygon, then the MultiPolygon's two parts.
        self.assertEqual([f["properties"]["pear"]["feature"] for f in out], [0, 2, 2])
        for f in out:
            props = dict(f["properties"])
            ours = props.pop("pear")
            want = dict(PROPERTIES[ours["feature"]] or {})
            want.pop("pear", None)  # pear's own member takes the name
            self.assertEqual(props, want)
            self.assertEqual(ours["status"], "ok")
            self.assertEqual(ours["triangles"], len(f["geometry"]["coordinates"]))
        self.assertEqual([f["properties"]["pear"]["index"] for f in out], [0, 1, 2])
        self.assertRegex(stderr, re.escape(source) + r":\d+:\d+: feature 1: skipped a LineString")

    def test_z_of_each_output_vertex_is_the_input_vertex_z(self):
        source = self.write("in.geojson", json.dumps(collection()))
        text, _ = self.triangulate(source, "out.geojson")
        positions = [tuple(p) for f in json.loads(text)["features"]
                     for triangle in f["geometry"]["coordinates"] for p in triangle[0]]
        self.assertTrue(all(len(p) == 3 for p in positions))
        self.assert_z_of_every_vertex(positions)
        obj, _ = self.triangulate(source, "out.obj")
        vertices = [tuple(float(v) for v in line.split()[1:]) for line in obj.splitlines()
                    if line.startswith("v ")]
        self.assertEqual(len(vertices), 3 * 8)  # three polygons of 8 vertices each
        self.assert_z_of_every_vertex(vertices)

    def test_z_from_wkt_and_ewkb_and_every_algorithm(self):
        ring = square(0, 4)[0]
        wkt = "POLYGON Z ((%s))" % ", ".join("%r %r %r" % tuple(p) for p in ring)
        body = struct.pack("<II", 1, len(ring)) + b"".join(struct.pack("<ddd", *p) for p in ring)
        ewkb = struct.pack("<BII", 1, 3 | 0x80000000 | 0x20000000, 32633) + body
        for name, data in (("z.wkt", wkt), ("z.wkb", ewkb), ("z.hexwkb", ewkb.hex())):
            with self.subTest(name):
                obj, _ = self.triangulate(self.write(name, data), name + ".obj")
                vertices = [tuple(float(v) for v in line.split()[1:])
                            for line in obj.splitlines() if line.startswith("v ")]
                self.assertEqual(len(vertices), 4)
                self.assert_z_of_every_vertex(vertices)

    def test_z_exact_with_parallel_algorithms_and_cdt(self):
        corpus.require(SOUTH_AFRICA)
        with open(SOUTH_AFRICA) as f:
            polygon = json.load(f)
        polygon["coordinates"] = [[[x, y, z_of(x, y)] for x, y in ring]
                                  for ring in polygon["coordinates"]]
        source = self.write("za.geojson", json.dumps(polygon))
        for options in (["--algorithm", "divide-and-conquer", "--partitions", "4"],
                        ["--algorithm", "partition-and-cut", "--cdt"]):
            with self.subTest(options[1]):
                text, _ = self.triangulate(source, "za.out.geojson", *options)
                [feature] = json.loads(text)["features"]
                positions = [tuple(p) for t in feature["geometry"]["coordinates"] for p in t[0]]
                self.assert_z_of_every_vertex(positions)

    def test_the_srid_becomes_a_crs_that_names_it(self):
        source = self.write("srid.wkt", "SRID=32633;POLYGON ((0 0, 4 0, 4 4, 0 0))")
        text, _ = self.triangulate(source, "srid.geojson")
        crs = json.loads(text)["crs"]
        self.assertEqual(crs["properties"]["name"], "urn:ogc:def:crs:EPSG::32633")
        plain, _ = self.triangulate(self.write("plain.wkt", "POLYGON ((0 0, 4 0, 4 4, 0 0))"),
                                    "plain.geojson")
        self.assertNotIn("crs", json.loads(plain))

    def test_a_file_of_lines_only_is_still_bad_input(self):
        source = self.write("lines.wkt", "LINESTRING (0 0, 1 1)\nPOINT (3 4)")
        r = pear("triangulate", source)
        self.assertEqual(r.returncode, 1)
        self.assertIn(source + ":1:1: expected POLYGON", r.stderr)

    def test_mixed_wkt_collection_names_what_it_skipped(self):
        source = self.write("mixed.wkt", "GEOMETRYCOLLECTION (POINT (9 9), "
                                         "POLYGON ((0 0, 4 0, 4 4, 0 0)))\nLINESTRING (0 0, 1 1)")
        r = pear("triangulate", "--stats", source)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(len(r.stdout.splitlines()), 1)
        self.assertIn(source + ":1:21: feature 0: skipped a POINT", r.stderr)
        self.assertIn(source + ":2:1: feature 1: skipped a LINESTRING", r.stderr)


if __name__ == "__main__":
    PEAR = os.path.abspath(sys.argv.pop(1))
    corpus.main()
