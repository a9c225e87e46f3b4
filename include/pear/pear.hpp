// pear: Parallel EAR clipping. The umbrella header and the triangulation entry points.
//
//   std::vector<std::vector<pear::Point>> polygon = {outer, hole1, hole2};
//   auto result = pear::triangulate(polygon);           // index type uint32_t by default
//   if (result.status == pear::Status::ok) use(result.triangles);
//
// Pre-conditions: none beyond "a range of rings"; every input is accepted and answered with a
// status. Post-conditions for Status::ok: result.triangles is a triangulation of the polygon
// (outer ring minus holes) using only input vertices, numbered ring after ring in input order
// (ring 0's first point is 0), counterclockwise, with n + 2h - 2 - 2m triangles where n counts the
// vertices left after dropping repeated consecutive points, the closing point and zero-width
// spikes, plus one for every vertex lying inside an edge (the edge is split there), h the holes
// kept, and m the vertices that repeat an already used point (holes or rings touching at a
// vertex, every split). Exact wherever no ring passes a point twice. See README.md
// "Pre- and post-conditions" for the full contract.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

#include "pear/detail/flat_polygon.hpp"
#include "pear/export.hpp"
#include "pear/geometry.hpp"
#include "pear/options.hpp"

namespace pear {

/// What the constrained Delaunay conversion did (Options::delaunay).
struct DelaunayStatistics {
  std::size_t edges = 0;                ///< interior edges that are not constraints
  std::size_t flips = 0;                ///< all flips
  std::size_t flips_in_partitions = 0;  ///< flips done by the parallel tasks
  std::size_t flips_on_borders = 0;     ///< flips in the fix-up across partition borders
};

/// Ear statistics of a polygon's (bridged) boundary before clipping: the paper's Fig. 7 numbers.
struct EarStatistics {
  std::size_t vertices = 0;  ///< boundary nodes after cleaning and bridging
  std::size_t convex = 0;
  std::size_t reflex = 0;  ///< reflex or collinear
  std::size_t ears = 0;
};

template <class Index = std::uint32_t>
struct Triangulation {
  std::vector<std::array<Index, 3>> triangles;
  Status status = Status::ok;
  std::vector<Diagnostic> diagnostics;
  DelaunayStatistics delaunay;  ///< filled when Options::delaunay was set
};

/// One polygon as flat arrays, the layout of GeoArrow and shapely's `to_ragged_array`: its
/// points ring after ring (outer first), ring r being points [ring_offsets[r], ring_offsets[r+1]).
/// So ring_offsets has one entry more than there are rings, starts at 0 and ends at
/// points.size(). Triangles and diagnostics index `points`.
struct PolygonView {
  std::span<const Point> points;
  std::span<const std::uint32_t> ring_offsets;
};

/// One polygon as interleaved coordinates: point i is (xy[2i], xy[2i+1]), the layout of a
/// numpy (N, 2) float64 array and of GeoArrow's interleaved coordinates; ring r is points
/// [ring_offsets[r], ring_offsets[r+1]), as in PolygonView. Read where it is, never copied into
/// points first. An odd xy.size() is Status::invalid_input (Issue::invalid_offsets).
struct CoordinateView {
  std::span<const double> xy;
  std::span<const std::uint32_t> ring_offsets;
};

namespace detail {
class Engine;
}  // namespace detail

/// A reusable triangulator: keeps its buffers between calls, so many small polygons cost no
/// allocation but their results. Not thread-safe; use one per thread (or triangulate_batch).
class PEAR_API Triangulator {
 public:
  Triangulator() noexcept;
  ~Triangulator();
  Triangulator(Triangulator&&) noexcept;
  Triangulator& operator=(Triangulator&&) noexcept;

  /// Triangulates a range of rings, outer first. Indices number the points ring after ring.
  template <class Index = std::uint32_t, ring_range Rings>
  Triangulation<Index> triangulate(const Rings& rings, const Options& options = {}) {
    Triangulation<Index> result;
    if (!engine_) acquire(detail::vertex_count(rings));
    detail::FlatPolygon& flat = input_buffer();
    bool counted;
    if constexpr (detail::point_array_rings<Rings>)
      counted = detail::ring_spans(rings, flat);
    else
      counted = detail::flatten(rings, flat);
    if (!counted) {
      result.status = Status::index_overflow;
      result.diagnostics.push_back({Issue::index_overflow, 0, 0});
      return result;
    }
    if constexpr (detail::point_array_rings<Rings>)
      into(detail::RingSpans{flat.rings, flat.ring_starts}, flat.ring_starts.back(), options,
           result);
    else
      triangulate_into(PolygonView{flat.points, flat.ring_starts}, options, result);
    return result;
  }

  /// Triangulates a polygon given as flat arrays (no copy of the points is made on the way).
  template <class Index = std::uint32_t>
  Triangulation<Index> triangulate(const PolygonView& polygon, const Options& options = {}) {
    Triangulation<Index> result;
    triangulate_into(polygon, options, result);
    return result;
  }

  /// Triangulates a polygon given as interleaved coordinates (read where they are).
  template <class Index = std::uint32_t>
  Triangulation<Index> triangulate(const CoordinateView& polygon, const Options& options = {}) {
    Triangulation<Index> result;
    triangulate_into(polygon, options, result);
    return result;
  }

  /// Triangulates into `result`, reusing its buffers: a loop over many small polygons then
  /// allocates nothing once they have grown. Its previous contents are replaced.
  template <class Index = std::uint32_t>
  void triangulate_into(const PolygonView& polygon, const Options& options,
                        Triangulation<Index>& result) {
    into(polygon, polygon.points.size(), options, result);
  }

  /// The same for a polygon as interleaved coordinates (numpy's (N, 2), GeoArrow's layout).
  template <class Index = std::uint32_t>
  void triangulate_into(const CoordinateView& polygon, const Options& options,
                        Triangulation<Index>& result) {
    into(polygon, polygon.xy.size() / 2, options, result);
  }

  /// Ear statistics of the cleaned, bridged boundary (no clipping is done).
  template <ring_range Rings>
  EarStatistics ear_statistics(const Rings& rings) {
    if (!engine_) acquire(detail::vertex_count(rings));
    detail::FlatPolygon& flat = input_buffer();
    if (!detail::flatten(rings, flat)) return {};
    return run_statistics(PolygonView{flat.points, flat.ring_starts});
  }

 private:
  template <class View, class Index>
  void into(const View& polygon, std::size_t count, const Options& options,
            Triangulation<Index>& result) {
    result.triangles.clear();
    result.diagnostics.clear();
    result.delaunay = {};
    result.status = Status::ok;
    if (count > 0 && count - 1 > static_cast<std::size_t>(std::numeric_limits<Index>::max())) {
      result.status = Status::index_overflow;
      result.diagnostics.push_back({Issue::index_overflow, 0, count - 1});
      return;
    }
    if constexpr (std::is_same_v<Index, std::uint32_t>) {
      result.status = run(polygon, options, result.triangles, result.diagnostics, result.delaunay);
    } else {
      std::vector<std::array<std::uint32_t, 3>>& wide = triangle_buffer();
      result.status = run(polygon, options, wide, result.diagnostics, result.delaunay);
      result.triangles.resize(wide.size());
      for (std::size_t t = 0; t < wide.size(); ++t)
        for (std::size_t k = 0; k < 3; ++k) result.triangles[t][k] = static_cast<Index>(wide[t][k]);
    }
  }

  /// Takes an engine from the pool for a polygon of `vertices` (a large one gets the pool's
  /// large engine, if it keeps one).
  void acquire(std::size_t vertices);
  detail::FlatPolygon& input_buffer();
  std::vector<std::array<std::uint32_t, 3>>& triangle_buffer();
  Status run(const PolygonView& polygon, const Options& options,
             std::vector<std::array<std::uint32_t, 3>>& triangles,
             std::vector<Diagnostic>& diagnostics, DelaunayStatistics& delaunay);
  Status run(const CoordinateView& polygon, const Options& options,
             std::vector<std::array<std::uint32_t, 3>>& triangles,
             std::vector<Diagnostic>& diagnostics, DelaunayStatistics& delaunay);
  Status run(const detail::RingSpans& polygon, const Options& options,
             std::vector<std::array<std::uint32_t, 3>>& triangles,
             std::vector<Diagnostic>& diagnostics, DelaunayStatistics& delaunay);
  EarStatistics run_statistics(const PolygonView& polygon);

  std::unique_ptr<detail::Engine> engine_;  ///< from a pool, on first use
};

/// Triangulates a polygon given as a range of rings (outer first, then holes).
/// Index is the output index type; a vertex count it cannot number gives Status::index_overflow.
template <class Index = std::uint32_t, ring_range Rings>
Triangulation<Index> triangulate(const Rings& rings, const Options& options = {}) {
  Triangulator triangulator;
  return triangulator.triangulate<Index>(rings, options);
}

/// Frees the engines (every stage's arrays) that calls keep for the next ones: up to 64 sized
/// for small polygons, and the one a call on a polygon of more than about 21,800 vertices left
/// (buffers for more than 65,536 points), which holds about 300 bytes a vertex of that polygon
/// (400 once it has made a constrained Delaunay triangulation) until this is called or the
/// program ends.
/// Triangulators in use keep theirs. Thread-safe.
PEAR_API void release_cached_engines() noexcept;

}  // namespace pear

// Many polygons in one call (after everything above: it uses Options and Status).
#include "pear/batch.hpp"  // IWYU pragma: export
