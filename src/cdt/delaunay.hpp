// Constrained Delaunay triangulation by exact edge flips (paper §2.4), sequential and parallel.
#pragma once

#include <memory>
#include <span>

#include "core/stage.hpp"

namespace pear::detail {

/// The CDT's arrays (the mesh and its build's keys, the sets, the flags, the clip's copy, the
/// border rounds' marks), kept between runs: the engine keeps one, made on first use. Allocated
/// and freed by every run, Eurasia's took 13 ms of its CDT at 16 partitions on the calling
/// thread, outside every phase (most of it handing 150 MB back to the system).
struct DelaunayScratch;
struct DelaunayScratchDeleter {
  void operator()(DelaunayScratch* scratch) const noexcept;
};
using DelaunayScratchPtr = std::unique_ptr<DelaunayScratch, DelaunayScratchDeleter>;

/// The clipper's order, which the parallel flips' sets may follow (see partition.hpp).
struct ClipOrder {
  /// How many of the first triangles came out region by region (partition-and-cut's chains,
  /// one after another; divide-and-conquer's parts).
  std::size_t region_ordered = 0;
  /// Whether the rest lies along the regions' seams (divide-and-conquer's repair patches) and
  /// joins the set beside it; else (partition-and-cut's sequential finish, across the polygon:
  /// spread over the sets by neighbours, Koch-8's border flips at 16 took 2x as long) the rest
  /// goes to the last set.
  bool rest_on_seams = false;
};

/// Flips the triangulation `triangles` of the polygon `polygon` (triangles index the caller's
/// points, `points`) into the polygon's constrained Delaunay triangulation. The constraints are
/// the polygon's ring edges; bridges and other diagonals are not. Runs in parallel when
/// ctx.parallel(); the result depends on ctx.partitions at most through cocircular ties.
/// `order`: when nearly all triangles came out region by region, the parallel flips' sets are
/// runs of that order (see partition.hpp). `scratch` is made when empty.
/// Never inlined into the engine: the WebAssembly build compiles it for size and the engine for
/// speed (src/meson.build).
[[gnu::noinline]] void make_delaunay(std::span<const Point> points, const CleanPolygon& polygon,
                                     TriangleList& triangles, const RunContext& ctx,
                                     DelaunayStatistics& stats, DelaunayScratchPtr& scratch,
                                     ClipOrder order = {});

}  // namespace pear::detail
