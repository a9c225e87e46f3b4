// What the parallel variants allocate for a run, kept between runs by whoever runs them (the
// engine keeps one). Freed at the end of every call, a large polygon's arrays cost a serial
// tail, and their pages faulted in again at the next call: Eurasia at 16 partitions, on one
// thread, spent 7.5 ms after partition-and-cut's last phase and 18 ms after mark-and-cut's
// freeing them; divide-and-conquer's parts on the holes grid at 2 partitions faulted in 1,200
// pages a run (twice the sequential engine's time on this 2-core VM).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "chain_clipper.hpp"
#include "core/cycle_clipper.hpp"
#include "divide_conquer_fans.hpp"
#include "divide_conquer_repair.hpp"
#include "shared_boundary.hpp"
#include "split_pieces.hpp"

namespace pear::detail {

/// Divide-and-conquer: the pieces between two neighbouring split lines, lines [lo, hi) still
/// to cut.
struct DivideSlab {
  Pieces pieces;
  std::uint32_t lo = 0, hi = 0;
};

/// Divide-and-conquer: one part's clipper and buffers, and what its clipping gives: triangles
/// of input vertices only (already in caller indices), and the triangles at Steiner points, to
/// be redone.
struct DividePart {
  MakeClipper made_by = nullptr;  ///< what made `clipper`
  std::unique_ptr<CycleClipper> clipper;
  Boundary piece;
  FanReducer fans;
  TriangleList local;
  TriangleList kept;
  std::vector<SteinerTriangle> at_steiner;
  std::vector<std::uint8_t> on_boundary;  ///< per triangle at Steiner points, see find_holes
  std::vector<std::uint8_t> pinch;        ///< the piece's nodes at repeated positions
  std::vector<std::uint32_t> on_line;     ///< nodes of the piece that may share a position
  bool ok = true;

  /// The part's clipper from `make`, made again only when another function makes them.
  CycleClipper& clipper_from(MakeClipper make) {
    if (!clipper || made_by != make) clipper = make(), made_by = make;
    return *clipper;
  }
};

struct VariantScratch {
  SharedBoundary shared;
  std::vector<ChainClipper> clippers;            ///< partition-and-cut: one per chain
  std::vector<TriangleList> parts;               ///< each chain's or chunk's triangles
  std::vector<std::vector<std::uint32_t>> ears;  ///< mark-and-cut: each chunk's ears
  /// Divide-and-conquer: the slabs of each level of the halving, the first the whole cycle;
  /// each array keeps its role from run to run, so that it is as large as that role needs.
  std::vector<std::vector<DivideSlab>> slab_levels;
  /// Divide-and-conquer: one per part (by pointer: a part is never moved, and the .wasm keeps
  /// no code to move one).
  std::vector<std::unique_ptr<DividePart>> divide_parts;
  /// Divide-and-conquer: the search for the holes at Steiner points (made on first use).
  std::unique_ptr<SteinerRepair> steiner_repair;
};

}  // namespace pear::detail
