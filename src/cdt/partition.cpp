#include "partition.hpp"

namespace pear::detail {
namespace {

/// The first triangle with two constraint edges (an ear of the polygon), else triangle 0.
std::uint32_t first_ear(const Mesh& mesh) {
  const std::size_t count = mesh.triangles->size();
  for (std::uint32_t t = 0; t < count; ++t) {
    int constraints = 0;
    for (std::uint32_t k = 0; k < 3; ++k) constraints += mesh.twin[3 * t + k] == no_twin ? 1 : 0;
    if (constraints >= 2) return t;
  }
  return 0;
}

}  // namespace

void partition_triangles(const Mesh& mesh, std::uint32_t sets, TrianglePartition& partition) {
  const std::size_t count = mesh.triangles->size();
  constexpr std::uint32_t unvisited = UINT32_MAX;
  partition.part.assign(count, unvisited);
  partition.order.clear();
  partition.order.reserve(count);
  // The walk's queue is `order` itself; a new start is taken when a component is exhausted.
  std::uint32_t next_start = 0;
  std::uint32_t start = count > 0 ? first_ear(mesh) : 0;
  for (std::size_t head = 0; partition.order.size() < count;) {
    if (head == partition.order.size()) {
      while (partition.part[start] != unvisited) start = next_start++;
      partition.part[start] = 0;
      partition.order.push_back(start);
    }
    const std::uint32_t t = partition.order[head++];
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t g = mesh.twin[3 * t + k];
      if (g == no_twin || partition.part[g / 3] != unvisited) continue;
      partition.part[g / 3] = 0;
      partition.order.push_back(g / 3);
    }
  }
  partition.begin.assign(sets + 1, 0);
  for (std::uint32_t s = 0; s <= sets; ++s) partition.begin[s] = count * s / sets;
  for (std::uint32_t s = 0; s < sets; ++s)
    for (std::size_t i = partition.begin[s]; i < partition.begin[s + 1]; ++i)
      partition.part[partition.order[i]] = s;
}

bool runs_make_sets(std::size_t region_ordered, std::size_t count, std::uint32_t sets) {
  return sets > 1 && region_ordered <= count && 32 * (count - region_ordered) <= count;
}

void partition_in_runs(std::size_t count, std::uint32_t sets, const RunContext& ctx,
                       TrianglePartition& partition) {
  // Unfilled: a vector zeroed both on this thread, 2-3 ms of Eurasia's CDT at 16 partitions
  // outside every phase.
  regrow_unfilled(partition.part, count);
  regrow_unfilled(partition.order, count);
  partition.begin.assign(sets + 1, 0);
  for (std::uint32_t s = 0; s <= sets; ++s) partition.begin[s] = count * s / sets;
  ctx.run_tasks("cdt partition: clip order", sets, [&](std::size_t s) {
    for (std::size_t t = partition.begin[s]; t < partition.begin[s + 1]; ++t) {
      partition.part[t] = static_cast<std::uint32_t>(s);
      partition.order[t] = static_cast<std::uint32_t>(t);
    }
  });
}

}  // namespace pear::detail
