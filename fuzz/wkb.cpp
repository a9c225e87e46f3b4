// Fuzz target "wkb" (issue 30): pear::io's WKB reader, the flat form pear.triangulate_many uses,
// on arbitrary bytes: truncated values, counts the bytes cannot hold, wrong byte orders and
// types. Values are read one after the other into one PolygonArrays, as pear.triangulate_many
// reads a sequence, until the first ParseError. An error must name a byte inside the value and
// leave the arrays as they were; a value read must leave the flat arrays consistent (offsets
// monotone, each ending where the next array ends, no point without its 16 bytes), and its
// polygons, written again as WKB by this target (either byte order, with a Z ordinate or not,
// EWKB with an SRID or ISO), must read back bit for bit.
//
// Bytes: a header (values = 1 + header % 4; bit 2: big endian, bit 3: Z, bit 4: EWKB with an
// SRID for the rewrite), a little-endian 16-bit length for each value but the last, then the
// values; the last takes the rest.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "pear/io.hpp"
#include "support.hpp"

namespace {

using FlatPolygons = pear::io::PolygonArrays;

/// WKB bytes in a chosen byte order (the target's own writer, independent of the reader).
class Writer {
 public:
  explicit Writer(bool big_endian) : big_(big_endian) {}
  void order() { out_.push_back(static_cast<std::byte>(big_ ? 0 : 1)); }
  void u32(std::uint32_t value) { put(swap() ? __builtin_bswap32(value) : value); }
  void f64(double value) {
    const auto bits = std::bit_cast<std::uint64_t>(value);
    put(swap() ? __builtin_bswap64(bits) : bits);
  }
  std::span<const std::byte> bytes() const { return out_; }

 private:
  bool swap() const { return big_ != (std::endian::native == std::endian::big); }
  template <class T>
  void put(T value) {
    const auto* at = reinterpret_cast<const std::byte*>(&value);
    out_.insert(out_.end(), at, at + sizeof value);
  }
  bool big_;
  std::vector<std::byte> out_;
};

struct Rewrite {
  bool big_endian, z, ewkb;
};

void write_header(Writer& w, std::uint32_t type, const Rewrite& how) {
  w.order();
  if (how.ewkb) {
    w.u32(type | (how.z ? 0x80000000u : 0) | 0x20000000u);
    w.u32(4326);  // the SRID, skipped by the reader
  } else {
    w.u32(type + (how.z ? 1000 : 0));
  }
}

/// Polygons [p0, p1) of `flat` as one WKB value: a Polygon for one, else a MultiPolygon.
std::vector<std::byte> write_polygons(const FlatPolygons& flat, std::size_t p0, std::size_t p1,
                                      const Rewrite& how) {
  Writer w(how.big_endian);
  if (p1 - p0 != 1) {
    write_header(w, 6, how);
    w.u32(static_cast<std::uint32_t>(p1 - p0));
  }
  for (std::size_t p = p0; p < p1; ++p) {
    write_header(w, 3, how);
    const std::int64_t r0 = flat.polygon_offsets[p], r1 = flat.polygon_offsets[p + 1];
    w.u32(static_cast<std::uint32_t>(r1 - r0));
    for (std::int64_t r = r0; r < r1; ++r) {
      w.u32(static_cast<std::uint32_t>(flat.ring_offsets[r + 1] - flat.ring_offsets[r]));
      for (std::int64_t i = flat.ring_offsets[r]; i < flat.ring_offsets[r + 1]; ++i) {
        w.f64(flat.coordinates[2 * i]);
        w.f64(flat.coordinates[2 * i + 1]);
        if (how.z) w.f64(-1.5);  // dropped by the reader
      }
    }
  }
  return {w.bytes().begin(), w.bytes().end()};
}

/// The arrays after value g: geometry g's polygon range, each polygon with rings, monotone
/// offsets, every array ending where the next begins.
void check_consistent(const FlatPolygons& flat, std::size_t g, std::size_t points_before,
                      std::size_t value_size) {
  const std::string where = "value " + std::to_string(g);
  fuzz::require(flat.geometry_offsets.size() == g + 2, "not one geometry offset per value", where);
  fuzz::require(flat.geometry_offsets.back() == std::int64_t(flat.polygon_offsets.size() - 1) &&
                    flat.polygon_offsets.back() == std::int64_t(flat.ring_offsets.size() - 1) &&
                    2 * flat.ring_offsets.back() == std::int64_t(flat.coordinates.size()),
                "an offset array does not end at the next array's size", where);
  for (const auto* offsets : {&flat.geometry_offsets, &flat.polygon_offsets, &flat.ring_offsets})
    for (std::size_t i = 1; i < offsets->size(); ++i)
      fuzz::require((*offsets)[i - 1] <= (*offsets)[i], "offsets not monotone", where);
  for (std::size_t p = 1; p < flat.polygon_offsets.size(); ++p)
    fuzz::require(flat.polygon_offsets[p - 1] < flat.polygon_offsets[p], "a polygon without rings",
                  where);
  const std::size_t points = flat.coordinates.size() / 2 - points_before;
  fuzz::require(16 * points <= value_size, "more points than the value has bytes for", where);
}

/// Equal arrays, coordinates compared bit for bit (NaN included).
bool same_arrays(const FlatPolygons& a, const FlatPolygons& b) {
  return a.coordinates.size() == b.coordinates.size() &&
         (a.coordinates.empty() ||
          std::memcmp(a.coordinates.data(), b.coordinates.data(), 8 * a.coordinates.size()) == 0) &&
         a.ring_offsets == b.ring_offsets && a.polygon_offsets == b.polygon_offsets &&
         a.geometry_offsets == b.geometry_offsets;
}

/// Geometry g's polygons written again and read back: the same rings and coordinate bits.
void check_round_trip(const FlatPolygons& flat, std::size_t g, const Rewrite& how) {
  const auto p0 = static_cast<std::size_t>(flat.geometry_offsets[g]);
  const auto p1 = static_cast<std::size_t>(flat.geometry_offsets[g + 1]);
  const std::vector<std::byte> bytes = write_polygons(flat, p0, p1, how);
  FlatPolygons again;
  try {
    pear::io::read_wkb(bytes, again);
  } catch (const pear::io::ParseError& error) {
    fuzz::fail("written polygons do not read back", error.what());
  }
  const std::int64_t r0 = flat.polygon_offsets[p0], first = flat.ring_offsets[r0];
  fuzz::require(again.polygon_offsets.size() == p1 - p0 + 1, "polygon count changed");
  for (std::size_t p = 0; p < again.polygon_offsets.size(); ++p)
    fuzz::require(again.polygon_offsets[p] == flat.polygon_offsets[p0 + p] - r0,
                  "rings changed polygon");
  for (std::size_t r = 0; r < again.ring_offsets.size(); ++r)
    fuzz::require(again.ring_offsets[r] == flat.ring_offsets[r0 + r] - first,
                  "points changed ring");
  const std::size_t count = again.coordinates.size();
  fuzz::require(count == 0 || std::memcmp(again.coordinates.data(),
                                          flat.coordinates.data() + 2 * first, 8 * count) == 0,
                "coordinates changed in a round trip");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteReader bytes(data, size);
  const std::uint8_t header = bytes.byte();
  const std::size_t values = 1 + header % 4;
  std::vector<std::size_t> lengths;
  for (std::size_t g = 0; g + 1 < values; ++g) lengths.push_back(bytes.u16());
  const std::string_view rest = bytes.rest();
  const Rewrite how{(header & 4) != 0, (header & 8) != 0, (header & 16) != 0};

  FlatPolygons flat;
  std::size_t at = 0;
  for (std::size_t g = 0; g < values; ++g) {
    const std::size_t length =
        g + 1 < values ? std::min(lengths[g], rest.size() - at) : rest.size() - at;
    const auto value = std::as_bytes(std::span(rest.data() + at, length));
    at += length;
    const std::size_t points_before = flat.coordinates.size() / 2;
    const FlatPolygons before = flat;
    try {
      pear::io::read_wkb(value, flat);
    } catch (const pear::io::ParseError& error) {
      fuzz::require(error.offset() <= length &&
                        error.detail().starts_with("byte " + std::to_string(error.offset()) + ": "),
                    "a ParseError names a byte outside the value, or none", error.what());
      fuzz::require(same_arrays(flat, before), "a ParseError left part of the value in the arrays",
                    error.what());
      return 0;  // as pear.triangulate_many: the first error ends the read
    }
    check_consistent(flat, g, points_before, length);
    check_round_trip(flat, g, how);
  }
  return 0;
}
