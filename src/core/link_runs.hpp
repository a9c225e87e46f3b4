// A boundary made of rings is long runs of consecutive node numbers: node u links to u + 1 but
// where a ring ends, a bridge or a split joins, or a node was unlinked. Its cycles can then be
// walked run by run, a few hundred steps on a coast of a million nodes, once the links that
// jump are known; those are found by parallel tasks over node ranges. Used where a walk node by
// node would be a serial phase of a parallel run (SharedBoundary::start, TouchingPoints::cycles).
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/boundary.hpp"
#include "core/stage.hpp"

namespace pear::detail {

/// The fewest nodes worth a task of their own in a pass over the links (at 16,384 Borneo's
/// 53,410 nodes made three tasks at 16 partitions, the longest three times a sixteenth).
inline constexpr std::size_t min_nodes_per_link_task = 4096;
/// Runs pay off when they are this long on average; with more jumps (a boundary that clipping
/// or splitting has rearranged) the callers walk node by node.
inline constexpr std::size_t min_nodes_per_run = 64;

/// A stretch of a cycle whose nodes are consecutive numbers: `length` nodes from `first`.
struct LinkRun {
  std::uint32_t first, length;
};

/// The tasks a pass over `nodes` nodes takes at `partitions` partitions.
inline std::size_t link_tasks(std::size_t nodes, std::uint32_t partitions) {
  return std::clamp<std::size_t>(nodes / min_nodes_per_link_task, 1, partitions);
}

/// Every node u with b.next[u] != u + 1, ascending, found by `tasks` tasks of ctx (phase
/// `phase`), each calling also `visit(first, last)` for its range of nodes (to fill arrays
/// there). Returns false, with `jumps` incomplete, when they are more than one in
/// min_nodes_per_run nodes.
template <class Visit>
bool find_link_jumps(const Boundary& b, const RunContext& ctx, const char* phase, std::size_t tasks,
                     std::vector<std::uint32_t>& jumps, Visit&& visit) {
  const std::size_t size = b.size(), most = size / min_nodes_per_run + 1;
  std::vector<std::vector<std::uint32_t>> found(tasks);
  ctx.run_tasks(phase, tasks, [&](std::size_t task) {
    const std::size_t first = size * task / tasks, last = size * (task + 1) / tasks;
    visit(first, last);
    for (std::size_t u = first; u < last && found[task].size() <= most; ++u)
      if (b.next[u] != u + 1) found[task].push_back(static_cast<std::uint32_t>(u));
  });
  jumps.clear();
  for (const auto& part : found) jumps.insert(jumps.end(), part.begin(), part.end());
  return jumps.size() <= most;
}

/// The sorted, distinct nodes the jumps land on, and `also` (a cycle's entry): where runs
/// start.
inline std::vector<std::uint32_t> run_heads(const Boundary& b,
                                            const std::vector<std::uint32_t>& jumps,
                                            std::uint32_t also) {
  std::vector<std::uint32_t> heads{also};
  for (std::uint32_t u : jumps) heads.push_back(b.next[u]);
  std::sort(heads.begin(), heads.end());
  heads.erase(std::unique(heads.begin(), heads.end()), heads.end());
  return heads;
}

/// The run from `head`: it ends at the first jump at or after head, or before the next head.
/// `jumps` and `heads` ascending; false when no jump follows (the links do not close).
inline bool run_from(std::uint32_t head, const std::vector<std::uint32_t>& jumps,
                     const std::vector<std::uint32_t>& heads, LinkRun& run) {
  const auto jump = std::lower_bound(jumps.begin(), jumps.end(), head);
  const auto after = std::upper_bound(heads.begin(), heads.end(), head);
  if (jump == jumps.end()) return false;
  const std::uint32_t last = after == heads.end() ? *jump : std::min(*jump, *after - 1);
  run = {head, last - head + 1};
  return true;
}

/// Where each jump of `jumps` (ascending) leads: the node it links to, and the index of the
/// first jump at or after that node, where the run it starts ends.
struct JumpLinks {
  std::vector<std::uint32_t> target, next_jump;
};

/// JumpLinks for `jumps`, by `tasks` tasks of ctx (phase `phase`): each a binary search and a
/// read of a link far away, so the walk over the runs only follows indices.
inline void link_jumps(const Boundary& b, const std::vector<std::uint32_t>& jumps,
                       const RunContext& ctx, const char* phase, std::size_t tasks,
                       JumpLinks& links) {
  const std::size_t count = jumps.size();
  links.target.resize(count);
  links.next_jump.resize(count);
  ctx.run_tasks(phase, tasks, [&](std::size_t task) {
    for (std::size_t k = count * task / tasks; k < count * (task + 1) / tasks; ++k) {
      const std::uint32_t to = b.next[jumps[k]];
      links.target[k] = to;
      links.next_jump[k] = static_cast<std::uint32_t>(
          std::lower_bound(jumps.begin(), jumps.end(), to) - jumps.begin());
    }
  });
}

/// The cycle through `entry` as runs of consecutive node numbers, in cycle order: a run from a
/// node ends at the first jump at or after it (every node before that links to the next), or
/// where the cycle comes back to `entry`. Empty when the links do not close into a cycle (the
/// caller walks node by node then).
inline std::vector<LinkRun> cycle_runs(const Boundary& b, std::uint32_t entry,
                                       const std::vector<std::uint32_t>& jumps,
                                       const JumpLinks& links) {
  std::vector<LinkRun> runs;
  auto k =
      static_cast<std::size_t>(std::lower_bound(jumps.begin(), jumps.end(), entry) - jumps.begin());
  std::uint32_t head = entry;
  std::size_t nodes = 0;
  while (k < jumps.size() && runs.size() <= jumps.size()) {
    runs.push_back({head, jumps[k] - head + 1});
    nodes += runs.back().length;
    const std::uint32_t to = links.target[k];
    const std::size_t after = links.next_jump[k];
    if (to == entry) return nodes <= b.size() ? runs : std::vector<LinkRun>{};
    // The run from `to` reaches entry: entry - 1 links to it, the cycle closes there.
    if (to < entry && (after == jumps.size() || entry <= jumps[after])) {
      runs.push_back({to, entry - to});
      nodes += entry - to;
      return nodes <= b.size() ? runs : std::vector<LinkRun>{};
    }
    if (nodes > b.size()) break;
    head = to;
    k = after;
  }
  return {};
}

/// A cycle's runs (cycle_runs) with where each starts in the cycle: the node at any position
/// is known without a walk, so tasks can fill the cycle's order part by part.
struct CycleLayout {
  std::vector<LinkRun> runs;
  std::vector<std::size_t> start;  ///< each run's position in the cycle
  std::size_t size = 0;            ///< the cycle's nodes

  void assign(std::vector<LinkRun> cycle) {
    runs = std::move(cycle);
    start.clear();
    size = 0;
    for (const LinkRun& run : runs) start.push_back(std::exchange(size, size + run.length));
  }
  /// Calls visit(i, node) for the positions i in [from, to), in order.
  template <class Visit>
  void for_positions(std::size_t from, std::size_t to, Visit&& visit) const {
    auto r = static_cast<std::size_t>(std::upper_bound(start.begin(), start.end(), from) -
                                      start.begin() - 1);
    for (std::size_t i = from; i < to; ++r) {
      const std::size_t end = std::min(to, start[r] + runs[r].length);
      for (; i < end; ++i) visit(i, static_cast<std::uint32_t>(runs[r].first + (i - start[r])));
    }
  }
};

/// Every this many nodes by number one is a ruler of walk_cycle_by_rulers.
inline constexpr std::uint32_t ruler_stride = 64;

/// The cycle through `entry` into `cycle` (resized, then every entry written: a FillVector or
/// a vector) by a ruling set, list ranking for links that jump too often for runs (random
/// holes: runs of 2.5 nodes): every node numbered a multiple of ruler_stride is a ruler, and
/// the entry; tasks walk from each ruler to the next one along the links, keeping the nodes
/// they pass, this thread chains the rulers from the entry's (a 64th of the nodes), and tasks
/// copy each ruler's stretch to its place. Rulers off the cycle (rings left out, nodes
/// unlinked) are never reached from the entry. False, `cycle` untouched, where the links do
/// not close within the boundary's size.
template <class Cycle>
bool walk_cycle_by_rulers(const Boundary& b, std::uint32_t entry, const RunContext& ctx,
                          Cycle& cycle) {
  constexpr std::uint32_t none = UINT32_MAX;
  const auto n = static_cast<std::uint32_t>(b.size());
  const std::uint32_t multiples = (n + ruler_stride - 1) / ruler_stride;
  const std::uint32_t rulers = multiples + (entry % ruler_stride == 0 ? 0 : 1);
  const auto node_of = [&](std::uint32_t r) { return r < multiples ? r * ruler_stride : entry; };
  const auto ruler_of = [&](std::uint32_t v) {
    if (v % ruler_stride == 0) return v / ruler_stride;
    return v == entry ? multiples : none;
  };
  // Four tasks a partition of at least 16 rulers: the stretches differ in length and in how
  // far apart in memory their nodes lie (the holes grid: one task of 14 took 0.06 ms, the
  // others under 0.005). Ruler r's stretch is passed[task][start[r]...], length[r] nodes.
  const std::size_t tasks = ctx.tasks_for(rulers, 16);
  std::vector<std::uint32_t> next_ruler(rulers), length(rulers), start(rulers);
  std::vector<std::uint32_t> offset(rulers, none);
  std::vector<std::vector<std::uint32_t>> passed(tasks);
  const auto ruler_range = [&](std::size_t t) {
    return std::pair(static_cast<std::uint32_t>(part_begin(rulers, tasks, t)),
                     static_cast<std::uint32_t>(part_begin(rulers, tasks, t + 1)));
  };
  ctx.run_tasks("cycle: ruler walks", tasks, [&](std::size_t t) {
    std::vector<std::uint32_t>& nodes = passed[t];
    const auto [from, to] = ruler_range(t);
    nodes.reserve(std::size_t{to - from} * ruler_stride);  // about as many as they pass
    for (std::uint32_t r = from; r < to; ++r) {
      start[r] = static_cast<std::uint32_t>(nodes.size());
      std::uint32_t v = node_of(r);
      do {
        nodes.push_back(v);
        v = b.next[v];
      } while (ruler_of(v) == none && nodes.size() - start[r] < n);
      next_ruler[r] = ruler_of(v);  // none: the links do not close
      length[r] = static_cast<std::uint32_t>(nodes.size() - start[r]);
    }
  });
  std::size_t size = 0;
  bool closed = false;
  ctx.run_serial("cycle: rulers", [&] {
    const std::uint32_t first = ruler_of(entry);
    for (std::uint32_t r = first; r != none && offset[r] == none && size <= n;) {
      offset[r] = static_cast<std::uint32_t>(size);
      size += length[r];
      r = next_ruler[r];
      closed = r == first;
    }
  });
  if (!closed || size > n) return false;
  cycle.resize(size);
  ctx.run_tasks("cycle: copy", tasks, [&](std::size_t t) {
    for (auto [r, last] = ruler_range(t); r < last; ++r)
      if (offset[r] != none)
        std::copy_n(passed[t].begin() + start[r], length[r], cycle.begin() + offset[r]);
  });
  return true;
}

}  // namespace pear::detail
