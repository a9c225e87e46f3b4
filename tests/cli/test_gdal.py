#!/usr/bin/env python3
"""`pear triangulate` on GIS files through GDAL: real GeoPackage, Shapefile and FlatGeobuf files
made here with GDAL's ogr2ogr from bundled corpus polygons (with attributes, a line among them,
and a projected CRS), triangulated, and read back with GDAL: the feature count, the attributes
and FIDs equal the source's as GDAL reads it, the CRS is the source's, and the triangles' area
(shoelace, computed here) equals the source polygon's within 1e-9 relative. GeoJSON properties
become the fields (names, types, values) that GDAL's own GeoJSON driver makes of the same file;
a field named like pear's keeps its name and values and pear's is renamed, with a note. m (and
z) of WKT and of GDAL's own layers with M reach every output vertex, as GDAL reads the output
back. Errors: a file GDAL cannot open, a missing layer, a bad --where, a layer without polygons.

usage: test_gdal.py PATH/TO/pear gdal|no-gdal
Skips (exit 77) when pear was built without GDAL or GDAL's command-line tools are missing.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import corpus  # noqa: E402 (tests/support)

PEAR = None
COUNTRIES = ["armenia_000.json", "mozambique_000.json", "south_africa_000.json"]
FORMATS = {"gpkg": "GPKG", "shp": "ESRI Shapefile", "fgb": "FlatGeobuf"}


def run(*args):
    return subprocess.run(list(args), capture_output=True, text=True, timeout=120)


def ring_area(ring):
    return sum(ring[i][0] * ring[i + 1][1] - ring[i + 1][0] * ring[i][1]
               for i in range(len(ring) - 1)) / 2


def polygon_area(rings):
    """Outer ring's area less its holes', whatever their orientation."""
    return abs(ring_area(rings[0])) - sum(abs(ring_area(r)) for r in rings[1:])


def area(geometry):
    parts = [geometry["coordinates"]] if geometry["type"] == "Polygon" else geometry["coordinates"]
    return sum(polygon_area(p) for p in parts)


def as_geojson(path):
    """The dataset's first layer as GDAL reads it."""
    r = run("ogr2ogr", "-f", "GeoJSON", "/vsistdout/", path)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def fids_by_name(path):
    """FID of each feature, by its name attribute, from ogrinfo's listing."""
    text = run("ogrinfo", "-al", "-q", path).stdout
    fids = {}
    for block in re.split(r"\n(?=OGRFeature\()", text):
        m = re.match(r"OGRFeature\([^)]*\):(\d+)", block)
        name = re.search(r"^\s+name \(String\) = (.*)$", block, re.M)
        if m and name:
            fids[name.group(1)] = int(m.group(1))
    return fids


def field_types(path):
    """Field name -> type as ogrinfo lists them ("Integer(Boolean)", "String(JSON)"), in order."""
    text = run("ogrinfo", "-so", "-al", path).stdout
    return dict(re.findall(r"^(\w+): ([\w()]+) \(\d+\.\d+\)$", text, re.M))


def as_json(value):
    """A JSON field's value: text in some formats' GeoJSON output, an object in others'."""
    return json.loads(value) if isinstance(value, str) else value


def read_wkt_column(path):
    """Each feature's geometry as WKT, as GDAL reads the dataset (its CSV driver's output)."""
    r = run("ogr2ogr", "-f", "CSV", "-lco", "GEOMETRY=AS_WKT", "/vsistdout/", path)
    assert r.returncode == 0, r.stderr
    return [line.split('"')[1] for line in r.stdout.splitlines()[1:]]


def coordinates(wkt):
    """Every position of a WKT geometry as a list of floats."""
    return [[float(v) for v in position.split()]
            for ring in re.findall(r"\(([^()]+)\)", wkt) for position in ring.split(",")]


class Gdal(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.TemporaryDirectory()
        features = []
        for k, name in enumerate(COUNTRIES):
            path = corpus.bundled_root() / "countries" / name
            if not path.exists():
                continue
            with open(path) as f:
                geometry = json.load(f)
            features.append({"type": "Feature", "geometry": geometry, "properties": {
                "name": name.split("_0")[0], "rank": k + 1, "score": 0.25 + k, "note": None}})
            if k == 0:  # a line among the polygons: skipped and named
                features.append({"type": "Feature", "properties": {"name": "border", "rank": 0},
                                 "geometry": {"type": "LineString",
                                              "coordinates": [[44, 40], [45, 41]]}})
        cls.source = os.path.join(cls.dir.name, "countries.geojson")
        with open(cls.source, "w") as f:
            json.dump({"type": "FeatureCollection", "features": features}, f)
        cls.polygon_count = len(features) - 1

    @classmethod
    def tearDownClass(cls):
        cls.dir.cleanup()

    def path(self, name):
        return os.path.join(self.dir.name, name)

    def make(self, ext, *options):
        """The corpus polygons as a GDAL file of this format, in a projected CRS."""
        corpus.require(*(corpus.bundled_root() / "countries" / n for n in COUNTRIES))
        out = self.path("source." + ext)
        if not os.path.exists(out):
            r = run("ogr2ogr", "-f", FORMATS[ext], "-a_srs", "EPSG:32735", "-nln", "countries",
                    "-skipfailures", out, self.source, *options)
            self.assertEqual(r.returncode, 0, r.stderr)
        return out

    def check_output(self, source, output):
        src, out = as_geojson(source), as_geojson(output)
        self.assertEqual(out.get("crs"), src.get("crs"))
        self.assertIsNotNone(out.get("crs"))
        polygons = {f["properties"]["name"]: f for f in src["features"]
                    if f["geometry"] and "Polygon" in f["geometry"]["type"]}
        self.assertEqual(len(polygons), self.polygon_count)
        self.assertEqual(len(out["features"]), len(polygons))
        source_fids = fids_by_name(source)
        for feature in out["features"]:
            props = dict(feature["properties"])
            fid, triangles, status = props.pop("pear_fid"), props.pop("pear_tris"), props.pop("pear_stat")
            want = polygons[props["name"]]
            self.assertEqual(props, want["properties"])
            self.assertEqual(fid, source_fids[props["name"]])
            self.assertEqual(status, "ok")
            self.assertEqual(triangles, len(feature["geometry"]["coordinates"]))
            self.assertTrue(all(len(t) == 1 and len(t[0]) == 4 for t in feature["geometry"]["coordinates"]))
            self.assertAlmostEqual(area(feature["geometry"]) / area(want["geometry"]), 1, delta=1e-9)
        return out

    def test_each_format_round_trip_through_gdal(self):
        for ext in FORMATS:
            with self.subTest(ext):
                source = self.make(ext)
                output = self.path("out." + ext)
                r = run(PEAR, "triangulate", "--validate", source, "-o", output)
                self.assertEqual(r.returncode, 0, r.stderr)
                if ext != "shp":  # the Shapefile itself cannot hold the line
                    self.assertRegex(r.stderr, re.escape(source) + r": feature \d+: skipped a Line")
                self.check_output(source, output)

    def test_geopackage_keeps_the_fids(self):
        source = self.make("gpkg")
        output = self.path("fid.gpkg")
        self.assertEqual(run(PEAR, "triangulate", source, "-o", output).returncode, 0)
        want = {n: f for n, f in fids_by_name(source).items() if n != "border"}
        self.assertEqual(fids_by_name(output), want)

    def test_geojson_output_of_a_geopackage_keeps_attributes_and_crs(self):
        source = self.make("gpkg")
        output = self.path("gpkg.geojson")
        r = run(PEAR, "triangulate", source, "-o", output)
        self.assertEqual(r.returncode, 0, r.stderr)
        with open(output) as f:
            out = json.load(f)
        src = as_geojson(source)
        self.assertEqual(out["crs"]["properties"]["name"], "urn:ogc:def:crs:EPSG::32735")
        by_name = {f["properties"]["name"]: f["properties"] for f in src["features"]}
        for feature in out["features"]:
            props = dict(feature["properties"])
            props.pop("pear")
            self.assertEqual(props, by_name[props["name"]])

    def test_layer_and_where(self):
        source = self.make("gpkg")
        output = self.path("where.fgb")
        r = run(PEAR, "triangulate", source, "--layer", "countries", "--where", "rank >= 2",
                "-o", output)
        self.assertEqual(r.returncode, 0, r.stderr)
        names = sorted(f["properties"]["name"] for f in as_geojson(output)["features"])
        self.assertEqual(names, ["mozambique", "south_africa"][:self.polygon_count - 1])

    def test_ewkt_srid_becomes_the_layer_crs(self):
        source = self.path("srid.wkt")
        with open(source, "w") as f:
            f.write("SRID=32633;POLYGON ((0 0, 4 0, 4 4, 0 4, 0 0))")
        output = self.path("srid.gpkg")
        self.assertEqual(run(PEAR, "triangulate", source, "-o", output).returncode, 0)
        out = as_geojson(output)
        self.assertEqual(out["crs"]["properties"]["name"], "urn:ogc:def:crs:EPSG::32633")
        self.assertAlmostEqual(sum(area(f["geometry"]) for f in out["features"]), 16, delta=1e-12)

    def write_geojson(self, name, extra):
        """The source's features with extra(k, properties) merged into each one's properties."""
        with open(self.source) as f:
            collection = json.load(f)
        for k, feature in enumerate(collection["features"]):
            feature["properties"].update(extra(k, feature["properties"]))
        path = self.path(name)
        with open(path, "w") as f:
            json.dump(collection, f)
        return path

    def test_geojson_properties_become_the_fields_gdal_reads(self):
        # Every JSON kind, a property named like one of pear's fields, and one named like
        # another but for case: the fields (names, types) and values must be what GDAL's own
        # GeoJSON driver makes of the file (ogr2ogr), pear's fields after them.
        source = self.write_geojson("props.geojson", lambda k, p: {
            "flag": k % 2 == 0, "big": 5_000_000_000 + k, "tags": {"k": [k, "x"]},
            "pear_tris": -k, "Name": "upper " + p["name"], "huge": 10 ** 20})
        for ext in ("gpkg", "fgb"):
            with self.subTest(ext):
                output, reference = self.path("props." + ext), self.path("props-gdal." + ext)
                r = run(PEAR, "triangulate", source, "-o", output)
                self.assertEqual(r.returncode, 0, r.stderr)
                self.assertIn(output + ": the input's field 'Name' is written as 'Name2'", r.stderr)
                self.assertIn(output + ": pear's field 'pear_tris' is written as 'pear_tris2'",
                              r.stderr)
                # past int64: clamped by GDAL's JSON reader (ogr2ogr's too), and said
                self.assertIn(output + ": feature 0's property 'huge' is an integer at or past "
                              "64 bits' limit, written as 9223372036854775807", r.stderr)
                self.assertEqual(run("ogr2ogr", "-f", FORMATS[ext], reference, source,
                                     "-skipfailures").returncode, 0)
                fields = field_types(output)
                self.assertEqual(list(fields)[-3:], ["pear_fid", "pear_tris2", "pear_stat"])
                self.assertEqual(dict(list(fields.items())[:-3]), field_types(reference))
                self.assertEqual(fields["flag"], "Integer(Boolean)")
                want = {f["properties"]["name"]: f["properties"]
                        for f in as_geojson(reference)["features"]}
                features = as_geojson(output)["features"]
                self.assertEqual(len(features), self.polygon_count)
                for feature in features:
                    props = dict(feature["properties"])
                    triangles = len(feature["geometry"]["coordinates"])
                    self.assertEqual(props.pop("pear_tris2"), triangles)
                    props.pop("pear_fid"), props.pop("pear_stat")
                    expected = dict(want[props["name"]])
                    self.assertEqual(as_json(props.pop("tags")), as_json(expected.pop("tags")))
                    self.assertEqual(props, expected)

    def test_gdal_fields_named_like_pears_are_kept(self):
        source = self.path("named.gpkg")
        geojson = self.write_geojson("named.geojson", lambda k, p: {"pear_stat": "mine %d" % k})
        self.assertEqual(run("ogr2ogr", "-f", "GPKG", source, geojson, "-skipfailures",
                             "-nln", "named").returncode, 0)
        output = self.path("named-out.gpkg")
        r = run(PEAR, "triangulate", source, "-o", output)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("pear's field 'pear_stat' is written as 'pear_stat2'", r.stderr)
        want = {f["properties"]["name"]: f["properties"]["pear_stat"]
                for f in as_geojson(source)["features"]}
        for feature in as_geojson(output)["features"]:
            props = feature["properties"]
            self.assertEqual(props["pear_stat"], want[props["name"]])
            self.assertEqual(props["pear_stat2"], "ok")

    def check_m(self, wkt, output, has_z):
        """Every vertex of every triangle has the z and m of the input vertex at its x, y (as
        GDAL reads the output back)."""
        wanted = {(x, y): rest for x, y, *rest in coordinates(wkt)}
        read = 0
        for wkt in read_wkt_column(output):
            self.assertRegex(wkt, r"^MULTIPOLYGON (ZM|M) ")
            for x, y, *rest in coordinates(wkt):
                self.assertEqual(rest, wanted[(x, y)] if has_z else wanted[(x, y)][-1:])
                read += 1
        self.assertGreater(read, 0)

    def test_m_is_carried_through_gdal_layers(self):
        polygons = {"m": "POLYGON M ((0 0 1.5, 4 0 2, 4 4 3, 0 4 4, 0 0 1.5), "
                         "(1 1 7, 1 2 8, 2 2 9, 1 1 7))",
                    "zm": "POLYGON ZM ((0 0 5 6, 4 0 7 8, 4 4 9 10, 0 4 11 -12, 0 0 5 6))"}
        for kind, wkt in polygons.items():
            csv = self.path(kind + ".csv")
            with open(csv, "w") as f:
                f.write('WKT,id\n"%s",1\n' % wkt)
            gpkg = self.path(kind + "-source.gpkg")  # GDAL's own layer with M, for input
            r = run("ogr2ogr", "-f", "GPKG", gpkg, csv, "-oo", "GEOM_POSSIBLE_NAMES=WKT",
                    "-oo", "KEEP_GEOM_COLUMNS=NO", "-nlt", "POLYGON" + kind.upper())
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertIn("Measured Polygon", run("ogrinfo", "-so", "-al", gpkg).stdout)
            wkt_file = self.path(kind + ".wkt")
            with open(wkt_file, "w") as f:
                f.write(wkt)
            for source in (wkt_file, gpkg):
                for ext in FORMATS:
                    with self.subTest(kind=kind, source=source, ext=ext):
                        output = self.path("%s-from-%s.%s" % (kind, source[-4:], ext))
                        r = run(PEAR, "triangulate", source, "-o", output)
                        self.assertEqual(r.returncode, 0, r.stderr)
                        self.check_m(wkt, output, has_z=kind == "zm")

    def test_polygons_without_the_m_others_have_get_0_and_a_note(self):
        source = self.path("mixed.wkt")
        with open(source, "w") as f:
            f.write("POLYGON M ((0 0 1, 4 0 2, 4 4 3, 0 0 1))\n"
                    "POLYGON Z ((10 0 5, 14 0 7, 14 4 9, 10 0 5))\n")
        for ext in FORMATS:  # FlatGeobuf refuses a feature whose dimensions differ the layer's
            with self.subTest(ext):
                output = self.path("mixed." + ext)
                r = run(PEAR, "triangulate", source, "-o", output)
                self.assertEqual(r.returncode, 0, r.stderr)
                self.assertIn(output + ": 1 of 2 polygons have no z, written with z 0", r.stderr)
                self.assertIn(output + ": 1 of 2 polygons have no m, written with m 0", r.stderr)
                positions = [p for wkt in read_wkt_column(output) for p in coordinates(wkt)]
                self.assertEqual(sorted({tuple(p[2:]) for p in positions}),
                                 [(0, 1), (0, 2), (0, 3), (5, 0), (7, 0), (9, 0)])

    def test_errors_name_the_file_and_layer(self):
        source = self.make("gpkg")
        garbage = self.path("garbage.gpkg")
        with open(garbage, "w") as f:
            f.write("not a geopackage")
        lines = self.path("lines.gpkg")
        run("ogr2ogr", "-f", "GPKG", lines, self.source, "-where", "rank = 0", "-nln", "lines")
        cases = [
            ([garbage], garbage + ": GDAL cannot open it"),
            ([source, "--layer", "rivers"], source + ": no layer 'rivers' (its layers: countries)"),
            ([source, "--where", "no_such_field = 1"], source + ": layer 'countries': --where"),
            ([lines], lines + ": layer 'lines': no polygon in it"),
        ]
        for args, message in cases:
            with self.subTest(message):
                r = run(PEAR, "triangulate", *args)
                self.assertEqual(r.returncode, 1, r.stderr)
                self.assertIn(message, r.stderr)


if __name__ == "__main__":
    PEAR = os.path.abspath(sys.argv.pop(1))
    built_with_gdal = sys.argv.pop(1) == "gdal"
    if not built_with_gdal or shutil.which("ogr2ogr") is None or shutil.which("ogrinfo") is None:
        print("skipped: pear built without GDAL, or GDAL's ogr2ogr/ogrinfo missing (gdal-bin)")
        sys.exit(77)
    corpus.main()
