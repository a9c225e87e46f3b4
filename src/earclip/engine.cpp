#include "engine.hpp"

#include <algorithm>

namespace pear::detail {

Diagnostic Engine::locate(const FlatPolygon& input, Issue issue, std::uint32_t caller_index) const {
  const auto ring_end =
      std::upper_bound(input.ring_starts.begin(), input.ring_starts.end(), caller_index);
  const std::size_t ring = static_cast<std::size_t>(ring_end - input.ring_starts.begin()) - 1;
  return {issue, ring, caller_index - input.ring_starts[ring]};
}

bool Engine::prepare(const FlatPolygon& input, bool check_simplicity,
                     std::vector<Diagnostic>& diagnostics, Status& status) {
  status = clean_polygon(input, clean_, diagnostics);
  if (status != Status::ok) return false;
  if (check_simplicity) {
    if (const auto vertex = simplicity_.find_violation(clean_)) {
      diagnostics.push_back(locate(input, Issue::not_simple, clean_.original[*vertex]));
      status = Status::not_simple;
    }
  }
  boundary_.clear();
  for (std::size_t r = 0; r < clean_.ring_count(); ++r) {
    const std::uint32_t first = clean_.ring_starts[r], last = clean_.ring_starts[r + 1] - 1;
    for (std::uint32_t i = first; i <= last; ++i)
      boundary_.add(clean_.points[i], clean_.original[i]);
    for (std::uint32_t i = first; i < last; ++i) boundary_.link(i, i + 1);
    boundary_.link(last, first);
  }
  for (std::uint32_t hole : bridger_.join(clean_, boundary_)) {
    diagnostics.push_back(locate(input, Issue::not_simple, boundary_.vertex[hole]));
    status = Status::not_simple;
  }
  return true;
}

Status Engine::triangulate(const FlatPolygon& input, const Options& options, TriangleList& out,
                           std::vector<Diagnostic>& diagnostics) {
  out.clear();
  Status status;
  if (!prepare(input, options.check_simplicity, diagnostics, status)) return status;
  out.reserve(boundary_.size());
  if (!clipper_.run(boundary_, 0, options.heuristic, out) && status == Status::ok) {
    diagnostics.push_back(locate(input, Issue::not_simple, clipper_.best_effort_vertex()));
    status = Status::not_simple;
  }
  return status;
}

EarStatistics Engine::statistics(const FlatPolygon& input) {
  std::vector<Diagnostic> ignored;
  Status status;
  if (!prepare(input, false, ignored, status)) return {};
  return clipper_.statistics(boundary_, 0);
}

}  // namespace pear::detail
