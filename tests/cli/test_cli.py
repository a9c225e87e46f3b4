#!/usr/bin/env python3
"""Runs the built `pear` binary: exit codes 0/1/2/3, the --stats keys, outputs, inputs.

usage: test_cli.py PATH/TO/pear PATH/TO/pear-fault-injection
(meson passes both executables). The second is the same tool built for tests only, with a fault
that PEAR_TEST_DROP_A_TRIANGLE switches on; the shipped one has none. The polygons come from the
bundled corpus/ (tests/support/corpus.py); without it those tests skip, and all of them: exit 77.
"""
import gzip
import json
import math
import os
import struct
import subprocess
import sys
import tempfile
import time
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import corpus  # noqa: E402 (tests/support)

PEAR = None
PEAR_WITH_FAULTS = None
SOUTH_AFRICA = str(corpus.bundled_root() / "countries" / "south_africa_000.json")
GLYPHS = str(corpus.bundled_root() / "glyphs")

STATS_KEYS = {"file", "index", "vertices", "holes", "triangles", "status", "algorithm", "threads",
              "cdt", "ms", "min_angle_avg_deg", "dev60_avg_deg"}
SQUARE_WITH_HOLE = ('{"type":"Polygon","coordinates":[[[0,0],[10,0],[10,10],[0,10],[0,0]],'
                    '[[2,2],[2,8],[8,8],[8,2],[2,2]]]}')
BOWTIE = '{"type":"Polygon","coordinates":[[[0,0],[2,2],[2,0],[0,2],[0,0]]]}'


def pear(*args, stdin=None, env=None, exe=None):
    full_env = dict(os.environ)
    full_env.update(env or {})
    return subprocess.run([exe or PEAR, *args], input=stdin, capture_output=True, text=True,
                          env=full_env, timeout=120)


def stats_lines(result):
    return [json.loads(line) for line in result.stdout.splitlines() if line.strip()]


def south_africa_counts():
    """Vertices and holes of SOUTH_AFRICA by its MANIFEST row."""
    [row] = [f for f in corpus.read_folder(corpus.bundled_root(), "countries")
             if f.file == "south_africa_000.json"]
    return row.vertices, row.holes


class Files(unittest.TestCase):
    def setUp(self):
        self.dir = tempfile.TemporaryDirectory()

    def tearDown(self):
        self.dir.cleanup()

    def write(self, name, text, mode="w"):
        path = os.path.join(self.dir.name, name)
        with open(path, mode) as f:
            f.write(text)
        return path


class ExitCodes(Files):
    def test_success_with_stats_and_validation(self):
        corpus.require(SOUTH_AFRICA)
        r = pear("triangulate", SOUTH_AFRICA, "--stats", "--validate")
        self.assertEqual(r.returncode, 0, r.stderr)
        [line] = stats_lines(r)
        self.assertLessEqual(STATS_KEYS | {"valid", "area_rel_error"}, set(line))
        vertices, holes = south_africa_counts()
        self.assertEqual((line["vertices"], line["holes"]), (vertices, holes))
        self.assertEqual(line["status"], "ok")
        self.assertIs(line["valid"], True)
        self.assertIs(line["cdt"], False)
        self.assertEqual(line["triangles"], vertices + 2 * holes - 2)
        self.assertLess(line["area_rel_error"], 1e-12)
        self.assertGreater(line["min_angle_avg_deg"], 0)
        self.assertLessEqual(line["min_angle_avg_deg"], 60)

    def test_bad_input_names_the_place_and_other_files_go_on(self):
        bad = self.write("bad.json", '{"type":"Polygon",\n"coordinates":[[[0,0],[NaN,1],[1,1]]]}')
        good = self.write("good.json", SQUARE_WITH_HOLE)
        r = pear("triangulate", "--stats", bad, good)
        self.assertEqual(r.returncode, 1)
        self.assertIn(bad + ":2:24: expected a number but found 'NaN'", r.stderr)
        [line] = stats_lines(r)
        self.assertEqual(line["file"], good)
        self.assertEqual(line["triangles"], 8)

    def test_each_bad_file_is_exit_one_with_its_name(self):
        cases = {
            "empty.json": ("", ":1:1: expected"),
            "binary.json": ("\x00\x01\x02", ":1:1: expected"),
            "truncated.json": ('{"type":"Polygon","coordinates":[[[0,0],[1,', ":1:44: expected a number"),
            "huge.wkt": ("POLYGON ((0 0, 1e400 0, 1 1, 0 0))", ":1:16: expected a number within"),
            "small.json": ('[[[0,0],[1,1]]]', ":1:2: expected a ring of at least 3 points"),
            "type.json": ('{"type":"Point","coordinates":[0,0]}', ":1:9: expected type"),
        }
        for name, (text, message) in cases.items():
            with self.subTest(name):
                path = self.write(name, text)
                r = pear("triangulate", path)
                self.assertEqual(r.returncode, 1, r.stderr)
                self.assertIn(path + message, r.stderr)
        r = pear("triangulate", os.path.join(self.dir.name, "missing.json"))
        self.assertEqual(r.returncode, 1)
        self.assertIn("missing.json: cannot open", r.stderr)

    def test_not_simple_polygon_is_bad_input(self):
        r = pear("triangulate", "--stats", "-", stdin=BOWTIE)
        self.assertEqual(r.returncode, 1)
        [line] = stats_lines(r)
        self.assertEqual(line["status"], "not_simple")
        self.assertIn("not_simple", r.stderr)

    def test_not_simple_names_its_cause_not_an_earlier_warning(self):
        # Hole 1 is dropped (zero area, a warning); hole 2 crosses the outer ring: the message
        # names the crossing. A hole outside the outer ring is called that.
        crossing = ('{"type":"Polygon","coordinates":[[[0,0],[10,0],[10,10],[0,10],[0,0]],'
                    '[[1,1],[2,2],[3,3],[1,1]],[[8,8],[8,9],[12,9],[12,8],[8,8]]]}')
        r = pear("triangulate", "-", stdin=crossing)
        self.assertEqual(r.returncode, 1)
        self.assertIn("rings cross or overlap", r.stderr)
        self.assertNotIn("zero area", r.stderr)
        outside = ('{"type":"Polygon","coordinates":[[[0,0],[10,0],[10,10],[0,10],[0,0]],'
                   '[[1,1],[2,2],[3,3],[1,1]],[[20,2],[20,4],[22,4],[22,2],[20,2]]]}')
        r = pear("triangulate", "-", stdin=outside)
        self.assertEqual(r.returncode, 1)
        self.assertIn("ring 2, vertex 0: hole lies outside the outer ring", r.stderr)

    def test_usage_errors(self):
        corpus.require(SOUTH_AFRICA)
        for args, message in [
            ([], "usage"),
            (["frobnicate"], "unknown command"),
            (["triangulate"], "needs at least one FILE"),
            (["triangulate", "--bogus", SOUTH_AFRICA], "unknown option --bogus"),
            (["triangulate", "--algorithm", "fastest", SOUTH_AFRICA], "unknown algorithm 'fastest'"),
            (["triangulate", "--cdt=yes", SOUTH_AFRICA], "--cdt takes no value"),
            (["triangulate", "--partitions", "0", SOUTH_AFRICA], "--partitions expects an integer"),
            (["triangulate", "--threads", "0", SOUTH_AFRICA], "--threads expects an integer"),
            (["triangulate", "-o", "out.xyz", SOUTH_AFRICA], "cannot tell the format"),
            (["triangulate", "-o", "out.svg", SOUTH_AFRICA, SOUTH_AFRICA], "-o FILE takes one input"),
            (["triangulate", "--gzip-limit", "0", SOUTH_AFRICA], "--gzip-limit expects a size"),
            (["triangulate", "--gzip-limit", "1T", SOUTH_AFRICA], "--gzip-limit expects a size"),
            (["triangulate", "--gzip-limit", "99999999999G", SOUTH_AFRICA], "--gzip-limit expects"),
            (["stats", "--gzip-limit", "-1", SOUTH_AFRICA], "--gzip-limit expects a size"),
            (["triangulate", "--profile", SOUTH_AFRICA], "--profile adds to the lines of --stats"),
            (["generate", "nonagon", "10"], "unknown kind"),
            (["generate", "star", "ten"], "N must be a positive integer"),
        ]:
            with self.subTest(args=args):
                r = pear(*args)
                self.assertEqual(r.returncode, 2, r.stderr)
                self.assertIn(message, r.stderr)
                self.assertEqual(r.stdout, "")

    def test_invalid_result_is_exit_three(self):
        corpus.require(SOUTH_AFRICA)
        drop = {"PEAR_TEST_DROP_A_TRIANGLE": "1"}
        r = pear("triangulate", SOUTH_AFRICA, "--validate", "--stats", env=drop,
                 exe=PEAR_WITH_FAULTS)
        self.assertEqual(r.returncode, 3, r.stderr)
        [line] = stats_lines(r)
        self.assertIs(line["valid"], False)
        self.assertIn("invalid triangulation", r.stderr)
        # Without --validate nobody checks: the run itself succeeds.
        r = pear("triangulate", SOUTH_AFRICA, env=drop, exe=PEAR_WITH_FAULTS)
        self.assertEqual(r.returncode, 0)
        # The shipped tool has no such hook: the variable changes nothing.
        r = pear("triangulate", SOUTH_AFRICA, "--validate", "--stats", env=drop)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIs(stats_lines(r)[0]["valid"], True)

    def test_help_for_every_command(self):
        for command in ["triangulate", "stats", "generate"]:
            r = pear(command, "--help")
            self.assertEqual(r.returncode, 0)
            self.assertIn("usage: pear " + command, r.stdout)
        r = pear("triangulate", "--help")
        for name in ["auto", "sequential", "mark-and-cut", "partition-and-cut", "divide-and-conquer"]:
            self.assertIn(name, r.stdout)


class Algorithms(Files):
    def test_every_algorithm_thread_count_and_cdt_is_valid(self):
        corpus.require(SOUTH_AFRICA)
        vertices, holes = south_africa_counts()
        for algorithm in ["auto", "sequential", "partition-and-cut", "mark-and-cut",
                          "divide-and-conquer"]:
            for threads in ["1", "2", "3"]:
                for cdt in [[], ["--cdt"]]:
                    with self.subTest(algorithm=algorithm, threads=threads, cdt=cdt):
                        r = pear("triangulate", SOUTH_AFRICA, "--stats", "--validate",
                                 "--algorithm", algorithm, "--threads", threads, *cdt)
                        self.assertEqual(r.returncode, 0, r.stderr)
                        [line] = stats_lines(r)
                        self.assertIs(line["valid"], True)
                        self.assertEqual(line["threads"], int(threads))
                        self.assertIs(line["cdt"], bool(cdt))
                        self.assertEqual(line["triangles"], vertices + 2 * holes - 2)

    def test_output_depends_on_partitions_not_threads(self):
        corpus.require(SOUTH_AFRICA)
        outputs = []
        for threads in ["1", "2", "4"]:
            out = os.path.join(self.dir.name, "sa-" + threads + ".obj")
            r = pear("triangulate", SOUTH_AFRICA, "--algorithm", "partition-and-cut",
                     "--partitions", "3", "--threads", threads, "-o", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(out) as f:
                outputs.append(f.read())
        self.assertEqual(outputs[0], outputs[1])
        self.assertEqual(outputs[0], outputs[2])


class Outputs(Files):
    def triangulate_to(self, name, *extra):
        corpus.require(SOUTH_AFRICA)
        out = os.path.join(self.dir.name, name)
        r = pear("triangulate", SOUTH_AFRICA, "--stats", "-o", out, *extra)
        self.assertEqual(r.returncode, 0, r.stderr)
        return out, stats_lines(r)[0]

    def test_obj(self):
        out, line = self.triangulate_to("sa.obj")
        with open(out) as f:
            lines = f.read().splitlines()
        self.assertEqual(sum(l.startswith("v ") for l in lines), line["vertices"])
        self.assertEqual(sum(l.startswith("f ") for l in lines), line["triangles"])

    def test_geojson_triangles(self):
        out, line = self.triangulate_to("sa.geojson")
        with open(out) as f:
            doc = json.load(f)
        [feature] = doc["features"]
        self.assertEqual(len(feature["geometry"]["coordinates"]), line["triangles"])
        for triangle in feature["geometry"]["coordinates"]:
            self.assertEqual(len(triangle[0]), 4)
            self.assertEqual(triangle[0][0], triangle[0][3])

    def test_node_ele(self):
        out, line = self.triangulate_to("sa.ele")
        base = out[:-4]
        with open(base + ".node") as f:
            self.assertEqual(int(f.readline().split()[0]), line["vertices"])
        with open(base + ".ele") as f:
            self.assertEqual(int(f.readline().split()[0]), line["triangles"])

    def test_svg(self):
        out, line = self.triangulate_to("sa.svg")
        with open(out) as f:
            text = f.read()
        self.assertTrue(text.startswith("<svg"))
        self.assertTrue(text.rstrip().endswith("</svg>"))
        self.assertIn("%d triangles" % line["triangles"], text)

    def test_directory_output_and_stdout(self):
        corpus.require(GLYPHS)
        outdir = os.path.join(self.dir.name, "out") + "/"
        r = pear("triangulate", GLYPHS, "-o", outdir, "--format", "obj")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(len(os.listdir(outdir)), 4)
        r = pear("triangulate", "-", "-o", "-", "--format", "geojson", stdin=SQUARE_WITH_HOLE)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(len(json.loads(r.stdout)["features"][0]["geometry"]["coordinates"]), 8)


class Inputs(Files):
    def test_directory_gives_a_line_per_polygon_and_a_summary(self):
        corpus.require(GLYPHS)
        r = pear("triangulate", "--stats", GLYPHS)
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = stats_lines(r)
        self.assertEqual(len(lines), 4)
        self.assertIn("pear: 4 files, 4 polygons, 0 failures", r.stderr)
        self.assertNotIn("\r", r.stderr)  # no progress bar when stderr is not a terminal

    def test_multipolygon_gives_indexed_lines(self):
        path = self.write("two.json", '{"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[0,1]]],'
                                      '[[[5,5],[6,5],[6,6],[5,6]]]]}')
        lines = stats_lines(pear("triangulate", "--stats", path))
        self.assertEqual([(l["index"], l["vertices"], l["triangles"]) for l in lines],
                         [(0, 3, 1), (1, 4, 2)])

    def test_gzip_wkt_poly_and_glob(self):
        gz = os.path.join(self.dir.name, "square.json.gz")
        with gzip.open(gz, "wt") as f:
            f.write(SQUARE_WITH_HOLE)
        self.write("square.wkt", "POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), (2 2, 2 8, 8 8, 8 2, 2 2))")
        self.write("square.poly", "8 2 0 0\n0 0 0\n1 10 0\n2 10 10\n3 0 10\n4 2 2\n5 2 8\n6 8 8\n"
                                  "7 8 2\n8 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n4 4 5\n5 5 6\n6 6 7\n"
                                  "7 7 4\n1\n0 5 5\n")
        r = pear("triangulate", "--stats", "--validate", os.path.join(self.dir.name, "square.*"))
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = stats_lines(r)
        self.assertEqual(len(lines), 3)
        for line in lines:
            self.assertEqual((line["vertices"], line["holes"], line["triangles"]), (8, 1, 8))
            self.assertIs(line["valid"], True)


def run_as_nobody():
    """A command prefix that runs pear as user nobody (root reads any directory), or None (no
    setpriv, or nobody cannot run this build)."""
    if os.geteuid() != 0:
        return []
    for tool in ("/usr/bin/setpriv", "/bin/setpriv"):
        if os.path.exists(tool):
            prefix = [tool, "--reuid=65534", "--regid=65534", "--clear-groups"]
            # nobody must reach the build too (a checkout under a private folder is not).
            probe = subprocess.run([*prefix, PEAR, "--help"], capture_output=True)
            return prefix if probe.returncode == 0 else None
    return None


def built_with_asan():
    with open(PEAR, "rb") as f:
        return b"__asan_init" in f.read()


class Audit(Files):
    """The CLI findings of issue 19's audit of bad input."""

    def polygon_files(self, folder, count):
        os.makedirs(folder, exist_ok=True)
        for i in range(count):
            with open(os.path.join(folder, "p%02d.json" % i), "w") as f:
                f.write('[[[0,0],[1,0],[1,1]]]')

    def test_directory_walk_names_unreadable_subdirectory(self):
        prefix = run_as_nobody()
        if prefix is None:
            self.skipTest("running as root without setpriv, or nobody cannot reach this build: "
                          "no directory is unreadable")
        top = os.path.join(self.dir.name, "d")
        self.polygon_files(top, 20)
        self.polygon_files(os.path.join(top, "locked"), 2)
        self.polygon_files(os.path.join(top, "later"), 3)
        os.chmod(self.dir.name, 0o755)
        os.chmod(os.path.join(top, "locked"), 0)
        try:
            r = subprocess.run([*prefix, PEAR, "triangulate", "--stats", top],
                               capture_output=True, text=True, timeout=60)
            self.assertEqual(r.returncode, 1, r.stderr)
            self.assertIn(os.path.join(top, "locked") + ": cannot read the directory: "
                          "Permission denied", r.stderr)
            self.assertEqual(len(stats_lines(r)), 23)  # the rest is processed
            self.assertIn("24 files, 23 polygons, 1 failures", r.stderr)
            os.chmod(top, 0)
            r = subprocess.run([*prefix, PEAR, "triangulate", top],
                               capture_output=True, text=True, timeout=60)
            self.assertEqual(r.returncode, 1, r.stderr)
            self.assertIn(top + ": cannot read the directory", r.stderr)
        finally:
            os.chmod(top, 0o755)
            os.chmod(os.path.join(top, "locked"), 0o755)

    def test_empty_directory_and_empty_polygon_are_named(self):
        empty = os.path.join(self.dir.name, "empty")
        os.makedirs(empty)
        r = pear("triangulate", empty)
        self.assertEqual(r.returncode, 1)
        self.assertIn(empty + ": no polygon files (.json, .geojson, .wkt, .poly, .wkb", r.stderr)
        for text in ['{"type":"Polygon","coordinates":[]}', "POLYGON EMPTY",
                     '{"type":"FeatureCollection","features":[]}']:
            with self.subTest(text):
                r = pear("triangulate", "-", stdin=text)
                self.assertEqual(r.returncode, 1)
                self.assertIn("<stdin>: no polygon in it", r.stderr)

    def test_a_file_named_expected_json_is_read_like_any_other(self):
        folder = os.path.join(self.dir.name, "fixtures")
        self.polygon_files(folder, 1)
        with open(os.path.join(folder, "expected.json"), "w") as f:
            f.write(SQUARE_WITH_HOLE)
        r = pear("triangulate", "--stats", folder)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(sorted(os.path.basename(l["file"]) for l in stats_lines(r)),
                         ["expected.json", "p00.json"])

    def test_generate_with_an_absurd_count_is_a_usage_error(self):
        r = pear("generate", "holes", "99999999999999")
        self.assertEqual(r.returncode, 2)
        self.assertIn("N must be a positive integer up to 100000000", r.stderr)

    def test_cannot_write_says_why(self):
        missing = os.path.join(self.dir.name, "no", "such", "dir")
        r = pear("triangulate", "-", "-o", os.path.join(missing, "out.obj"), stdin=SQUARE_WITH_HOLE)
        self.assertEqual(r.returncode, 1)
        self.assertIn("out.obj: No such file or directory", r.stderr)
        r = pear("generate", "star", "10", "-o", os.path.join(missing, "star.json"))
        self.assertEqual(r.returncode, 1)
        self.assertIn("star.json: No such file or directory", r.stderr)

    def test_out_of_memory_names_the_file_and_goes_on(self):
        if built_with_asan():
            self.skipTest("AddressSanitizer reserves more address space than the limit leaves")
        import resource
        big = os.path.join(self.dir.name, "big.json")
        self.assertEqual(pear("generate", "koch", "800000", "-o", big).returncode, 0)
        small = self.write("small.json", SQUARE_WITH_HOLE)
        limit = 250 << 20
        r = subprocess.run([PEAR, "triangulate", "--stats", big, small], capture_output=True,
                           text=True, timeout=120,
                           preexec_fn=lambda: resource.setrlimit(resource.RLIMIT_AS,
                                                                 (limit, limit)))
        if r.returncode == 0:
            self.skipTest("250 MB of address space were enough here")
        self.assertEqual(r.returncode, 1, r.stderr)
        self.assertIn(big + ": out of memory while", r.stderr)
        self.assertNotIn("std::bad_alloc", r.stderr)
        self.assertEqual([l["file"] for l in stats_lines(r)], [small])


def run_measured(*args):
    """Runs pear; its exit code, stderr, wall seconds and peak resident memory in bytes."""
    with tempfile.TemporaryFile("w+") as err:
        start = time.monotonic()
        process = subprocess.Popen([PEAR, *args], stdout=subprocess.DEVNULL, stderr=err)
        _, status, usage = os.wait4(process.pid, 0)
        seconds = time.monotonic() - start
        process.returncode = os.waitstatus_to_exitcode(status)
        err.seek(0)
        return process.returncode, err.read(), seconds, usage.ru_maxrss * 1024


def star_json(points):
    """A star polygon of `points` vertices as GeoJSON: text long enough to span deflate blocks."""
    ring = [[round((10 if i % 2 else 4) * math.cos(i * 2 * math.pi / points), 6),
             round((10 if i % 2 else 4) * math.sin(i * 2 * math.pi / points), 6)]
            for i in range(points)]
    return json.dumps({"type": "Polygon", "coordinates": [ring + [ring[0]]]})


class Gzip(Files):
    """Issue 30: a .gz that is truncated, corrupt or a bomb is a gzip error naming the file."""

    def gz(self, name, data):
        return self.write(name, data, "wb")

    def assert_gzip_error(self, path, *phrases):
        r = pear("triangulate", path)
        self.assertEqual(r.returncode, 1, r.stderr)
        [line] = r.stderr.splitlines()
        self.assertTrue(line.startswith(path + ": gzip"), line)
        for phrase in phrases:
            self.assertIn(phrase, line)
        self.assertNotIn("expected", line)  # no reader's message about inflated garbage

    def test_members_are_read_one_after_another(self):
        text = SQUARE_WITH_HOLE.encode()
        path = self.gz("two.json.gz", gzip.compress(text[:30]) + gzip.compress(text[30:]))
        r = pear("triangulate", "--stats", path)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(stats_lines(r)[0]["triangles"], 8)

    def test_truncated_gzip_is_refused(self):
        packed = gzip.compress(star_json(2000).encode(), mtime=0)
        self.assertEqual(pear("triangulate", self.gz("whole.json.gz", packed)).returncode, 0)
        for name, cut in [("no-trailer.json.gz", packed[:-8]), ("half-trailer.json.gz", packed[:-3]),
                          ("half.json.gz", packed[:len(packed) // 2])]:
            with self.subTest(name):
                self.assert_gzip_error(self.gz(name, cut), "truncated")

    def test_corrupt_gzip_is_refused(self):
        packed = gzip.compress(star_json(2000).encode(), mtime=0)
        for name, at in [("middle.json.gz", len(packed) // 2), ("crc.json.gz", len(packed) - 6),
                         ("length.json.gz", len(packed) - 2)]:
            with self.subTest(name):
                flipped = bytearray(packed)
                flipped[at] ^= 0x40
                self.assert_gzip_error(self.gz(name, bytes(flipped)), "corrupt")

    def test_a_gz_that_is_not_gzip_is_refused(self):
        self.assert_gzip_error(self.write("plain.json.gz", SQUARE_WITH_HOLE), "not gzip data")
        self.assert_gzip_error(self.write("empty.json.gz", ""), "not gzip data")
        trailing = gzip.compress(SQUARE_WITH_HOLE.encode()) + b"junk"
        self.assert_gzip_error(self.gz("trailing.json.gz", trailing), "corrupt")

    def test_gzip_limit_is_exact(self):
        text = SQUARE_WITH_HOLE.encode()
        path = self.gz("square.json.gz", gzip.compress(text))
        r = pear("triangulate", "--gzip-limit", str(len(text)), path)
        self.assertEqual(r.returncode, 0, r.stderr)
        r = pear("triangulate", "--gzip-limit", str(len(text) - 1), path)
        self.assertEqual(r.returncode, 1)
        self.assertIn(path + ": gzip: inflates past %d bytes" % (len(text) - 1), r.stderr)

    def test_bomb_stops_at_the_limit_fast_and_in_little_memory(self):
        # 4 GiB of zeros in 4 MB: members of 1 MiB each, one after another. The memory is what
        # the bomb costs over a run that reads a small .gz: the process alone is 97 MB under
        # ASan (its libraries and shadow), 10-20 MB without.
        bomb = self.gz("bomb.json.gz", gzip.compress(bytes(1 << 20), mtime=0) * 4096)
        small = self.gz("small.json.gz", gzip.compress(SQUARE_WITH_HOLE.encode(), mtime=0))
        code, stderr, _, baseline = run_measured("triangulate", "--gzip-limit", "1M", small)
        self.assertEqual(code, 0, stderr)
        code, stderr, seconds, peak = run_measured("triangulate", "--gzip-limit", "1M", bomb)
        self.assertEqual(code, 1, stderr)
        self.assertIn(bomb + ": gzip: inflates past 1048576 bytes", stderr)
        self.assertLess(seconds, 5)
        self.assertLess(peak - baseline, 32 << 20)

    # Inflates a whole GiB: its own test in the 'large' suite (tests/cli/meson.build), which
    # sanitizer builds leave out.
    @unittest.skipIf(os.environ.get("PEAR_CLI_SKIP_LARGE"), "run as the test cli-gzip-limit")
    def test_default_limit_is_1_gib_whatever_the_compressed_size(self):
        # 11 MiB that do not compress, then 1 GiB and 64 MiB of zeros: a limit of 100 times the
        # compressed size (the rule before issue 30) would let all of it through.
        packed = (gzip.compress(os.urandom(11 << 20), compresslevel=0, mtime=0) +
                  gzip.compress(bytes(1 << 20), mtime=0) * 1088)
        self.assertGreater(100 * len(packed), 11 * (1 << 20) + (1088 << 20))
        path = self.gz("big.json.gz", packed)
        r = pear("triangulate", path)
        self.assertEqual(r.returncode, 1)
        self.assertIn(path + ": gzip: inflates past 1073741824 bytes", r.stderr)


class OutputCollisions(Files):
    """Issue 30: -o never writes one output for two inputs, nor over an input."""

    def polygon(self, *parts):
        path = os.path.join(self.dir.name, *parts)
        os.makedirs(os.path.dirname(path), exist_ok=True)
        with open(path, "w") as f:
            f.write(SQUARE_WITH_HOLE)
        return path

    def assert_refused(self, args, *names):
        r = pear("triangulate", *args)
        self.assertEqual(r.returncode, 2, r.stderr)
        for name in names:
            self.assertIn(name, r.stderr)
        return r

    def test_two_inputs_for_one_output_are_refused(self):
        c1, c2 = self.polygon("c1", "x.json"), self.polygon("c2", "x.json")
        out = os.path.join(self.dir.name, "out") + "/"
        self.assert_refused([c1, c2, "-o", out, "--format", "obj"], c1, c2, "x.obj")
        self.assertFalse(os.path.exists(os.path.join(out, "x.obj")))
        wkt = self.write("c1/x.wkt", "POLYGON ((0 0, 1 0, 1 1, 0 0))")
        self.assert_refused([c1, wkt, "-o", out, "--format", "node"], c1, wkt, "x.node")
        self.assert_refused([c1, c1, "-o", out, "--format", "svg"], c1)
        # Different names are written side by side.
        y = self.polygon("c2", "y.json")
        r = pear("triangulate", c1, y, "-o", out, "--format", "obj")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(sorted(os.listdir(out)), ["x.obj", "y.obj"])

    def test_an_output_that_is_an_input_is_refused(self):
        x = self.polygon("c1", "x.json")
        self.assert_refused([x, "-o", x, "--format", "geojson"], x, "overwrite")
        other_spelling = os.path.join(self.dir.name, "c1", "..", "c1", "x.json")
        self.assert_refused([other_spelling, "-o", x, "--format", "geojson"], x, "overwrite")
        link = os.path.join(self.dir.name, "link.json")
        os.link(x, link)
        self.assert_refused([link, "-o", x, "--format", "geojson"], x, link, "overwrite")
        # A directory written into itself: c1/y.geojson would replace the input c1/y.geojson.
        y = self.polygon("c1", "y.geojson")
        c1 = os.path.dirname(x)
        self.assert_refused([c1, "-o", c1, "--format", "geojson"], y, "overwrite")
        self.assertFalse(os.path.exists(os.path.join(c1, "x.geojson")))
        for path in (x, y):
            with open(path) as f:
                self.assertEqual(f.read(), SQUARE_WITH_HOLE)


SQUARE_RINGS = [[(0, 0), (10, 0), (10, 10), (0, 10)], [(2, 2), (2, 8), (8, 8), (8, 2)]]


def wkb_square(order="<", srid=None, z=False):
    """SQUARE_RINGS as a WKB Polygon, rings closed, built field by field: ISO (type 3, 1003 with
    z) or, with an srid, EWKB (flag bits and the SRID after the type)."""
    code = 3 + (1000 if z and srid is None else 0)
    if srid is not None:
        code |= 0x20000000 | (0x80000000 if z else 0)
    out = struct.pack(order + "BI", 0 if order == ">" else 1, code)
    if srid is not None:
        out += struct.pack(order + "I", srid)
    out += struct.pack(order + "I", len(SQUARE_RINGS))
    for ring in SQUARE_RINGS:
        out += struct.pack(order + "I", len(ring) + 1)
        for x, y in ring + ring[:1]:
            out += struct.pack(order + ("ddd" if z else "dd"), x, y, *([5.0] if z else []))
    return out


class WkbInputs(Files):
    """WKB (binary, hex, gzipped, stdin) and EWKT files read as the square with a hole."""

    def assert_squares(self, r, count):
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = stats_lines(r)
        self.assertEqual(len(lines), count)
        for line in lines:
            self.assertEqual((line["vertices"], line["holes"], line["triangles"]), (8, 1, 8))
            self.assertIs(line["valid"], True)

    def test_wkb_hex_and_ewkt_files(self):
        self.write("little.wkb", wkb_square(), "wb")
        self.write("big_ewkb_z.wkb", wkb_square(">", srid=4326, z=True), "wb")
        # Two values, a line each, upper and lower case: two polygons.
        self.write("two.hexwkb", wkb_square().hex().upper() + "\n" + wkb_square(">").hex() + "\n")
        self.write("ewkb.wkb.hex", wkb_square(srid=3857).hex())
        with gzip.open(os.path.join(self.dir.name, "zipped.wkb.gz"), "wb") as f:
            f.write(wkb_square(">", z=True))
        self.write("srid.wkt", "SRID=4326;POLYGON ((0 0, 10 0, 10 10, 0 10, 0 0), "
                               "(2 2, 2 8, 8 8, 8 2, 2 2))")
        r = pear("triangulate", "--stats", "--validate", self.dir.name)
        self.assert_squares(r, 7)
        self.assertEqual(sorted({os.path.basename(l["file"]) for l in stats_lines(r)}),
                         ["big_ewkb_z.wkb", "ewkb.wkb.hex", "little.wkb", "srid.wkt", "two.hexwkb",
                          "zipped.wkb.gz"])

    def test_outputs_are_named_after_the_input_without_its_wkb_extensions(self):
        inputs = [self.write("a.wkb", wkb_square(), "wb"), self.write("b.wkb.hex", wkb_square().hex()),
                  self.write("c.hexwkb", wkb_square().hex())]
        outdir = os.path.join(self.dir.name, "out") + "/"
        r = pear("triangulate", *inputs, "-o", outdir, "--format", "obj")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(sorted(os.listdir(outdir)), ["a.obj", "b.obj", "c.obj"])

    def test_stdin_binary_or_hex_by_its_content(self):
        for data in (wkb_square(">"), wkb_square(srid=4326).hex().encode() + b"\n"):
            r = subprocess.run([PEAR, "triangulate", "--stats", "--validate", "-"], input=data,
                               capture_output=True, timeout=120)
            r.stdout, r.stderr = r.stdout.decode(), r.stderr.decode()
            self.assert_squares(r, 1)

    def test_bad_wkb_names_the_byte_and_bad_hex_the_column(self):
        cases = {
            "cut.wkb": (wkb_square()[:-3], "wb", ": byte 97: a ring of 5 points needs 80 bytes, 77"),
            "order.wkb": (b"\x02" + wkb_square()[1:], "wb", ": byte 0: byte order 2 is neither"),
            "point.wkb": (struct.pack("<BIdd", 1, 1, 0, 0), "wb", ": byte 1: geometry type 1 is not"),
            "digit.hexwkb": ("0103000000z", "w", ":1:11: expected a hex digit but found 'z'"),
            "value.hexwkb": (wkb_square().hex() + "\n" + wkb_square().hex()[:40], "w",
                             ":2:27: value 2, byte 13: a ring of 5 points needs 80 bytes, 7"),
            "srid.wkt": ("SRID=x;POLYGON EMPTY", "w", ":1:6: expected an integer SRID"),
        }
        for name, (data, mode, message) in cases.items():
            with self.subTest(name):
                path = self.write(name, data, mode)
                r = pear("triangulate", path)
                self.assertEqual(r.returncode, 1, r.stderr)
                self.assertIn(path + message, r.stderr)


class StatsAndGenerate(Files):
    def test_ear_statistics(self):
        corpus.require(SOUTH_AFRICA)
        r = pear("stats", "--json", "-", stdin='[[[0,0],[4,0],[4,4],[0,4]]]')
        self.assertEqual(r.returncode, 0, r.stderr)
        [line] = stats_lines(r)
        # A convex quadrilateral: every vertex convex and an ear.
        self.assertEqual((line["vertices"], line["convex"], line["reflex"], line["ears"]), (4, 4, 0, 4))
        self.assertEqual(line["convex_ear_fraction"], 1.0)
        r = pear("stats", "--json", SOUTH_AFRICA)
        [line] = stats_lines(r)
        self.assertEqual(line["convex"] + line["reflex"], line["vertices"])
        self.assertLessEqual(line["ears"], line["convex"])
        table = pear("stats", SOUTH_AFRICA)
        self.assertEqual(table.returncode, 0)
        self.assertIn("ears/convex", table.stdout)

    def test_generate_is_deterministic_and_triangulates(self):
        first = pear("generate", "star", "100", "--seed", "3")
        self.assertEqual(first.returncode, 0, first.stderr)
        self.assertEqual(pear("generate", "star", "100", "--seed", "3").stdout, first.stdout)
        self.assertNotEqual(pear("generate", "star", "100", "--seed", "4").stdout, first.stdout)
        self.assertEqual(json.loads(first.stdout)["type"], "Polygon")
        r = pear("triangulate", "--stats", "--validate", "-", stdin=first.stdout)
        self.assertEqual(r.returncode, 0, r.stderr)
        [line] = stats_lines(r)
        self.assertEqual(line["vertices"], 100)
        self.assertIs(line["valid"], True)


class Profile(Files):
    """--stats --profile: each line's work, span and projected speedup (RunProfile)."""
    THREADS = ["2", "4", "8", "16"]

    def check_scaling_fields(self, line):
        """Properties of Brent's bound: span <= work, 1 <= bound(t) <= t, non-decreasing in t."""
        self.assertLessEqual({"work_ms", "span_ms", "projected_speedup"}, set(line))
        self.assertGreater(line["work_ms"], 0)
        self.assertGreater(line["span_ms"], 0)
        self.assertLessEqual(line["span_ms"], line["work_ms"])
        speedup = line["projected_speedup"]
        self.assertEqual(sorted(speedup), sorted(self.THREADS))
        bounds = [speedup[t] for t in self.THREADS]
        for t, bound in zip(self.THREADS, bounds):
            self.assertGreaterEqual(bound, 1.0)
            self.assertLessEqual(bound, int(t))
        self.assertEqual(bounds, sorted(bounds))
        # Brent's bound never beats the critical path: work / span caps every thread count.
        self.assertLessEqual(bounds[-1], line["work_ms"] / line["span_ms"] * (1 + 1e-9))

    def test_every_algorithm_and_the_cdt_give_bounded_monotone_figures(self):
        corpus.require(SOUTH_AFRICA)
        vertices, holes = south_africa_counts()
        for algorithm in ["sequential", "partition-and-cut", "mark-and-cut", "divide-and-conquer"]:
            for cdt in [[], ["--cdt"]]:
                with self.subTest(algorithm=algorithm, cdt=cdt):
                    r = pear("triangulate", SOUTH_AFRICA, "--stats", "--profile", "--validate",
                             "--algorithm", algorithm, "--partitions", "4", *cdt)
                    self.assertEqual(r.returncode, 0, r.stderr)
                    [line] = stats_lines(r)
                    self.assertIs(line["valid"], True)
                    self.assertEqual(line["triangles"], vertices + 2 * holes - 2)
                    self.check_scaling_fields(line)

    def test_parts_clipped_apart_project_a_speedup(self):
        # 40,000 vertices cut into 8 chains: the clip phase has 8 tasks, so 2 threads halve
        # part of the work and the bound exceeds 1 (a profile of one task per phase gives 1).
        maze = pear("generate", "random", "40000", "--seed", "5")
        self.assertEqual(maze.returncode, 0, maze.stderr)
        r = pear("triangulate", "-", "--stats", "--profile", "--algorithm", "partition-and-cut",
                 "--partitions", "8", "--threads", "1", stdin=maze.stdout)
        self.assertEqual(r.returncode, 0, r.stderr)
        [line] = stats_lines(r)
        self.check_scaling_fields(line)
        self.assertGreater(line["projected_speedup"]["2"], 1.0)
        self.assertLess(line["span_ms"], line["work_ms"])

    def test_a_line_per_polygon_each_with_its_own_run(self):
        multi = ('{"type":"MultiPolygon","coordinates":[[[[0,0],[4,0],[4,4],[0,4],[0,0]]],'
                 '[[[10,0],[14,0],[14,4],[10,4],[10,0]],[[11,1],[11,3],[13,3],[13,1],[11,1]]]]}')
        r = pear("triangulate", "-", "--stats", "--profile", stdin=multi)
        self.assertEqual(r.returncode, 0, r.stderr)
        lines = stats_lines(r)
        self.assertEqual([line["triangles"] for line in lines], [2, 8])
        for line in lines:
            self.check_scaling_fields(line)

    def test_without_profile_no_scaling_fields(self):
        r = pear("triangulate", "-", "--stats", stdin=SQUARE_WITH_HOLE)
        self.assertEqual(r.returncode, 0, r.stderr)
        [line] = stats_lines(r)
        self.assertFalse({"work_ms", "span_ms", "projected_speedup"} & set(line))

    def test_bad_input_still_named_and_exit_one(self):
        r = pear("triangulate", "-", "--stats", "--profile", stdin=BOWTIE)
        self.assertEqual(r.returncode, 1)
        self.assertIn("not_simple", r.stderr)


if __name__ == "__main__":
    PEAR = os.path.abspath(sys.argv.pop(1))
    PEAR_WITH_FAULTS = os.path.abspath(sys.argv.pop(1))
    corpus.main()
