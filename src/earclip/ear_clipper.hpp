// Ear classification and clipping (paper §1.1-1.2), with FIST's fallbacks for input that is not
// simple. Works on one cycle of a Boundary.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "bitset_clipper.hpp"
#include "core/boundary.hpp"
#include "core/cycle_clipper.hpp"
#include "core/ear_queue.hpp"
#include "core/ear_test.hpp"
#include "core/pinches.hpp"
#include "core/reflex_grid.hpp"
#include "core/stage.hpp"
#include "pear/pear.hpp"

namespace pear::detail {

class EarClipper final : public CycleClipper {
 public:
  bool clip(Boundary& b, std::uint32_t entry, EarHeuristic heuristic, TriangleList& out,
            SharedPositions shared) override {
    return run(b, entry, heuristic, out, shared);
  }
  /// Clips the cycle through `entry` down to nothing, appending triangles (the caller's vertex
  /// indices, counterclockwise) to `out`. Returns false when a best-effort fallback had to be
  /// used: the boundary was not weakly simple, and the result may overlap. The strategy
  /// follows the size: bit sets up to BitsetClipper::max_nodes nodes (where they find no ear,
  /// the queue and its fallbacks take what is left), a reflex grid and a queue (or `fast`'s
  /// walk) beyond.
  bool run(Boundary& b, std::uint32_t entry, EarHeuristic heuristic, TriangleList& out,
           SharedPositions shared = {});
  /// run() with the queue whatever the size: for tests and for bench_small's crossover of the
  /// two strategies.
  bool run_queue(Boundary& b, std::uint32_t entry, EarHeuristic heuristic, TriangleList& out,
                 SharedPositions shared = {}) {
    prepare(b, entry, heuristic, out, shared);
    return clip_prepared(entry);
  }

  /// Convex, reflex and ear counts of the cycle through `entry` (nothing is clipped).
  EarStatistics statistics(Boundary& b, std::uint32_t entry);

  /// Node visits and edge tests the fallbacks made in the last run: at most
  /// fallback_budget(n) + fallback_window per removed node, linear in n (also summed over the
  /// many small cycles of a polygon that touches itself, each clipped in a run of its own).
  std::size_t fallback_work() const { return fallback_work_; }
  /// Once the budget is spent, a fallback looks at this many nodes after the place where
  /// clipping stopped instead of the whole cycle.
  static constexpr std::size_t fallback_window = 64;
  static std::size_t fallback_budget(std::size_t nodes) {
    return 64 * nodes + std::min<std::size_t>(4'000'000, 4096 * nodes);
  }

  /// The strips (core/strip_fans.hpp) the last run finished in two fans.
  std::size_t strips() const { return strips_; }

  /// The caller's index of the vertex where the first best-effort fallback acted.
  std::uint32_t best_effort_vertex() const override { return best_effort_vertex_; }

 private:
  /// The queue's two steps: dissolving spikes, marking pinches and hashing the reflex nodes;
  /// then clipping.
  void prepare(Boundary& b, std::uint32_t entry, EarHeuristic heuristic, TriangleList& out,
               SharedPositions shared);
  bool clip_prepared(std::uint32_t entry);
  void classify(std::uint32_t entry, SharedPositions shared);
  bool is_ear(std::uint32_t v) const;
  /// is_ear, and when v is an ear the turns its neighbours will have once it is clipped.
  bool is_ear(std::uint32_t v, DiagonalTurns& turns) const;
  /// is_ear with the grid's query `scanned` (ReflexGrid::scans_cells).
  template <bool scanned>
  bool test_ear(std::uint32_t v, DiagonalTurns& turns) const;
  double quality(std::uint32_t v) const;
  void clip(std::uint32_t v);
  /// After a change next to v, whose corner turns by `turn` (orient2d) now: v leaves the grid
  /// if it stopped being reflex, and its queued entries go stale.
  void update_neighbour(std::uint32_t v, double turn);
  void remove(std::uint32_t v);
  void mark_pinches(SharedPositions shared);
  /// Every node's shared position, for the bit sets: given, none, or found here.
  const std::vector<std::uint8_t>* shared_marks(std::uint32_t entry, SharedPositions shared);
  void drop_reflex(std::uint32_t v);
  std::uint32_t dissolve_spikes(std::uint32_t v);
  /// `turn`: v's turn when the caller knows it (the tested ear's, for its neighbours), or null.
  std::uint32_t settle(std::uint32_t v, bool queue, const double* turn = nullptr);
  /// Settles the neighbours p and n of an ear just clipped, with the turns its test gave them
  /// (n's first; p's only while it is still n's neighbour, as settling n may dissolve spikes).
  /// Returns what settle returned for each.
  std::array<std::uint32_t, 2> settle_clipped(std::uint32_t p, std::uint32_t n,
                                              const DiagonalTurns& turns, bool queue);
  /// A live node at or after v: removed nodes keep pointing at nodes live when they left.
  std::uint32_t live(std::uint32_t v) const {
    while (!alive_[v]) v = b_->next[v];
    return v;
  }
  void offer(std::uint32_t v) { offer(v, b_->turn(v)); }
  /// offer for v whose corner turns by `turn` now.
  void offer(std::uint32_t v, double turn);
  /// The best queued node that is still current and an ear; `turns` as is_ear gives them.
  bool pop(std::uint32_t& v, DiagonalTurns& turns);
  bool fall_back(std::uint32_t near);
  bool split_along_diagonal(std::uint32_t near);
  void split_cycle(std::uint32_t a, std::uint32_t c, std::size_t first_part);
  static constexpr std::size_t split_limit = 512;
  /// Node visits and edge tests left to the fallbacks in this run: a boundary with no ear
  /// anywhere (random points joined in random order) would otherwise cost a scan of the cycle
  /// per removed node, quadratic time.
  std::size_t fallback_budget_ = 0;
  std::size_t fallback_work_ = 0;
  void finish(std::uint32_t any);
  void clip_ears(std::uint32_t entry);

  bool walk_ears(std::uint32_t& entry);
  bool finish_strip();
  void enqueue_cycle(std::uint32_t entry);

  Boundary* b_ = nullptr;
  TriangleList* out_ = nullptr;
  EarHeuristic heuristic_ = EarHeuristic::top;
  std::size_t remaining_ = 0;
  bool best_effort_ = false;
  std::uint32_t best_effort_vertex_ = 0;
  std::uint32_t touched_ = 0;
  std::uint32_t anchor_ = 0;  ///< a live node of the cycle being clipped (moved on by remove)  ///<
                              ///< a live node next to the last fallback's change
  /// Strictly reflex and still on the boundary. Collinear nodes need no hashing: a node inside
  /// an ear's triangle implies a strictly reflex one there too (the node farthest from the
  /// diagonal turns away from it), except for chains along the diagonal, checked at its ends.
  std::vector<std::uint8_t> reflex_;
  std::vector<std::uint8_t> alive_;
  std::vector<std::uint8_t> pinch_;  ///< shares its position with another node: always hashed
  std::vector<std::uint32_t> position_table_;
  std::vector<std::uint32_t> stamp_;   ///< bumped when a node's ear status may have changed
  std::vector<std::uint32_t> failed_;  ///< stamp + 1 when the node last failed the ear test
  std::vector<std::uint32_t> walk_;    ///< "fast": nodes to visit, in boundary order
  mutable std::size_t boxed_ = 0;      ///< hashed nodes met in ear tests' boxes (walk budget)
  std::vector<std::uint32_t> scratch_;
  struct PendingCycle {
    std::uint32_t entry;
    std::size_t nodes;
  };
  std::vector<PendingCycle> pending_;  ///< parts of split cycles still to clip
  /// finish_strip looks at the cycle again only at or below this many nodes.
  std::size_t strip_check_at_ = SIZE_MAX;
  std::size_t strips_ = 0;
  EarQueue queue_;
  ReflexGrid grid_;
  bool grid_built_ = false;  ///< spikes are dissolved before the grid exists
  BitsetClipper bits_;
};

/// A new EarClipper, for the parallel variants (MakeClipper).
inline std::unique_ptr<CycleClipper> make_ear_clipper() {
  return std::make_unique<EarClipper>();
}

}  // namespace pear::detail
