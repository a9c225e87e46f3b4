// Bad input: each case throws ParseError naming the file, the line and column (counted by hand
// from the test text), and what was expected.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "pear/io.hpp"

namespace {

using pear::io::ParseError;
using pear::io::read_geojson;
using pear::io::read_poly;
using pear::io::read_wkt;

// Runs `read`, requires a ParseError at line:column whose message contains `phrase`.
void expect_error(const std::function<void()>& read, const std::string& file, std::size_t line,
                  std::size_t column, const std::string& phrase) {
  try {
    read();
    ADD_FAILURE() << "no ParseError; expected one at " << line << ":" << column;
  } catch (const ParseError& e) {
    const std::string where =
        file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": ";
    EXPECT_EQ(std::string(e.what()).rfind(where, 0), 0u) << e.what();
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.column(), column) << e.what();
    EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos)
        << "message '" << e.what() << "' lacks '" << phrase << "'";
  }
}

void geojson_error(const std::string& text, std::size_t line, std::size_t column,
                   const std::string& phrase) {
  expect_error([&] { read_geojson(text, "in.json"); }, "in.json", line, column, phrase);
}

TEST(GeoJsonErrors, EmptyFile) {
  geojson_error("", 1, 1, "but found end of file");
}
TEST(GeoJsonErrors, OnlyWhiteSpace) {
  geojson_error("\n\n  ", 3, 3, "but found end of file");
}

TEST(GeoJsonErrors, BinaryFile) {
  geojson_error(std::string("\x89PNG\r\n\x1a\n\0\0", 10), 1, 1, "but found byte 0x89");
}

TEST(GeoJsonErrors, TruncatedInsideARing) {
  geojson_error("{\"type\":\"Polygon\",\n\"coordinates\":[[[0,0],[1,0],[1,", 2, 32,
                "expected a number but found end of file");
}

TEST(GeoJsonErrors, TruncatedAfterTheValue) {
  geojson_error("{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1,0],[1,1]]]", 1, 54,
                "expected ',' or '}'");
}

TEST(GeoJsonErrors, MissingComma) {
  geojson_error("[[[0,0] [1,0],[1,1]]]", 1, 9, "expected ',' or ']' in an array but found '['");
}

TEST(GeoJsonErrors, NaNIsNotANumber) {
  geojson_error("[[[0,0],\n  [NaN,0],[1,1]]]", 2, 4, "expected a number but found 'NaN'");
}

TEST(GeoJsonErrors, OutOfRangeNumber) {
  geojson_error("[[[0,0],[1e400,0],[1,1]]]", 1, 10,
                "expected a number within the range of a double but found '1e400'");
}

TEST(GeoJsonErrors, JsonForbidsLeadingPlusAndZeros) {
  geojson_error("[[[+1,0],[1,0],[1,1]]]", 1, 4, "expected a number but found '+1'");
  geojson_error("[[[01,0],[1,0],[1,1]]]", 1, 4, "expected a number but found '01'");
  geojson_error("[[[1.,0],[1,0],[1,1]]]", 1, 4, "expected a number");
}

TEST(GeoJsonErrors, RingWithTwoPoints) {
  geojson_error(
      "{\"type\":\"Polygon\",\"coordinates\":[[[0,0],[1,1],[0,0]]]}", 1, 34,
      "expected a ring of at least 3 points (besides a closing point) but found 2 points");
}

TEST(GeoJsonErrors, PositionWithOneNumber) {
  geojson_error("[[[0,0],[1],[1,1]]]", 1, 11, "expected ',' and the y coordinate but found ']'");
}

TEST(GeoJsonErrors, WrongGeometryType) {
  geojson_error("{\"type\":\"LineString\",\"coordinates\":[[0,0],[1,1]]}", 1, 9,
                "expected type Polygon, MultiPolygon, Feature, FeatureCollection or "
                "GeometryCollection but found \"LineString\"");
}

TEST(GeoJsonErrors, WrongTypeInsideFeatureCollection) {
  geojson_error("{\"type\":\"FeatureCollection\",\"features\":[\n{\"type\":\"Polygon\"}]}", 2, 9,
                "expected type Feature but found \"Polygon\"");
}

TEST(GeoJsonErrors, CoordinatesOfTheWrongType) {
  geojson_error("{\"type\":\"Polygon\",\"coordinates\":\"abc\"}", 1, 33,
                "expected a polygon: an array of rings '[' but found '\"abc\"'");
}

TEST(GeoJsonErrors, MissingCoordinates) {
  geojson_error("{\"type\":\"Polygon\"}", 1, 1,
                "expected a \"coordinates\" member in this Polygon");
}

TEST(GeoJsonErrors, MissingType) {
  geojson_error("{\"coordinates\":[]}", 1, 1, "expected a \"type\" member");
}

TEST(GeoJsonErrors, DuplicateMember) {
  geojson_error("{\"type\":\"Polygon\",\"type\":\"Polygon\",\"coordinates\":[]}", 1, 19,
                "found \"type\" again");
}

TEST(GeoJsonErrors, TrailingGarbage) {
  geojson_error("[[[0,0],[1,0],[1,1]]] x", 1, 23, "expected end of file after the GeoJSON value");
}

TEST(GeoJsonErrors, UnterminatedString) {
  geojson_error("{\"type\":\"Polyg", 1, 9, "expected a string closed by '\"'");
}

TEST(GeoJsonErrors, DeepNestingIsRefusedNotACrash) {
  const std::string deep = "{\"type\":\"Feature\",\"properties\":" + std::string(100000, '[');
  geojson_error(deep, 1, 31 + 513, "expected at most 512 nested JSON values");
}

TEST(GeoJsonErrors, WrongDepthOfBareArray) {
  geojson_error("[[0,0],[1,0],[1,1]]", 1, 3, "expected an array of rings");
}

void wkt_error(const std::string& text, std::size_t line, std::size_t column,
               const std::string& phrase) {
  expect_error([&] { read_wkt(text, "in.wkt"); }, "in.wkt", line, column, phrase);
}

TEST(WktErrors, EmptyFile) {
  wkt_error("", 1, 1, "expected POLYGON or MULTIPOLYGON but found end of file");
}
TEST(WktErrors, WrongGeometry) {
  wkt_error("LINESTRING (0 0, 1 1)", 1, 1,
            "expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION but found 'LINESTRING'");
}
TEST(WktErrors, Truncated) {
  wkt_error("POLYGON ((0 0, 1 0,\n 1", 2, 3, "expected white space and the y coordinate");
}
TEST(WktErrors, NaN) {
  wkt_error("POLYGON ((0 0, nan 0, 1 1, 0 0))", 1, 16, "expected a number but found 'nan'");
}
TEST(WktErrors, OutOfRange) {
  wkt_error("POLYGON ((0 0, 1 -1e999, 1 1, 0 0))", 1, 18, "within the range of a double");
}
TEST(WktErrors, SmallRing) {
  wkt_error("POLYGON ((0 0, 1 1, 0 0))", 1, 10, "at least 3 points");
}
TEST(WktErrors, WrongOrdinateCount) {
  wkt_error("POLYGON Z ((0 0, 1 0, 1 1, 0 0))", 1, 16, "expected 3 ordinates per point");
}
TEST(WktErrors, MalformedSridPrefix) {
  wkt_error("SRID=;POLYGON EMPTY", 1, 6, "expected an integer SRID but found ';'");
  wkt_error("SRID=-1;POLYGON EMPTY", 1, 6, "expected a non-negative SRID but found '-1'");
  wkt_error("srid:4326;POLYGON EMPTY", 1, 5, "expected '=' after SRID but found ':'");
  wkt_error("SRID=4326 POLYGON EMPTY", 1, 10, "expected ';' after the SRID but found white space");
  wkt_error("POLYGON EMPTY\nSRID=4326;", 2, 11,
            "expected POLYGON, MULTIPOLYGON or GEOMETRYCOLLECTION but found end");
}
TEST(WktErrors, ColumnsCountTheByteOrderMark) {
  // The mark is skipped but stays in the text: offsets and columns are those of the file.
  wkt_error("\xEF\xBB\xBFPOLYGON ((0 0, 1 0))", 1, 13, "at least 3 points");
}

void poly_error(const std::string& text, std::size_t line, std::size_t column,
                const std::string& phrase) {
  expect_error([&] { read_poly(text, "in.poly"); }, "in.poly", line, column, phrase);
}

TEST(PolyErrors, EmptyFile) {
  poly_error("# nothing\n", 2, 1, "expected an integer vertex count but found end of file");
}
TEST(PolyErrors, DimensionThree) {
  poly_error("3 3 0 0\n", 1, 3, "expected dimension 2 but found '3'");
}
TEST(PolyErrors, SeparateNodeFile) {
  poly_error("0 2 0 0\n", 1, 1, "separate .node file");
}
TEST(PolyErrors, VertexNumbering) {
  poly_error("3 2 0 0\n1 0 0\n2 1 0\n4 0 1\n", 4, 1,
             "expected vertex number 3 (consecutive from 1)");
}
TEST(PolyErrors, SegmentEndpointOutOfRange) {
  poly_error("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n3 0\n0 0 1\n1 1 2\n2 2 3\n0\n", 8, 5,
             "expected a vertex number from 0 to 2 but found 3");
}
TEST(PolyErrors, OpenChain) {
  poly_error("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n2 0\n0 0 1\n1 1 2\n0\n", 2, 1,
             "expected vertex 0 on two segments (closed rings) but it is on only one");
}
// Found by fuzz/readers (corpus/fuzz/readers/crash-poly-open-chain-after-closed-start): vertex 0
// is on two segments, but the ring walked from it reaches vertex 3, on one only; the walk read
// past its table (heap-buffer-overflow under ASan).
TEST(PolyErrors, OpenChainReachedFromAVertexOnTwoSegments) {
  poly_error("4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n3 0\n0 0 1\n1 0 2\n2 1 3\n0\n", 4, 1,
             "expected vertex 2 on two segments (closed rings) but it is on only one");
}
TEST(PolyErrors, VertexOnThreeSegments) {
  poly_error("4 2 0 0\n0 0 0\n1 1 0\n2 0 1\n3 1 1\n4 0\n0 0 1\n1 1 2\n2 2 0\n3 0 3\n0\n", 10, 1,
             "vertex 0 is on a third one here");
}
TEST(PolyErrors, HolePointInTheFilledArea) {
  poly_error(
      "8 2 0 0\n0 0 0\n1 10 0\n2 10 10\n3 0 10\n4 4 4\n5 6 4\n6 6 6\n7 4 6\n"
      "8 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n4 4 5\n5 5 6\n6 6 7\n7 7 4\n1\n0 1 1\n",
      20, 1, "expected hole point 0 inside a hole or outside every ring");
}
TEST(PolyErrors, MissingHoleCount) {
  poly_error("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n3 0\n0 0 1\n1 1 2\n2 2 0\n", 9, 1,
             "expected the hole count but found end of file");
}
TEST(PolyErrors, BinaryGarbage) {
  poly_error(std::string("3\0\0", 3), 1, 2, "expected white space but found byte 0x00");
}
// Issue 30: a negative count was reported after the number, as "found white space".
TEST(PolyErrors, NegativeCountsNameTheNumber) {
  const std::string square = "4 2 0 0\n0 0 0\n1 1 0\n2 1 1\n3 0 1\n";
  const std::string segments = "4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n";
  poly_error("-5 2 0 0\n", 1, 1, "expected a non-negative vertex count but found '-5'");
  poly_error("4 -2 0 0\n", 1, 3, "expected a non-negative dimension but found '-2'");
  poly_error("4 2 -1 0\n", 1, 5, "expected a non-negative attribute count but found '-1'");
  poly_error("4 2 0 -1\n", 1, 7,
             "expected a non-negative boundary marker count (0 or 1) but found '-1'");
  poly_error(square + "-4 0\n", 6, 1, "expected a non-negative segment count but found '-4'");
  poly_error(square + "4 -1\n", 6, 3,
             "expected a non-negative boundary marker count (0 or 1) but found '-1'");
  poly_error(square + segments + "-1\n", 11, 1,
             "expected a non-negative hole count but found '-1'");
  poly_error(square + segments + "0\n-2\n", 12, 1,
             "expected a non-negative regional attribute count but found '-2'");
}
TEST(MeshErrors, NegativeCountsNameTheNumber) {
  expect_error([] { pear::io::read_node_ele("-3 2 0 0\n", "", "m"); }, "m (.node)", 1, 1,
               "expected a non-negative vertex count but found '-3'");
  expect_error([] { pear::io::read_node_ele("0 2 0 0\n", "-1 3 0\n", "m"); }, "m (.ele)", 1, 1,
               "expected a non-negative triangle count but found '-1'");
}

TEST(ReadFile, MissingFileNamesIt) {
  try {
    pear::io::read_file("/nonexistent/dir/x.json");
    ADD_FAILURE() << "no ParseError";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.file(), "/nonexistent/dir/x.json");
    EXPECT_NE(std::string(e.what()).find("cannot open"), std::string::npos) << e.what();
  }
}

TEST(ReadFile, FormatFromExtensionThenContent) {
  using pear::io::Format;
  using pear::io::guess_format;
  EXPECT_EQ(guess_format("a.GeoJSON", "POLYGON"), Format::geojson);
  EXPECT_EQ(guess_format("a.wkt", "{"), Format::wkt);
  EXPECT_EQ(guess_format("a.poly", ""), Format::poly);
  EXPECT_EQ(guess_format("-", "  MULTIPOLYGON EMPTY"), Format::wkt);
  EXPECT_EQ(guess_format("-", "\n# comment\n4 2 0 0"), Format::poly);
  EXPECT_EQ(guess_format("-", "[[[0,0]]]"), Format::geojson);
}

TEST(ReadFile, ErrorInAFileNamesThePath) {
  const auto path = std::filesystem::temp_directory_path() / "pear_io_test_bad.wkt";
  std::ofstream(path) << "POLYGON ((0 0, 1 0, 1 1, 0 0)\n";
  expect_error([&] { pear::io::read_file(path); }, path.string(), 2, 1, "expected ',' or ')'");
  std::filesystem::remove(path);
}

}  // namespace
