// Boundaries as the engine builds them, for the tests of the stages that read one (the bridges,
// the clipping strategies): every ring of a cleaned polygon a cycle, nothing joined yet.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "clean/clean.hpp"
#include "core/boundary.hpp"
#include "core/stage.hpp"
#include "pear/detail/flat_polygon.hpp"

namespace pear::detail::testing {

/// The polygon as the engine cleans it (expected to be clean: status ok).
inline CleanPolygon cleaned(const Polygon& polygon) {
  FlatPolygon flat;
  flatten(polygon, flat);
  CleanPolygon clean;
  std::vector<Diagnostic> diagnostics;
  EXPECT_EQ(clean_polygon(PolygonView{flat.points, flat.ring_starts}, clean, diagnostics),
            Status::ok);
  return clean;
}

/// One node per clean vertex, each ring linked as a cycle (node i is clean vertex i).
inline Boundary rings_as_cycles(const CleanPolygon& clean) {
  Boundary b;
  for (std::size_t r = 0; r < clean.ring_count(); ++r) {
    const std::uint32_t first = clean.ring_starts[r], last = clean.ring_starts[r + 1] - 1;
    for (std::uint32_t i = first; i <= last; ++i) b.add(clean.points[i], clean.original[i]);
    for (std::uint32_t i = first; i < last; ++i) b.link(i, i + 1);
    b.link(last, first);
  }
  return b;
}

/// The nodes of the cycle through v (stops past b.size(): a broken list cannot hang a test).
inline std::size_t cycle_length(const Boundary& b, std::uint32_t v) {
  std::size_t n = 0;
  std::uint32_t u = v;
  do {
    ++n;
    u = b.next[u];
  } while (u != v && n <= b.size());
  return n;
}

}  // namespace pear::detail::testing
