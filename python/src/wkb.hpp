// WKB (well-known binary) polygons in, triangles as WKB polygons out: what shapely 1.8's `.wkb`,
// geopandas' `to_wkb()` and PostGIS hand over, for pear.triangulate_many and pear.geopandas.
// Plain C++ (no Python): the module calls it with the GIL released.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace pear::python {

/// A WKB value that cannot be read: which geometry of the input, at which byte, and why.
class WkbError : public std::runtime_error {
 public:
  WkbError(std::size_t geometry, std::size_t offset, const std::string& reason);
  std::size_t geometry;  ///< index of the geometry in the caller's sequence
  std::size_t offset;    ///< byte offset of the problem in that geometry's WKB
};

/// Polygons read from WKB, flat, as pear::PolygonBatch and shapely 2's to_ragged_array lay them
/// out: every ring's points including its closing point, so that point i of a geometry is the
/// i-th coordinate shapely lists for it. Geometry g is polygons [geometry_offsets[g],
/// geometry_offsets[g+1]): one for a Polygon, one per non-empty part for a MultiPolygon, none
/// for an empty one or a missing one.
struct FlatPolygons {
  std::vector<double> coordinates;  ///< x0, y0, x1, y1, ...
  std::vector<std::int64_t> ring_offsets{0};
  std::vector<std::int64_t> polygon_offsets{0};
  std::vector<std::int64_t> geometry_offsets{0};
};

/// Appends geometry number `geometry` (for error messages), a Polygon or MultiPolygon in ISO WKB
/// or PostGIS' EWKB, either byte order, with Z, M or ZM ordinates (dropped) and an optional
/// SRID (ignored). An empty span is a missing geometry and an empty GeometryCollection (GEOS'
/// empty Polygon) an empty one: no polygons. Throws WkbError for any
/// other type, a truncated or over-long value, or counts that do not fit the bytes.
void read_wkb(std::span<const std::byte> wkb, std::size_t geometry, FlatPolygons& out);

/// Bytes of one triangle as a WKB Polygon.
inline constexpr std::size_t triangle_wkb_size = 1 + 4 + 4 + 4 + 4 * 16;

/// Every triangle (indices into the points of `coordinates`) as a little-endian WKB Polygon of
/// one closed ring, back to back: triangle t is bytes [t * triangle_wkb_size, (t+1) * ...).
/// The indices must be in range (the caller checks).
std::string triangles_to_wkb(std::span<const double> coordinates,
                             std::span<const std::array<std::uint32_t, 3>> triangles);

}  // namespace pear::python
