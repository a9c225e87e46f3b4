// Nodes that share their position with another live node (bridge ends, rings touching at a
// vertex): they stay hashed whatever their angle, since a convex one at an ear's corner can
// still reach into the ear (the strictly-reflex argument does not cover a chain that touches
// a corner).
#pragma once

#include <bit>
#include <cstdint>
#include <span>
#include <vector>

#include "boundary.hpp"

namespace pear::detail {

/// A hash of a position that depends on every bit of both coordinates (splitmix64's finalizer):
/// integer coordinates have all-zero low mantissa bits, and table indices take the low bits.
inline std::uint64_t position_hash(const Point& p) {
  const std::uint64_t x = std::bit_cast<std::uint64_t>(p.x + 0.0);  // -0 and +0 alike
  const std::uint64_t y = std::bit_cast<std::uint64_t>(p.y + 0.0);
  std::uint64_t h = x ^ (y * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull);
  h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
  h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
  return h ^ (h >> 31);
}

/// Which nodes share their position with another node (bridge ends, rings touching at a
/// vertex), as the pipeline learnt it before clipping: the clippers test those in every ear
/// test, whatever their angle. Marks may include nodes whose twin is in another cycle: an extra
/// hashed node can only make an ear test stricter.
struct SharedPositions {
  const std::vector<std::uint8_t>* marks = nullptr;  ///< per node, when known (TouchingPoints)
  bool none = false;  ///< the caller knows that no two nodes share a position
};

/// Sets pinch[u] for every live node u (alive[u] != 0) whose position another live node has;
/// `live` is the number of live nodes, `table` scratch memory. Exact (hash on the coordinates).
void find_pinches(const Boundary& b, std::span<const std::uint8_t> alive, std::size_t live,
                  std::vector<std::uint8_t>& pinch, std::vector<std::uint32_t>& table);

/// pinch as find_pinches sets it, taken from `shared` where the pipeline already knows the
/// repeated positions (its marks for every node of b, or none at all): no hashing then.
void fill_pinches(const Boundary& b, std::span<const std::uint8_t> alive, std::size_t live,
                  SharedPositions shared, std::vector<std::uint8_t>& pinch,
                  std::vector<std::uint32_t>& table);

}  // namespace pear::detail
