// The benchmark's inputs: synthetic families at several sizes and the shared corpus's files.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "pear/geometry.hpp"

namespace bench {

struct Input {
  std::string name;      ///< "koch-100k", "coast/eurasia", ...
  std::size_t vertices;  ///< about how many, to choose before loading
  std::function<pear::Polygon()> load;
};

/// Families at 1k, 10k, 100k and 1M vertices (4M too when PEAR_BENCH_LARGE=1), then the
/// corpus's synthetic/ and coast/ files when the corpus directory exists (PEAR_BENCH_CORPUS,
/// else the build's default); inputs above PEAR_BENCH_MAX_VERTICES are left out. Messages
/// about what is left out go to stderr.
std::vector<Input> inputs();

}  // namespace bench
