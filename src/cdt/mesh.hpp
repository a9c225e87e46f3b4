// The triangulation as half-edges with twins: what Lawson's edge flips (paper §2.4) work on.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/fill_vector.hpp"
#include "core/stage.hpp"
#include "geometry/segments.hpp"

namespace pear::detail {

/// Twin of an edge nobody may flip: a polygon edge (constraint) or the polygon's boundary.
inline constexpr std::uint32_t no_twin = UINT32_MAX;

/// build_mesh's arrays (the edges' keys and their buckets), kept with the mesh: a mesh built
/// again (an engine keeps its CDT's) then neither allocates nor frees them. Freed at the end of
/// every build, Eurasia's 72 MB took 3.4 ms on the calling thread, outside every phase.
struct MeshBuildArrays {
  FillVector<std::uint32_t> low, high, edges;
};

/// Half-edge h = 3t + k of triangle t runs from corner k to corner k + 1; corner k + 2 is the
/// apex across it. A flip keeps both triangles' numbers, so a triangle stays in its partition.
struct Mesh {
  std::span<const Point> points;
  TriangleList* triangles = nullptr;
  /// The same edge seen from the neighbour, or no_twin. Resized unwritten, then filled by the
  /// adjacency build's tasks (filled on one thread it was Eurasia's 4 ms serial allocation).
  FillVector<std::uint32_t> twin;
  std::size_t interior_edges = 0;  ///< edges with a twin: the ones that may be flipped
  MeshBuildArrays build;

  std::uint32_t corner(std::uint32_t h, std::uint32_t step) const {
    return (*triangles)[h / 3][(h % 3 + step) % 3];
  }
  std::uint32_t origin(std::uint32_t h) const { return corner(h, 0); }
  std::uint32_t destination(std::uint32_t h) const { return corner(h, 1); }
};

/// An edge's endpoints by position, lower first (lexicographically): the same for both
/// half-edges, even where touching rings give one point two caller indices.
struct EdgeEnds {
  Point low, high;
  EdgeEnds(const Point& p, const Point& q);
  friend bool operator==(const EdgeEnds&, const EdgeEnds&) = default;
  friend bool operator<(const EdgeEnds& e, const EdgeEnds& f) {
    return e.low != f.low ? lexicographic_less(e.low, f.low) : lexicographic_less(e.high, f.high);
  }
};

/// The half-edge after h in its triangle (counterclockwise).
inline std::uint32_t next_half_edge(std::uint32_t h) {
  return h % 3 == 2 ? h - 2 : h + 1;
}

/// The fewest edges (half-edges and ring edges) worth a task of their own in build_mesh.
inline constexpr std::size_t mesh_edges_per_task = 4096;

/// The most chunks and buckets build_mesh cuts the edges into (each chunk counts its edges per
/// bucket on the stack).
inline constexpr std::size_t max_mesh_parts = 256;

/// How many tasks build_mesh cuts each phase into: the partitions rounded up to a power of two
/// (buckets are picked by bits), at most one per mesh_edges_per_task edges and max_mesh_parts.
std::size_t mesh_parts(std::size_t edges, std::uint32_t partitions);

/// Which of `parts` buckets (a power of two) an edge goes to by its low vertex: blocks of at
/// least 64 vertices, about 4 per bucket, dealt to the buckets in turn. A bucket per range of
/// vertices would leave one nearly all the edges where low vertices cluster: the 100k spiral's
/// walls pair vertex i with n - i, so at 2 parts every edge fell in the first bucket and the CDT
/// at 2 threads was slower than on one. Blocks keep a coast's neighbouring edges together.
class VertexBuckets {
 public:
  VertexBuckets() = default;
  VertexBuckets(std::size_t vertices, std::size_t parts);
  std::size_t bucket(std::uint32_t v) const { return (v >> block_shift_) & (parts_ - 1); }
  /// v's place among its bucket's vertices: its block's turn, then its place in the block.
  std::uint32_t slot(std::uint32_t v) const {
    return (v >> (block_shift_ + parts_shift_) << block_shift_) |
           (v & ((std::uint32_t{1} << block_shift_) - 1));
  }
  /// Slots of a bucket: slot(v) < width() for every v < vertices.
  std::size_t width() const { return width_; }

 private:
  std::size_t parts_ = 1;
  std::uint32_t block_shift_ = 0, parts_shift_ = 0;
  std::size_t width_ = 0;
};

/// Sorts a fan's `high << 32 | edge` values by high alone, 11 bits a pass from the lowest (a
/// comparison sort took the comb's 100,000-edge fans 8 ms), with `scratch` as large. The order
/// within one high is left as it came: the twins do not depend on it (two half-edges of one edge
/// pair either way round).
void sort_by_high(std::uint64_t* first, std::uint64_t* last, std::vector<std::uint64_t>& scratch);

/// Fills mesh.twin for `triangles`: half-edges and the polygon's ring edges are matched by their
/// endpoints (caller indices), sorted in buckets by the lower one, in mesh_parts tasks per phase
/// (close to linear work; the twins do not depend on the partitions). An
/// edge of a ring is a constraint; so is an edge with one triangle. Bridges and other diagonals
/// have two triangles and may be flipped, so the result is the CDT of the polygon, not of its
/// bridged boundary. Returns false when an edge has more than two triangles, or a corner is not one
/// of `points`: not a triangulation, nothing may be flipped.
bool build_mesh(std::span<const Point> points, const CleanPolygon& polygon, TriangleList& triangles,
                Mesh& mesh, const RunContext& ctx);

/// Whether the edge h must be flipped: its two triangles and their apexes form a strictly convex
/// quadrilateral (the flip gives two counterclockwise triangles) and the apex across h lies
/// strictly inside the circumcircle, by exact incircle. Cocircular points are never flipped:
/// that tie rule makes the end result unique for a given order of flips. A zero-area triangle
/// (collinear corners from the input) is flipped away whenever the flip gives two proper
/// triangles, since no CDT contains it.
bool must_flip(const Mesh& mesh, std::uint32_t h);

/// Which triangles a flip may touch: all (part == nullptr) or those of partition `own`.
struct FlipScope {
  const std::uint32_t* part = nullptr;
  std::uint32_t own = 0;
  bool contains(std::uint32_t h) const { return part == nullptr || part[h / 3] == own; }
};

/// Replaces the edge h by the other diagonal of its quadrilateral. The twins of the four outer
/// edges are updated where they lie in `scope`; outside it they are left stale (the caller
/// relinks them). Half-edge h stays the new diagonal.
void flip(Mesh& mesh, std::uint32_t h, FlipScope scope);

/// Lawson's flip loop: pops suspect half-edges from `stack` (flags in `queued`) and flips those
/// that must be flipped, pushing the outer edges of every flipped quadrilateral. Only edges with
/// both triangles in `scope` are looked at. Stops after `budget` flips. Returns the flip count.
std::size_t flip_until_delaunay(Mesh& mesh, std::vector<std::uint32_t>& stack,
                                std::span<std::uint8_t> queued, FlipScope scope,
                                std::size_t budget);

}  // namespace pear::detail
