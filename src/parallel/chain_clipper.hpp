// Paper §2.2: one task clips the ears of one chain with its own queue. A node is clipped only
// when it and both its neighbours belong to the chain, so the landmarks and their links never
// change, and the task writes only its own nodes (see shared_boundary.hpp).
#pragma once

#include <cstdint>

#include "core/ear_queue.hpp"
#include "core/ear_test.hpp"
#include "shared_boundary.hpp"

namespace pear::detail {

class ChainClipper {
 public:
  /// Clips chain `chain`: the nodes of s.order strictly between positions `first` and `last`
  /// (cyclically). Appends the triangles to `out`.
  void run(SharedBoundary& s, std::uint32_t chain, std::size_t first, std::size_t last,
           EarHeuristic heuristic, TriangleList& out);

 private:
  struct OwnLinks {
    const SharedBoundary* s;
    std::uint32_t chain;
    bool readable(std::uint32_t q) const { return s->owner[q] == chain; }
  };
  bool own(std::uint32_t v) const { return s_->owner[v] == chain_; }
  /// Whether v is an ear; if so, `turns` as detail::is_ear gives them.
  bool is_ear(std::uint32_t v, DiagonalTurns& turns) const;
  /// is_ear with the grid's query `scanned` (ReflexGrid::scans_cells).
  template <bool scanned>
  bool test_ear(std::uint32_t v, DiagonalTurns& turns) const;
  /// Returns the span of the chain's node numbers from first_node_, which it sets.
  std::uint32_t build_grid(std::size_t first, std::size_t last);
  void offer(std::uint32_t v) { offer(v, s_->b->turn(v)); }
  /// offer for v whose corner turns by `turn` now.
  void offer(std::uint32_t v, double turn);
  bool clippable(std::uint32_t v, DiagonalTurns& turns) const;
  /// After v lost a neighbour, its corner turning by `turn` now: it may have stopped being
  /// strictly reflex.
  void update(std::uint32_t v, double turn);
  void unhash(std::uint32_t v);
  void remove(std::uint32_t v);
  std::uint32_t dissolve_spikes(std::uint32_t v);
  /// `turn`: v's turn when the caller knows it (the clipped ear's test gave it), or null.
  void settle(std::uint32_t v, const double* turn = nullptr);

  SharedBoundary* s_ = nullptr;
  std::uint32_t chain_ = 0;
  EarHeuristic heuristic_ = EarHeuristic::top;
  EarQueue queue_;
  std::uint32_t first_node_ = 0;  ///< the lowest node number of the chain (queue blocks)
  ReflexGrid own_grid_;           ///< see build_grid
  std::vector<std::uint32_t> scratch_;
};

}  // namespace pear::detail
