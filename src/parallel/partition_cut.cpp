// Placeholder until partition-and-cut lands: leaves the whole cycle to the sequential engine.
#include "variants.hpp"

namespace pear::detail {

std::uint32_t partition_and_cut(Boundary&, std::uint32_t entry, const ParallelContext&,
                                TriangleList&) {
  return entry;
}

}  // namespace pear::detail
