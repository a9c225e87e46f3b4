// The simplicity check's runs monotone in x, prepared in parts (issue 27: no serial phase that
// can be split). Up to two partitions a large coast-like outline is checked by its runs
// (simplicity.cpp, check_chains); counting the reversals, the edges' boxes, cutting the rings
// into runs and sorting them was one serial step (Australia: 4 ms of a 45 ms run at 2
// threads). Here each is tasks over ranges of edges, runs or positions, and the runs come out
// as the serial code makes them, in the same order.
#include <algorithm>
#include <bit>

#include "core/sort_in_parts.hpp"
#include "geometry/segments.hpp"
#include "pear/predicates.hpp"
#include "simplicity.hpp"

namespace pear::detail {
namespace {

/// Range t of `tasks` over [0, n).
std::uint32_t range_start(std::size_t n, std::size_t t, std::size_t tasks) {
  return static_cast<std::uint32_t>(n * t / tasks);
}

/// For each edge of [first, end), in order, `visit(e, ring_first, ring_end)` with its ring's range.
template <class Visit>
void for_edges(const CleanPolygon& polygon, std::uint32_t first, std::uint32_t end, Visit&& visit) {
  if (first >= end) return;
  std::size_t r = polygon.ring_of(first);
  for (std::uint32_t e = first; e < end; ++e) {
    while (e >= polygon.ring_starts[r + 1]) ++r;
    visit(e, polygon.ring_starts[r], polygon.ring_starts[r + 1]);
  }
}

/// Positions [first, end) of the runs' order (each ring's own range, from run_start[r] on):
/// `at_position(p, e, starts)` with the edge e at position p and whether a run starts there.
template <class AtPosition>
void walk_run_positions(const CleanPolygon& polygon, const std::vector<std::uint32_t>& run_start,
                        const FillVector<std::int8_t>& direction, std::uint32_t first,
                        std::uint32_t end, AtPosition&& at_position) {
  if (first >= end) return;
  std::size_t r = polygon.ring_of(first);
  const auto edge_at = [&](std::uint32_t p, std::uint32_t ring_first, std::uint32_t ring_end) {
    const std::uint32_t e = run_start[r] + (p - ring_first);
    return e >= ring_end ? e - (ring_end - ring_first) : e;
  };
  std::int8_t last = 0;
  for (std::uint32_t p = first; p < end; ++p) {
    while (p >= polygon.ring_starts[r + 1]) ++r;
    const std::uint32_t ring_first = polygon.ring_starts[r], ring_end = polygon.ring_starts[r + 1];
    if (p == ring_first) {
      last = 0;
    } else if (p == first) {  // the last direction before it, as the positions before found it
      for (std::uint32_t q = p; last == 0 && q-- > ring_first;)
        last = direction[edge_at(q, ring_first, ring_end)];
    }
    const std::uint32_t e = edge_at(p, ring_first, ring_end);
    const std::int8_t d = direction[e];
    at_position(p, e, p == ring_first || (d != 0 && last != 0 && d != last));
    last = d != 0 ? d : last;
  }
}

}  // namespace

/// x_reversals(polygon) in tasks: each edge against the last edge before it in its ring
/// (cyclically) that is not vertical, found by a walk back at a range's or a ring's first edge.
std::size_t x_reversals(const CleanPolygon& polygon, const RunContext& ctx, std::size_t tasks) {
  const auto& pts = polygon.points;
  const std::size_t n = pts.size();
  std::vector<std::size_t> counts(tasks, 0);
  ctx.run_tasks("check simplicity: reversals", tasks, [&](std::size_t t) {
    std::size_t reversals = 0;
    int before = 0;
    const std::uint32_t first = range_start(n, t, tasks);
    for_edges(polygon, first, range_start(n, t + 1, tasks),
              [&](std::uint32_t e, std::uint32_t ring_first, std::uint32_t ring_end) {
                const auto next = [&](std::uint32_t i) {
                  return i + 1 == ring_end ? ring_first : i + 1;
                };
                if (e == first || e == ring_first) {
                  before = 0;
                  for (std::uint32_t i = e == ring_first ? ring_end - 1 : e - 1;
                       before == 0 && i != e; i = i == ring_first ? ring_end - 1 : i - 1)
                    before = x_direction(pts[i], pts[next(i)]);
                }
                const int d = x_direction(pts[e], pts[next(e)]);
                reversals += d * before < 0;
                before = d != 0 ? d : before;
              });
    counts[t] = reversals;
  });
  std::size_t reversals = 0;
  for (std::size_t c : counts) reversals += c;
  return reversals;
}

/// prepare_runs(polygon, true, budget) in tasks: the same fold, runs and order.
std::optional<std::uint32_t> SimplicityCheck::prepare_runs_in_parts(const CleanPolygon& polygon,
                                                                    std::size_t budget,
                                                                    const RunContext& ctx,
                                                                    std::size_t tasks) {
  const std::uint32_t fold = link_edges_in_parts(polygon, ctx, tasks);
  if (!cut_runs_in_parts(polygon, ctx, tasks)) return std::nullopt;
  finish_runs_in_parts(ctx, tasks);
  sort_runs_in_parts(ctx, tasks);
  if (chains_.size() * 64 < polygon.points.size() && !chains_within(budget)) return std::nullopt;
  return fold;
}

/// link_edges in tasks: each edge's successor, box and direction; returns the smallest edge
/// of a fold-back.
std::uint32_t SimplicityCheck::link_edges_in_parts(const CleanPolygon& polygon,
                                                   const RunContext& ctx, std::size_t tasks) {
  const auto& pts = polygon.points;
  const auto n = static_cast<std::uint32_t>(pts.size());
  edges_.points = &pts;
  edges_.next.resize(n);
  edges_.boxes.resize(n);
  direction_.resize(n);
  std::vector<std::uint32_t> folds(tasks, SmallestViolation::none);
  ctx.run_tasks("check simplicity: edges", tasks, [&](std::size_t t) {
    std::uint32_t smallest = SmallestViolation::none;
    for_edges(polygon, range_start(n, t, tasks), range_start(n, t + 1, tasks),
              [&](std::uint32_t e, std::uint32_t ring_first, std::uint32_t ring_end) {
                const std::uint32_t f = e + 1 == ring_end ? ring_first : e + 1;
                const std::uint32_t before = e == ring_first ? ring_end - 1 : e - 1;
                edges_.next[e] = f;
                const Point &a = pts[e], &b = pts[f], &p = pts[before];
                edges_.boxes[e] = edge_box(a, b);
                direction_[e] = x_direction(a, b);
                if (before < smallest && orient2d(p, a, b) == 0 &&
                    (on_open_segment(p, a, b) || on_open_segment(b, p, a) || p == b))
                  smallest = std::min(before, e);
              });
    folds[t] = smallest;
  });
  return *std::min_element(folds.begin(), folds.end());
}

/// Each ring's positions in chain_order_ are its own range, from the edge where its direction
/// first turns (monotone_chains: no run wraps around the ring's first point). A position starts
/// a run at its ring's first position, or where the direction turns from the last one that is
/// not vertical since then. Counted in tasks, then written; false for runs of under three
/// edges on average (not worth it, as monotone_chains says).
bool SimplicityCheck::cut_runs_in_parts(const CleanPolygon& polygon, const RunContext& ctx,
                                        std::size_t tasks) {
  const auto n = static_cast<std::uint32_t>(polygon.points.size());
  const std::size_t rings = polygon.ring_count();
  run_start_.resize(rings);
  // In tasks of rings: on one thread, 0.12 ms of a 12,499-hole polygon's check at 16 partitions.
  const std::size_t ring_tasks = ctx.tasks_for(rings, 256);
  ctx.run_tasks("check simplicity: ring starts", ring_tasks, [&](std::size_t t) {
    for (std::size_t r = range_start(rings, t, ring_tasks);
         r < range_start(rings, t + 1, ring_tasks); ++r)
      run_start_[r] = first_turn(polygon.ring_starts[r], polygon.ring_starts[r + 1]);
  });
  const auto walk = [&](std::size_t t, auto&& at_position) {
    walk_run_positions(polygon, run_start_, direction_, range_start(n, t, tasks),
                       range_start(n, t + 1, tasks), at_position);
  };
  std::vector<std::uint32_t> runs_before(tasks + 1, 0);
  ctx.run_tasks("check simplicity: runs", tasks, [&](std::size_t t) {
    std::uint32_t count = 0;
    walk(t, [&](std::uint32_t, std::uint32_t, bool starts) { count += starts; });
    runs_before[t + 1] = count;
  });
  for (std::size_t t = 0; t < tasks; ++t) runs_before[t + 1] += runs_before[t];
  constexpr std::size_t min_chain_edges = 3;
  if (runs_before[tasks] * min_chain_edges > n + min_chain_edges) return false;
  chains_.resize(runs_before[tasks]);
  chain_order_.resize(n);
  ctx.run_tasks("check simplicity: runs", tasks, [&](std::size_t t) {
    std::uint32_t k = runs_before[t];
    walk(t, [&](std::uint32_t p, std::uint32_t e, bool starts) {
      chain_order_[p] = e;
      if (starts) chains_[k++].begin = p;
    });
  });
  return true;
}

/// Each run's end, direction (its first edge that is not vertical), order and boxes.
void SimplicityCheck::finish_runs_in_parts(const RunContext& ctx, std::size_t tasks) {
  const auto runs = static_cast<std::uint32_t>(chains_.size());
  const auto n = static_cast<std::uint32_t>(chain_order_.size());
  chain_boxes_.resize(n);
  ctx.run_tasks("check simplicity: run boxes", tasks, [&](std::size_t t) {
    for (std::uint32_t k = range_start(runs, t, tasks); k < range_start(runs, t + 1, tasks); ++k) {
      Chain& chain = chains_[k];
      chain.end = k + 1 < runs ? chains_[k + 1].begin : n;
      std::int8_t direction = 0;
      for (std::uint32_t p = chain.begin; direction == 0 && p < chain.end; ++p)
        direction = direction_[chain_order_[p]];
      chain.decreasing = direction < 0;
      finish_run(chain);
    }
  });
}

/// The order of monotone_chains' sort (a strict total one, so any sort gives it): sorted in
/// up to `tasks` pieces (rounded up to a power of two) and merged in rounds whose merges are cut at
/// equal output positions, so that the last rounds run on every thread too (one merge of all the
/// runs was Eurasia's longest task of the check at 16 threads).
void SimplicityCheck::sort_runs_in_parts(const RunContext& ctx, std::size_t tasks) {
  sort_in_parts(ctx, "check simplicity: sort runs", "check simplicity: merge runs", chains_,
                chain_before, 256, std::bit_ceil(tasks));
}

}  // namespace pear::detail
