#include "shared_boundary.hpp"

#include <algorithm>
#include <cmath>

#include "core/link_runs.hpp"
#include "core/pinches.hpp"
#include "pear/config.hpp"
#include "variants.hpp"

namespace pear::detail {

#if PEAR_HAS_THREADS
void SharedBoundary::walk_cycle(std::uint32_t entry, const RunContext& ctx) {
  const std::size_t size = b->size();
  const std::size_t parts = link_tasks(size, ctx.partitions);
  ctx.run_serial("classify: allocate", [&] {
    alive.resize(size);
    hashed.resize(size);
    owner.resize(size);
    stamp.resize(size);
  });
  // The arrays' fill and the links that jump, in parts; the cycle's order from them.
  std::vector<std::uint32_t> jumps;
  const bool few = find_link_jumps(
      *b, ctx, "classify: jumps", parts, jumps, [&](std::size_t first, std::size_t last) {
        std::fill(alive.begin() + first, alive.begin() + last, 0);
        std::fill(hashed.begin() + first, hashed.begin() + last, 0);
        std::fill(owner.begin() + first, owner.begin() + last, landmark);
        std::fill(stamp.begin() + first, stamp.begin() + last, 0);
      });
  JumpLinks links;
  if (few) link_jumps(*b, jumps, ctx, "classify: jump links", parts, links);
  CycleLayout layout;
  ctx.run_serial("classify: walk", [&] {
    if (few) layout.assign(cycle_runs(*b, entry, jumps, links));
    if (layout.runs.empty()) return walk_node_by_node(entry);  // many jumps
    order.resize(layout.size);
  });
  if (!layout.runs.empty()) {
    ctx.run_tasks("classify: order", parts, [&](std::size_t part) {
      layout.for_positions(part_begin(order.size(), parts, part),
                           part_begin(order.size(), parts, part + 1),
                           [&](std::size_t i, std::uint32_t node) {
                             order[i] = node;
                             alive[node] = 1;
                           });
    });
  }
}
#else
/// Without threads no part runs beside another: the walk node by node (the runs' code would
/// only add to the .wasm).
void SharedBoundary::walk_cycle(std::uint32_t entry, const RunContext& ctx) {
  ctx.run_serial("classify: walk", [&] {
    const std::size_t size = b->size();
    alive.assign(size, 0);
    hashed.assign(size, 0);
    owner.assign(size, landmark);
    stamp.assign(size, 0);
    walk_node_by_node(entry);
  });
}
#endif

void SharedBoundary::walk_node_by_node(std::uint32_t entry) {
  order.clear();
  std::uint32_t v = entry;
  do {
    alive[v] = 1;
    order.push_back(v);
    v = b->next[v];
  } while (v != entry);
}

std::size_t SharedBoundary::start(Boundary& boundary, std::uint32_t entry, const RunContext& ctx,
                                  SharedPositions shared) {
  b = &boundary;
  walk_cycle(entry, ctx);
  ctx.run_serial("classify: pinches", [&] {
    // Known from the check and the bridges (the engine's marks): no hashing of every node.
    std::vector<std::uint32_t> table;
    fill_pinches(*b, alive, order.size(), shared, pinch, table);
  });
  ctx.run_tasks("classify", ctx.partitions, [&](std::size_t part) {
    const std::size_t first = part_begin(order.size(), ctx.partitions, part);
    const std::size_t last = part_begin(order.size(), ctx.partitions, part + 1);
    for (std::size_t i = first; i < last; ++i) {
      const std::uint32_t u = order[i];
      hashed[u] = pinch[u] || b->turn(u) < 0;
    }
  });
  return order.size();
}

std::uint32_t SharedBoundary::refresh_order(const RunContext& ctx) {
  std::uint32_t entry = no_node;
  for (std::uint32_t u : order)
    if (alive[u]) {
      entry = u;
      break;
    }
  order.clear();
  if (entry == no_node) return entry;
  ctx.run_serial("walk", [&] {
    std::uint32_t v = entry;
    do {
      order.push_back(v);
      v = b->next[v];
    } while (v != entry);
  });
  return entry;
}

std::vector<std::size_t> SharedBoundary::place_landmarks(std::size_t chain_count,
                                                         std::size_t offset, const RunContext& ctx,
                                                         StartIndex index) {
  chains = chain_count;
  std::vector<std::size_t> marks(chains);
  const std::size_t count = order.size();
  for (std::size_t i = 0; i < chains; ++i)
    marks[i] = (offset + part_begin(count, chains, i)) % count;
  landmarks.clear();
  for (std::size_t mark : marks)
    if (hashed[order[mark]]) landmarks.push_back(order[mark]);
  if (index == StartIndex::grids)
    start_grids.resize(chains);
  else if (start_lists.size() < chains)  // a fresh vector where resize's code cost the .wasm
    start_lists = std::vector<StartList>(chains);
  ctx.run_tasks("place landmarks", chains, [&](std::size_t chain) {
    const std::size_t first = marks[chain], last = marks[(chain + 1) % chains];
    owner[order[first]] = landmark;
    std::vector<std::uint32_t> nodes;
    for (const auto run : between(first, last))
      for (const std::uint32_t u : run) {
        owner[u] = static_cast<std::uint32_t>(chain);
        if (hashed[u]) nodes.push_back(u);
      }
    if (index == StartIndex::grids)
      start_grids[chain].build(*b, nodes);
    else
      start_lists[chain].build(*b, nodes);
  });
  return marks;
}

void StartList::build(const Boundary& b, const std::vector<std::uint32_t>& nodes) {
  entries.resize(nodes.size());
  blocks.resize(2 * ((nodes.size() + block - 1) / block));
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const Point& p = b.pos[nodes[i]];
    entries[i] = {p, nodes[i]};
    Point& low = blocks[2 * (i / block)];
    Point& high = blocks[2 * (i / block) + 1];
    if (i % block == 0) low = high = p;
    low = {std::min(low.x, p.x), std::min(low.y, p.y)};
    high = {std::max(high.x, p.x), std::max(high.y, p.y)};
  }
}

}  // namespace pear::detail
