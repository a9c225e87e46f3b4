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

}  // namespace pear::detail
