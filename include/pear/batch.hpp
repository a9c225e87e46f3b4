// pear: many polygons in one call, in parallel over the polygons.
//
//   pear::PolygonBatch batch{coordinates, ring_offsets, polygon_offsets};   // GeoArrow layout
//   pear::BatchTriangulation<> result = pear::triangulate_batch(batch);
//   for (std::size_t p = 0; p < result.size(); ++p)
//     if (result.status[p] == pear::Status::ok)
//       for (auto t = result.triangle_offsets[p]; t < result.triangle_offsets[p + 1]; ++t)
//         use(result.triangles[t]);        // indices into the batch's points
//
// Each polygon is triangulated as pear::triangulate would do it with the same Options, by
// one engine per worker of pear's scheduler; for fixed Options::partitions the result is the
// same for any thread count and schedule (polygon order, then each polygon's own deterministic
// output). Left at 0, partitions is the thread count, which decides how polygons of 20,000
// vertices or more are cut, as for pear::triangulate.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <ranges>
#include <span>
#include <type_traits>
#include <vector>

#include "pear/export.hpp"
#include "pear/geometry.hpp"
#include "pear/options.hpp"

namespace pear {

/// Many polygons as flat arrays, the layout of GeoArrow and of shapely 2's `to_ragged_array`:
/// point i is (coordinates[2i], coordinates[2i+1]); ring r is points [ring_offsets[r],
/// ring_offsets[r+1]); polygon p is rings [polygon_offsets[p], polygon_offsets[p+1]), the
/// first of them its outer ring. Offsets are into the whole batch (they need not start at 0).
struct PolygonBatch {
  std::span<const double> coordinates;
  std::span<const std::int64_t> ring_offsets;     ///< one more entry than there are rings
  std::span<const std::int64_t> polygon_offsets;  ///< one more entry than there are polygons
};

/// The triangulations of a batch, polygon after polygon, as flat arrays. Index is the type of
/// the triangles' indices (uint16_t for a GPU's small index buffers, say).
template <class Index = std::uint32_t>
struct BatchTriangulation {
  /// Counterclockwise triples of indices into the batch's points.
  std::vector<std::array<Index, 3>> triangles;
  /// Polygon p's triangles are [triangle_offsets[p], triangle_offsets[p + 1]).
  std::vector<std::int64_t> triangle_offsets;
  /// Each polygon's status, as pear::triangulate would give it (Status::ok: a valid
  /// triangulation). A polygon whose offsets are out of order or range is invalid_input with
  /// Issue::invalid_offsets; one with a point index that Index cannot hold is index_overflow
  /// (and has no triangles).
  std::vector<Status> status;
  /// Polygon p's diagnostics are [diagnostic_offsets[p], diagnostic_offsets[p + 1]); their
  /// `ring` counts within the polygon (0 = its outer ring), their `vertex` within that ring.
  std::vector<Diagnostic> diagnostics;
  std::vector<std::int64_t> diagnostic_offsets;
  /// CDT flips summed over the polygons (Options::delaunay).
  std::size_t delaunay_flips = 0;

  std::size_t size() const { return status.size(); }
};

/// triangulate_batch for an index type whose largest value is `max_index` (at most
/// 2^32 - 1): a polygon with a point index above it is Status::index_overflow and has no
/// triangles. The template below calls it; the triangles come as uint32_t either way.
PEAR_API BatchTriangulation<std::uint32_t> triangulate_batch(const PolygonBatch& batch,
                                                             const Options& options,
                                                             std::uint64_t max_index);

/// Triangulates every polygon of the batch with `options`: Options::threads (or ::executor)
/// says where the polygons run in parallel; the rest applies to each polygon as to one.
/// Options::profile, when set, gets one phase whose tasks are the polygons (each one's time).
/// Never throws for bad geometry or offsets (a status per polygon says what was wrong);
/// std::bad_alloc can escape when memory runs out.
template <class Index = std::uint32_t>
BatchTriangulation<Index> triangulate_batch(const PolygonBatch& batch,
                                            const Options& options = {}) {
  static_assert(std::is_unsigned_v<Index>, "indices are unsigned");
  constexpr auto max_index = std::min<std::uint64_t>(std::numeric_limits<Index>::max(),
                                                     std::numeric_limits<std::uint32_t>::max());
  BatchTriangulation<std::uint32_t> wide = triangulate_batch(batch, options, max_index);
  if constexpr (std::is_same_v<Index, std::uint32_t>) {
    return wide;
  } else {
    BatchTriangulation<Index> narrow;
    narrow.triangles.resize(wide.triangles.size());
    for (std::size_t t = 0; t < wide.triangles.size(); ++t)
      for (std::size_t k = 0; k < 3; ++k)
        narrow.triangles[t][k] = static_cast<Index>(wide.triangles[t][k]);
    narrow.triangle_offsets = std::move(wide.triangle_offsets);
    narrow.status = std::move(wide.status);
    narrow.diagnostics = std::move(wide.diagnostics);
    narrow.diagnostic_offsets = std::move(wide.diagnostic_offsets);
    narrow.delaunay_flips = wide.delaunay_flips;
    return narrow;
  }
}

/// A range of polygons, each a range of rings (as pear::triangulate takes one), flattened into
/// a batch: indices then number the points polygon after polygon, ring after ring.
template <class Index = std::uint32_t, class Polygons>
requires std::ranges::forward_range<Polygons> &&
    ring_range<std::remove_cvref_t<std::ranges::range_reference_t<Polygons>>>
        BatchTriangulation<Index> triangulate_batch(const Polygons& polygons,
                                                    const Options& options = {}) {
  std::vector<double> coordinates;
  std::vector<std::int64_t> ring_offsets{0}, polygon_offsets{0};
  for (const auto& polygon : polygons) {
    for (const auto& ring : polygon) {
      for (const auto& p : ring) {
        using P = std::remove_cvref_t<decltype(p)>;
        coordinates.push_back(point_traits<P>::x(p));
        coordinates.push_back(point_traits<P>::y(p));
      }
      ring_offsets.push_back(static_cast<std::int64_t>(coordinates.size() / 2));
    }
    polygon_offsets.push_back(static_cast<std::int64_t>(ring_offsets.size() - 1));
  }
  return triangulate_batch<Index>(PolygonBatch{coordinates, ring_offsets, polygon_offsets},
                                  options);
}

}  // namespace pear
