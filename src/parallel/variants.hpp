// The three parallel ear-clipping variants of the paper (§2.1-2.3). Each works on the bridged
// boundary that the sequential engine prepared; the output depends on ctx.partitions only.
#pragma once

#include <cstdint>
#include <memory>

#include "core/boundary.hpp"
#include "core/cycle_clipper.hpp"
#include "core/pinches.hpp"
#include "core/stage.hpp"

namespace pear::detail {

inline constexpr std::uint32_t no_node = UINT32_MAX;

/// The parallel variants' arrays, kept between runs (variant_scratch.hpp);
/// opaque here, so that the engine's header and destructor stay small.
struct VariantScratch;
struct VariantScratchDeleter {
  void operator()(VariantScratch* scratch) const noexcept;
};
using VariantScratchPtr = std::unique_ptr<VariantScratch, VariantScratchDeleter>;

// The variants are never inlined into the engine (its one call site each would take them in
// whole): the WebAssembly build compiles them for size and the engine for speed (src/meson.build).

/// Paper §2.2: landmarks cut the cycle through `entry` into two chains a partition (one where
/// `flipped_after`: the CDT's sets are then runs of the chains' order), each clipped by its own
/// task with its own ear queue; landmarks are never clipped. Appends the triangles (chain after
/// chain) to `out` and returns a live node of what is left for the sequential engine to finish,
/// or no_node when nothing is left. `shared`: the nodes at repeated positions when the engine
/// knows them (else they are hashed here). `scratch`: made on first use, kept for the next run.
[[gnu::noinline]] std::uint32_t partition_and_cut(Boundary& b, std::uint32_t entry,
                                                  EarHeuristic heuristic, const RunContext& ctx,
                                                  TriangleList& out, VariantScratchPtr& scratch,
                                                  SharedPositions shared = {},
                                                  bool flipped_after = false);

/// Paper §2.3: rounds of "mark every second convex node, clip in parallel the marked ones that
/// are ears" until a round clips few; returns what is left, as partition_and_cut does.
[[gnu::noinline]] std::uint32_t mark_and_cut(Boundary& b, std::uint32_t entry,
                                             const RunContext& ctx, TriangleList& out,
                                             VariantScratchPtr& scratch,
                                             SharedPositions shared = {});

/// Paper §2.1: splits the polygon bounded by the cycle through `entry` along ctx.partitions - 1
/// vertical lines, triangulates the parts in parallel, and removes the Steiner points again, so
/// that the triangles use input vertices only. Returns false when a best-effort fallback acted
/// (the boundary was not weakly simple); best_effort_vertex then names where (caller's index).
/// The parts, the holes the Steiner points leave and a fallback are clipped by clippers from
/// `make_clipper` (the sequential engine).
/// `region_ordered`: set to the size of `out` after the parts' triangles (part after part, each
/// a slab of the plane; the holes around the Steiner points come after), or left where it was
/// when the sequential engine did it all. `scratch`: made on first use (the parts' clippers
/// among it), kept for the next run.
/// `shared`: as for partition_and_cut; the parts' clippers get it for their input vertices
/// (a Steiner point can only meet nodes on its line, which each part compares).
/// `last_share`: the rightmost part's share of the vertices against each other part's.
[[gnu::noinline]] bool divide_and_conquer(Boundary& b, std::uint32_t entry, EarHeuristic heuristic,
                                          MakeClipper make_clipper, const RunContext& ctx,
                                          TriangleList& out, std::uint32_t& best_effort_vertex,
                                          std::size_t& region_ordered, VariantScratchPtr& scratch,
                                          SharedPositions shared, double last_share = 1);

}  // namespace pear::detail
