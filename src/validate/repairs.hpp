// The validator's own reading of the repairs the README promises, independent of pear's engine.
//
// Zero-width spikes: the ring's vertices where it turns straight back leave before counting.
//
// T-junctions: where a vertex lies inside a boundary edge (a hole touching the outer ring inside
// one of its edges), a valid triangulation uses the edge's parts, not the edge: the edge uses
// do not balance one by one. What is left over (the residue: the triangles' boundary chain minus
// the polygon's, edge by edge) must then cancel as segments, line by line, the boundary's edges
// split only at points lying inside them, the triangles' edges never (no vertex may lie inside
// a triangle's edge).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "pear/geometry.hpp"

namespace pear::detail {

/// Removes from the ring `kept` (indices into points, no repeated consecutive points, at least
/// 3) its zero-width spikes, in rounds: every vertex where the ring turns straight back leaves
/// at once, then repeated points merge, until no such vertex is left (README).
void dissolve_tips(std::span<const Point> points, std::vector<std::uint32_t>& kept);

/// An edge whose uses do not balance, between two distinct points (canonical indices).
struct Residue {
  std::uint32_t lo, hi;
  int triangle_uses;  ///< uses by triangles from lo to hi, minus those from hi to lo
  int boundary_uses;  ///< the same for the polygon's boundary; they differ
};

/// A point lying inside the boundary edge of a residue that cancels: the edge is split there.
struct BoundarySplit {
  std::uint32_t residue;
  std::uint32_t point;
};

struct ResidueBalance {
  std::vector<std::uint8_t> cancelled;  ///< per residue: the residue on its line cancels
  std::vector<BoundarySplit> splits;    ///< for the cancelled residues with boundary uses
};

/// Groups the residues into runs of collinear edges joined at their ends, and checks each run
/// exactly: along its line, the triangles' uses minus the boundary's sum to zero between any
/// two consecutive points, no two boundary edges cover the same stretch (overlapping boundary
/// edges are no polygon), and no point of the run lies inside a triangle's edge.
ResidueBalance balance_residue(std::span<const Point> points, std::span<const Residue> residues);

}  // namespace pear::detail
