// Nodes that share their position with another live node (bridge ends, rings touching at a
// vertex): they stay hashed whatever their angle, since a convex one at an ear's corner can
// still reach into the ear (the strictly-reflex argument does not cover a chain that touches
// a corner).
#pragma once

#include <cstdint>
#include <vector>

#include "boundary.hpp"

namespace pear::detail {

/// Sets pinch[u] for every live node u (alive[u] != 0) whose position another live node has;
/// `live` is the number of live nodes, `table` scratch memory. Exact (hash on the coordinates).
void find_pinches(const Boundary& b, const std::vector<std::uint8_t>& alive, std::size_t live,
                  std::vector<std::uint8_t>& pinch, std::vector<std::uint32_t>& table);

}  // namespace pear::detail
