// What partition-and-cut and mark-and-cut allocate for a run, kept between runs by whoever runs
// them (the engine keeps one). Freed at the end of every call, a large polygon's arrays cost a
// serial tail, and their pages faulted in again at the next call: Eurasia at 16 partitions, on
// one thread, spent 7.5 ms after partition-and-cut's last phase and 18 ms after mark-and-cut's
// freeing them.
#pragma once

#include <cstdint>
#include <vector>

#include "chain_clipper.hpp"
#include "shared_boundary.hpp"

namespace pear::detail {

struct VariantScratch {
  SharedBoundary shared;
  std::vector<ChainClipper> clippers;            ///< partition-and-cut: one per chain
  std::vector<TriangleList> parts;               ///< each chain's or chunk's triangles
  std::vector<std::vector<std::uint32_t>> ears;  ///< mark-and-cut: each chunk's ears
};

}  // namespace pear::detail
