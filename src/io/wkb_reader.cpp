// WKB and PostGIS' EWKB: Polygon and MultiPolygon values, from bytes or hex text, into Polygons or
// into flat arrays. One parser; a sink decides where the points go (the flat one is the hot path
// of pear.triangulate_many, so the points are copied in one tight loop per ring).
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "pear/io.hpp"
#include "readers.hpp"
#include "scanner.hpp"

namespace pear::io {
namespace {

// Type codes: ISO adds 1000 (Z), 2000 (M), 3000 (ZM); EWKB sets these flag bits instead.
constexpr std::uint32_t wkb_point = 1;
constexpr std::uint32_t wkb_linestring = 2;
constexpr std::uint32_t wkb_polygon = 3;
constexpr std::uint32_t wkb_multipoint = 4;
constexpr std::uint32_t wkb_multilinestring = 5;
constexpr std::uint32_t wkb_multipolygon = 6;
// Read whole by read_features; else only empty: shapely 1.8's empty Polygon.
constexpr std::uint32_t wkb_collection = 7;
constexpr int max_nesting = 64;  // collections nested deeper are refused, not a stack overflow
constexpr std::uint32_t ewkb_z = 0x80000000u;
constexpr std::uint32_t ewkb_m = 0x40000000u;
constexpr std::uint32_t ewkb_srid = 0x20000000u;

/// Why a value cannot be read, at which of its bytes. Thrown inside the parser; each entry
/// point turns it into a ParseError that names the place its own way (byte, or line and column
/// of the hex digits).
struct Fault {
  std::size_t byte;
  std::string reason;
};

template <class U>
U swap_bytes(U value) {
#if defined(__GNUC__) || defined(__clang__)
  if constexpr (sizeof(U) == 4) return __builtin_bswap32(value);
  if constexpr (sizeof(U) == 8) return __builtin_bswap64(value);
#endif
  U out = 0;
  for (std::size_t i = 0; i < sizeof(U); ++i, value >>= 8) out = (out << 8) | (value & 0xFF);
  return out;
}

/// A cursor over one value's bytes that knows the current byte order and faults where the
/// bytes run out.
class Cursor {
 public:
  explicit Cursor(std::span<const std::byte> bytes) : bytes_(bytes) {}

  std::size_t offset() const { return offset_; }
  std::size_t left() const { return bytes_.size() - offset_; }
  bool swapped() const { return swap_; }
  [[noreturn]] static void fail(std::size_t at, std::string reason) {
    throw Fault{at, std::move(reason)};
  }

  void read_byte_order() {
    need(1, "a byte order");
    const auto order = static_cast<unsigned char>(bytes_[offset_]);
    if (order > 1) fail(offset_, "byte order " + std::to_string(order) + " is neither 0 nor 1");
    swap_ = (order == 1) != (std::endian::native == std::endian::little);
    ++offset_;
  }

  std::uint32_t read_uint32(const char* what) {
    need(4, what);
    std::uint32_t value;
    std::memcpy(&value, bytes_.data() + offset_, 4);
    offset_ += 4;
    return swap_ ? swap_bytes(value) : value;
  }

  /// The bytes of `count` points of `stride` bytes each, skipped over; faults if they are not
  /// all there.
  const std::byte* take_points(std::uint32_t count, std::size_t stride) {
    if (std::size_t{count} > left() / stride)
      fail(offset_, "a ring of " + std::to_string(count) + " points needs " +
                        std::to_string(std::size_t{count} * stride) + " bytes, " +
                        std::to_string(left()) + " are left");
    const std::byte* at = bytes_.data() + offset_;
    offset_ += std::size_t{count} * stride;
    return at;
  }

 private:
  void need(std::size_t size, const char* what) const {
    if (left() < size)
      fail(offset_, std::string("expected ") + what + " but the value ends (" +
                        std::to_string(bytes_.size()) + " bytes)");
  }

  std::span<const std::byte> bytes_;
  std::size_t offset_ = 0;
  bool swap_ = false;
};

/// x and y of the point whose ordinates start at `at`.
inline Point point_at(const std::byte* at, bool swap) {
  std::uint64_t xy[2];
  std::memcpy(xy, at, 16);
  if (swap) xy[0] = swap_bytes(xy[0]), xy[1] = swap_bytes(xy[1]);
  return {std::bit_cast<double>(xy[0]), std::bit_cast<double>(xy[1])};
}

/// Ordinate k (0: x) of the point whose ordinates start at `at`.
inline double ordinate_at(const std::byte* at, std::size_t k, bool swap) {
  std::uint64_t bits;
  std::memcpy(&bits, at + 8 * k, 8);
  return std::bit_cast<double>(swap ? swap_bytes(bits) : bits);
}

/// The points of one ring, as the cursor found them.
struct RingBytes {
  std::size_t offset;  ///< of the ring's point count, for errors about the whole ring
  const std::byte* points;
  std::uint32_t count;
  std::size_t stride;  ///< bytes a point: 16, 24 or 32
  bool swap;
  bool z, m;  ///< which ordinates follow x and y (z first)
};

/// A geometry header: byte order, type (with its ordinates) and an EWKB SRID (0 if none).
struct Header {
  std::uint32_t base_type;
  std::uint32_t dimensions;
  bool z, m;
  std::uint32_t srid;
  std::uint32_t code;  ///< the type as written
  std::size_t type_offset;
};

[[noreturn]] void not_polygonal(const Header& header) {
  Cursor::fail(header.type_offset, "geometry type " + std::to_string(header.code) +
                                       " is not a Polygon (3) or MultiPolygon (6)");
}

Header read_header(Cursor& cursor) {
  cursor.read_byte_order();
  const std::size_t type_offset = cursor.offset();
  const std::uint32_t code = cursor.read_uint32("a geometry type");
  std::uint32_t iso = code & 0x0FFFFFFFu;
  bool has_z = (code & ewkb_z) != 0, has_m = (code & ewkb_m) != 0;
  if (iso >= 1000 && iso < 4000) {
    has_z = has_z || iso / 1000 == 1 || iso / 1000 == 3;
    has_m = has_m || iso / 1000 == 2 || iso / 1000 == 3;
    iso %= 1000;
  }
  const std::uint32_t srid = (code & ewkb_srid) ? cursor.read_uint32("an SRID") : 0;
  return {iso, 2u + (has_z ? 1u : 0u) + (has_m ? 1u : 0u), has_z, has_m, srid, code, type_offset};
}

/// A polygon's body (after its header): sink.ring for each ring, then sink.end_polygon unless
/// it has none.
template <class Sink>
void read_polygon_body(Cursor& cursor, const Header& header, Sink& sink) {
  const std::size_t count_offset = cursor.offset();
  const std::uint32_t rings = cursor.read_uint32("a ring count");
  if (rings > cursor.left() / 4)
    cursor.fail(count_offset, std::to_string(rings) + " rings cannot fit in the " +
                                  std::to_string(cursor.left()) + " bytes left");
  const std::size_t stride = 8 * std::size_t{header.dimensions};
  for (std::uint32_t r = 0; r < rings; ++r) {
    const std::size_t ring_offset = cursor.offset();
    const std::uint32_t points = cursor.read_uint32("a point count");
    const std::byte* at = cursor.take_points(points, stride);
    sink.ring(RingBytes{ring_offset, at, points, stride, cursor.swapped(), header.z, header.m});
  }
  if (rings > 0) sink.end_polygon();
}

template <class Sink>
void read_multipolygon_body(Cursor& cursor, Sink& sink) {
  const std::size_t count_offset = cursor.offset();
  const std::uint32_t parts = cursor.read_uint32("a polygon count");
  if (parts > cursor.left() / 9)  // a part is at least a header and a ring count
    cursor.fail(count_offset, std::to_string(parts) + " polygons cannot fit in the " +
                                  std::to_string(cursor.left()) + " bytes left");
  for (std::uint32_t p = 0; p < parts; ++p) {
    const std::size_t part_offset = cursor.offset();
    const Header part = read_header(cursor);
    if (part.base_type != wkb_polygon)
      cursor.fail(part_offset, "a MultiPolygon's part " + std::to_string(p) + " is not a Polygon");
    read_polygon_body(cursor, part, sink);
  }
}

/// The body of a geometry that is no polygon (a point, a line, several), passed over.
void skip_body(Cursor& cursor, const Header& header, int depth) {
  const std::size_t stride = 8 * std::size_t{header.dimensions};
  if (header.base_type == wkb_point) {
    cursor.take_points(1, stride);
    return;
  }
  const std::uint32_t count =
      cursor.read_uint32(header.base_type == wkb_linestring ? "a point count" : "a geometry count");
  if (header.base_type == wkb_linestring) {
    cursor.take_points(count, stride);
    return;
  }
  if (depth >= max_nesting) Cursor::fail(header.type_offset, "expected at most 64 nested parts");
  for (std::uint32_t k = 0; k < count; ++k) skip_body(cursor, read_header(cursor), depth + 1);
}

/// One geometry at the cursor: its polygons to the sink. What is no polygon is a Fault, or
/// skipped (named to the sink) when the sink says so.
template <class Sink>
void read_geometry(Cursor& cursor, Sink& sink, int depth) {
  const Header header = read_header(cursor);
  if (header.srid != 0) sink.srid(header.srid, header.type_offset);
  const std::uint32_t type = header.base_type;
  if (type == wkb_polygon) return read_polygon_body(cursor, header, sink);
  if (type == wkb_multipolygon) return read_multipolygon_body(cursor, sink);
  const bool other = type == wkb_point || type == wkb_linestring || type == wkb_multipoint ||
                     type == wkb_multilinestring;
  if (other && sink.skips()) {
    sink.skip(type, header.type_offset - 1);
    return skip_body(cursor, header, depth);
  }
  if (type != wkb_collection) not_polygonal(header);
  const std::size_t count_offset = cursor.offset();
  const std::uint32_t count = cursor.read_uint32("a geometry count");
  if (count != 0 && !sink.skips())
    cursor.fail(count_offset, "a GeometryCollection of " + std::to_string(count) +
                                  " geometries is not a Polygon or MultiPolygon");
  if (count != 0 && depth >= max_nesting)
    cursor.fail(count_offset, "expected at most 64 nested collections");
  for (std::uint32_t k = 0; k < count; ++k) read_geometry(cursor, sink, depth + 1);
}

/// One whole value: its polygons to the sink, a Fault for anything else or any byte left over.
template <class Sink>
void read_value(std::span<const std::byte> bytes, Sink& sink) {
  Cursor cursor(bytes);
  read_geometry(cursor, sink, 0);
  if (cursor.left() != 0)
    cursor.fail(cursor.offset(),
                std::to_string(cursor.left()) + " bytes follow the end of the geometry");
}

/// Rings as the value has them, into flat arrays.
struct ArraysSink {
  PolygonArrays& out;

  static bool skips() { return false; }
  static void skip(std::uint32_t, std::size_t) {}
  static void srid(std::uint32_t, std::size_t) {}

  void ring(const RingBytes& ring) {
    std::vector<double>& xy = out.coordinates;
    const std::byte* from = ring.points;
    for (std::uint32_t i = 0; i < ring.count; ++i, from += ring.stride) {
      const Point p = point_at(from, ring.swap);
      xy.push_back(p.x);
      xy.push_back(p.y);
    }
    if (out.keep_z) keep_z(ring);
    out.ring_offsets.push_back(static_cast<std::int64_t>(xy.size() / 2));
  }
  void keep_z(const RingBytes& ring) {
    const std::byte* from = ring.points;
    for (std::uint32_t i = 0; i < ring.count; ++i, from += ring.stride)
      out.z.push_back(ring.z ? ordinate_at(from, 2, ring.swap)
                             : std::numeric_limits<double>::quiet_NaN());
  }
  void end_polygon() {
    out.polygon_offsets.push_back(static_cast<std::int64_t>(out.ring_offsets.size() - 1));
  }
};

/// Rings as the text readers give them: finite points, closing point dropped, 3 points or more;
/// z and m kept in features mode.
struct PolygonsSink {
  ReadResult& out;
  const ReadOptions& options;
  detail::Mode mode;
  std::size_t feature_index = 0;
  Feature feature = {};

  bool skips() const { return mode == detail::Mode::features; }
  void skip(std::uint32_t type, std::size_t offset) {
    constexpr const char* names[] = {"", "Point",      "LineString",
                                     "", "MultiPoint", "MultiLineString"};
    out.skipped.push_back({feature_index, names[type], 0, 0, offset});
  }
  void srid(std::uint32_t srid, std::size_t offset) {
    detail::merge_srid(out, srid, [&](const std::string& why) { Cursor::fail(offset, why); });
  }

  void ring(const RingBytes& bytes) {
    Ring& ring = feature.polygon.emplace_back();
    ring.reserve(bytes.count);
    const std::byte* from = bytes.points;
    const bool extras = mode == detail::Mode::features;
    for (std::uint32_t i = 0; i < bytes.count; ++i, from += bytes.stride) {
      const Point p = point_at(from, bytes.swap);
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) not_finite(bytes, i, p);
      ring.push_back(p);
      if (extras && bytes.z) feature.z.push_back(ordinate_at(from, 2, bytes.swap));
      if (extras && bytes.m) feature.m.push_back(ordinate_at(from, bytes.z ? 3 : 2, bytes.swap));
    }
    if (ring.size() >= 2 && ring.front() == ring.back()) {
      ring.pop_back();
      if (!feature.z.empty()) feature.z.pop_back();
      if (!feature.m.empty()) feature.m.pop_back();
    }
    if (ring.size() < 3 && !options.keep_small_rings)
      Cursor::fail(bytes.offset,
                   "expected a ring of at least 3 points (besides a closing point) but found " +
                       std::to_string(ring.size()) + (ring.size() == 1 ? " point" : " points"));
  }
  void end_polygon() {
    feature.feature_index = feature_index;
    out.features.push_back(std::exchange(feature, {}));
  }

  /// Names the first ordinate of point i that is NaN or infinite, at its byte.
  [[noreturn]] static void not_finite(const RingBytes& bytes, std::uint32_t i, Point p) {
    const bool x_bad = !std::isfinite(p.x);
    const double bad = x_bad ? p.x : p.y;
    const char* found = std::isnan(bad) ? "NaN" : bad > 0 ? "infinity" : "-infinity";
    Cursor::fail(bytes.offset + 4 + i * bytes.stride + (x_bad ? 0 : 8),
                 std::string("expected a finite coordinate but found ") + found);
  }
};

/// The hex digit's value, or -1.
int hex_value(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

/// The bytes of the hex word at the scanner, which moves past it.
void decode_hex(detail::Scanner& s, std::vector<std::byte>& bytes) {
  bytes.clear();
  const std::string_view text = s.text();
  while (s.pos < text.size() && !is_space(text[s.pos])) {
    const int high = hex_value(text[s.pos]);
    if (high < 0) s.fail_expected(s.pos, "a hex digit");
    ++s.pos;
    const int low = hex_value(s.peek());
    if (low < 0) s.fail_expected(s.pos, "the second hex digit of a byte");
    ++s.pos;
    bytes.push_back(static_cast<std::byte>(high * 16 + low));
  }
}

/// A fault in bytes that have no lines: "NAME: byte N: reason".
ParseError binary_error(std::string_view name, const Fault& fault) {
  return ParseError(std::string(name), 0, 0, fault.byte,
                    "byte " + std::to_string(fault.byte) + ": " + fault.reason);
}

}  // namespace

ReadResult detail::read_wkb(std::span<const std::byte> wkb, std::string_view name,
                            const ReadOptions& options, Mode mode) {
  ReadResult result;
  PolygonsSink sink{result, options, mode};
  try {
    read_value(wkb, sink);
  } catch (const Fault& fault) {
    throw binary_error(name, fault);
  }
  return result;
}

std::vector<Polygon> read_wkb(std::span<const std::byte> wkb, std::string_view name,
                              const ReadOptions& options) {
  return detail::polygons_of(detail::read_wkb(wkb, name, options, detail::Mode::polygons));
}

void read_wkb(std::span<const std::byte> wkb, PolygonArrays& out, std::string_view name) {
  if (!wkb.empty()) {
    const std::size_t points = out.coordinates.size(), rings = out.ring_offsets.size(),
                      polygons = out.polygon_offsets.size();
    ArraysSink sink{out};
    try {
      read_value(wkb, sink);
    } catch (const Fault& fault) {
      out.coordinates.resize(points);
      out.ring_offsets.resize(rings);
      out.polygon_offsets.resize(polygons);
      if (out.keep_z) out.z.resize(points / 2);
      throw binary_error(name, fault);
    }
  }
  out.geometry_offsets.push_back(static_cast<std::int64_t>(out.polygon_offsets.size() - 1));
}

ReadResult detail::read_hex_wkb(std::string_view text, std::string_view name,
                                const ReadOptions& options, Mode mode) {
  detail::Scanner s(text, name);
  s.skip_space();
  if (s.at_end()) s.fail_expected(s.pos, "hex WKB");
  ReadResult result;
  std::vector<std::byte> bytes;
  for (std::size_t value = 1; !s.at_end(); ++value) {
    const std::size_t start = s.pos;
    decode_hex(s, bytes);
    const std::size_t skipped_before = result.skipped.size();
    PolygonsSink sink{result, options, mode, value - 1};
    try {
      read_value(bytes, sink);
    } catch (const Fault& fault) {
      s.fail(start + 2 * fault.byte, "value " + std::to_string(value) + ", byte " +
                                         std::to_string(fault.byte) + ": " + fault.reason);
    }
    for (std::size_t k = skipped_before; k < result.skipped.size(); ++k) {
      SkippedGeometry& skipped = result.skipped[k];  // at its hex digits in the text
      skipped.offset = start + 2 * skipped.offset;
      const detail::Location where = s.location(skipped.offset);
      skipped.line = where.line, skipped.column = where.column;
    }
    s.skip_space();
  }
  return result;
}

std::vector<Polygon> read_hex_wkb(std::string_view text, std::string_view name,
                                  const ReadOptions& options) {
  return detail::polygons_of(detail::read_hex_wkb(text, name, options, detail::Mode::polygons));
}

}  // namespace pear::io
