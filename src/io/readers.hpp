// The readers' two modes: the Polygon API (strict: a geometry that is no polygon is an error;
// no side data kept) and read_features (z, m, properties, skipped geometries, SRID).
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "pear/io.hpp"

namespace pear::io::detail {

enum class Mode { polygons, features };

ReadResult read_geojson(std::string_view text, std::string_view name, const ReadOptions& options,
                        Mode mode);
ReadResult read_wkt(std::string_view text, std::string_view name, const ReadOptions& options,
                    Mode mode);
ReadResult read_wkb(std::span<const std::byte> wkb, std::string_view name,
                    const ReadOptions& options, Mode mode);
ReadResult read_hex_wkb(std::string_view text, std::string_view name, const ReadOptions& options,
                        Mode mode);

/// The polygons alone, in order.
std::vector<Polygon> polygons_of(ReadResult&& result);

/// Keeps the SRID of a text's geometries: the first one given; another one later is an error
/// (`fail` is called with the message).
template <class Fail>
void merge_srid(ReadResult& result, std::uint32_t srid, Fail fail) {
  if (srid == 0 || srid == result.srid) return;
  if (result.srid != 0)
    fail("expected every geometry's SRID to be " + std::to_string(result.srid) +
         " as the first one's but found " + std::to_string(srid));
  result.srid = srid;
}

}  // namespace pear::io::detail
