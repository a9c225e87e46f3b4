// WKB reading (ISO and EWKB Polygon/MultiPolygon) and writing (triangles as Polygons).
#include "wkb.hpp"

#include <bit>
#include <cstring>
#include <string_view>

namespace pear::python {

WkbError::WkbError(std::size_t geometry_index, std::size_t byte_offset, const std::string& reason)
    : std::runtime_error("geometry " + std::to_string(geometry_index) + ", byte " +
                         std::to_string(byte_offset) + ": " + reason),
      geometry(geometry_index),
      offset(byte_offset) {}

namespace {

// Type codes: ISO adds 1000 (Z), 2000 (M), 3000 (ZM); EWKB sets these flag bits instead.
constexpr std::uint32_t wkb_polygon = 3;
constexpr std::uint32_t wkb_multipolygon = 6;
constexpr std::uint32_t wkb_collection = 7;  // only empty: shapely 1.8's empty Polygon
constexpr std::uint32_t ewkb_z = 0x80000000u;
constexpr std::uint32_t ewkb_m = 0x40000000u;
constexpr std::uint32_t ewkb_srid = 0x20000000u;

/// A cursor over one geometry's bytes that knows its byte order and throws where it runs out.
class Reader {
 public:
  Reader(std::span<const std::byte> bytes, std::size_t geometry)
      : bytes_(bytes), geometry_(geometry) {}

  std::size_t offset() const { return offset_; }
  std::size_t left() const { return bytes_.size() - offset_; }
  [[noreturn]] void fail(std::size_t at, const std::string& reason) const {
    throw WkbError(geometry_, at, reason);
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
    return swap_ ? __builtin_bswap32(value) : value;
  }

  /// `count` points of `dimensions` doubles each, the first two appended to `out`.
  void read_points(std::uint32_t count, std::uint32_t dimensions, std::vector<double>& out) {
    const std::size_t stride = 8 * std::size_t{dimensions};
    if (std::size_t{count} > left() / stride)
      fail(offset_, "a ring of " + std::to_string(count) + " points needs " +
                        std::to_string(std::size_t{count} * stride) + " bytes, " +
                        std::to_string(left()) + " are left");
    const std::byte* at = bytes_.data() + offset_;
    for (std::uint32_t i = 0; i < count; ++i, at += stride) {
      std::uint64_t xy[2];
      std::memcpy(xy, at, 16);
      if (swap_) xy[0] = __builtin_bswap64(xy[0]), xy[1] = __builtin_bswap64(xy[1]);
      out.push_back(std::bit_cast<double>(xy[0]));
      out.push_back(std::bit_cast<double>(xy[1]));
    }
    offset_ += std::size_t{count} * stride;
  }

 private:
  void need(std::size_t size, const char* what) const {
    if (left() < size)
      fail(offset_, std::string("expected ") + what + " but the value ends (" +
                        std::to_string(bytes_.size()) + " bytes)");
  }

  std::span<const std::byte> bytes_;
  std::size_t geometry_;
  std::size_t offset_ = 0;
  bool swap_ = false;
};

/// A geometry header: byte order, type (with its ordinates) and an EWKB SRID, which is skipped.
struct Header {
  std::uint32_t base_type;
  std::uint32_t dimensions;
};

Header read_header(Reader& reader) {
  reader.read_byte_order();
  const std::size_t type_offset = reader.offset();
  const std::uint32_t code = reader.read_uint32("a geometry type");
  std::uint32_t iso = code & 0x0FFFFFFFu;
  bool has_z = (code & ewkb_z) != 0, has_m = (code & ewkb_m) != 0;
  if (iso >= 1000 && iso < 4000) {
    has_z = has_z || iso / 1000 == 1 || iso / 1000 == 3;
    has_m = has_m || iso / 1000 == 2 || iso / 1000 == 3;
    iso %= 1000;
  }
  if (code & ewkb_srid) reader.read_uint32("an SRID");
  if (iso != wkb_polygon && iso != wkb_multipolygon && iso != wkb_collection)
    reader.fail(type_offset, "geometry type " + std::to_string(code) +
                                 " is not a Polygon (3) or MultiPolygon (6)");
  return {iso, 2u + (has_z ? 1u : 0u) + (has_m ? 1u : 0u)};
}

/// A polygon's body (after its header); appended as a polygon unless it has no rings.
void read_polygon_body(Reader& reader, std::uint32_t dimensions, FlatPolygons& out) {
  const std::size_t count_offset = reader.offset();
  const std::uint32_t rings = reader.read_uint32("a ring count");
  if (rings > reader.left() / 4)
    reader.fail(count_offset, std::to_string(rings) + " rings cannot fit in the " +
                                  std::to_string(reader.left()) + " bytes left");
  for (std::uint32_t r = 0; r < rings; ++r) {
    const std::uint32_t points = reader.read_uint32("a point count");
    reader.read_points(points, dimensions, out.coordinates);
    out.ring_offsets.push_back(static_cast<std::int64_t>(out.coordinates.size() / 2));
  }
  if (rings > 0)
    out.polygon_offsets.push_back(static_cast<std::int64_t>(out.ring_offsets.size() - 1));
}

}  // namespace

void read_wkb(std::span<const std::byte> wkb, std::size_t geometry, FlatPolygons& out) {
  if (!wkb.empty()) {
    Reader reader(wkb, geometry);
    const Header header = read_header(reader);
    if (header.base_type == wkb_polygon) {
      read_polygon_body(reader, header.dimensions, out);
    } else if (header.base_type == wkb_collection) {
      const std::size_t count_offset = reader.offset();
      if (const std::uint32_t count = reader.read_uint32("a geometry count"); count != 0)
        reader.fail(count_offset, "a GeometryCollection of " + std::to_string(count) +
                                      " geometries is not a Polygon or MultiPolygon");
    } else {
      const std::size_t count_offset = reader.offset();
      const std::uint32_t parts = reader.read_uint32("a polygon count");
      if (parts > reader.left() / 9)  // a part is at least a header and a ring count
        reader.fail(count_offset, std::to_string(parts) + " polygons cannot fit in the " +
                                      std::to_string(reader.left()) + " bytes left");
      for (std::uint32_t p = 0; p < parts; ++p) {
        const std::size_t part_offset = reader.offset();
        const Header part = read_header(reader);
        if (part.base_type != wkb_polygon)
          reader.fail(part_offset,
                      "a MultiPolygon's part " + std::to_string(p) + " is not a Polygon");
        read_polygon_body(reader, part.dimensions, out);
      }
    }
    if (reader.left() != 0)
      reader.fail(reader.offset(),
                  std::to_string(reader.left()) + " bytes follow the end of the geometry");
  }
  out.geometry_offsets.push_back(static_cast<std::int64_t>(out.polygon_offsets.size() - 1));
}

namespace {
void put_uint32(char*& at, std::uint32_t value) {
  if constexpr (std::endian::native == std::endian::big) value = __builtin_bswap32(value);
  std::memcpy(at, &value, 4);
  at += 4;
}
void put_double(char*& at, double value) {
  auto bits = std::bit_cast<std::uint64_t>(value);
  if constexpr (std::endian::native == std::endian::big) bits = __builtin_bswap64(bits);
  std::memcpy(at, &bits, 8);
  at += 8;
}
}  // namespace

std::string triangles_to_wkb(std::span<const double> coordinates,
                             std::span<const std::array<std::uint32_t, 3>> triangles) {
  std::string out(triangles.size() * triangle_wkb_size, '\0');
  char* at = out.data();
  for (const auto& t : triangles) {
    *at++ = 1;  // little endian
    put_uint32(at, wkb_polygon);
    put_uint32(at, 1);  // one ring
    put_uint32(at, 4);  // closed: the first corner again
    for (int k = 0; k < 4; ++k) {
      const std::size_t i = t[k % 3];
      put_double(at, coordinates[2 * i]);
      put_double(at, coordinates[2 * i + 1]);
    }
  }
  return out;
}

}  // namespace pear::python
