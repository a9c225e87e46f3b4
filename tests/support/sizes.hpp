// Sizes of test polygons. Under the sanitizers (CI's ASan and TSan builds) the largest
// families shrink: what those builds look for (a read past a buffer, a race between tasks) shows
// at a few thousand vertices, split into the same chains, chunks and parts, while 40,000-vertex
// families took a minute each of CI's 30. The release builds run the full sizes.
#pragma once

#include <algorithm>
#include <cstddef>

#include "pear/geometry.hpp"

namespace pear::testing {

#ifdef PEAR_TEST_SANITIZED
inline constexpr bool sanitized = true;
#else
inline constexpr bool sanitized = false;
#endif

/// `n` in a release build, a quarter of it (at least 2,000) under the sanitizers.
constexpr std::size_t family_size(std::size_t n) {
  return !sanitized || n <= 2000 ? n : std::max<std::size_t>(n / 4, 2000);
}

/// Past this many vertices (of the corpus only GSHHG's Eurasia, 1.5M) the corpus tests run a
/// smaller matrix than on the other coastlines.
inline constexpr std::size_t huge_vertices = 1'000'000;

/// Every ring's points, all rings.
inline std::size_t vertex_count(const Polygon& polygon) {
  std::size_t n = 0;
  for (const Ring& ring : polygon) n += ring.size();
  return n;
}

}  // namespace pear::testing
