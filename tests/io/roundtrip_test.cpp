// Round trips: what a writer prints, the matching reader gives back bit for bit; and WKT and
// .poly read the same polygons as the equivalent GeoJSON.
#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <random>
#include <sstream>

#include "corpus.hpp"
#include "missing_data.hpp"
#include "pear/io.hpp"
#include "same_polygons.hpp"

namespace {

using pear::Point;
using pear::Polygon;
using pear::Ring;
namespace io = pear::io;

using pear::testing::expect_same_polygons;
using pear::testing::same_bits;

// A finite double from random bits: every exponent and sign, subnormals and -0 included.
double random_double(std::mt19937_64& rng) {
  for (;;) {
    const double d = std::bit_cast<double>(rng());
    if (std::isfinite(d)) return d;
  }
}

TEST(FormatDouble, ShortestFormReadsBackBitIdentical) {
  std::mt19937_64 rng(7);
  for (int i = 0; i < 100000; ++i) {
    const double d = random_double(rng);
    const std::string text = io::format_double(d);
    double back = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), back);
    ASSERT_EQ(ec, std::errc()) << text;
    ASSERT_TRUE(same_bits(back, d)) << text;
  }
  EXPECT_EQ(io::format_double(0.1), "0.1");
  EXPECT_EQ(io::format_double(-0.0), "-0");
  EXPECT_EQ(io::format_double(1e300), "1e+300");
}

// Squares with a square hole at random positions and scales, coordinates with random low bits.
std::vector<Polygon> random_polygons(std::mt19937_64& rng, int count) {
  std::vector<Polygon> polygons;
  std::uniform_real_distribution<double> unit(0, 1);
  for (int k = 0; k < count; ++k) {
    const double scale = std::ldexp(1.0 + unit(rng), static_cast<int>(rng() % 200) - 100);
    const double x = (unit(rng) - 0.5) * scale * 1000;
    const double y = (unit(rng) - 0.5) * scale * 1000;
    auto at = [&](double u, double v) { return Point{x + u * scale, y + v * scale}; };
    Ring outer = {at(0, 0), at(4 + unit(rng), 0), at(4, 4 + unit(rng)), at(0, 4)};
    Ring hole = {at(1 + unit(rng) * 0.1, 1), at(1, 3), at(3, 3 - unit(rng) * 0.1), at(3, 1)};
    polygons.push_back({outer, hole});
  }
  return polygons;
}

TEST(RoundTrip, GeoJsonPolygons) {
  std::mt19937_64 rng(1);
  for (const int count : {1, 5}) {
    const auto polygons = random_polygons(rng, count);
    std::ostringstream out;
    io::write_geojson_polygons(out, polygons);
    expect_same_polygons(io::read_geojson(out.str()), polygons);
  }
}

TEST(RoundTrip, Wkt) {
  std::mt19937_64 rng(2);
  const auto polygons = random_polygons(rng, 6);
  std::ostringstream out;
  io::write_wkt(out, polygons);
  expect_same_polygons(io::read_wkt(out.str()), polygons);
}

TEST(RoundTrip, PolyWithHolesAndIslands) {
  std::mt19937_64 rng(3);
  auto polygons = random_polygons(rng, 4);
  // An island inside the first polygon's hole: the hole point must avoid it.
  const Ring& hole = polygons[0][1];
  const Point c{(hole[0].x + hole[2].x) / 2, (hole[0].y + hole[2].y) / 2};
  const double s = (hole[2].x - hole[0].x) / 8;
  polygons.push_back(
      {{{c.x - s, c.y - s}, {c.x + s, c.y - s}, {c.x + s, c.y + s}, {c.x - s, c.y + s}}});
  std::ostringstream out;
  io::write_poly(out, polygons);
  const auto back = io::read_poly(out.str());
  // read_poly lists polygons in the order of their outer rings in the file, which is this order.
  expect_same_polygons(back, polygons);
}

TEST(Formats, WktAndPolyReadLikeGeoJson) {
  const auto json = io::read_geojson(
      R"({"type":"MultiPolygon","coordinates":[[[[0,0],[10,0],[10,10],[0,10],[0,0]],)"
      R"([[2,2],[2,4],[4,4],[4,2],[2,2]]],[[[20,0],[21,0],[20.5,1],[20,0]]]]})");
  const auto wkt = io::read_wkt(
      "multipolygon z (((0 0 1, 10 0 1, 10 10 1, 0 10 1, 0 0 1), (2 2 0, 2 4 0, 4 4 0, 4 2 0, 2 2 "
      "0)),"
      "\n ((20 0 0,21 0 0,20.5 1 0,20 0 0)))  POLYGON EMPTY");
  expect_same_polygons(wkt, json);
  const auto poly = io::read_poly(R"(# a square with a hole, and a triangle
11 2 1 1
1 0 0 7 1
2 10 0 7 1
3 10 10 7 1
4 0 10 7 1
5 2 2 7 1
6 2 4 7 1
7 4 4 7 1
8 4 2 7 1
9 20 0 7 1
10 21 0 7 1
11 20.5 1 7 1
11 1
1 1 2 1   # outer ring
2 2 3 1
3 3 4 1
4 4 1 1
5 5 6 0
6 6 7 0
7 7 8 0
8 8 5 0
9 9 10 2
10 10 11 2
11 11 9 2
1
1 3 3
1
1 15 5 1.5 -1
)");
  expect_same_polygons(poly, json);
}

TEST(Formats, EwktSridPrefixesAreSkipped) {
  const std::vector<Polygon> expected = {{{{0, 0}, {4, 0}, {4, 4}}}, {{{5, 5}, {6, 5}, {6, 6}}}};
  expect_same_polygons(io::read_wkt("SRID=4326;POLYGON ((0 0, 4 0, 4 4, 0 0))\n"
                                    "srid=0; MULTIPOLYGON Z (((5 5 1, 6 5 1, 6 6 1, 5 5 1)))"),
                       expected);
  const std::string ewkt = "SRID=3857;POLYGON((0 0,4 0,4 4,0 0))";
  EXPECT_EQ(io::guess_format("-", ewkt), io::Format::wkt);
  expect_same_polygons(io::read_text(ewkt, io::guess_format("-", ewkt), "-"), {expected[0]});
}

TEST(Formats, TextsMayStartWithAByteOrderMark) {
  const std::string bom = "\xEF\xBB\xBF";
  const Polygon triangle = {{{0, 0}, {4, 0}, {4, 4}}};
  for (const std::string text :
       {R"({"type":"Polygon","coordinates":[[[0,0],[4,0],[4,4]]]})", "POLYGON ((0 0, 4 0, 4 4))",
        "3 2 0 0\n1 0 0\n2 4 0\n3 4 4\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n"}) {
    SCOPED_TRACE(text);
    const std::string marked = bom + text;
    expect_same_polygons(io::read_text(marked, io::guess_format("-", marked), "-"), {triangle});
  }
}

// Valid real polygons (Natural Earth countries and font glyphs, many holes) come back bit
// identical through every polygon format.
TEST(RoundTrip, BundledCorpusThroughEveryFormat) {
  std::size_t files = 0;
  for (const char* name : {"countries", "glyphs"}) {
    const auto folder = pear::corpus::read_folder(pear::corpus::bundled_root(), name);
    PEAR_SKIP_IF_MISSING(folder);
    for (const auto& file : folder.files) {
      SCOPED_TRACE(file.name());
      const auto polygons = io::read_file(file.path);
      std::ostringstream json, wkt, poly;
      io::write_geojson_polygons(json, polygons);
      io::write_wkt(wkt, polygons);
      io::write_poly(poly, polygons);
      expect_same_polygons(io::read_geojson(json.str()), polygons);
      expect_same_polygons(io::read_wkt(wkt.str()), polygons);
      expect_same_polygons(io::read_poly(poly.str()), polygons);
      ++files;
    }
  }
  EXPECT_EQ(files, 7u);
}

// Regression: a hole whose first vertex lies on the outer ring, and a ring nested only in a ring
// that crosses out of its own container, made the .poly nesting index a polygon that did not
// exist (a crash on earcut's water-huge3 written as .poly).
TEST(PolyReader, TouchingAndCrossingRingsNestWithoutCrashing) {
  const auto touching = io::read_poly(
      "7 2 0 0\n0 0 0\n1 10 0\n2 10 10\n3 0 10\n4 0 5\n5 3 4\n6 3 6\n"
      "7 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n4 4 5\n5 5 6\n6 6 4\n0\n");
  ASSERT_EQ(touching.size(), 1u);
  EXPECT_EQ(touching[0].size(), 2u);
  // Z = [0,10]^2; Y = (2,8),(2,2),(20,2),(20,8) starts inside Z and crosses out; X lies in Y
  // outside Z. Y is a hole of Z; X, inside only a hole, starts a polygon of its own.
  const auto crossing = io::read_poly(
      "11 2 0 0\n0 0 0\n1 10 0\n2 10 10\n3 0 10\n4 2 8\n5 2 2\n6 20 2\n7 20 8\n"
      "8 14 4\n9 16 4\n10 15 6\n11 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n4 4 5\n5 5 6\n6 6 7\n"
      "7 7 4\n8 8 9\n9 9 10\n10 10 8\n0\n");
  ASSERT_EQ(crossing.size(), 2u);
  EXPECT_EQ(crossing[0].size(), 2u);
  EXPECT_EQ(crossing[1], (Polygon{{{14, 4}, {16, 4}, {15, 6}}}));
}

TEST(RoundTrip, TriangleMeshesAsObjNodeEleAndGeoJson) {
  std::mt19937_64 rng(4);
  const auto polygons = random_polygons(rng, 3);
  // A valid triangulation of a square with a square hole, in this ring order: 8 triangles.
  const std::vector<std::array<std::uint32_t, 3>> triangles = {
      {0, 1, 4}, {1, 7, 4}, {1, 2, 7}, {2, 6, 7}, {2, 3, 6}, {3, 5, 6}, {3, 0, 5}, {0, 4, 5}};
  std::vector<io::TriangulatedPolygon> meshes;
  for (const auto& p : polygons) meshes.push_back({.polygon = p, .triangles = triangles});

  std::vector<Point> points;  // all polygons' points, as the writers number them
  std::vector<std::array<std::uint32_t, 3>> all_triangles;
  for (const auto& p : polygons) {
    const auto offset = static_cast<std::uint32_t>(points.size());
    for (const auto& t : triangles)
      all_triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    for (const auto& ring : p) points.insert(points.end(), ring.begin(), ring.end());
  }
  auto expect_mesh = [&](const io::Mesh& mesh) {
    ASSERT_EQ(mesh.points.size(), points.size());
    for (std::size_t i = 0; i < points.size(); ++i) {
      EXPECT_TRUE(same_bits(mesh.points[i].x, points[i].x));
      EXPECT_TRUE(same_bits(mesh.points[i].y, points[i].y));
    }
    EXPECT_EQ(mesh.triangles, all_triangles);
  };
  std::ostringstream obj, node, ele, json;
  io::write_obj(obj, meshes);
  expect_mesh(io::read_obj(obj.str()));
  io::write_node_ele(node, ele, meshes);
  expect_mesh(io::read_node_ele(node.str(), ele.str()));

  io::write_geojson(json, meshes);  // each triangle comes back as a 3-point polygon
  const auto back = io::read_geojson(json.str());
  ASSERT_EQ(back.size(), all_triangles.size());
  for (std::size_t t = 0; t < back.size(); ++t) {
    ASSERT_EQ(back[t].size(), 1u);
    ASSERT_EQ(back[t][0].size(), 3u);
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(same_bits(back[t][0][k].x, points[all_triangles[t][k]].x));
      EXPECT_TRUE(same_bits(back[t][0][k].y, points[all_triangles[t][k]].y));
    }
  }
}

TEST(Writers, RejectTriangleIndexPastThePoints) {
  const std::vector<io::TriangulatedPolygon> bad = {
      {.polygon = {{{0, 0}, {1, 0}, {0, 1}}}, .triangles = {{0, 1, 3}}}};
  std::ostringstream out, ele;
  EXPECT_THROW(io::write_obj(out, bad), std::invalid_argument);
  EXPECT_THROW(io::write_node_ele(out, ele, bad), std::invalid_argument);
  EXPECT_THROW(io::write_svg(out, bad), std::invalid_argument);
}

TEST(ObjReader, NegativeIndicesAndSlashesAsOtherToolsWrite) {
  const auto mesh = io::read_obj(
      "# other tool\nv 0 0 0\nv 1 0 0\nvt 0 0\nv 0 1 0\nf 1/1 2/1 3/1\nf -3//1 -2//1 -1//1\n");
  ASSERT_EQ(mesh.points.size(), 3u);
  const std::vector<std::array<std::uint32_t, 3>> want = {{0, 1, 2}, {0, 1, 2}};
  EXPECT_EQ(mesh.triangles, want);
  EXPECT_THROW(io::read_obj("v 0 0\nv 1 0\nv 0 1\nf 1 2 3 4\n"), io::ParseError);
  EXPECT_THROW(io::read_obj("v 0 0\nf 1 2 3\n"), io::ParseError);
}

// Found by fuzz/readers (corpus/fuzz/readers/crash-wkt-polygon-empty): "POLYGON EMPTY" reads as
// no polygons, which write_wkt wrote as an empty text that read_wkt refuses.
TEST(RoundTrip, WktOfNoPolygonsReadsBack) {
  std::ostringstream out;
  io::write_wkt(out, std::vector<Polygon>{});
  EXPECT_TRUE(io::read_wkt(out.str()).empty());
}

}  // namespace
