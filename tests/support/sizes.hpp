// Sizes of generated test polygons. Under the sanitizers (CI's ASan and TSan builds) the largest
// families shrink: what those builds look for (a read past a buffer, a race between tasks) shows
// at a few thousand vertices, split into the same chains, chunks and parts, while 40,000-vertex
// families took a minute each of CI's 30. The release builds run the full sizes.
#pragma once

#include <cstddef>

namespace pear::testing {

#ifdef PEAR_TEST_SANITIZED
inline constexpr bool sanitized = true;
#else
inline constexpr bool sanitized = false;
#endif

/// `n` in a release build, a quarter of it (at least 2,000) under the sanitizers.
constexpr std::size_t family_size(std::size_t n) {
  if (!sanitized || n <= 2000) return n;
  return n / 4 > 2000 ? n / 4 : 2000;
}

}  // namespace pear::testing
