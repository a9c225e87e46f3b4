// Ear clipping for small polygons: one ring of at most 384 nodes, simple (the pipeline checks
// this first), or the boundary of a polygon with holes joined by bridges, whose bridge ends
// repeat positions. The same ear test as the general clipper (ear_test.hpp's blocks()), but
// the strictly reflex, convex and candidate nodes are bit sets, the next ear is the candidate
// with the smallest key (a scan of the set), and the key is read from the bits of the doubles
// instead of computed with roots: no grid, bucket queue or pinch table to set up. Up to 64
// nodes the ear test takes the nodes in the ear's box from a SIMD scan of the positions
// (box_scan's points_in_box); past 64, slabs narrow it to reflex nodes near the ear and the
// scan to the words that changed; each step still scans, so the cost per vertex grows with n:
// at about 512 vertices the general clipper is as fast (bench_small's crossover;
// docs/engine.md).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "core/boundary.hpp"
#include "core/stage.hpp"
#include "geometry/box_scan.hpp"

namespace pear::detail {

class SmallClipper {
 public:
  static constexpr std::size_t max_nodes = 384;
  static constexpr std::size_t max_words = max_nodes / 64;

  /// Clips the counterclockwise ring `points` (original[i]: the caller's index of point i; at
  /// most max_nodes), appending its n - 2 triangles to `out`. `repeated` says that positions
  /// may repeat (bridge ends): those nodes then take part in every ear test whatever their
  /// angle, as the general clipper's pinches do. Returns false, with `out` as it was, when it
  /// finds no ear: the ring was not simple after all (the caller skipped the check), and the
  /// general engine, with its fallbacks, must take it.
  bool run(std::span<const Point> points, std::span<const std::uint32_t> original,
           EarHeuristic heuristic, TriangleList& out, bool repeated = false);

 private:
  void load(std::span<const Point> points, std::span<const std::uint32_t> original);
  void mark_repeated_positions();
  bool is_ear(std::uint32_t v) const;
  void clip(std::uint32_t v, TriangleList& out);
  void refresh(std::uint32_t v);
  bool clip_by_key(TriangleList& out);
  bool clip_by_walk(TriangleList& out);
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
  /// the reflex nodes near its triangle instead of all of them.
  struct Slabs {
    static constexpr std::uint32_t count = 16;
    double origin = 0, scale = 0;
    std::array<NodeSet, count> upto, from;
    std::uint32_t slab(double c) const {
      return std::min(count - 1, static_cast<std::uint32_t>((c - origin) * scale));
    }
    void build(std::span<const Point> points, double Point::*axis, std::uint32_t words);
  };

  Boundary b_;
  std::vector<std::int64_t> key_;  ///< `top`'s order of each convex node (smaller first)
  std::vector<double> side_;       ///< squared length of the edge from each node (`top`)
  NodeSet reflex_;                 ///< strictly reflex nodes still on the boundary
  NodeSet shared_;                 ///< nodes whose position another node has (bridge ends)
  NodeSet convex_;                 ///< strictly convex nodes still on the boundary
  NodeSet candidates_;             ///< convex nodes not found blocked since they last changed
  /// Each word's candidate with the smallest key (UINT32_MAX: none), found again only for the
  /// words whose bit in stale_words_ is set: past 64 nodes a step scans what changed.
  std::array<std::uint32_t, max_words> word_best_;
  std::uint32_t stale_words_ = 0;
  Slabs xs_, ys_;
  PointColumns columns_;                    ///< the positions, when one word holds every node
  bool slabbed_ = false;                    ///< whether xs_ and ys_ are built (more than one word)
  bool keyed_ = true;                       ///< whether key_ is kept (`top`)
  std::uint32_t words_ = 0;                 ///< words of the sets in use
  std::vector<std::uint8_t> live_, pinch_;  ///< mark_repeated_positions' scratch
  std::vector<std::uint32_t> position_table_;
  std::uint32_t remaining_ = 0;
  std::uint32_t anchor_ = 0;  ///< a live node
};

}  // namespace pear::detail
