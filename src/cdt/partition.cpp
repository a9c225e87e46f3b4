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

/// The triangles past the region-ordered ones a task assigns to sets.
constexpr std::size_t rest_per_task = 4096;
constexpr std::uint32_t unassigned = UINT32_MAX;

/// The run set s takes of the first `ordered` triangles.
std::size_t run_begin(std::size_t ordered, std::uint32_t sets, std::size_t s) {
  return part_begin(ordered, sets, s);
}

/// Sets for the triangles [first, last) past the `ordered` ones (divide-and-conquer's repair
/// patches): each beside an ordered triangle takes the set of its first such neighbour; the
/// others, in passes while they reach further, the set of their first neighbour in this range
/// that has one (never another task's: the result depends on the ranges only); any left the set
/// of the one before them in the range, the first ones the set of the first assigned.
void assign_rest(const Mesh& mesh, std::size_t ordered, std::size_t first, std::size_t last,
                 std::uint32_t* part) {
  const auto first_neighbour = [&](std::size_t t, auto has_set) {
    for (std::size_t h = 3 * t; h < 3 * t + 3; ++h)
      if (const std::uint32_t g = mesh.twin[h]; g != no_twin && has_set(g / 3)) return part[g / 3];
    return unassigned;
  };
  for (std::size_t t = first; t < last; ++t)
    part[t] = first_neighbour(t, [&](std::uint32_t u) { return u < ordered; });
  const auto in_range_with_set = [&](std::uint32_t u) {
    return u >= first && u < last && part[u] != unassigned;
  };
  for (bool reached = true, left = true; reached && left;) {
    reached = left = false;
    for (std::size_t t = first; t < last; ++t) {
      if (part[t] != unassigned) continue;
      part[t] = first_neighbour(t, in_range_with_set);
      (part[t] == unassigned ? left : reached) = true;
    }
  }
  const auto known =
      std::find_if(part + first, part + last, [](std::uint32_t s) { return s != unassigned; });
  std::uint32_t previous = known == part + last ? 0 : *known;
  for (std::size_t t = first; t < last; ++t)
    previous = part[t] = part[t] == unassigned ? previous : part[t];
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
  regrow_unfilled(partition.order, count);
  ctx.run_tasks("cdt partition: clip order", sets, [&](std::size_t s) {
    for (std::size_t t = run_begin(ordered, sets, s); t < run_begin(ordered, sets, s + 1); ++t)
      part[t] = static_cast<std::uint32_t>(s);
  });
  // The rest by ranges of their own; rest[r * sets + s]: range r's triangles in set s.
  const std::size_t ranges = (count - ordered + rest_per_task - 1) / rest_per_task;
  std::vector<std::size_t> rest(ranges * sets, 0);
  ctx.run_tasks("cdt partition: the rest", ranges, [&](std::size_t r) {
    const std::size_t first = ordered + r * rest_per_task;
    const std::size_t last = std::min(count, first + rest_per_task);
    assign_rest(mesh, ordered, first, last, part);
    for (std::size_t t = first; t < last; ++t) ++rest[r * sets + part[t]];
  });
  // Set s: its run, then its share of the rest, range by range, each in triangle order.
  partition.begin.assign(sets + 1, 0);
  for (std::uint32_t s = 0; s < sets; ++s) {
    std::size_t at =
        partition.begin[s] + run_begin(ordered, sets, s + 1) - run_begin(ordered, sets, s);
    for (std::size_t r = 0; r < ranges; ++r) at += std::exchange(rest[r * sets + s], at);
    partition.begin[s + 1] = at;
  }
  std::uint32_t* const order = partition.order.data();
  ctx.run_tasks("cdt partition: order", sets + ranges, [&](std::size_t task) {
    if (task < sets) {
      const std::size_t from = run_begin(ordered, sets, task);
      for (std::size_t t = from; t < run_begin(ordered, sets, task + 1); ++t)
        order[partition.begin[task] + t - from] = static_cast<std::uint32_t>(t);
      return;
    }
    const std::size_t r = task - sets, first = ordered + r * rest_per_task;
    for (std::size_t t = first; t < std::min(count, first + rest_per_task); ++t)
      order[rest[r * sets + part[t]]++] = static_cast<std::uint32_t>(t);
  });
}

}  // namespace pear::detail
