// Input checks and cleaning: the first stage of the engine (see STYLE.md "data flows one way").
#pragma once

#include <cstdint>
#include <vector>

#include "pear/geometry.hpp"
#include "pear/pear.hpp"

namespace pear::detail {

/// The polygon after cleaning: repeated consecutive points and closing points dropped, outer ring
/// counterclockwise, holes clockwise, degenerate holes removed.
struct CleanPolygon {
  std::vector<Point> points;               ///< kept vertices, ring after ring
  std::vector<std::uint32_t> original;     ///< the caller's index of each kept vertex
  std::vector<std::uint32_t> ring_starts;  ///< kept ring r is [ring_starts[r], ring_starts[r+1])
  std::vector<std::uint32_t> ring_source;  ///< the caller's ring number of each kept ring
  std::size_t ring_count() const { return ring_starts.empty() ? 0 : ring_starts.size() - 1; }
  void clear() {
    points.clear();
    original.clear();
    ring_starts.clear();
    ring_source.clear();
  }
};

/// Checks the input and fills `out`. Returns Status::invalid_input (with an error diagnostic
/// naming ring and vertex) when nothing can be triangulated; warnings are appended too.
Status clean_polygon(const FlatPolygon& in, CleanPolygon& out,
                     std::vector<Diagnostic>& diagnostics);

}  // namespace pear::detail
