// Points where the boundary passes more than once (holes touching the outer ring or each other
// at several vertices, rings touching themselves in chains of lobes). The bridges join every
// ring at one place; at its other touching points a ring may pass through in an order whose
// interior wedges overlap (a figure eight as one ring). There the passes are relinked so that
// each one's wedge holds no other edge; this can cut the boundary into several cycles, each a
// region of its own (the arms of a plus sign whose centre is a hole).
#pragma once

#include <cstdint>
#include <vector>

#include "core/boundary.hpp"
#include "core/stage.hpp"

namespace pear::detail {

class TouchingPoints {
 public:
  /// Relinks the passes at every point that several nodes share. Exact; leaves a point alone
  /// when two of its edges overlap or its edges do not alternate in and out. Returns the first
  /// node (by index) of the first point (in node order) whose edges do not alternate: two
  /// passes' interior wedges overlap there, so the boundary is not weakly simple (a lobe inside
  /// a lobe of the same ring, a hole outside its ring touching it); UINT32_MAX when none.
  /// In `tasks` > 1 parts (ctx's tasks), the hashing of every node, which is most of the work
  /// on a large boundary; the same result. Records its phases in ctx's profile.
  std::uint32_t untangle(Boundary& b, const RunContext& ctx = RunContext{}, std::size_t tasks = 1);
  /// After untangle: 1 for every node whose position another node has (bridge ends, touching
  /// rings), what the clipper calls pinches; it need not hash the positions again.
  const std::vector<std::uint8_t>& shared_positions() const { return shared_; }

  /// One node of every cycle of `b` with at least three nodes, the cycle through `first` first
  /// (entered there), the others in the order of their lowest nodes (entered there); the
  /// cycles through `skip` (holes that could not be joined) are left out. With `tasks` > 1
  /// the links that jump are found in ctx's tasks and the cycles walked by runs of consecutive
  /// nodes (link_runs.hpp): the same entries. Records its phases in ctx's profile.
  std::vector<std::uint32_t> cycles(const Boundary& b, std::uint32_t first,
                                    const std::vector<std::uint32_t>& skip,
                                    const RunContext& ctx = RunContext{}, std::size_t tasks = 1);

 private:
  struct Spoke {
    Point to;
    std::uint32_t node;
    bool out;
  };
  /// False when the point's edges do not alternate in and out.
  bool untangle_point(Boundary& b, const std::uint32_t* nodes, std::size_t count);
  /// order_: the nodes whose hash slot another node shares, in node order.
  void find_candidates(const Boundary& b, const RunContext& ctx, std::size_t tasks);
  /// Groups the candidates by position and relinks each point; see untangle().
  std::uint32_t untangle_points(Boundary& b);
  std::vector<std::uint32_t> cycles_node_by_node(const Boundary& b, std::uint32_t first,
                                                 const std::vector<std::uint32_t>& skip);
  /// cycles() from the runs between `jumps`; false when the links are not all cycles.
  bool cycles_by_runs(const Boundary& b, std::uint32_t first,
                      const std::vector<std::uint32_t>& skip,
                      const std::vector<std::uint32_t>& jumps, std::vector<std::uint32_t>& entries);

  std::vector<std::uint64_t> seen_once_, seen_twice_;  ///< per hash slot: nodes there
  std::vector<std::uint32_t> order_;  ///< nodes whose hash slot another node shares
  std::vector<std::vector<std::uint32_t>> chunk_order_;  ///< in parts: order_ per chunk
  std::vector<std::uint32_t> group_slots_;  ///< position -> a candidate there (index in order_)
  std::vector<std::uint32_t> same_;         ///< the next candidate at the same position
  std::vector<std::uint32_t> heads_;        ///< the first candidate at each position
  std::vector<std::uint32_t> group_;
  std::vector<Spoke> spokes_;
  std::vector<std::uint32_t> successor_;
  std::vector<std::uint8_t> seen_;
  std::vector<std::uint8_t> shared_;
};

}  // namespace pear::detail
