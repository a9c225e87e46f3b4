#include "strip_fans.hpp"

#include <algorithm>
#include <vector>

#include "core/ear_test.hpp"
#include "geometry/segments.hpp"
#include "pear/predicates.hpp"

namespace pear::detail {
namespace {

/// A strip has at most four nodes that are not straight: the run's ends, A and B.
constexpr std::size_t max_bends = 4;

/// Places of the cycle a task of its passes takes.
constexpr std::size_t places_per_task = 4096;

/// The places in `order` of the nodes that are not exactly between their neighbours on one
/// line (or lie where another node does), in order; more than max_bends: none.
std::vector<std::size_t> bends(const Boundary& b, std::span<const std::uint32_t> order,
                               std::span<const std::uint8_t> pinch, const RunContext& ctx) {
  const std::size_t m = order.size(), tasks = ctx.tasks_for(m, places_per_task);
  // Each task's first max_bends + 1 (one more: too many), and how many it found.
  std::vector<std::size_t> found(tasks * (max_bends + 2), 0);
  ctx.run_tasks("strip: bends", tasks, [&](std::size_t task) {
    std::size_t* mine = &found[task * (max_bends + 2)];
    for (std::size_t i = part_begin(m, tasks, task); i < part_begin(m, tasks, task + 1); ++i) {
      const Point& p = b.pos[order[(i == 0 ? m : i) - 1]];
      const Point& t = b.pos[order[i]];
      const Point& n = b.pos[order[i + 1 == m ? 0 : i + 1]];
      if (!pinch[order[i]] && orient2d(p, t, n) == 0 && on_open_segment(t, p, n)) continue;
      mine[1 + mine[0]] = i;
      if (++mine[0] > max_bends) return;
    }
  });
  std::vector<std::size_t> places;
  for (std::size_t task = 0; task < tasks && places.size() <= max_bends; ++task) {
    const std::size_t* mine = &found[task * (max_bends + 2)];
    places.insert(places.end(), mine + 1, mine + 1 + mine[0]);
  }
  if (places.size() > max_bends) places.clear();
  return places;
}

}  // namespace

bool finish_strip_in_fans(const Boundary& b, std::span<const std::uint32_t> order,
                          std::span<const std::uint8_t> pinch, const RunContext& ctx,
                          TriangleList& out) {
  const std::size_t m = order.size();
  if (m < min_strip_nodes) return false;
  const std::vector<std::size_t> places = bends(b, order, pinch, ctx);
  // The run: the longest stretch of straight nodes between two bends, all nodes but 2 or 3.
  std::size_t first = 0, last_edge = 0;  // r_j is order[(first + j) % m], j in [0, last_edge]
  for (std::size_t k = 0; k < places.size(); ++k) {
    const std::size_t from = places[k], to = places[(k + 1) % places.size()];
    const std::size_t edges = (to + m - from) % m;
    if (edges > last_edge) first = from, last_edge = edges;
  }
  if (last_edge + 3 < m) return false;
  const auto run = [&](std::size_t j) { return order[(first + j) % m]; };
  const std::uint32_t a = order[(first + last_edge + 1) % m], bb = order[(first + m - 1) % m];
  const Point &pa = b.pos[a], &pb = b.pos[bb];
  const Point &p0 = b.pos[run(0)], &pl = b.pos[run(last_edge)];
  const bool whole = a == bb;
  const bool use_a = !pinch[a] && orient2d(b.pos[run(last_edge - 1)], pl, pa) > 0;
  const bool use_b = !whole && !pinch[bb] && orient2d(pb, p0, b.pos[run(1)]) > 0;
  if (!use_a && !use_b) return false;
  // B's fan takes r_0 .. r_split, A's r_split .. r_last.
  const std::size_t tasks = ctx.tasks_for(last_edge, places_per_task);
  std::size_t split = use_a ? 0 : last_edge;
  if (use_a && use_b) {
    std::vector<std::size_t> first_nearer(tasks, last_edge);
    ctx.run_tasks("strip: split", tasks, [&](std::size_t task) {
      for (std::size_t j = part_begin(last_edge, tasks, task);
           j < part_begin(last_edge, tasks, task + 1); ++j) {
        const Point& x = b.pos[run(j)];
        if (squared_distance(pa, x) < squared_distance(pb, x)) {
          first_nearer[task] = j;
          return;
        }
      }
    });
    split = *std::min_element(first_nearer.begin(), first_nearer.end());
  }
  // The two diagonals at r_split lie inside: a side they could cross, B's or A's, has its end
  // in the other fan's triangle, since no other node is left to hold one. The middle triangle
  // turns left.
  const Point& ps = b.pos[run(split)];
  const auto in_closed_triangle = [](const Point& u, const Point& v, const Point& w,
                                     const Point& x) {
    return orient2d(u, v, x) >= 0 && orient2d(v, w, x) >= 0 && orient2d(w, u, x) >= 0;
  };
  if (!whole && ((split < last_edge && in_closed_triangle(ps, pl, pa, pb)) ||
                 (split > 0 && in_closed_triangle(pb, p0, ps, pa)) || !(orient2d(pb, ps, pa) > 0)))
    return false;
  const std::size_t base = out.size();
  out.resize(base + m - 2);
  const std::uint32_t va = b.vertex[a], vb = b.vertex[bb];
  ctx.run_tasks("strip: fans", tasks, [&](std::size_t task) {
    for (std::size_t j = part_begin(last_edge, tasks, task);
         j < part_begin(last_edge, tasks, task + 1); ++j)
      out[base + j] = {j < split ? vb : va, b.vertex[run(j)], b.vertex[run(j + 1)]};
  });
  if (!whole) out[base + last_edge] = {vb, b.vertex[run(split)], va};
  return true;
}

}  // namespace pear::detail
