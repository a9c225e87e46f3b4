// GeoJSON reading: every accepted form gives the right rings, and real files give the vertex and
// hole counts their MANIFEST.tsv lists (an independent count made when the corpus was built).
#include <gtest/gtest.h>

#include "corpus.hpp"
#include "missing_data.hpp"
#include "pear/io.hpp"

namespace {

using pear::Point;
using pear::io::read_geojson;

const pear::Ring unit_square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};

TEST(GeoJson, PolygonDropsTheClosingPoint) {
  const auto polygons =
      read_geojson(R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,1],[0,0]]]})");
  ASSERT_EQ(polygons.size(), 1u);
  ASSERT_EQ(polygons[0].size(), 1u);
  EXPECT_EQ(polygons[0][0], unit_square);
}

TEST(GeoJson, UnclosedRingIsKeptWhole) {
  const auto polygons =
      read_geojson(R"({"type":"Polygon","coordinates":[[[0,0],[1,0],[1,1],[0,1]]]})");
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_EQ(polygons[0][0], unit_square);
}

TEST(GeoJson, PolygonWithHoleAndAltitudes) {
  const auto polygons = read_geojson(R"(
    { "type" : "Polygon",
      "coordinates" : [ [ [0,0,5], [10,0,5], [10,10,5], [0,10,5], [0,0,5] ],
                        [ [2,2], [2,8], [8,8], [8,2], [2,2] ] ] })");
  ASSERT_EQ(polygons.size(), 1u);
  ASSERT_EQ(polygons[0].size(), 2u);
  EXPECT_EQ(polygons[0][0][1], (Point{10, 0}));
  EXPECT_EQ(polygons[0][1][1], (Point{2, 8}));
  EXPECT_EQ(polygons[0][1].size(), 4u);
}

TEST(GeoJson, MultiPolygonGivesOnePolygonPerPart) {
  const auto polygons =
      read_geojson(R"({"type":"MultiPolygon","coordinates":[[[[0,0],[1,0],[1,1],[0,0]]],)"
                   R"([[[5,5],[6,5],[6,6],[5,5]]],[]]})");
  ASSERT_EQ(polygons.size(), 2u);  // the empty part gives none
  EXPECT_EQ(polygons[1][0][0], (Point{5, 5}));
}

TEST(GeoJson, FeatureCollectionAndGeometryCollection) {
  const auto polygons = read_geojson(R"({"type":"FeatureCollection","features":[
    {"type":"Feature","properties":{"name":"a \"quoted\" \u00e9 name","n":[1,2,{"x":null}]},
     "geometry":{"type":"Polygon","coordinates":[[[0,0],[1,0],[0,1],[0,0]]]}},
    {"type":"Feature","properties":null,"geometry":null},
    {"type":"Feature","geometry":{"type":"GeometryCollection","geometries":[
      {"type":"Polygon","coordinates":[[[2,0],[3,0],[2,1],[2,0]]]},
      {"type":"GeometryCollection","geometries":[
        {"type":"MultiPolygon","coordinates":[[[[4,0],[5,0],[4,1],[4,0]]]]}]}]}}]})");
  ASSERT_EQ(polygons.size(), 3u);
  EXPECT_EQ(polygons[0][0][1], (Point{1, 0}));
  EXPECT_EQ(polygons[1][0][1], (Point{3, 0}));
  EXPECT_EQ(polygons[2][0][1], (Point{5, 0}));
}

TEST(GeoJson, MembersInAnyOrder) {
  const auto polygons = read_geojson(
      R"({"coordinates":[[[0,0],[1,0],[1,1],[0,1]]],"bbox":[0,0,1,1],"type":"Polygon"})");
  ASSERT_EQ(polygons.size(), 1u);
  EXPECT_EQ(polygons[0][0], unit_square);
  const auto features = read_geojson(
      R"({"features":[{"geometry":{"coordinates":[[[0,0],[1,0],[1,1],[0,1]]],"type":"Polygon"},)"
      R"("type":"Feature"}],"type":"FeatureCollection"})");
  ASSERT_EQ(features.size(), 1u);
  EXPECT_EQ(features[0][0], unit_square);
}

TEST(GeoJson, BareArrayOfRingsAsEarcutFixtures) {
  const auto one = read_geojson("[[[0,0],[1,0],[1,1],[0,1]],[[0.25,0.25],[0.5,0.75],[0.75,0.25]]]");
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].size(), 2u);
  const auto two = read_geojson("[[[[0,0],[1,0],[1,1]]],[[[2,0],[3,0],[3,1]]]]");
  EXPECT_EQ(two.size(), 2u);
  EXPECT_TRUE(read_geojson(" [ ] ").empty());
}

TEST(GeoJson, NumbersAreReadExactly) {
  const auto polygons = read_geojson(
      "[[[-0.1,1e-300],[1.7976931348623157e308,-2.5E+3],[4.9e-324,0.30000000000000004]]]");
  ASSERT_EQ(polygons.size(), 1u);
  const pear::Ring& r = polygons[0][0];
  EXPECT_EQ(r[0].x, -0.1);
  EXPECT_EQ(r[0].y, 1e-300);
  EXPECT_EQ(r[1].x, 1.7976931348623157e308);
  EXPECT_EQ(r[1].y, -2500.0);
  EXPECT_EQ(r[2].x, 4.9e-324);
  EXPECT_EQ(r[2].y, 0.1 + 0.2);
}

TEST(GeoJson, SmallRingsKeptOnlyWhenAsked) {
  const std::string text = "[[[0,0],[4,0],[4,4],[0,4]],[[1,1]],[[2,2],[3,3]]]";
  EXPECT_THROW(read_geojson(text), pear::io::ParseError);
  const auto polygons = read_geojson(text, "steiner", {.keep_small_rings = true});
  ASSERT_EQ(polygons.size(), 1u);
  ASSERT_EQ(polygons[0].size(), 3u);
  EXPECT_EQ(polygons[0][1].size(), 1u);
  EXPECT_EQ(polygons[0][2].size(), 2u);
}

/// Each file's vertex and hole counts against its MANIFEST.tsv row.
void expect_manifest_counts(const pear::corpus::Folder& folder) {
  ASSERT_FALSE(folder.files.empty()) << folder.dir;
  for (const auto& e : folder.files) {
    const auto polygons = pear::io::read_file(e.path, {.keep_small_rings = true});
    ASSERT_EQ(polygons.size(), 1u) << e.file;
    std::size_t vertices = 0;
    for (const auto& ring : polygons[0]) vertices += ring.size();
    EXPECT_EQ(vertices, e.vertices) << e.file;
    EXPECT_EQ(polygons[0].size() - 1, e.holes) << e.file;
  }
}

TEST(GeoJson, BundledCorpusMatchesItsManifest) {
  for (const char* name : {"earcut", "countries", "glyphs"}) {
    const auto folder = pear::corpus::read_folder(pear::corpus::bundled_root(), name);
    PEAR_SKIP_IF_MISSING(folder);
    expect_manifest_counts(folder);
  }
}

TEST(GeoJson, SharedCountriesMatchTheirManifest) {
  const auto folder = pear::corpus::read_folder(pear::corpus::shared_root(), "countries");
  PEAR_SKIP_IF_MISSING(folder);
  expect_manifest_counts(folder);
}

}  // namespace
