// Paper §2.1, Fig. 2: removing the Steiner points again. The paper removes the triangles around
// each pair of Steiner points and re-triangulates the double-star-shaped hole. We remove every
// triangle that has a Steiner corner at once; each connected hole that is left is bounded by
// input vertices only (the two halves of a split input edge, a -> s -> b, become a -> b again)
// and is re-triangulated by the sequential ear clipper with exact predicates.
//
// Why the result is right although the parts were clipped on rounded Steiner points: if the
// triangles' boundaries add up (as a chain of directed edges between points) to the input
// boundary, and every triangle is strictly counterclockwise, then each point is covered exactly
// winding-number-many times: once inside the polygon, never outside. The parts' triangles add
// up to the boundary with Steiner points (the split segments cancel); check_chain() verifies
// that the holes' triangles make up exactly for the removed ones and the Steiner points; the
// orientation of every triangle is checked exactly. Anything else falls back.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/cycle_clipper.hpp"
#include "core/stage.hpp"
#include "split_pieces.hpp"

namespace pear::detail {

/// A triangle of a part with at least one Steiner corner, counterclockwise.
using SteinerTriangle = std::array<PieceCorner, 3>;

/// An undirected edge's use in the repair's chain check: +1 from lo to hi, -1 the other way.
struct ChainUse {
  PieceCorner lo, hi;
  int sign;
};

/// A task's scratch memory for clipping holes.
struct HoleClipper {
  explicit HoleClipper(MakeClipper make) : clipper(make()) {}
  Boundary hole;
  TriangleList local;
  std::unique_ptr<CycleClipper> clipper;
};

class SteinerRepair {
 public:
  /// Finds the holes the triangles leave: one boundary cycle of input nodes per connected
  /// group of triangles. Corners are compared by point (nodes at one position, a Steiner point
  /// on both sides of a bridge are one), as the clippers may use either at a pinch. Returns
  /// false when a group is not a disk or the triangles do not fit together. Bit c of
  /// on_boundary[t] says that edge c -> c + 1 of triangle t lies on the input boundary.
  /// In tasks of ctx where a pass is worth them (phases "find Steiner holes: ..."); the same
  /// holes for any partitions.
  bool find_holes(const Boundary& b, const std::vector<SplitLine>& lines,
                  const std::vector<SteinerTriangle>& triangles,
                  std::vector<std::uint8_t> on_boundary, const RunContext& ctx);

  std::size_t hole_count() const { return starts_.size() - 1; }
  /// How many nodes the holes before h have together.
  std::size_t nodes_before(std::size_t h) const { return starts_[h]; }

  /// Triangulates hole h from its input vertices; appends the triangles in caller indices to
  /// out and in corners to `corners`. Returns false unless every triangle is strictly
  /// counterclockwise.
  bool triangulate_hole(std::size_t h, const Boundary& b, EarHeuristic heuristic,
                        HoleClipper& scratch, TriangleList& out,
                        std::vector<SteinerTriangle>& corners) const;

  /// Whether the holes' triangles (`fills`, in any number of lists) have the boundary of the
  /// removed triangles with every input edge a -> s1 -> ... -> b through Steiner points
  /// replaced by a -> b. In tasks of ctx (phases "check Steiner holes: ..."); the same verdict
  /// for any partitions.
  bool check_chain(const Boundary& b, const std::vector<SplitLine>& lines,
                   const std::vector<std::vector<SteinerTriangle>>& fills, const RunContext& ctx);

  /// What makes two corners the same point: an input node by its position, a Steiner point by
  /// its line and the ends of its input edge (so both sides of a bridge give one point).
  struct CornerKey {
    std::uint32_t line = 0;  ///< 0 for an input node, else the Steiner point's line + 1
    Point a{}, b{};
    friend bool operator<(const CornerKey& p, const CornerKey& q) {
      if (p.line != q.line) return p.line < q.line;
      if (p.a != q.a) return lexicographic_less(p.a, q.a);
      return lexicographic_less(p.b, q.b);
    }
    friend bool operator==(const CornerKey&, const CornerKey&) = default;
  };

 private:
  struct DirectedEdge {
    PieceCorner from, to;
    std::uint32_t id;  ///< triangle * 3 + corner of `from`
  };
  static constexpr std::uint32_t none = UINT32_MAX;
  void canonical_corners(const Boundary& b, const std::vector<SplitLine>& lines,
                         const std::vector<SteinerTriangle>& triangles, const RunContext& ctx);
  void canonicalize(const std::vector<SteinerTriangle>& triangles, std::size_t from,
                    std::size_t to);
  bool index_edges(const RunContext& ctx);
  void glue(std::size_t from, std::size_t to);
  bool walk_holes();
  PieceCorner canonical(PieceCorner c) const;
  std::uint32_t find(PieceCorner from, PieceCorner to) const;
  std::uint32_t glued(std::uint32_t edge) const;
  std::uint32_t across(std::uint32_t edge) const;
  std::uint32_t next_on_boundary(std::uint32_t edge) const;
  bool walk_hole(std::uint32_t start, std::vector<std::uint8_t>& visited);
  bool holes_are_disks(const std::vector<std::uint32_t>& hole_starts) const;
  void sort_steiner_points(const Boundary& b, const std::vector<SplitLine>& lines,
                           const RunContext& ctx);
  void add_split_edges(const std::vector<SplitLine>& lines, std::size_t from, std::size_t to,
                       std::vector<ChainUse>& uses) const;

  // canonical_corners' arrays, kept between runs (their pages were a third of its time).
  std::vector<PieceCorner> corners_;
  std::vector<std::pair<CornerKey, PieceCorner>> keyed_;
  std::vector<std::pair<PieceCorner, PieceCorner>> canonical_;  ///< sorted by corner
  std::vector<SteinerTriangle> triangles_;                      ///< in canonical corners
  std::vector<PieceCorner> steiner_;  ///< every Steiner point, by input edge and along it
  std::vector<std::uint8_t> on_boundary_;
  std::vector<DirectedEdge> edges_;    ///< sorted by (from, to)
  std::vector<std::uint32_t> across_;  ///< glued() of each edge (triangle * 3 + corner)
  std::vector<std::uint32_t> nodes_;   ///< the holes' input nodes, one hole after another
  std::vector<std::uint32_t> starts_{0};
};

}  // namespace pear::detail
