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

/// Flips the triangulation `triangles` of the polygon `polygon` (triangles index the caller's
/// points, `points`) into the polygon's constrained Delaunay triangulation. The constraints are
/// the polygon's ring edges; bridges and other diagonals are not. Runs in parallel when
/// ctx.parallel(); the result depends on ctx.partitions at most through cocircular ties.
/// `region_ordered`: how many of the first triangles the clipper emitted region by region
/// (partition-and-cut's chains, one after another); when they are nearly all, the parallel
/// flips' sets are runs of that order (see partition.hpp). `scratch` is made when empty.
/// Never inlined into the engine: the WebAssembly build compiles it for size and the engine for
/// speed (src/meson.build).
[[gnu::noinline]] void make_delaunay(std::span<const Point> points, const CleanPolygon& polygon,
                                     TriangleList& triangles, const RunContext& ctx,
                                     DelaunayStatistics& stats, DelaunayScratchPtr& scratch,
                                     std::size_t region_ordered = 0);

}  // namespace pear::detail
