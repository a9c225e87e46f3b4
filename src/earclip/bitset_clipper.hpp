// Ear clipping with bit sets: the strategy EarClipper takes on boundaries of at most 1,024 nodes
// (docs/engine.md, "Strategies"). The same ear test as the queue's (ear_test.hpp), but the
// strictly reflex, convex and candidate nodes are bit sets over the node numbers, the next ear
// is the candidate with the smallest top_key (a scan of the set) or, for `fast`, the next one
// met walking the cycle (`top`'s order once the walk has taken 3 steps a node), and the ear test
// looks only at the reflex nodes near the ear: up to 64 nodes (one word, whose loops keep the
// sets in registers) those a SIMD scan of their positions finds in its box (box_scan's
// points_in_box), past 64 those of the slabs the box meets. No grid, bucket queue or pinch
// table to set up; each step still scans, so the cost per vertex grows with n
// (bench_strategies: at 1,024 nodes 0.84-0.99x the queue's time, at 16 a third, at 2,048 up to
// 1.5x; docs/engine.md).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/boundary.hpp"
#include "core/ear_test.hpp"
#include "core/stage.hpp"
#include "geometry/box_scan.hpp"

namespace pear::detail {

class BitsetClipper {
 public:
  static constexpr std::size_t max_nodes = 1024;  // stale_words_ holds 32 words at most
  static constexpr std::size_t max_words = max_nodes / 64;

  /// Clips the cycle of `b` through `entry` in place (b.size() <= max_nodes), appending its
  /// triangles (the caller's vertex indices, counterclockwise) to `out`. `shared` marks every
  /// node whose position another node has (bridge ends, touching rings): those take part in
  /// every ear test whatever their angle, as the queue's pinches do; nullptr when no two nodes
  /// share a position. Returns false when it finds no ear: the triangles clipped so far stay,
  /// and the rest of the cycle, through anchor(), is left for the queue and its fallbacks.
  bool clip(Boundary& b, std::uint32_t entry, EarHeuristic heuristic, TriangleList& out,
            const std::vector<std::uint8_t>* shared);
  /// A node of what clip() left.
  std::uint32_t anchor() const { return anchor_; }
  /// The ear tests the last clip() took: its work.
  std::size_t ear_tests() const { return ear_tests_; }

 private:
  void load(std::uint32_t entry, const std::vector<std::uint8_t>* shared);
  bool is_ear(std::uint32_t v);
  void add_blocker(std::uint32_t q);
  void add_strays();
  /// Clips v, just found an ear by is_ear (whose turns_ its neighbours take).
  void clip_ear(std::uint32_t v, TriangleList& out);
  /// v's corner turns by `turn` now (orient2d of it and its neighbours).
  void refresh(std::uint32_t v, double turn);
  bool clip_by_key(TriangleList& out);
  template <bool keyed>
  struct OneWord;
  bool clip_one_word_by_key(TriangleList& out);
  bool clip_one_word_by_walk(TriangleList& out);
  bool clip_by_walk(TriangleList& out);
  bool clip_by_key_after_walk(TriangleList& out);
  /// Steps a node `fast`'s walk may take before it hands over to `top`'s order.
  static constexpr std::uint32_t walk_budget = 3;
  bool finish(TriangleList& out);

  /// One bit per node, in words of 64 kept in place (no allocation, no indirection).
  struct NodeSet {
    std::array<std::uint64_t, max_words> words;
    void add(std::uint32_t v) { words[v / 64] |= std::uint64_t{1} << (v % 64); }
    void erase(std::uint32_t v) { words[v / 64] &= ~(std::uint64_t{1} << (v % 64)); }
    bool contains(std::uint32_t v) const { return (words[v / 64] >> (v % 64)) & 1; }
  };
  std::uint32_t best_candidate();
  std::uint32_t best_in_word(std::uint32_t w) const;
  void drop_candidate(std::uint32_t v);

  /// The nodes in each of `count` slabs along one axis, accumulated from either end: those
  /// whose coordinate lies in [lo, hi] are among upto[slab(hi)] & from[slab(lo)]. slab() is
  /// monotone, so no node in the range is left out. Past 64 nodes the ear test then looks at
  /// the reflex nodes near its triangle instead of all of them. 64 slabs, not 16: a glyph's
  /// slab held several reflex nodes that the ear's box then ruled out one branch each
  /// (bench_small glyphs 1.04x, node 1.02-1.04x; 32 KB of sets a clipper).
  struct Slabs {
    static constexpr std::uint32_t count = 64;
    double origin = 0, scale = 0;
    std::array<NodeSet, count> upto, from;
    std::uint32_t slab(double c) const {
      return std::min(count - 1, static_cast<std::uint32_t>((c - origin) * scale));
    }
    void build(std::span<const Point> points, double Point::*axis, std::uint32_t words);
  };

  Boundary* b_ = nullptr;
  std::array<std::int64_t, max_nodes> key_;  ///< `top`'s order of each convex node
  std::array<double, max_nodes> side_;       ///< squared length of the edge from each node
  NodeSet reflex_;                           ///< strictly reflex nodes still on the cycle
  NodeSet shared_;                           ///< nodes whose position another node has
  NodeSet convex_;                           ///< strictly convex nodes still on the cycle
  NodeSet candidates_;                       ///< convex nodes not found blocked since they changed
  /// Each word's candidate with the smallest key (UINT32_MAX: none), found again only for the
  /// words whose bit in stale_words_ is set: past 64 nodes a step scans what changed.
  std::array<std::uint32_t, max_words> word_best_;
  std::uint32_t stale_words_ = 0;
  Slabs xs_, ys_;
  /// When one word holds every node: the positions of the nodes that may block an ear (strictly
  /// reflex or shared) as columns, padded for four-wide loads, so that the ear test's box scan
  /// reads those, not every node (on the counties the scan's instructions 4.7M -> 2.5M); each
  /// blocker's node, each node's bit among the blockers (0: none), and the blockers still
  /// blocking. In a simple polygon a corner only turns from reflex to convex; where a crossing
  /// lets a clip turn a neighbour reflex that is no blocker, it joins them (add_strays).
  std::array<double, 64 + 4> xs_column_{}, ys_column_{};
  std::array<std::uint32_t, 64> blocker_node_{};
  std::array<std::uint64_t, 64> blocker_bit_{};
  std::uint32_t blockers_ = 0;
  std::uint64_t live_blockers_ = 0;
  PointsInBox points_in_box_ = points_in_box_function();  ///< the best the processor has
  bool slabbed_ = false;  ///< whether xs_ and ys_ are built (more than one word)
  bool keyed_ = true;     ///< whether key_ is kept (`top`)
  std::uint32_t words_ = 0;
  std::uint32_t remaining_ = 0;
  std::uint32_t anchor_ = 0;  ///< a node of the cycle
  std::size_t ear_tests_ = 0;
  /// The turns the last ear tested by is_ear gives its neighbours once clipped.
  DiagonalTurns turns_;
};

}  // namespace pear::detail
