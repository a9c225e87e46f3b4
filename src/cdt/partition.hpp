// Triangle sets for the parallel flips (paper §2.4, Fig. 6b).
#pragma once

#include <cstdint>
#include <vector>

#include "core/stage.hpp"
#include "delaunay.hpp"
#include "mesh.hpp"

namespace pear::detail {

/// The triangles cut into consecutive pieces of one breadth-first walk of the dual graph, or of
/// the clipper's own order. FillVectors: partition_in_runs fills them in tasks.
struct TrianglePartition {
  FillVector<std::uint32_t> part;   ///< the set of each triangle
  FillVector<std::uint32_t> order;  ///< triangles in walk order
  std::vector<std::size_t> begin;   ///< set s is order[begin[s], begin[s + 1])
  std::size_t sets() const { return begin.empty() ? 0 : begin.size() - 1; }
};

/// Walks the dual graph breadth first (across edges with twins) from the first ear, a triangle
/// with two constraint edges, and cuts the walk into `sets` pieces of equal size. The paper found
/// breadth-first sets less fragmented than depth-first ones: fewer border flips. Deterministic.
void partition_triangles(const Mesh& mesh, std::uint32_t sets, TrianglePartition& partition);

/// Whether `sets` runs of the triangles' own order make good sets: when all but at most 1/32 of
/// the `count` triangles came out region by region (`order.region_ordered` first ones), 1/8
/// where the rest lies on the seams, whatever the number of sets. Partition-and-cut's chains do
/// on the coasts (99.8% at 16 partitions), divide-and-conquer's parts before their repair's
/// patches (random-holes-100k at 16: 93%). A sequential clip's order is by ear quality,
/// scattered over the polygon, and where chains emit less a corridor's two walls fall in
/// different chains: on the 100k spiral (52% from chains at 16 partitions, over 75% at 2) runs
/// made 2.3 million border flips against the walk's 81,000 at 16, and 2.27 million against
/// 1,800 at 2. Runs need no walk, which is serial.
bool runs_make_sets(ClipOrder order, std::size_t count, std::uint32_t sets);

/// Set s is the run [R * s / sets, R * (s + 1) / sets) of the first R triangles, then those of
/// the rest that join it: each the set of its first neighbour among the R, else of its first
/// neighbour before it in its range (a repair's patch is clipped from its border in), else of
/// the triangle before it. The ranges are fixed by the triangle count, never by the threads;
/// all by ctx's tasks. R is `order.region_ordered` where the rest lies on the seams, else all
/// the triangles. Eurasia at 16 sets: 77,694 border flips against the walk's 303,300 and no
/// 44 ms serial walk; random-holes-100k at 16, 6.9% of its triangles in divide-and-conquer's
/// patches: no 1.8 ms serial walk.
void partition_in_runs(const Mesh& mesh, ClipOrder order, std::uint32_t sets, const RunContext& ctx,
                       TrianglePartition& partition);

}  // namespace pear::detail
