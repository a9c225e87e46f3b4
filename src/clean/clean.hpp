// Input checks, cleaning and repairs: the first stage of the pipeline (docs/architecture.md).
#pragma once

#include <span>
#include <vector>

#include "core/stage.hpp"

namespace pear::detail {

/// Checks the input and fills `out`. Returns Status::invalid_input (with an error diagnostic
/// naming ring and vertex) when nothing can be triangulated; warnings are appended too.
Status clean_polygon(const InputPolygon& in, CleanPolygon& out,
                     std::vector<Diagnostic>& diagnostics);

/// `in` with every edge split at the vertices lying inside it (sorted along each edge, as
/// SimplicityCheck::find_t_junctions gives them): a copy of such a vertex, with its caller's
/// index, goes into the edge, so the vertex is used by both rings (or twice by its own ring).
void split_at_t_junctions(const CleanPolygon& in, std::span<const TJunction> junctions,
                          CleanPolygon& out);

}  // namespace pear::detail
