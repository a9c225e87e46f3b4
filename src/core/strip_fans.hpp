// What a comb becomes once its teeth are clipped: a strip between the teeth's feet, tens of
// thousands of nodes on a line, and the one or two nodes across from them. Its ears come one at
// a time (each spans the strip): mark-and-cut's rounds stop there (2.6 of the comb's 3.5 ms at
// 16 partitions went to the sequential engine clipping it), and the sequential engine spent
// half its clip on it. Every triangle there joins two neighbours on the line to one of the
// nodes across, so the triangulation is two fans; both write them instead (in ctx's tasks).
#pragma once

#include <cstdint>
#include <span>

#include "core/boundary.hpp"
#include "core/stage.hpp"

namespace pear::detail {

/// The fewest nodes worth the fans' tasks; below, the sequential engine finishes.
inline constexpr std::size_t min_strip_nodes = 4096;

/// Triangulates the cycle whose nodes `order` lists along b's links when it is a strip: a
/// straight run r_0 .. r_last (every node between its ends exactly on the segment between its
/// neighbours, none at a position another node has: `pinch`, by node) and the node A after it
/// and the node B before it (the same node: a triangle with a run on one side), the cycle
/// turning strictly left at r_0 towards B and at r_last towards A where they take part. B's
/// fan takes the run up to its first node nearer to A than to B, A's fan the rest (one of them
/// all of it, where the other cannot see the run), and the triangle A, B and the node where the
/// fans meet joins them: each node goes to the nearer of the two, as `top` clips a strip from
/// both ends. Appends the m - 2 triangles (caller's indices, counterclockwise, the same for
/// every thread count and ctx.partitions) in ctx's tasks and returns true; returns false, with
/// nothing appended, for any other cycle.
bool finish_strip_in_fans(const Boundary& b, std::span<const std::uint32_t> order,
                          std::span<const std::uint8_t> pinch, const RunContext& ctx,
                          TriangleList& out);

}  // namespace pear::detail
