#include "partition.hpp"

#include <algorithm>
#include <utility>

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

bool runs_make_sets(ClipOrder order, std::size_t count, std::uint32_t sets) {
  const std::size_t rest_limit = order.rest_on_seams ? 8 : 32;
  return sets > 1 && order.region_ordered <= count &&
         rest_limit * (count - order.region_ordered) <= count;
}

namespace {

/// The triangles a task sorts into sets (a range of the rest is also how far its triangles'
/// sets reach each other).
constexpr std::size_t triangles_per_range = 8192;
constexpr std::uint32_t unassigned = UINT32_MAX;

/// Sets for the triangles of [first, last): an ordered one (of the first `ordered`) by its run,
/// one of the rest (divide-and-conquer's repair patches, clipped ear by ear from their borders)
/// by its first neighbour among the ordered ones, else among the range's triangles before it
/// (never another task's: the result depends on the ranges only), else as the one before it.
void assign_range(const Mesh& mesh, std::size_t ordered, std::uint32_t sets, std::size_t first,
                  std::size_t last, std::uint32_t* part) {
  // The run of triangle u < ordered: the largest s with ordered * s / sets <= u.
  const auto run_of = [&](std::uint64_t u) {
    return static_cast<std::uint32_t>(((u + 1) * sets - 1) / ordered);
  };
  std::uint32_t previous = 0;
  for (std::size_t t = first; t < last; ++t) {
    std::uint32_t set = t < ordered ? run_of(t) : unassigned;
    for (std::size_t h = 3 * t; h < 3 * t + 3 && set == unassigned; ++h)
      if (const std::uint32_t u = mesh.twin[h] / 3; mesh.twin[h] != no_twin && u < ordered)
        set = run_of(u);
    for (std::size_t h = 3 * t; h < 3 * t + 3 && set == unassigned; ++h)
      if (const std::uint32_t u = mesh.twin[h] / 3; mesh.twin[h] != no_twin && u >= first && u < t)
        set = part[u];
    previous = part[t] = set == unassigned ? previous : set;
  }
}

}  // namespace

void partition_in_runs(const Mesh& mesh, ClipOrder clip_order, std::uint32_t sets,
                       const RunContext& ctx, TrianglePartition& partition) {
  const std::size_t count = mesh.triangles->size();
  const std::size_t ordered =
      clip_order.rest_on_seams ? std::min(clip_order.region_ordered, count) : count;
  // Unfilled: a vector zeroed both on this thread, 2-3 ms of Eurasia's CDT at 16 partitions
  // outside every phase.
  std::uint32_t* const part = regrow_unfilled(partition.part, count);
  std::uint32_t* const order = regrow_unfilled(partition.order, count);
  // A counting sort by set, stable: each set's run, then its share of the rest.
  // place[r * sets + s]: how many of range r's triangles are in set s, then where they go.
  const std::size_t ranges = (count + triangles_per_range - 1) / triangles_per_range;
  const auto range = [&](std::size_t r) {
    return std::pair(r * triangles_per_range, std::min(count, (r + 1) * triangles_per_range));
  };
  std::vector<std::size_t> place(ranges * sets, 0);
  ctx.run_tasks("cdt partition: clip order", ranges, [&](std::size_t r) {
    const auto [first, last] = range(r);
    assign_range(mesh, ordered, sets, first, last, part);
    for (std::size_t t = first; t < last; ++t) ++place[r * sets + part[t]];
  });
  partition.begin.assign(sets + 1, 0);
  for (std::size_t s = 0, at = 0; s < sets; ++s) {
    for (std::size_t r = 0; r < ranges; ++r) at += std::exchange(place[r * sets + s], at);
    partition.begin[s + 1] = at;
  }
  ctx.run_tasks("cdt partition: order", ranges, [&](std::size_t r) {
    const auto [first, last] = range(r);
    for (std::size_t t = first; t < last; ++t)
      order[place[r * sets + part[t]]++] = static_cast<std::uint32_t>(t);
  });
}

}  // namespace pear::detail
