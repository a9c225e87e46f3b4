// The last step of the parallel flips (paper §2.4): the empty-circle condition across the
// borders of the triangle sets, in rounds of independent flips run in parallel.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/stage.hpp"
#include "mesh.hpp"
#include "partition.hpp"

namespace pear::detail {

/// The half-edges of set s whose twin lies in another set: the set's task did not flip them and
/// their twins may be stale.
void collect_borders(const Mesh& mesh, const TrianglePartition& partition, std::uint32_t s,
                     std::vector<std::uint32_t>& borders);

/// Pairs the border half-edges again by their endpoints' positions: the sets' flips moved them
/// to other slots without telling the other side. Returns one half-edge of each pair, in the
/// order of their ends (then half-edge numbers). In parallel: ranges of that order, cut at
/// sampled keys, are sorted and paired by tasks of their own.
std::vector<std::uint32_t> relink_borders(Mesh& mesh,
                                          const std::vector<std::vector<std::uint32_t>>& sets,
                                          const RunContext& ctx);

/// flip_borders' round numbers per triangle (own, touched) and per half-edge (listed), kept with
/// the CDT's other arrays between runs: cleared by tasks, never zeroed or freed on the calling
/// thread (a vector's zeroing pass took Eurasia's 16-thread CDT 12 ms on one thread).
struct BorderFlipMarks {
  FillVector<std::uint32_t> own, touched, listed;
};

/// Flips until every edge is locally Delaunay, given that only the `suspects` may not be, in
/// rounds: test all suspects (in parallel), pick in list order those whose flips touch disjoint
/// triangles, flip them (in parallel), and make their outer edges and the suspects left over the
/// next round's. Small rounds run on this thread. The picks depend on the mesh only, never on
/// timing or on whether a round ran in parallel. Returns the flip count (at most `budget`).
/// `queued`: a flag per half-edge, all clear (the sets' flips leave theirs so), and so left.
std::size_t flip_borders(Mesh& mesh, std::vector<std::uint32_t> suspects,
                         std::span<std::uint8_t> queued, BorderFlipMarks& kept,
                         const RunContext& ctx, std::size_t budget);

}  // namespace pear::detail
