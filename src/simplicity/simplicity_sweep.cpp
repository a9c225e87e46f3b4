// The Shamos-Hoey sweep for SimplicityCheck: edges enter a status ordered bottom to top when the
// sweep reaches their left end and leave at their right end; only edges that become neighbours
// there are tested. The first conflict in sweep order is always found before the order could
// go wrong, and the search stops at the first conflict found. It works on any subset of the
// edges (a conflict among them is found if there is one), which lets slabs be swept apart.
// The same sweep lists the T-junctions (a vertex inside an edge): touching edges never swap
// places in the status, so it goes on past them and stops only at a crossing or an overlap.
#include <algorithm>
#include <set>

#include "geometry/segments.hpp"
#include "geometry/sort.hpp"
#include "pear/predicates.hpp"
#include "simplicity.hpp"

namespace pear::detail {
namespace {

struct Segment {
  Point left, right;
};

/// Orders edges (by position in the subset) from bottom to top where the later-starting one
/// begins (or, sharing a start, just after it). Collinear overlapping edges compare equal in
/// geometry: that is a conflict, recorded, and ordered by position to stay a strict order.
struct Below {
  const std::vector<Segment>* segments;
  std::span<const std::uint32_t> subset;
  mutable std::uint32_t overlap = UINT32_MAX;

  bool operator()(std::uint32_t s, std::uint32_t t) const {
    if (s == t) return false;
    const Segment &a = (*segments)[s], &b = (*segments)[t];
    const bool a_later = !lexicographic_less(a.left, b.left);
    const Segment &later = a_later ? a : b, &earlier = a_later ? b : a;
    double side =
        later.left == earlier.left ? 0 : orient2d(earlier.left, earlier.right, later.left);
    if (side == 0) side = orient2d(earlier.left, earlier.right, later.right);
    if (side == 0) {
      overlap = std::min(subset[s], subset[t]);
      return s < t;
    }
    return a_later ? side < 0 : side > 0;  // is a below b?
  }
};

/// Code 2s inserts the subset's edge s at its left end, 2s + 1 removes it at its right end.
struct Event {
  Point at;
  std::uint32_t code;
};

/// In sweep order; at one point, removals come before insertions, so edges meeting end to end
/// are never both in the status. The point is copied in: sorting then reads no other array.
std::vector<Event> sorted_events(const std::vector<Segment>& segments) {
  std::vector<Event> events(2 * segments.size());
  for (std::uint32_t s = 0; s < segments.size(); ++s) {
    events[2 * s] = {segments[s].left, 2 * s};
    events[2 * s + 1] = {segments[s].right, 2 * s + 1};
  }
  detail::sort(events.begin(), events.end(), [](const Event& p, const Event& q) {
    if (p.at.x != q.at.x) return p.at.x < q.at.x;
    if (p.at.y != q.at.y) return p.at.y < q.at.y;
    if (p.code % 2 != q.code % 2) return p.code % 2 > q.code % 2;
    return p.code < q.code;
  });
  return events;
}

/// The sweep over a subset: visit(e, f) (edge indices) for every pair of edges that become
/// neighbours in the status; a value it returns stops the sweep and is returned, as is the
/// smaller edge of two that the order finds collinear and overlapping.
template <class Visit>
std::optional<std::uint32_t> sweep(const RingEdges& edges, std::span<const std::uint32_t> subset,
                                   Visit&& visit) {
  const auto& pts = *edges.points;
  std::vector<Segment> segments(subset.size());
  for (std::size_t s = 0; s < subset.size(); ++s) {
    const Point &a = pts[subset[s]], &b = pts[edges.next[subset[s]]];
    segments[s] = lexicographic_less(a, b) ? Segment{a, b} : Segment{b, a};
  }
  Below below{&segments, subset};
  std::set<std::uint32_t, Below> status(below);
  std::vector<std::set<std::uint32_t, Below>::iterator> place(subset.size());
  const auto meet = [&](std::uint32_t s, std::uint32_t t) { return visit(subset[s], subset[t]); };
  // Where a ring passes through a vertex, its edge ending there leaves the status and the next
  // one enters at the same place: the entering edge is inserted with the leaving one's
  // successor as a hint, in constant time instead of a search (std::set checks the hint and
  // searches only when it is wrong).
  Point left_at{};  // where the last edge left; an erase always renews the hint, so it is live
  auto hint = status.end();
  for (const Event& event : sorted_events(segments)) {
    const std::uint32_t s = event.code / 2;
    if (event.code % 2) {  // removal: its neighbours meet
      const auto it = place[s];
      const auto above = std::next(it);
      const bool has_below = it != status.begin();
      const auto under = has_below ? std::prev(it) : it;
      status.erase(it);
      left_at = event.at;
      hint = above;
      if (has_below && above != status.end())
        if (const auto found = meet(*under, *above)) return found;
      continue;
    }
    const auto it = left_at == event.at ? status.insert(hint, s) : status.insert(s).first;
    if (status.key_comp().overlap != UINT32_MAX) return status.key_comp().overlap;
    place[s] = it;
    if (it != status.begin())
      if (const auto found = meet(*std::prev(it), s)) return found;
    if (std::next(it) != status.end())
      if (const auto found = meet(s, *std::next(it))) return found;
  }
  return std::nullopt;
}

/// Each slab's edges (slab_borders), an edge in every slab its x-range meets. A conflict's
/// point lies in both edges' x-ranges, so its slab holds both edges: the slabs together miss no
/// conflict (nor a vertex inside an edge), wherever the borders are.
std::vector<std::vector<std::uint32_t>> slab_edges(const RingEdges& edges, std::uint32_t slabs,
                                                   const RunContext& ctx) {
  const std::uint32_t n = edges.size();
  const std::vector<double> borders = slab_borders(edges, slabs, ctx);
  const auto slab_of = [&](double x) {
    return static_cast<std::size_t>(std::upper_bound(borders.begin(), borders.end(), x) -
                                    borders.begin());
  };
  // Each chunk of edges lists its own per slab; a slab's list joins them in chunk order, so it
  // holds its edges in index order whatever the chunks. Four chunks a partition (in chunks of
  // 32,768 the 100k star's lists were four tasks, 0.45 ms over a sixteenth of their work).
  const std::size_t chunks = ctx.tasks_for(n, 4096);
  std::vector<std::vector<std::vector<std::uint32_t>>> parts(
      chunks, std::vector<std::vector<std::uint32_t>>(slabs));
  ctx.run_tasks("check simplicity: slab lists", chunks, [&](std::size_t c) {
    const auto end = static_cast<std::uint32_t>(part_begin(n, chunks, c + 1));
    for (auto e = static_cast<std::uint32_t>(part_begin(n, chunks, c)); e < end; ++e)
      for (std::size_t s = slab_of(edges.boxes[e].x0); s <= slab_of(edges.boxes[e].x1); ++s)
        parts[c][s].push_back(e);
  });
  std::vector<std::vector<std::uint32_t>> lists(slabs);
  ctx.run_tasks("check simplicity: slab lists, join", slabs, [&](std::size_t s) {
    std::size_t size = 0;
    for (const auto& part : parts) size += part[s].size();
    lists[s].reserve(size);
    for (const auto& part : parts) lists[s].insert(lists[s].end(), part[s].begin(), part[s].end());
  });
  return lists;
}

}  // namespace

/// Slab borders that give each slab about as many edges, an edge counted in every slab its
/// x-range meets (what a slab's sweep costs): chosen on a sample of the edges (every n/m-th),
/// by the smallest count per slab for which slabs - 1 borders, each placed as far right as
/// that count allows, leave no more for the last slab. Quantiles of the left ends alone gave
/// the 100k star's 12 slabs 8,332 to 19,890 edges (its longest sweep 2.9x its shortest).
/// The sample is read and sorted by ctx's tasks: on one thread, reading every n/m-th box missed
/// the cache at each, 0.25-0.32 ms serial of the star's 12.3 ms projected at 16 threads.
std::vector<double> slab_borders(const RingEdges& edges, std::uint32_t slabs,
                                 const RunContext& ctx) {
  const std::size_t n = edges.size(), m = std::min<std::size_t>(n, std::size_t{256} * slabs);
  std::vector<double> left(m), right(m);
  const std::size_t tasks = ctx.tasks_for(m, 256);
  ctx.run_tasks_if_threads("check simplicity: slab sample", tasks, [&](std::size_t t) {
    for (std::size_t k = part_begin(m, tasks, t); k < part_begin(m, tasks, t + 1); ++k) {
      const std::size_t e = static_cast<std::size_t>(std::uint64_t{k} * n / m);
      left[k] = edges.boxes[e].x0;
      right[k] = edges.boxes[e].x1;
    }
  });
  // 256 values a slab: the sort that costs the .wasm least is fast enough (0.14 ms for each of
  // the star's 4,096 values at 16 partitions, std::sort's time too), the two as two tasks.
  ctx.run_tasks_if_threads("check simplicity: slab sample, sort", 2, [&](std::size_t t) {
    std::vector<double>& values = t == 0 ? left : right;
    compact_sort(values.begin(), values.end(), std::less<>{});
  });
  // Slab s holds x in [borders[s - 1], borders[s]): an edge meets it when x0 < borders[s] and
  // x1 >= borders[s - 1]. Fills `borders` for `per_slab` and returns the last slab's count.
  std::vector<double> borders(slabs - 1);
  const auto place = [&](std::size_t per_slab) {
    std::size_t ended = 0;  // sampled edges wholly left of the current slab
    for (double& border : borders) {
      border = left[std::min(m - 1, per_slab + ended)];
      ended = static_cast<std::size_t>(std::lower_bound(right.begin(), right.end(), border) -
                                       right.begin());
    }
    return m - ended;
  };
  ctx.run_serial("check simplicity: slabs", [&] {
    std::size_t low = 1, high = m;  // place(high) fits: every border at the right end
    while (low < high) {
      const std::size_t mid = low + (high - low) / 2;
      if (place(mid) <= mid)
        high = mid;
      else
        low = mid + 1;
    }
    place(low);
  });
  return borders;
}

std::optional<std::uint32_t> sweep_edges(const RingEdges& edges,
                                         std::span<const std::uint32_t> subset) {
  return sweep(edges, subset,
               [&](std::uint32_t e, std::uint32_t f) -> std::optional<std::uint32_t> {
                 if (edges.conflict(e, f)) return std::min(e, f);
                 return std::nullopt;
               });
}

void sweep_in_slabs(const RingEdges& edges, std::uint32_t slabs, const RunContext& ctx,
                    SmallestViolation& found) {
  const auto lists = slab_edges(edges, slabs, ctx);
  ctx.run_tasks("check simplicity: sweep slabs", slabs, [&](std::size_t s) {
    if (const auto violation = sweep_edges(edges, lists[s])) found.offer(*violation);
  });
}

/// Touching edges keep their order in the status (neither crosses the other), so the sweep
/// goes on past them: every pair of touching edges becomes neighbours at some event, where it
/// is recorded. It stops at the first crossing or overlap, which no split resolves.
TJunctionSearch find_t_junctions_in_slabs(const RingEdges& edges, std::uint32_t slabs,
                                          const RunContext& ctx) {
  const auto lists = slab_edges(edges, slabs, ctx);
  std::vector<std::vector<TJunction>> found(slabs);
  SmallestViolation conflict;
  ctx.run_tasks("find t-junctions: sweep slabs", slabs, [&](std::size_t s) {
    const auto stop = sweep(edges, lists[s], [&](std::uint32_t e, std::uint32_t f) {
      return edges.t_junctions(e, f, found[s]) ? std::nullopt
                                               : std::optional<std::uint32_t>(std::min(e, f));
    });
    if (stop) conflict.offer(*stop);
  });
  TJunctionSearch search;
  if (conflict.get() != SmallestViolation::none) {
    search.conflict = conflict.get();
    return search;
  }
  for (const auto& list : found)
    search.junctions.insert(search.junctions.end(), list.begin(), list.end());
  return search;
}

}  // namespace pear::detail
