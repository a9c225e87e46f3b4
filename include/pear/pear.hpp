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
// vertices left after dropping repeated consecutive points and the closing point, h the holes
// kept, and m the kept vertices that repeat an already used point (holes or rings touching at a
// vertex). See README.md "Pre- and post-conditions" for the full contract.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "pear/geometry.hpp"

namespace pear {

/// Which triangulation algorithm to run.
enum class Algorithm : std::uint8_t {
  automatic,   ///< pear picks (the sequential engine for now)
  sequential,  ///< the sequential FIST-style ear clipper
};

/// How the sequential engine chooses the next ear.
enum class EarHeuristic : std::uint8_t {
  top,   ///< priority queue: clip the ear closest to equilateral first (FIST's "top")
  fast,  ///< clip the ear with the shortest diagonal first: cheaper key, small triangles
};

struct Options {
  Algorithm algorithm = Algorithm::automatic;
  EarHeuristic heuristic = EarHeuristic::top;
  /// Check exactly, before clipping, that no two edges cross or overlap and that no vertex lies
  /// inside another edge; a violation gives Status::not_simple and names the place. Without
  /// the check, such input may come back as Status::ok with a triangulation that is not valid.
  bool check_simplicity = true;
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
};

namespace detail {
/// The polygon as the engine sees it: all points in input order, ring after ring.
struct FlatPolygon {
  std::vector<Point> points;
  std::vector<std::uint32_t> ring_starts;  ///< ring r is [ring_starts[r], ring_starts[r+1])
  void clear() {
    points.clear();
    ring_starts.clear();
  }
};

/// Copies any ring range into a FlatPolygon. Returns false when the count exceeds 2^32 - 2.
template <ring_range Rings>
bool flatten(const Rings& rings, FlatPolygon& flat) {
  flat.clear();
  std::size_t total = 0;
  for (const auto& ring : rings) {
    flat.ring_starts.push_back(static_cast<std::uint32_t>(total));
    for (const auto& p : ring) {
      using P = std::remove_cvref_t<decltype(p)>;
      if (++total >= std::numeric_limits<std::uint32_t>::max()) return false;
      flat.points.push_back(Point{point_traits<P>::x(p), point_traits<P>::y(p)});
    }
  }
  flat.ring_starts.push_back(static_cast<std::uint32_t>(total));
  return true;
}

class Engine;
}  // namespace detail

/// A reusable triangulator: keeps its buffers between calls, so many small polygons are cheap.
/// Not thread-safe; use one per thread.
class Triangulator {
 public:
  Triangulator();
  ~Triangulator();
  Triangulator(Triangulator&&) noexcept;
  Triangulator& operator=(Triangulator&&) noexcept;

  template <class Index = std::uint32_t, ring_range Rings>
  Triangulation<Index> triangulate(const Rings& rings, const Options& options = {}) {
    Triangulation<Index> result;
    if (!detail::flatten(rings, flat_)) {
      result.status = Status::index_overflow;
      result.diagnostics.push_back({Issue::index_overflow, 0, 0});
      return result;
    }
    result.status = run(options, result.diagnostics);
    convert<Index>(result);
    return result;
  }

  /// Ear statistics of the cleaned, bridged boundary (no clipping is done).
  template <ring_range Rings>
  EarStatistics ear_statistics(const Rings& rings) {
    if (!detail::flatten(rings, flat_)) return {};
    return run_statistics();
  }

 private:
  Status run(const Options& options, std::vector<Diagnostic>& diagnostics);
  EarStatistics run_statistics();

  template <class Index>
  void convert(Triangulation<Index>& result) {
    const std::size_t vertex_count = flat_.points.size();
    if (vertex_count > 0 &&
        vertex_count - 1 > static_cast<std::size_t>(std::numeric_limits<Index>::max())) {
      result.status = Status::index_overflow;
      result.diagnostics.push_back({Issue::index_overflow, 0, vertex_count - 1});
      result.triangles.clear();
      return;
    }
    result.triangles.resize(triangles_.size());
    for (std::size_t t = 0; t < triangles_.size(); ++t)
      for (int k = 0; k < 3; ++k) result.triangles[t][k] = static_cast<Index>(triangles_[t][k]);
  }

  detail::FlatPolygon flat_;
  std::vector<std::array<std::uint32_t, 3>> triangles_;
  std::unique_ptr<detail::Engine> engine_;
};

/// Triangulates a polygon given as a range of rings (outer first, then holes).
/// Index is the output index type; a vertex count it cannot number gives Status::index_overflow.
template <class Index = std::uint32_t, ring_range Rings>
Triangulation<Index> triangulate(const Rings& rings, const Options& options = {}) {
  Triangulator triangulator;
  return triangulator.triangulate<Index>(rings, options);
}

}  // namespace pear
