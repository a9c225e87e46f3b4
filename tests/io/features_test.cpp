// read_features: z and m per vertex, GeoJSON properties, feature indices, the SRID, and
// geometries that are no polygon skipped and named (the whole file only fails when nothing is
// left). Expected values are those written into each input here.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "pear/io.hpp"

namespace {

namespace io = pear::io;
using io::Format;
using pear::Point;

io::ReadResult features(std::string_view text, Format format) {
  return io::read_features(text, format, "in");
}

TEST(Features, GeoJsonPropertiesAreKeptVerbatimAndSharedByMultiPolygonParts) {
  const auto result = features(R"({"type":"FeatureCollection","features":[
    {"type":"Feature","geometry":{"type":"MultiPolygon","coordinates":[
       [[[0,0],[1,0],[0,1],[0,0]]], [[[5,5],[6,5],[5,6],[5,5]]]]},
     "properties":{"name":"a \"quoted\" name","n":[1,2.5,{"x":null}],"ok":true}},
    {"type":"Feature","properties":null,"geometry":{"type":"Polygon",
     "coordinates":[[[0,0],[1,0],[0,1]]]}},
    {"type":"Feature","properties":{},"geometry":null}]})",
                               Format::geojson);
  ASSERT_EQ(result.features.size(), 3u);
  const std::string want = R"({"name":"a \"quoted\" name","n":[1,2.5,{"x":null}],"ok":true})";
  EXPECT_EQ(result.features[0].properties, want);
  EXPECT_EQ(result.features[1].properties, want);  // the MultiPolygon's second part
  EXPECT_EQ(result.features[1].polygon[0][0], (Point{5, 5}));
  EXPECT_EQ(result.features[0].feature_index, 0u);
  EXPECT_EQ(result.features[1].feature_index, 0u);
  EXPECT_EQ(result.features[2].feature_index, 1u);
  EXPECT_EQ(result.features[2].properties, "");  // null
  EXPECT_TRUE(result.features[0].z.empty());
  EXPECT_TRUE(result.skipped.empty());
  EXPECT_EQ(result.srid, 0u);
}

TEST(Features, GeoJsonZPerVertexWithoutTheClosingPoint) {
  const auto result = features(R"({"type":"Polygon","coordinates":[
    [[0,0,5],[10,0,6],[10,10,7],[0,10,8],[0,0,5]], [[2,2,1],[2,8,2],[8,8,3]]]})",
                               Format::geojson);
  ASSERT_EQ(result.features.size(), 1u);
  EXPECT_EQ(result.features[0].z, (std::vector<double>{5, 6, 7, 8, 1, 2, 3}));
  EXPECT_TRUE(result.features[0].m.empty());
}

TEST(Features, GeoJsonPositionsMixingZAndNoZAreAnError) {
  const std::string text = R"({"type":"Polygon","coordinates":[[[0,0,5],[1,0],[0,1,5]]]})";
  EXPECT_THROW(features(text, Format::geojson), io::ParseError);
  EXPECT_EQ(io::read_geojson(text).size(), 1u);  // the Polygon API ignores z, as it did
}

TEST(Features, GeoJsonOtherGeometriesAreSkippedAndNamed) {
  const std::string text = R"({"type":"FeatureCollection","features":[
    {"type":"Feature","properties":{"k":1},"geometry":{"type":"Polygon",
     "coordinates":[[[0,0],[1,0],[0,1]]]}},
    {"type":"Feature","properties":{"k":2},"geometry":{"type":"LineString",
     "coordinates":[[0,0],[1,1]]}},
    {"type":"Feature","properties":{"k":3},"geometry":{"type":"GeometryCollection","geometries":[
      {"type":"Point","coordinates":[0,0]},
      {"type":"Polygon","coordinates":[[[2,0],[3,0],[2,1]]]}]}}]})";
  const auto result = features(text, Format::geojson);
  ASSERT_EQ(result.features.size(), 2u);
  EXPECT_EQ(result.features[1].feature_index, 2u);
  EXPECT_EQ(result.features[1].properties, R"({"k":3})");
  ASSERT_EQ(result.skipped.size(), 2u);
  EXPECT_EQ(result.skipped[0].type, "LineString");
  EXPECT_EQ(result.skipped[0].feature_index, 1u);
  EXPECT_EQ(result.skipped[0].line, 4u);
  EXPECT_EQ(result.skipped[1].type, "Point");
  EXPECT_EQ(result.skipped[1].feature_index, 2u);
  EXPECT_THROW(io::read_geojson(text), io::ParseError);  // the Polygon API stays strict
}

TEST(Features, TopLevelGeometryCollectionNumbersItsGeometries) {
  const auto result = features(R"({"type":"GeometryCollection","geometries":[
    {"type":"MultiLineString","coordinates":[[[0,0],[1,1]]]},
    {"type":"Polygon","coordinates":[[[2,0],[3,0],[2,1]]]}]})",
                               Format::geojson);
  ASSERT_EQ(result.features.size(), 1u);
  EXPECT_EQ(result.features[0].feature_index, 1u);
  ASSERT_EQ(result.skipped.size(), 1u);
  EXPECT_EQ(result.skipped[0].feature_index, 0u);
}

TEST(Features, AFileWithoutAnyPolygonIsStillAnError) {
  try {
    features(R"({"type":"FeatureCollection","features":[{"type":"Feature","properties":null,
      "geometry":{"type":"Point","coordinates":[1,2]}}]})",
             Format::geojson);
    FAIL() << "no error";
  } catch (const io::ParseError& e) {
    EXPECT_EQ(e.line(), 2u);
    EXPECT_NE(std::string(e.what()).find("\"Point\""), std::string::npos) << e.what();
  }
  EXPECT_THROW(features("LINESTRING (0 0, 1 1)", Format::wkt), io::ParseError);
}

TEST(Features, GeoJsonCrsNamesTheSrid) {
  const auto epsg = features(R"({"type":"FeatureCollection","crs":{"type":"name",
    "properties":{"name":"urn:ogc:def:crs:EPSG::32633"}},"features":[]})",
                             Format::geojson);
  EXPECT_EQ(epsg.srid, 32633u);
  const auto crs84 = features(R"({"type":"FeatureCollection","crs":{"type":"name",
    "properties":{"name":"urn:ogc:def:crs:OGC:1.3:CRS84"}},"features":[]})",
                              Format::geojson);
  EXPECT_EQ(crs84.srid, 4326u);
}

TEST(Features, GeoJsonPropertiesMustBeAnObjectOrNull) {
  EXPECT_THROW(features(R"({"type":"Feature","properties":[1],"geometry":null})", Format::geojson),
               io::ParseError);
}

TEST(Features, WktZMAndZMOrdinates) {
  const auto z = features("POLYGON Z ((0 0 1, 1 0 2, 0 1 3, 0 0 1))", Format::wkt);
  EXPECT_EQ(z.features[0].z, (std::vector<double>{1, 2, 3}));
  EXPECT_TRUE(z.features[0].m.empty());
  const auto m = features("POLYGON M ((0 0 1, 1 0 2, 0 1 3, 0 0 1))", Format::wkt);
  EXPECT_TRUE(m.features[0].z.empty());
  EXPECT_EQ(m.features[0].m, (std::vector<double>{1, 2, 3}));
  const auto zm = features("MULTIPOLYGON ZM (((0 0 1 4, 1 0 2 5, 0 1 3 6)))", Format::wkt);
  EXPECT_EQ(zm.features[0].z, (std::vector<double>{1, 2, 3}));
  EXPECT_EQ(zm.features[0].m, (std::vector<double>{4, 5, 6}));
  const auto untagged = features("POLYGON ((0 0 1, 1 0 2, 0 1 3))", Format::wkt);
  EXPECT_EQ(untagged.features[0].z, (std::vector<double>{1, 2, 3}));
  EXPECT_THROW(features("POLYGON ((0 0 1, 1 0, 0 1 3))", Format::wkt), io::ParseError);
}

TEST(Features, WktSridAndSkippedGeometriesAndByteOrderMark) {
  const auto result = features(
      "\xEF\xBB\xBFSRID=3857;POINT (1 2)\n"
      "SRID=3857;GEOMETRYCOLLECTION (LINESTRING Z (0 0 0, 1 1 1), POLYGON ((0 0, 1 0, 0 1)))\n"
      "POLYGON ((5 5, 6 5, 5 6))",
      Format::wkt);
  EXPECT_EQ(result.srid, 3857u);
  ASSERT_EQ(result.features.size(), 2u);
  EXPECT_EQ(result.features[0].feature_index, 1u);
  EXPECT_EQ(result.features[1].feature_index, 2u);
  ASSERT_EQ(result.skipped.size(), 2u);
  EXPECT_EQ(result.skipped[0].type, "POINT");
  EXPECT_EQ(result.skipped[0].column, 14u);  // after the byte order mark (3 bytes) and SRID
  EXPECT_EQ(result.skipped[1].type, "LINESTRING");
  EXPECT_EQ(result.skipped[1].line, 2u);
  EXPECT_THROW(features("SRID=3857;POLYGON EMPTY SRID=4326;POLYGON EMPTY", Format::wkt),
               io::ParseError);
}

/// Little-endian WKB, field by field.
struct Wkb {
  std::string bytes;
  Wkb& u8(unsigned v) {
    bytes.push_back(static_cast<char>(v));
    return *this;
  }
  Wkb& u32(std::uint32_t v) {
    for (int i = 0; i < 4; ++i) u8((v >> (8 * i)) & 0xFF);
    return *this;
  }
  Wkb& f64(double v) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    for (int i = 0; i < 8; ++i) u8(static_cast<unsigned>((bits >> (8 * i)) & 0xFF));
    return *this;
  }
};

TEST(Features, WkbZMAndTheEwkbSrid) {
  Wkb w;  // EWKB Polygon ZM with SRID 2154: one closed ring of 4 points
  w.u8(1).u32(3u | 0x80000000u | 0x40000000u | 0x20000000u).u32(2154).u32(1).u32(4);
  const double points[4][4] = {{0, 0, 10, 1}, {4, 0, 11, 2}, {0, 4, 12, 3}, {0, 0, 10, 1}};
  for (const auto& p : points) w.f64(p[0]).f64(p[1]).f64(p[2]).f64(p[3]);
  const auto result = features(w.bytes, Format::wkb);
  EXPECT_EQ(result.srid, 2154u);
  ASSERT_EQ(result.features.size(), 1u);
  EXPECT_EQ(result.features[0].z, (std::vector<double>{10, 11, 12}));
  EXPECT_EQ(result.features[0].m, (std::vector<double>{1, 2, 3}));
}

TEST(Features, WkbCollectionSkipsPointsAndLines) {
  Wkb w;  // GeometryCollection: Point, LineString Z (ISO 1002), Polygon
  w.u8(1).u32(7).u32(3);
  w.u8(1).u32(1).f64(1).f64(2);
  w.u8(1).u32(1002).u32(2).f64(0).f64(0).f64(0).f64(1).f64(1).f64(1);
  w.u8(1).u32(3).u32(1).u32(3).f64(0).f64(0).f64(1).f64(0).f64(0).f64(1);
  const auto result = features(w.bytes, Format::wkb);
  ASSERT_EQ(result.features.size(), 1u);
  ASSERT_EQ(result.skipped.size(), 2u);
  EXPECT_EQ(result.skipped[0].type, "Point");
  EXPECT_EQ(result.skipped[0].offset, 9u);
  EXPECT_EQ(result.skipped[1].type, "LineString");
  EXPECT_EQ(result.skipped[1].offset, 30u);
  EXPECT_THROW(io::read_wkb(std::as_bytes(std::span(w.bytes))), io::ParseError);
}

TEST(Features, GeoJsonWriterWritesZAndTheCrs) {
  const io::TriangulatedPolygon triangle{.polygon = {{{0, 0}, {1, 0}, {0, 1}}},
                                         .triangles = {{0, 1, 2}},
                                         .z = {7, 8, 9},
                                         .properties = R"({"a":1})"};
  std::ostringstream out;
  io::write_geojson(out, std::span(&triangle, 1), 32633);
  const auto back = features(out.str(), Format::geojson);
  EXPECT_EQ(back.srid, 32633u);
  ASSERT_EQ(back.features.size(), 1u);
  EXPECT_EQ(back.features[0].polygon[0], (pear::Ring{{0, 0}, {1, 0}, {0, 1}}));
  EXPECT_EQ(back.features[0].z, (std::vector<double>{7, 8, 9}));
}

}  // namespace
