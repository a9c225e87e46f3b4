// The boundary as parallel tasks share it. Every node has one owner (a chain between two
// landmarks); during a phase a task writes only the links and flags of the nodes it owns, and
// reads another task's nodes only through what does not change during the phase: positions and
// the nodes hashed at the phase's start, one grid or list per chain. Landmarks have no
// owner and are never clipped. Since nodes only ever turn from reflex to convex while ears are
// clipped, a node hashed at the start of a phase is a safe stand-in for whatever it has become
// since: it can only reject an ear, never accept a wrong one.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/boundary.hpp"
#include "core/pinches.hpp"
#include "core/reflex_grid.hpp"
#include "core/stage.hpp"

namespace pear::detail {

/// A chain's hashed nodes at a phase's start in cycle order, with the box of each block of
/// `block` of them: what partition-and-cut's chains take the other chains' nodes in their box
/// from. A chain's nodes follow its outline, so on a coast a block's box is small; one pass
/// builds it where a grid takes five (New Guinea at 4 partitions: the grids 0.6 of 18 ms).
struct StartList {
  static constexpr std::size_t block = 32;
  std::vector<ReflexGrid::Entry> entries;
  std::vector<Point> blocks;  ///< per block its box's low corner, then its high one

  /// Makes the entries and blocks of `nodes`.
  void build(const Boundary& b, const std::vector<std::uint32_t>& nodes);
  /// Calls visit(entry) for the entries within [lo, hi], in list order.
  template <class Visit>
  void for_each_in_box(const Point& lo, const Point& hi, Visit&& visit) const {
    for (std::size_t k = 0; 2 * k < blocks.size(); ++k) {
      const Point &low = blocks[2 * k], &high = blocks[2 * k + 1];
      if (high.x < lo.x || low.x > hi.x || high.y < lo.y || low.y > hi.y) continue;
      const std::size_t last = std::min(entries.size(), (k + 1) * block);
      for (std::size_t i = k * block; i < last; ++i) {
        const Point& p = entries[i].pos;
        if (p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y) visit(entries[i]);
      }
    }
  }
};

struct SharedBoundary {
  static constexpr std::uint32_t landmark = UINT32_MAX;
  /// What a phase keeps of each chain's hashed nodes at its start: grids that its own tasks
  /// query and take nodes out of (mark-and-cut), or lists that other chains' tasks read once
  /// (partition-and-cut).
  enum class StartIndex { grids, lists };

  Boundary* b = nullptr;
  std::vector<ReflexGrid> start_grids;   ///< per chain: its hashed nodes at the phase start
  std::vector<StartList> start_lists;    ///< the same as lists
  std::vector<std::uint32_t> landmarks;  ///< the hashed landmarks
  // Filled in tasks (start): resize() leaves them unwritten (fill_vector.hpp).
  FillVector<std::uint8_t> alive;   ///< still on the boundary
  std::vector<std::uint8_t> pinch;  ///< shares its position: always hashed
  FillVector<std::uint8_t> hashed;  ///< strictly reflex or pinch now (owner writes)
  FillVector<std::uint32_t> owner;  ///< chain of each node, or `landmark`
  FillVector<std::uint32_t> stamp;  ///< bumped when a node's ear status may have changed
  FillVector<std::uint32_t> order;  ///< live nodes in cycle order (refreshed per round)

  /// Walks the cycle through `entry`, marks it alive, finds pinches (unless `shared` knows
  /// them) and hashed nodes. Returns the cycle's length. In parts: the arrays' fill, the links
  /// that jump (next[u] != u + 1), and `order` from the runs of consecutive nodes between them;
  /// only the runs are followed on one thread (node by node where jumps are many).
  std::size_t start(Boundary& boundary, std::uint32_t entry, const RunContext& ctx,
                    SharedPositions shared = {});
  /// Refreshes `order` from a live node of the cycle; returns a live node or no node.
  std::uint32_t refresh_order(const RunContext& ctx);
  /// Cuts `order` into `chains` runs at evenly spaced landmarks, the first at `offset`; sets
  /// owner, builds the start grids or lists as `index` says and returns the landmarks'
  /// positions in `order`.
  std::vector<std::size_t> place_landmarks(std::size_t chains, std::size_t offset,
                                           const RunContext& ctx, StartIndex index);

  /// Calls visit(entry) for the nodes every chain held hashed at the phase start (its start
  /// grid) within `box`, the bounding box of triangle (a, b, c), and for the landmarks within
  /// it, until visit returns true; returns whether it did.
  template <class Visit>
  bool any_hashed_near(const Point& a, const Point& b, const Point& c, const Box& box,
                       Visit&& visit) const {
    for (std::uint32_t mark : landmarks) {
      const Point& at = this->b->pos[mark];
      if (box.contains(at.x, at.y) && visit(ReflexGrid::Entry{at, mark})) return true;
    }
    for (std::size_t chain = 0; chain < chains; ++chain)
      if (start_grids[chain].any_in_box_near_triangle(a, b, c, box, visit)) return true;
    return false;
  }
  std::size_t chains = 0;

  /// The nodes of `order` strictly between positions `first` and `last`, around the cycle: two
  /// runs of it, the second empty unless the range wraps (no division a node to step through).
  std::array<std::span<const std::uint32_t>, 2> between(std::size_t first, std::size_t last) const {
    const std::span<const std::uint32_t> all(order.data(), order.size());
    if (last > first) return {all.subspan(first + 1, last - first - 1), {}};
    return {all.subspan(first + 1), all.first(last)};
  }

 private:
  /// Fills the arrays and `order` with the cycle through `entry`, alive set on it.
  void walk_cycle(std::uint32_t entry, const RunContext& ctx);
  /// `order` from entry along the links, alive set on the way (the arrays cleared before).
  void walk_node_by_node(std::uint32_t entry);
};

}  // namespace pear::detail
