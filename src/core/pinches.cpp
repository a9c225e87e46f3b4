#include "pinches.hpp"

namespace pear::detail {

void find_pinches(const Boundary& b, std::span<const std::uint8_t> alive, std::size_t live,
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

void fill_pinches(const Boundary& b, std::span<const std::uint8_t> alive, std::size_t live,
                  SharedPositions shared, std::vector<std::uint8_t>& pinch,
                  std::vector<std::uint32_t>& table) {
  if (shared.marks != nullptr && shared.marks->size() == b.size())
    pinch = *shared.marks;
  else if (shared.none)
    pinch.assign(b.size(), 0);
  else
    find_pinches(b, alive, live, pinch, table);
}

}  // namespace pear::detail
