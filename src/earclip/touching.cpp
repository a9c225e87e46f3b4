#include "touching.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <utility>

#include "core/link_runs.hpp"
#include "core/pinches.hpp"
#include "geometry/sort.hpp"

namespace pear::detail {
namespace {

/// fetch_or on a word other tasks may set bits in too: std::atomic_ref where the library has
/// it (libc++ 14, the WebAssembly build's, has not: there the builtin it wraps).
std::uint64_t fetch_or_relaxed(std::uint64_t& word, std::uint64_t bit) {
#if defined(__cpp_lib_atomic_ref)
  return std::atomic_ref(word).fetch_or(bit, std::memory_order_relaxed);
#else
  return __atomic_fetch_or(&word, bit, __ATOMIC_RELAXED);
#endif
}

/// 0 for directions in [0, 180) degrees, 1 for [180, 360), from exact coordinate comparisons.
int half(const Point& centre, const Point& to) {
  return to.y < centre.y || (to.y == centre.y && to.x < centre.x) ? 1 : 0;
}

}  // namespace

std::uint32_t TouchingPoints::untangle(Boundary& b, const RunContext& ctx, std::size_t tasks) {
  if (tasks <= 1) {
    std::uint32_t overlapping = UINT32_MAX;
    ctx.run_serial("bridge: touching points", [&] {
      find_candidates(b, ctx, 1);
      overlapping = untangle_points(b);
    });
    return overlapping;
  }
  find_candidates(b, ctx, tasks);
  std::uint32_t overlapping = UINT32_MAX;
  ctx.run_serial("bridge: touching points", [&] { overlapping = untangle_points(b); });
  return overlapping;
}

void TouchingPoints::find_candidates(const Boundary& b, const RunContext& ctx, std::size_t tasks) {
  // Most boundaries visit only a few points more than once (bridge ends, touching rings), so
  // only the nodes whose position hashes to a slot another node shares are looked at again.
  // In parts, 16 slots a node instead of 4: a fifth as many false candidates (about 6% of the
  // nodes, not 22%) for the serial grouping that follows, for tasks that cost more memory.
  const std::size_t per_node = tasks <= 1 ? 4 : 16;
  const std::size_t table_bits = std::bit_width(std::max<std::size_t>(per_node * b.size(), 2) - 1);
  const auto slot = [&](const Point& p) {
    // + 0.0 makes -0 and +0 (equal points) hash alike.
    const std::uint64_t x = std::bit_cast<std::uint64_t>(p.x + 0.0);
    const std::uint64_t y = std::bit_cast<std::uint64_t>(p.y + 0.0);
    const std::uint64_t h = (x * 0x9e3779b97f4a7c15ull) ^ (y * 0xc2b2ae3d27d4eb4full);
    return static_cast<std::size_t>((h ^ (h >> 29)) >> (64 - table_bits));
  };
  // Two bits per slot (seen, seen twice), not a byte: a quarter of the memory, mostly in cache
  // on a boundary of millions of nodes.
  const std::size_t words = ((std::size_t{1} << table_bits) + 63) / 64;
  seen_once_.assign(words, 0);
  seen_twice_.assign(words, 0);
  order_.clear();
  if (tasks <= 1) {
    for (std::uint32_t u = 0; u < b.size(); ++u) {
      const std::size_t s = slot(b.pos[u]);
      const std::uint64_t bit = std::uint64_t{1} << (s % 64);
      seen_twice_[s / 64] |= seen_once_[s / 64] & bit;
      seen_once_[s / 64] |= bit;
    }
    for (std::uint32_t u = 0; u < b.size(); ++u) {
      const std::size_t s = slot(b.pos[u]);
      if ((seen_twice_[s / 64] >> (s % 64)) & 1) order_.push_back(u);
    }
    return;
  }
  // In parts: the bits by atomic or (the same bits in any order; the phase's end orders them
  // before the candidates are read), the candidates per chunk, joined in chunk order.
  const auto first = [&](std::size_t t) {
    return static_cast<std::uint32_t>(std::size_t{b.size()} * t / tasks);
  };
  ctx.run_tasks("bridge: touching points, hash", tasks, [&](std::size_t t) {
    for (std::uint32_t u = first(t); u < first(t + 1); ++u) {
      const std::size_t s = slot(b.pos[u]);
      const std::uint64_t bit = std::uint64_t{1} << (s % 64);
      if (fetch_or_relaxed(seen_once_[s / 64], bit) & bit)
        fetch_or_relaxed(seen_twice_[s / 64], bit);
    }
  });
  chunk_order_.resize(tasks);
  ctx.run_tasks("bridge: touching points, candidates", tasks, [&](std::size_t t) {
    std::vector<std::uint32_t>& found = chunk_order_[t];
    found.clear();
    for (std::uint32_t u = first(t); u < first(t + 1); ++u) {
      const std::size_t s = slot(b.pos[u]);
      if ((seen_twice_[s / 64] >> (s % 64)) & 1) found.push_back(u);
    }
  });
  for (const std::vector<std::uint32_t>& found : chunk_order_)
    order_.insert(order_.end(), found.begin(), found.end());
}

std::uint32_t TouchingPoints::untangle_points(Boundary& b) {
  // The candidates grouped by position in an open-addressing table (another hash: they share
  // slots of the first): same_[i] links the candidates at the position of order_[i]. Points
  // are independent (relinking one changes no position another reads), so their order is free.
  std::size_t capacity = 16;
  while (capacity < 2 * order_.size()) capacity *= 2;
  group_slots_.assign(capacity, UINT32_MAX);
  same_.assign(order_.size(), UINT32_MAX);
  heads_.clear();
  for (std::uint32_t i = 0; i < order_.size(); ++i) {
    const Point& at = b.pos[order_[i]];
    for (std::size_t s = position_hash(at) & (capacity - 1);; s = (s + 1) & (capacity - 1)) {
      const std::uint32_t k = group_slots_[s];
      if (k == UINT32_MAX) {
        group_slots_[s] = i;
        heads_.push_back(i);
        break;
      }
      if (b.pos[order_[k]] == at) {
        same_[i] = std::exchange(same_[k], i);
        break;
      }
    }
  }
  shared_.assign(b.size(), 0);
  std::uint32_t overlapping = UINT32_MAX;
  for (const std::uint32_t head : heads_) {
    if (same_[head] == UINT32_MAX) continue;
    group_.clear();
    for (std::uint32_t k = head; k != UINT32_MAX; k = same_[k]) {
      group_.push_back(order_[k]);
      shared_[order_[k]] = 1;
    }
    detail::sort(group_.begin(), group_.end());
    if (!untangle_point(b, group_.data(), group_.size()) && overlapping == UINT32_MAX)
      overlapping = group_[0];
  }
  return overlapping;
}

bool TouchingPoints::untangle_point(Boundary& b, const std::uint32_t* nodes, std::size_t count) {
  const Point centre = b.pos[nodes[0]];
  spokes_.clear();
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint32_t u = nodes[i];
    if (b.pos[b.prev[u]] == centre || b.pos[b.next[u]] == centre) return true;
    spokes_.push_back({b.pos[b.prev[u]], u, false});
    spokes_.push_back({b.pos[b.next[u]], u, true});
  }
  // Counterclockwise by direction, exactly: by half plane, then by orientation.
  const auto before = [&](const Spoke& s, const Spoke& t) {
    const int hs = half(centre, s.to), ht = half(centre, t.to);
    if (hs != ht) return hs < ht;
    return orient2d(centre, s.to, t.to) > 0;
  };
  // Along one direction, a bridge's two copies: the pass that comes back from the hole is the
  // clockwise one, so that the slit between them is outside. A spike tip's own two spokes go
  // the other way round: its wedge is empty.
  const auto order = [&](const Spoke& s, const Spoke& t) {
    if (before(s, t)) return true;
    if (before(t, s)) return false;
    if (s.out == t.out) return s.node < t.node;
    return s.node == t.node ? s.out : t.out;
  };
  detail::sort(spokes_.begin(), spokes_.end(), order);
  const std::size_t n = spokes_.size();
  for (std::size_t i = 0; i < n; ++i)  // not alternating: not a weakly simple crossing point
    if (spokes_[i].out == spokes_[(i + 1) % n].out) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Spoke &s = spokes_[i], &t = spokes_[(i + 1) % n];
    const bool along = !before(s, t) && !before(t, s);
    // Two spokes along one direction are a bridge (in, out) or a spike tip; more overlap.
    const Spoke& u = spokes_[(i + 2) % n];
    if (along && (s.out != (s.node == t.node) || (!before(t, u) && !before(u, t)))) return true;
  }
  // A pass enters along an in-spoke and leaves along the out-spoke just before it
  // counterclockwise: its interior wedge, from the out-spoke round to the in-spoke, is empty.
  successor_.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (spokes_[i].out) continue;
    const std::uint32_t leaving = spokes_[(i + n - 1) % n].node;
    successor_.push_back(spokes_[i].node);
    successor_.push_back(b.next[leaving]);
  }
  for (std::size_t i = 0; i < successor_.size(); i += 2) b.link(successor_[i], successor_[i + 1]);
  return true;
}

std::vector<std::uint32_t> TouchingPoints::cycles(const Boundary& b, std::uint32_t first,
                                                  const std::vector<std::uint32_t>& skip,
                                                  const RunContext& ctx, std::size_t tasks) {
  std::vector<std::uint32_t> entries;
#if !PEAR_HAS_THREADS
  (void)tasks;  // one walk: no runs to find in tasks
#else
  std::vector<std::uint32_t> jumps;
  if (tasks > 1 && find_link_jumps(b, ctx, "bridge: link jumps", tasks, jumps,
                                   [](std::size_t, std::size_t) {})) {
    bool found = false;
    ctx.run_serial("bridge: cycles",
                   [&] { found = cycles_by_runs(b, first, skip, jumps, entries); });
    if (found) return entries;
  }
#endif
  ctx.run_serial("bridge: cycles", [&] { entries = cycles_node_by_node(b, first, skip); });
  return entries;
}

std::vector<std::uint32_t> TouchingPoints::cycles_node_by_node(
    const Boundary& b, std::uint32_t first, const std::vector<std::uint32_t>& skip) {
  seen_.assign(b.size(), 0);
  const auto walk = [&](std::uint32_t start) {
    std::size_t length = 0;
    std::uint32_t v = start;
    do {
      seen_[v] = 1;
      ++length;
      v = b.next[v];
    } while (v != start);
    return length;
  };
  for (std::uint32_t hole : skip) walk(hole);
  std::vector<std::uint32_t> entries;
  if (!seen_[first] && walk(first) >= 3) entries.push_back(first);
  for (std::uint32_t u = 0; u < b.size(); ++u)
    if (!seen_[u] && walk(u) >= 3) entries.push_back(u);
  return entries;
}

#if PEAR_HAS_THREADS
bool TouchingPoints::cycles_by_runs(const Boundary& b, std::uint32_t first,
                                    const std::vector<std::uint32_t>& skip,
                                    const std::vector<std::uint32_t>& jumps,
                                    std::vector<std::uint32_t>& entries) {
  // Every node lies on one cycle (untangling only relinks), so the runs tile the nodes, and a
  // run's successor is the run its last link lands on.
  const std::vector<std::uint32_t> heads = run_heads(b, jumps, 0);
  std::vector<LinkRun> runs(heads.size());
  std::vector<std::uint32_t> successor(heads.size());
  const auto run_of = [&](std::uint32_t node) {
    return static_cast<std::uint32_t>(std::upper_bound(heads.begin(), heads.end(), node) -
                                      heads.begin() - 1);
  };
  for (std::size_t r = 0; r < heads.size(); ++r) {
    if (!run_from(heads[r], jumps, heads, runs[r])) return false;
    const std::uint32_t to = b.next[runs[r].first + runs[r].length - 1];
    successor[r] = run_of(to);
    if (heads[successor[r]] != to) return false;  // lands inside a run: not a cycle there
  }
  // Each cycle of runs once: its nodes, the lowest node first met in node order.
  std::vector<std::uint8_t> seen(heads.size(), 0);
  const auto walk = [&](std::uint32_t start) {
    std::size_t length = 0, steps = 0;
    std::uint32_t r = start;
    do {
      seen[r] = 1;
      length += runs[r].length;
      r = successor[r];
    } while (r != start && ++steps <= heads.size());
    return r == start ? length : 0;
  };
  for (std::uint32_t hole : skip)
    if (!seen[run_of(hole)] && walk(run_of(hole)) == 0) return false;
  entries.clear();
  if (!seen[run_of(first)]) {
    const std::size_t length = walk(run_of(first));
    if (length == 0) return false;
    if (length >= 3) entries.push_back(first);
  }
  for (std::uint32_t r = 0; r < heads.size(); ++r) {
    if (seen[r]) continue;
    const std::size_t length = walk(r);
    if (length == 0) return false;
    if (length >= 3) entries.push_back(heads[r]);
  }
  return true;
}
#endif

}  // namespace pear::detail
