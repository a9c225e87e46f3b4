// Input checks, cleaning and repairs: the first stage of the pipeline (docs/architecture.md).
#pragma once

#include <span>
#include <vector>

#include "core/stage.hpp"

namespace pear::detail {

/// From this many points, when ctx has threads or partitions, the common case (every coordinate
/// in range, no spike, no ring dropped) is cleaned in parallel passes on ctx's runner; an input
/// that is not that case is cleaned again serially, which names what it finds. The same result
/// either way.
inline constexpr std::size_t clean_in_parts_from = std::size_t{1} << 15;
/// A parallel pass's share of the points (or corners) of the input or of a ring (at 8,192 a
/// polygon of 50,000 points made 7 tasks, fewer than 16 partitions).
inline constexpr std::size_t clean_chunk = std::size_t{1} << 12;

/// Checks the input and fills `out`. Returns Status::invalid_input (with an error diagnostic
/// naming ring and vertex) when nothing can be triangulated; warnings are appended too.
/// Records its phases in ctx's profile. `in_parts_from`: for tests.
Status clean_polygon(const InputPolygon& in, CleanPolygon& out,
                     std::vector<Diagnostic>& diagnostics, const RunContext& ctx = {},
                     std::size_t in_parts_from = clean_in_parts_from);

/// `in` with every edge split at the vertices lying inside it (sorted along each edge, as
/// SimplicityCheck::find_t_junctions gives them): a copy of such a vertex, with its caller's
/// index, goes into the edge, so the vertex is used by both rings (or twice by its own ring).
void split_at_t_junctions(const CleanPolygon& in, std::span<const TJunction> junctions,
                          CleanPolygon& out);

}  // namespace pear::detail
