#include "pinches.hpp"

#include <bit>

namespace pear::detail {
namespace {

std::uint64_t position_hash(const Point& p) {
  const std::uint64_t x = std::bit_cast<std::uint64_t>(p.x + 0.0);  // -0 and +0 alike
  const std::uint64_t y = std::bit_cast<std::uint64_t>(p.y + 0.0);
  // splitmix64's finalizer: integer coordinates have all-zero low mantissa bits, so the table
  // index must depend on every bit.
  std::uint64_t h = x ^ (y * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull);
  h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
  h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
  return h ^ (h >> 31);
}

}  // namespace

void find_pinches(const Boundary& b, const std::vector<std::uint8_t>& alive, std::size_t live,
                  std::vector<std::uint8_t>& pinch, std::vector<std::uint32_t>& table) {
  pinch.assign(b.size(), 0);
  std::size_t capacity = 16;
  while (capacity < 2 * live) capacity *= 2;
  table.assign(capacity, UINT32_MAX);
  for (std::uint32_t u = 0; u < b.size(); ++u) {
    if (!alive[u]) continue;
    for (std::size_t slot = position_hash(b.pos[u]) & (capacity - 1);;
         slot = (slot + 1) & (capacity - 1)) {
      const std::uint32_t other = table[slot];
      if (other == UINT32_MAX) {
        table[slot] = u;
        break;
      }
      if (b.pos[other] == b.pos[u]) {
        pinch[u] = pinch[other] = 1;
        break;
      }
    }
  }
}

}  // namespace pear::detail
