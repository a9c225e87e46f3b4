// Input checks and cleaning: the first stage of the pipeline (docs/architecture.md).
#pragma once

#include <vector>

#include "core/stage.hpp"

namespace pear::detail {

/// Checks the input and fills `out`. Returns Status::invalid_input (with an error diagnostic
/// naming ring and vertex) when nothing can be triangulated; warnings are appended too.
Status clean_polygon(const PolygonView& in, CleanPolygon& out,
                     std::vector<Diagnostic>& diagnostics);

}  // namespace pear::detail
