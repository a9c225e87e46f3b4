// Triangle sets for the parallel flips (paper §2.4, Fig. 6b).
#pragma once

#include <cstdint>
#include <vector>

#include "mesh.hpp"

namespace pear::detail {

/// The triangles cut into consecutive pieces of one breadth-first walk of the dual graph.
struct TrianglePartition {
  std::vector<std::uint32_t> part;   ///< the set of each triangle
  std::vector<std::uint32_t> order;  ///< triangles in walk order
  std::vector<std::size_t> begin;    ///< set s is order[begin[s], begin[s + 1])
  std::size_t sets() const { return begin.empty() ? 0 : begin.size() - 1; }
};

/// Walks the dual graph breadth first (across edges with twins) from the first ear, a triangle
/// with two constraint edges, and cuts the walk into `sets` pieces of equal size. The paper found
/// breadth-first sets less fragmented than depth-first ones: fewer border flips. Deterministic.
void partition_triangles(const Mesh& mesh, std::uint32_t sets, TrianglePartition& partition);

}  // namespace pear::detail
