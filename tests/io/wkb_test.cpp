// WKB and EWKB in: values built byte by byte here (an encoder of the test's own, either byte
// order, with Z, M or ZM ordinates and an SRID) read back to the polygons that were encoded;
// hex text; the flat arrays pear.triangulate_many fills; errors naming the byte.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "pear/io.hpp"
#include "same_polygons.hpp"

namespace {

using pear::Point;
using pear::Polygon;
using pear::Ring;
using pear::testing::expect_same_polygons;
namespace io = pear::io;

/// How a value is encoded: byte order, type code flavour and the extra ordinates it carries.
struct Flavour {
  bool big_endian = false;
  bool z = false, m = false;
  bool ewkb = false;  ///< EWKB flag bits (with an SRID) instead of ISO's +1000s
};

/// WKB bytes, written field by field.
class Wkb {
 public:
  Wkb& byte(unsigned value) {
    bytes_.push_back(static_cast<std::byte>(value));
    return *this;
  }
  Wkb& u32(std::uint32_t value, bool big) {
    for (int i = 0; i < 4; ++i) byte((value >> (8 * (big ? 3 - i : i))) & 0xFF);
    return *this;
  }
  Wkb& f64(double value, bool big) {
    const auto bits = std::bit_cast<std::uint64_t>(value);
    for (int i = 0; i < 8; ++i) byte((bits >> (8 * (big ? 7 - i : i))) & 0xFF);
    return *this;
  }
  /// Byte order, type (3: Polygon, 6: MultiPolygon, 7: GeometryCollection) and an SRID.
  Wkb& header(std::uint32_t type, const Flavour& f) {
    byte(f.big_endian ? 0 : 1);
    if (f.ewkb)
      u32(type | (f.z ? 0x80000000u : 0) | (f.m ? 0x40000000u : 0) | 0x20000000u, f.big_endian)
          .u32(4326, f.big_endian);
    else
      u32(type + (f.z ? 1000 : 0) + (f.m ? 2000 : 0), f.big_endian);
    return *this;
  }
  /// A Polygon, each ring written closed (its first point again), extra ordinates 7 and 9.
  Wkb& polygon(const Polygon& polygon, const Flavour& f) {
    header(3, f).u32(static_cast<std::uint32_t>(polygon.size()), f.big_endian);
    for (const Ring& ring : polygon) {
      u32(static_cast<std::uint32_t>(ring.size() + 1), f.big_endian);
      for (std::size_t i = 0; i <= ring.size(); ++i) {
        const Point& p = ring[i % ring.size()];
        f64(p.x, f.big_endian).f64(p.y, f.big_endian);
        if (f.z) f64(7, f.big_endian);
        if (f.m) f64(9, f.big_endian);
      }
    }
    return *this;
  }
  std::span<const std::byte> bytes() const { return bytes_; }
  std::string hex() const {
    std::string out;
    for (const std::byte b : bytes_) {
      out += "0123456789ABCDEF"[std::to_integer<unsigned>(b) >> 4];
      out += "0123456789ABCDEF"[std::to_integer<unsigned>(b) & 15];
    }
    return out;
  }
  std::vector<std::byte> copy() const { return bytes_; }

 private:
  std::vector<std::byte> bytes_;
};

// A square with a hole whose coordinates use every bit of the double (bit-exactness shows).
const Polygon square_with_hole = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                                  {{2.1, 2.3}, {2.1, 8.7}, {8.9, 8.7}, {1.0 / 3, -0.0}}};
const Polygon triangle = {{{20, 0}, {21, 0}, {20.5, 1e-300}}};

std::vector<Flavour> every_flavour() {
  std::vector<Flavour> all;
  for (const bool big : {false, true})
    for (const bool ewkb : {false, true})
      for (const bool z : {false, true})
        for (const bool m : {false, true}) all.push_back({big, z, m, ewkb});
  return all;
}

std::string describe(const Flavour& f) {
  return std::string(f.big_endian ? "big" : "little") + (f.ewkb ? " EWKB" : " ISO") +
         (f.z ? " Z" : "") + (f.m ? " M" : "");
}

TEST(Wkb, PolygonOfEveryFlavourReadsBackBitForBit) {
  for (const Flavour& f : every_flavour()) {
    SCOPED_TRACE(describe(f));
    Wkb wkb;
    wkb.polygon(square_with_hole, f);
    expect_same_polygons(io::read_wkb(wkb.bytes()), {square_with_hole});
  }
}

TEST(Wkb, MultiPolygonPartsEachInTheirOwnFlavour) {
  const Flavour big_z{true, true, false, false}, little_ewkb_m{false, false, true, true};
  Wkb wkb;
  wkb.header(6, {}).u32(3, false);
  wkb.polygon(square_with_hole, big_z);
  wkb.header(3, big_z).u32(0, true);  // an empty part: no polygon
  wkb.polygon(triangle, little_ewkb_m);
  expect_same_polygons(io::read_wkb(wkb.bytes()), {square_with_hole, triangle});
}

TEST(Wkb, EmptyValuesHaveNoPolygons) {
  Wkb polygon, multipolygon, collection, ewkb;
  polygon.header(3, {}).u32(0, false);
  multipolygon.header(6, {true}).u32(0, true);
  collection.header(7, {}).u32(0, false);
  ewkb.header(3, {.z = true, .ewkb = true}).u32(0, false);
  for (const Wkb* w : {&polygon, &multipolygon, &collection, &ewkb})
    EXPECT_TRUE(io::read_wkb(w->bytes()).empty()) << w->hex();
}

TEST(Wkb, KeepSmallRingsPassesATwoPointHole) {
  const Polygon with_short_hole = {square_with_hole[0], {{5, 5}, {6, 6}}};
  Wkb wkb;
  wkb.polygon(with_short_hole, {});
  expect_same_polygons(io::read_wkb(wkb.bytes(), "x", {.keep_small_rings = true}),
                       {with_short_hole});
}

TEST(Wkb, RingsWithoutAClosingPointKeepEveryPoint) {
  Wkb wkb;  // not valid OGC WKB, but a polygon nonetheless: nothing to drop
  wkb.header(3, {}).u32(1, false).u32(3, false);
  for (const Point& p : triangle[0]) wkb.f64(p.x, false).f64(p.y, false);
  expect_same_polygons(io::read_wkb(wkb.bytes()), {triangle});
}

TEST(HexWkb, ValuesOnLinesInEitherCaseReadLikeTheBytes) {
  Wkb first, second;
  first.polygon(square_with_hole, {.ewkb = true});
  second.header(6, {true}).u32(1, true).polygon(triangle, {true, true, true, false});
  std::string lower = second.hex();
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::string text = "\xEF\xBB\xBF" + first.hex() + "\r\n  " + lower + "\n";
  expect_same_polygons(io::read_hex_wkb(text), {square_with_hole, triangle});
  expect_same_polygons(io::read_text(text, io::guess_format("-", text), "-"),
                       {square_with_hole, triangle});
}

// The flat form: closing points kept, offsets per geometry, a missing value is no polygon.
TEST(WkbArrays, GeometriesAppendToTheSameArrays) {
  Wkb polygon, multipolygon, empty;
  polygon.polygon(triangle, {.big_endian = true});
  multipolygon.header(6, {}).u32(2, false);
  multipolygon.polygon(square_with_hole, {.z = true}).polygon(triangle, {.m = true, .ewkb = true});
  empty.header(7, {}).u32(0, false);
  io::PolygonArrays arrays;
  io::read_wkb(polygon.bytes(), arrays);
  io::read_wkb({}, arrays);
  io::read_wkb(multipolygon.bytes(), arrays);
  io::read_wkb(empty.bytes(), arrays);
  EXPECT_EQ(arrays.geometry_offsets, (std::vector<std::int64_t>{0, 1, 1, 3, 3}));
  EXPECT_EQ(arrays.polygon_offsets, (std::vector<std::int64_t>{0, 1, 3, 4}));
  EXPECT_EQ(arrays.ring_offsets, (std::vector<std::int64_t>{0, 4, 9, 14, 18}));
  std::vector<double> expected;
  for (const Polygon* p : {&triangle, &square_with_hole, &triangle})
    for (const Ring& ring : *p)
      for (std::size_t i = 0; i <= ring.size(); ++i)
        expected.insert(expected.end(), {ring[i % ring.size()].x, ring[i % ring.size()].y});
  ASSERT_EQ(arrays.coordinates.size(), expected.size());
  for (std::size_t i = 0; i < expected.size(); ++i)
    EXPECT_EQ(std::bit_cast<std::uint64_t>(arrays.coordinates[i]),
              std::bit_cast<std::uint64_t>(expected[i]))
        << i;
}

TEST(WkbArrays, CoordinatesAreNotCheckedThere) {
  // NaN and a two-point ring are pear::triangulate_batch's to report, with the polygon's index.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Wkb wkb;
  wkb.header(3, {})
      .u32(1, false)
      .u32(2, false)
      .f64(nan, false)
      .f64(1, false)
      .f64(2, false)
      .f64(3, false);
  io::PolygonArrays arrays;
  io::read_wkb(wkb.bytes(), arrays);
  ASSERT_EQ(arrays.coordinates.size(), 4u);
  EXPECT_TRUE(std::isnan(arrays.coordinates[0]));
  EXPECT_EQ(arrays.ring_offsets, (std::vector<std::int64_t>{0, 2}));
}

TEST(WkbArrays, AnErrorLeavesTheArraysAsTheyWere) {
  Wkb good, bad;
  good.polygon(triangle, {});
  bad.header(6, {}).u32(2, false).polygon(square_with_hole, {});  // the second part is missing
  io::PolygonArrays arrays;
  io::read_wkb(good.bytes(), arrays);
  const io::PolygonArrays before = arrays;
  EXPECT_THROW(io::read_wkb(bad.bytes(), arrays), io::ParseError);
  EXPECT_EQ(arrays.coordinates, before.coordinates);
  EXPECT_EQ(arrays.ring_offsets, before.ring_offsets);
  EXPECT_EQ(arrays.polygon_offsets, before.polygon_offsets);
  EXPECT_EQ(arrays.geometry_offsets, before.geometry_offsets);
}

// Errors: the byte (counted by hand from the layout: 1 byte order, 4 type, 4 ring count, then
// per ring 4 point count and 16 a point) and the reason, in what() and in offset().
void expect_wkb_error(std::span<const std::byte> bytes, std::size_t byte,
                      const std::string& phrase) {
  for (const bool flat : {false, true}) {
    SCOPED_TRACE(flat ? "into arrays" : "as polygons");
    try {
      io::PolygonArrays arrays;
      flat ? io::read_wkb(bytes, arrays, "in.wkb") : (void)io::read_wkb(bytes, "in.wkb");
      ADD_FAILURE() << "no ParseError; expected one at byte " << byte;
    } catch (const io::ParseError& e) {
      const std::string where = "in.wkb: byte " + std::to_string(byte) + ": ";
      EXPECT_EQ(std::string(e.what()).rfind(where, 0), 0u) << e.what();
      EXPECT_EQ(e.offset(), byte) << e.what();
      EXPECT_EQ(e.line(), 0u);
      EXPECT_NE(e.detail().find(phrase), std::string::npos)
          << "message '" << e.what() << "' lacks '" << phrase << "'";
    }
  }
}

std::vector<std::byte> square_bytes() {
  Wkb wkb;
  wkb.polygon(square_with_hole, {});
  return wkb.copy();
}

TEST(WkbErrors, TruncatedAtEveryField) {
  const std::vector<std::byte> whole = square_bytes();  // 9 + 2 * (4 + 5 * 16) = 177 bytes
  ASSERT_EQ(whole.size(), 177u);
  const auto cut = [&](std::size_t size) { return std::span(whole).first(size); };
  expect_wkb_error(cut(1), 1, "expected a geometry type but the value ends (1 bytes)");
  expect_wkb_error(cut(7), 5, "expected a ring count but the value ends (7 bytes)");
  expect_wkb_error(cut(10), 5, "2 rings cannot fit in the 1 bytes left");
  expect_wkb_error(cut(95), 93, "expected a point count but the value ends (95 bytes)");
  expect_wkb_error(cut(100), 97, "a ring of 5 points needs 80 bytes, 3 are left");
  // No bytes: an empty file is an error, while into arrays it is a missing geometry.
  EXPECT_THROW(io::read_wkb(cut(0)), io::ParseError);
  io::PolygonArrays arrays;
  io::read_wkb(cut(0), arrays);
  EXPECT_EQ(arrays.geometry_offsets, (std::vector<std::int64_t>{0, 0}));
}

TEST(WkbErrors, BadByteOrderTypeAndTrailingBytes) {
  std::vector<std::byte> bytes = square_bytes();
  bytes[0] = std::byte{2};
  expect_wkb_error(bytes, 0, "byte order 2 is neither 0 nor 1");
  bytes = square_bytes();
  bytes[1] = std::byte{1};  // Point
  expect_wkb_error(bytes, 1, "geometry type 1 is not a Polygon (3) or MultiPolygon (6)");
  bytes = square_bytes();
  bytes.push_back(std::byte{0});
  expect_wkb_error(bytes, 177, "1 bytes follow the end of the geometry");
}

TEST(WkbErrors, CountsPastTheEnd) {
  std::vector<std::byte> bytes = square_bytes();
  bytes[5] = std::byte{200};  // ring count 200: needs at least 800 bytes
  expect_wkb_error(bytes, 5, "200 rings cannot fit in the 168 bytes left");
  bytes = square_bytes();
  bytes[11] = std::byte{1};  // first ring: 65541 points
  expect_wkb_error(bytes, 13, "a ring of 65541 points needs 1048656 bytes, 164 are left");
  Wkb multi;
  multi.header(6, {}).u32(0xFFFFFFFF, false).polygon(triangle, {});
  expect_wkb_error(multi.bytes(), 5, "4294967295 polygons cannot fit in the 77 bytes left");
}

TEST(WkbErrors, PartsAndCollectionsThatAreNotPolygons) {
  Wkb nested;
  nested.header(6, {}).u32(1, false).header(6, {}).u32(0, false);
  expect_wkb_error(nested.bytes(), 9, "a MultiPolygon's part 0 is not a Polygon");
  Wkb collection;
  collection.header(7, {}).u32(1, false).polygon(triangle, {});
  expect_wkb_error(collection.bytes(), 5, "a GeometryCollection of 1 geometries");
}

/// The message of the ParseError that reading `bytes` as polygons throws.
std::string polygons_error(std::span<const std::byte> bytes, const std::string& name) {
  try {
    io::read_wkb(bytes, name);
  } catch (const io::ParseError& e) {
    return e.what();
  }
  return "no ParseError";
}

TEST(WkbErrors, PolygonsNeedFiniteCoordinatesAndThreePoints) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  constexpr double infinity = std::numeric_limits<double>::infinity();
  Wkb x_nan;  // the second point's x: byte 9 + 4 + 16
  x_nan.polygon({{{0, 0}, {nan, 1}, {1, 1}}}, {});
  EXPECT_EQ(polygons_error(x_nan.bytes(), "nan.wkb"),
            "nan.wkb: byte 29: expected a finite coordinate but found NaN");
  Wkb y_infinite;  // the third point's y: byte 9 + 4 + 2 * 16 + 8
  y_infinite.polygon({{{0, 0}, {1, 0}, {1, -infinity}}}, {.big_endian = true});
  EXPECT_EQ(polygons_error(y_infinite.bytes(), "inf.wkb"),
            "inf.wkb: byte 53: expected a finite coordinate but found -infinity");
  Wkb small;  // the hole (its point count at byte 9 + 4 + 5 * 16 = 93) has two points
  small.polygon({square_with_hole[0], {{5, 5}, {6, 6}}}, {});
  EXPECT_EQ(polygons_error(small.bytes(), "small.wkb"),
            "small.wkb: byte 93: expected a ring of at least 3 points (besides a closing point) "
            "but found 2 points");
}

// Hex text: line and column of the failing byte's digits, and which value.
void expect_hex_error(const std::string& text, std::size_t line, std::size_t column,
                      const std::string& phrase) {
  try {
    io::read_hex_wkb(text, "in.hex");
    ADD_FAILURE() << "no ParseError; expected one at " << line << ":" << column;
  } catch (const io::ParseError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_EQ(e.column(), column) << e.what();
    EXPECT_NE(std::string(e.what()).find(phrase), std::string::npos)
        << "message '" << e.what() << "' lacks '" << phrase << "'";
  }
}

TEST(HexWkbErrors, DigitsAndValues) {
  const std::string square = Wkb().polygon(square_with_hole, {}).hex();
  expect_hex_error("", 1, 1, "expected hex WKB but found end of file");
  expect_hex_error(square + "\n0103x0", 2, 5, "expected a hex digit but found 'x0'");
  expect_hex_error("  01030", 1, 8, "expected the second hex digit of a byte but found end");
  // value 2 on line 2: its ring count (byte 5) is 200, at column 1 + 2 * 5.
  std::string bad = square;
  bad.replace(10, 2, "C8");
  expect_hex_error(square + "\n" + bad, 2, 11,
                   "in.hex:2:11: value 2, byte 5: 200 rings cannot fit in the 168 bytes left");
  expect_hex_error(square + "00", 1, 355, "value 1, byte 177: 1 bytes follow the end");
}

TEST(WkbFiles, FormatFromTheNameOrTheFirstBytes) {
  using io::Format;
  const std::string hex = Wkb().polygon(triangle, {}).hex();
  EXPECT_EQ(io::guess_format("a.wkb", "POLYGON"), Format::wkb);
  EXPECT_EQ(io::guess_format("a.WKB.hex", "{"), Format::hex_wkb);
  EXPECT_EQ(io::guess_format("a.hexwkb", ""), Format::hex_wkb);
  EXPECT_EQ(io::guess_format("-", std::string("\x01\x03\0\0\0", 5)), Format::wkb);
  EXPECT_EQ(io::guess_format("-", std::string("\0\0\0\0\x03", 5)), Format::wkb);
  EXPECT_EQ(io::guess_format("-", "\n  " + hex + "\n" + hex), Format::hex_wkb);
  EXPECT_EQ(io::guess_format("-", "\xEF\xBB\xBF" + hex), Format::hex_wkb);
  EXPECT_EQ(io::guess_format("-", "\xEF\xBB\xBFPOLYGON EMPTY"), Format::wkt);
  // Not hex WKB: a .poly header, a word too short, one that is not all hex digits.
  EXPECT_EQ(io::guess_format("-", "4 2 0 0\n"), Format::poly);
  EXPECT_EQ(io::guess_format("-", "0103000000000000"), Format::poly);
  EXPECT_EQ(io::guess_format("-", "01030000000000000g"), Format::poly);
}

TEST(WkbFiles, ReadFileTakesTheBytesAsTheyAre) {
  const auto path = std::filesystem::temp_directory_path() / "pear_wkb_test.wkb";
  Wkb wkb;
  wkb.polygon(square_with_hole, {.big_endian = true, .z = true});
  {
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(wkb.bytes().data()),
              static_cast<std::streamsize>(wkb.bytes().size()));
  }
  expect_same_polygons(io::read_file(path), {square_with_hole});
  std::filesystem::remove(path);
}

}  // namespace
