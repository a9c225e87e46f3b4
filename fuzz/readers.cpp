// Fuzz target "readers": pear::io's GeoJSON, WKT and .poly readers on arbitrary bytes (with the
// dictionary readers.dict). Each read either throws ParseError with a position inside the text,
// or returns polygons that survive a round trip: written in the same format and read back, they
// are bit-identical (GeoJSON, WKT), or hold the same points (.poly, whose reader regroups rings
// by nesting); read_features gives the same polygons with z and m one per vertex. Any other
// exception escapes and is a crash.
#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "pear/io.hpp"
#include "support.hpp"

namespace {

using pear::io::Format;

std::vector<std::uint64_t> coordinate_bits(const std::vector<pear::Polygon>& polygons) {
  std::vector<std::uint64_t> bits;
  for (const pear::Polygon& polygon : polygons)
    for (const pear::Ring& ring : polygon)
      for (const pear::Point& p : ring) {
        bits.push_back(std::bit_cast<std::uint64_t>(p.x));
        bits.push_back(std::bit_cast<std::uint64_t>(p.y));
      }
  return bits;
}

/// Ring sizes in order, then every coordinate's bits: equal means bit-identical polygons.
std::vector<std::uint64_t> fingerprint(const std::vector<pear::Polygon>& polygons) {
  std::vector<std::uint64_t> print;
  for (const pear::Polygon& polygon : polygons) {
    print.push_back(~std::uint64_t{0});
    for (const pear::Ring& ring : polygon) print.push_back(ring.size());
  }
  const std::vector<std::uint64_t> bits = coordinate_bits(polygons);
  print.insert(print.end(), bits.begin(), bits.end());
  return print;
}

/// The points' pairs of coordinate bits, sorted: what a .poly round trip keeps.
std::vector<std::uint64_t> point_multiset(const std::vector<pear::Polygon>& polygons) {
  const std::vector<std::uint64_t> bits = coordinate_bits(polygons);
  std::vector<std::pair<std::uint64_t, std::uint64_t>> points;
  for (std::size_t i = 0; i + 1 < bits.size(); i += 2) points.emplace_back(bits[i], bits[i + 1]);
  std::sort(points.begin(), points.end());
  std::vector<std::uint64_t> flat;
  for (const auto& [x, y] : points) flat.insert(flat.end(), {x, y});
  return flat;
}

std::string write(const std::vector<pear::Polygon>& polygons, Format format) {
  std::ostringstream out;
  if (format == Format::geojson) pear::io::write_geojson_polygons(out, polygons);
  if (format == Format::wkt) pear::io::write_wkt(out, polygons);
  if (format == Format::poly) pear::io::write_poly(out, polygons);
  return out.str();
}

void check_round_trip(const std::vector<pear::Polygon>& polygons, Format format,
                      const pear::io::ReadOptions& options) {
  std::string text;
  try {
    text = write(polygons, format);
  } catch (const std::invalid_argument&) {  // documented: .poly cannot mark a zero-area hole
    return;
  }
  std::vector<pear::Polygon> again;
  try {
    again = pear::io::read_text(text, format, "round trip", options);
  } catch (const pear::io::ParseError& error) {
    // A .poly file of rings that cross or touch need not nest; GeoJSON and WKT must read back.
    if (format == Format::poly) return;
    fuzz::fail("written polygons do not read back", std::string(error.what()) + "\n" + text);
  }
  if (format == Format::poly)
    fuzz::require(point_multiset(again) == point_multiset(polygons),
                  ".poly round trip changed the points", text);
  else
    fuzz::require(fingerprint(again) == fingerprint(polygons), "round trip changed the polygons",
                  text);
}

/// read_features on the same text: the same polygons where the strict read found no other
/// geometry, z and m one per vertex or none.
void check_features(std::string_view text, Format format, const pear::io::ReadOptions& options,
                    const std::vector<pear::Polygon>& polygons) {
  pear::io::ReadResult result;
  try {
    result = pear::io::read_features(text, format, "fuzz", options);
  } catch (const pear::io::ParseError& error) {  // partial z, a second SRID: documented
    fuzz::require(error.line() >= 1 && error.offset() <= text.size(),
                  "ParseError points outside the text", error.what());
    return;
  }
  std::vector<pear::Polygon> again;
  for (const pear::io::Feature& feature : result.features) {
    std::size_t vertices = 0;
    for (const pear::Ring& ring : feature.polygon) vertices += ring.size();
    fuzz::require(feature.z.empty() || feature.z.size() == vertices, "z not one per vertex", "");
    fuzz::require(feature.m.empty() || feature.m.size() == vertices, "m not one per vertex", "");
    again.push_back(feature.polygon);
  }
  fuzz::require(fingerprint(again) == fingerprint(polygons),
                "read_features and read_text give other polygons", std::string(text));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteReader bytes(data, size);
  const std::uint8_t header = bytes.byte();
  const Format format = static_cast<Format>(header % 3);
  pear::io::ReadOptions options;
  options.keep_small_rings = header & 4;
  const std::string_view text = bytes.rest();
  std::vector<pear::Polygon> polygons;
  try {
    polygons = pear::io::read_text(text, format, "fuzz", options);
  } catch (const pear::io::ParseError& error) {
    fuzz::require(error.line() >= 1 && error.offset() <= text.size(),
                  "ParseError points outside the text", error.what());
    return 0;
  }
  check_features(text, format, options, polygons);
  check_round_trip(polygons, format, options);
  return 0;
}
