#include "simplicity.hpp"

#include <algorithm>
#include <bit>
#include <limits>
#include <utility>

#include "geometry/box_scan.hpp"
#include "geometry/segments.hpp"
#include "geometry/sort.hpp"
#include "pear/config.hpp"
#include "pear/predicates.hpp"

namespace pear::detail {
namespace {

bool opposite(double s, double t) {
  return (s > 0 && t < 0) || (s < 0 && t > 0);
}

/// Slabs for the sweep when the grid gives up. Up to two partitions, enough for two threads and
/// few enough that the edges crossing slab borders (swept twice) stay a small part; past two,
/// one a partition while each keeps 4,096 edges: a star's long edges cross many borders (100,000
/// vertices at 16 partitions in 12 slabs of 8,192 or more: 1.3x the work, span 31 -> 10 ms; in
/// 16: the sweeps' work 68.6 -> 84.5 ms, their longest 6.3 -> 5.8 ms). Counts only.
std::uint32_t slab_count(std::uint32_t n, std::uint32_t partitions) {
  if (partitions <= 2) return std::clamp<std::uint32_t>(n / 16384, 1, 2);
  return std::clamp<std::uint32_t>(n / 4096, 1, partitions);
}

}  // namespace

/// One pass, no branch but at the ends of the rings.
std::size_t x_reversals(const CleanPolygon& polygon) {
  const Point* pts = polygon.points.data();
  std::size_t reversals = 0;
  for (std::size_t r = 0; r < polygon.ring_count(); ++r) {
    const std::uint32_t first = polygon.ring_starts[r], last = polygon.ring_starts[r + 1] - 1;
    const auto direction = [](double dx) { return (dx > 0) - (dx < 0); };
    // Entering the ring from its last edge that is not vertical: a cycle turns back evenly.
    int before = direction(pts[first].x - pts[last].x);
    for (std::uint32_t i = last; before == 0 && i > first; --i)
      before = direction(pts[i].x - pts[i - 1].x);
    for (std::uint32_t i = first; i < last; ++i) {
      const int d = direction(pts[i + 1].x - pts[i].x);
      reversals += d * before < 0;
      before = d != 0 ? d : before;
    }
    reversals += direction(pts[first].x - pts[last].x) * before < 0;
  }
  return reversals;
}

/// Two edges that are not neighbours conflict when they cross properly, when an endpoint of
/// one lies inside the other, or when they are the same segment.
bool RingEdges::separate_edges_conflict(std::uint32_t e, std::uint32_t f) const {
  const auto& pts = *points;
  const Point &a = pts[e], &b = pts[next[e]], &c = pts[f], &d = pts[next[f]];
  const double o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  if (opposite(o1, o2)) {
    const double o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
    if (opposite(o3, o4)) return true;
    return (o3 == 0 && on_open_segment(a, c, d)) || (o4 == 0 && on_open_segment(b, c, d));
  }
  if ((o1 == 0 && on_open_segment(c, a, b)) || (o2 == 0 && on_open_segment(d, a, b))) return true;
  if (o1 == 0 && o2 == 0) {
    if (on_open_segment(a, c, d) || on_open_segment(b, c, d)) return true;
    return (a == c && b == d) || (a == d && b == c);
  }
  return false;
}

bool RingEdges::conflict(std::uint32_t e, std::uint32_t f) const {
  if (e == f) return false;
  const EdgeBox &s = boxes[e], &t = boxes[f];
  // Edges whose boxes do not meet cannot touch; most pairs sharing a cell end here.
  if (s.x1 < t.x0 || t.x1 < s.x0 || s.y1 < t.y0 || t.y1 < s.y0) return false;
  if (next[e] != f && next[f] != e) return separate_edges_conflict(e, f);
  const auto& pts = *points;
  const std::uint32_t shared = next[e] == f ? f : e;
  const std::uint32_t before = shared == f ? e : f, after = next[shared];
  return orient2d(pts[before], pts[shared], pts[after]) == 0 &&
         (on_open_segment(pts[before], pts[shared], pts[after]) ||
          on_open_segment(pts[after], pts[before], pts[shared]) || pts[before] == pts[after]);
}

bool RingEdges::t_junctions(std::uint32_t e, std::uint32_t f, std::vector<TJunction>& out) const {
  if (!conflict(e, f)) return true;
  if (next[e] == f || next[f] == e) return false;  // neighbours conflict only by folding back
  const auto& pts = *points;
  const Point &a = pts[e], &b = pts[next[e]], &c = pts[f], &d = pts[next[f]];
  const double o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  if (o1 == 0 && o2 == 0) return false;  // collinear and meeting: an overlap
  const double o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (opposite(o1, o2) && opposite(o3, o4)) return false;  // a proper crossing
  // Not collinear, so they meet in one point: an end of one inside the other.
  if (o1 == 0 && on_open_segment(c, a, b))
    out.push_back({e, f});
  else if (o2 == 0 && on_open_segment(d, a, b))
    out.push_back({e, next[f]});
  else if (o3 == 0 && on_open_segment(a, c, d))
    out.push_back({f, e});
  else if (o4 == 0 && on_open_segment(b, c, d))
    out.push_back({f, next[e]});
  return true;
}

void SimplicityCheck::index_edges(const CleanPolygon& polygon, const RunContext& ctx) {
  const auto n = static_cast<std::uint32_t>(polygon.points.size());
  edges_.points = &polygon.points;
  edges_.next.resize(n);
  edges_.boxes.resize(n);
  // Every edge as if it led to the next point, in tasks (in chunks of 65,536 and linked on one
  // thread, a polygon of 100,000 points made two tasks and a serial pass: at 16 partitions 0.1
  // ms where a sixteenth of the work was 0.01); then, in the same task, each ring's last edge
  // of the task's range, back to its ring's first point (a loop over the rings after the tasks
  // was 0.05 ms of a 12,499-hole polygon's check). The bounds need no correction: an edge from
  // a ring's last point to the next ring's first lies in the box of all points, which the true
  // edges' boxes span.
  const auto& pts = polygon.points;
  if (n == 0) return;
  const std::size_t tasks = ctx.tasks_for(n, 4096);
  std::vector<EdgeBox> bounds(tasks);
  ctx.run_tasks("check simplicity: edge boxes", tasks, [&](std::size_t t) {
    const std::size_t begin = part_begin(n, tasks, t), end = part_begin(n, tasks, t + 1);
    EdgeBox all = {pts[begin].x, pts[begin].y, pts[begin].x, pts[begin].y};
    for (std::size_t e = begin; e < end; ++e) {
      const std::size_t to = e + 1 < n ? e + 1 : e;
      edges_.next[e] = static_cast<std::uint32_t>(to);
      edges_.boxes[e] = edge_box(pts[e], pts[to]);
      all = merged(all, edges_.boxes[e]);
    }
    bounds[t] = all;
    const auto& starts = polygon.ring_starts;
    // The rings ending in [begin, end): from the ring of point `begin` on.
    for (std::size_t r = polygon.ring_of(begin); r + 1 < starts.size() && starts[r + 1] <= end;
         ++r) {
      const std::uint32_t first = starts[r], last = starts[r + 1] - 1;
      edges_.next[last] = first;
      edges_.boxes[last] = edge_box(pts[last], pts[first]);
    }
  });
  edges_.bounds = bounds[0];
  for (const EdgeBox& b : bounds) edges_.bounds = merged(edges_.bounds, b);
}

std::optional<std::uint32_t> SimplicityCheck::find_violation(const CleanPolygon& polygon,
                                                             const RunContext& ctx, Method method) {
  if (polygon.points.empty()) return std::nullopt;
  index_edges(polygon, ctx);
  GridLimits limits;
  if (method == Method::grid_only) {
    limits.leaf_edges = 2;
    limits.root_entries_per_edge = std::numeric_limits<double>::infinity();
    limits.allow_sweep = false;
  }
  SmallestViolation found;
  const bool decided =
      method != Method::sweep_only && check_on_grid(edges_, limits, ctx, root_, found);
  if (!decided)
    sweep_in_slabs(edges_,
                   method == Method::sweep_only ? 3 : slab_count(edges_.size(), ctx.partitions),
                   ctx, found);
  if (found.get() == SmallestViolation::none) return std::nullopt;
  return found.get();
}

TJunctionSearch SimplicityCheck::find_t_junctions(const CleanPolygon& polygon,
                                                  const RunContext& ctx, Method method) {
  if (polygon.points.empty()) return {};
  index_edges(polygon, ctx);
  const std::uint32_t slabs =
      method == Method::sweep_only ? 3 : slab_count(edges_.size(), ctx.partitions);
  TJunctionSearch search = find_t_junctions_in_slabs(edges_, slabs, ctx);
  auto& found = search.junctions;
  const auto& pts = polygon.points;
  // Along each edge from its start; at one point the smallest vertex.
  const auto before = [&](const TJunction& s, const TJunction& t) {
    if (s.edge != t.edge) return s.edge < t.edge;
    const Point &p = pts[s.vertex], &q = pts[t.vertex];
    if (!(p == q))
      return lexicographic_less(pts[s.edge], pts[edges_.next[s.edge]]) ? lexicographic_less(p, q)
                                                                       : lexicographic_less(q, p);
    return s.vertex < t.vertex;
  };
  detail::sort(found.begin(), found.end(), before);
  found.erase(std::unique(found.begin(), found.end(),
                          [&](const TJunction& s, const TJunction& t) {
                            return s.edge == t.edge && pts[s.vertex] == pts[t.vertex];
                          }),
              found.end());
  return search;
}

bool SimplicityCheck::unresolvable_conflict_at(const CleanPolygon& polygon, std::uint32_t e,
                                               const RunContext& ctx) {
  index_edges(polygon, ctx);
  std::vector<TJunction> junctions;  // the T-junctions e takes part in: not asked for here
  for (std::uint32_t f = 0; f < edges_.size(); ++f)
    if (!edges_.t_junctions(e, f, junctions)) return true;
  return false;
}

/// The ring's edges as maximal runs along which x never reverses (vertical edges join the run
/// they are in), each run's edges listed in increasing x. Within a run, edges that are not
/// neighbours cannot meet: their x-ranges are apart, or touch only across a run of vertical
/// edges, which would have to fold back (a neighbour conflict) to bring them together.
bool SimplicityCheck::monotone_chains(const CleanPolygon& polygon, std::size_t min_chain_edges) {
  chain_order_.clear();
  chains_.clear();
  for (std::size_t r = 0; r < polygon.ring_count(); ++r) {
    const std::uint32_t first = polygon.ring_starts[r], end = polygon.ring_starts[r + 1];
    const std::uint32_t start = first_turn(first, end);
    std::int8_t direction = 0;
    for (std::uint32_t e = start, step = 0; step < end - first; ++step) {
      const std::int8_t d = direction_[e];
      if (step == 0 || (d != 0 && direction != 0 && d != direction)) {
        chains_.push_back({static_cast<std::uint32_t>(chain_order_.size()), 0, false, 0, 0, 0, 0});
        direction = d;
      } else if (direction == 0) {
        direction = d;
      }
      chain_order_.push_back(e);
      chains_.back().end = static_cast<std::uint32_t>(chain_order_.size());
      chains_.back().decreasing = direction < 0;
      e = e + 1 == end ? first : e + 1;
    }
  }
  if (chains_.size() * min_chain_edges > chain_order_.size() + min_chain_edges) return false;
  chain_boxes_.resize(chain_order_.size());
  for (Chain& chain : chains_) finish_run(chain);
  detail::sort(chains_.begin(), chains_.end(), chain_before);
  return true;
}

std::uint32_t SimplicityCheck::first_turn(std::uint32_t first, std::uint32_t end) const {
  std::int8_t last = 0;
  for (std::uint32_t i = first; i < end; ++i) {
    if (direction_[i] == 0) continue;
    if (last != 0 && direction_[i] != last) return i;
    last = direction_[i];
  }
  return first;
}

/// A run's edges in increasing x, its boxes in that order, and its x- and y-range.
void SimplicityCheck::finish_run(Chain& chain) {
  if (chain.decreasing)
    std::reverse(chain_order_.begin() + chain.begin, chain_order_.begin() + chain.end);
  chain.x0 = edges_.boxes[chain_order_[chain.begin]].x0;
  chain.x1 = edges_.boxes[chain_order_[chain.end - 1]].x1;
  chain.y0 = INFINITY, chain.y1 = -INFINITY;
  for (std::uint32_t i = chain.begin; i < chain.end; ++i) {
    const EdgeBox& box = chain_boxes_[i] = edges_.boxes[chain_order_[i]];
    chain.y0 = std::min(chain.y0, box.y0), chain.y1 = std::max(chain.y1, box.y1);
  }
}

namespace {

/// Whether the runs monotone in x (about `runs`, x_reversals, among n edges) are worth trying
/// past chains_limit: not when they are short (fractals, stars, grids of small holes: 1.5-2.3
/// edges a run), nor when there are more than a few long ones (they may be wound around each
/// other, as a spiral's are).
bool runs_worth_trying(std::size_t runs, std::size_t n) {
  return runs * 3 <= n && (runs <= 16 || runs * 64 >= n);
}

/// Tasks for the runs' preparation: in parts from 8,192 edges where the run is parallel or
/// partitioned (the same runs either way), a few a partition so that stealing evens them out.
std::size_t runs_preparation_tasks(std::size_t n, const RunContext& ctx) {
  if (!PEAR_HAS_THREADS || !(ctx.parallel() || ctx.partitions > 1)) return 1;
  return std::clamp<std::size_t>(n / 4096, 1, 4 * std::max<std::size_t>(ctx.partitions, 2));
}

/// The few-edges strategies' shared set-up, sequentially: each edge's successor, its box handed
/// to `store(e, a, b)`; returns the smallest edge of a fold-back (a ring turning straight back
/// over itself, the one way neighbours conflict) when `find_folds`, else none.
template <class Store>
std::uint32_t link_edges(const CleanPolygon& polygon, RingEdges& edges, bool find_folds,
                         Store&& store) {
  const auto& pts = polygon.points;
  edges.points = &pts;
  edges.next.resize(pts.size());
  std::uint32_t smallest = SmallestViolation::none;
  for (std::size_t r = 0; r < polygon.ring_count(); ++r) {
    const std::uint32_t first = polygon.ring_starts[r], last = polygon.ring_starts[r + 1] - 1;
    for (std::uint32_t e = first; e <= last; ++e) {
      const std::uint32_t f = e == last ? first : e + 1, before = e == first ? last : e - 1;
      edges.next[e] = f;
      const Point &a = pts[e], &b = pts[f];
      store(e, a, b);
      if (!find_folds) continue;
      const Point& p = pts[before];
      if (before < smallest && orient2d(p, a, b) == 0 &&
          (on_open_segment(p, a, b) || on_open_segment(b, p, a) || p == b))
        smallest = std::min(before, e);
    }
  }
  return smallest;
}

/// A look at edges e and f whose boxes meet in x: records a shared endpoint position, and a
/// conflict (as its smaller edge) when it is smaller than `smallest`.
void visit_pair(const RingEdges& edges, std::uint32_t e, std::uint32_t f, bool find_crossings,
                std::uint32_t& smallest, bool& touching) {
  const EdgeBox &s = edges.boxes[e], &t = edges.boxes[f];
  // One branch (`&`): most pairs are apart in y, which the predictor then learns.
  const std::uint32_t after_e = edges.next[e], after_f = edges.next[f];
  if (!((t.y0 <= s.y1) & (s.y0 <= t.y1) & (after_e != f) & (after_f != e))) return;
  const auto& pts = *edges.points;
  const Point &a = pts[e], &b = pts[edges.next[e]], &c = pts[f], &d = pts[edges.next[f]];
  if (a == c || a == d || b == c || b == d) touching = true;
  if (find_crossings && std::min(e, f) < smallest && edges.conflict(e, f))
    smallest = std::min(e, f);
}

Verdict verdict_of(std::uint32_t smallest, bool touching) {
  Verdict verdict;
  if (smallest != SmallestViolation::none) verdict.violation = smallest;
  verdict.touching = touching ? Verdict::Touching::yes : Verdict::Touching::no;
  return verdict;
}

}  // namespace

/// Every pair of edges that are not neighbours, by branch-free box tests of rows (an edge
/// against the edges after it) in floats, then the exact tests for the few rows where boxes
/// meet; up to pair_by_pair_limit edges pair by pair. The float boxes are taken relative to the
/// first point (a county's coordinates are degrees, a building's metres in the millions, its
/// extent small) and rounded: twice the boxes a step of doubles, and no row missed (the
/// subtraction and the rounding are both monotone, so the boxes that meet still meet).
Verdict SimplicityCheck::check_all_pairs(const CleanPolygon& polygon, bool find_crossings) {
  const auto n = static_cast<std::uint32_t>(polygon.points.size());
  if (n <= pair_by_pair_limit) return check_pair_by_pair(polygon, find_crossings);
  // References, not a structured binding: clang 14 cannot capture bindings in a lambda.
  auto &x0 = float_columns_[0], &y0 = float_columns_[1];
  auto &x1 = float_columns_[2], &y1 = float_columns_[3];
  // IEEE floats: a double past a float's range rounds to the infinity on its side, monotone
  // still (never undefined: each double lies between two adjacent floats, infinities included).
  static_assert(std::numeric_limits<float>::is_iec559);
  const Point origin = polygon.points[0];
  link_edges(polygon, edges_, false, [&](std::uint32_t e, const Point& a, const Point& b) {
    x0[e] = static_cast<float>(std::min(a.x, b.x) - origin.x);
    y0[e] = static_cast<float>(std::min(a.y, b.y) - origin.y);
    x1[e] = static_cast<float>(std::max(a.x, b.x) - origin.x);
    y1[e] = static_cast<float>(std::max(a.y, b.y) - origin.y);
  });
  // Edge e of ring [first, end) meets the edges after it but e + 1 (unless e ends the ring)
  // and, for e == first, end - 1. Neighbours conflict only by folding back at their shared
  // vertex, and clean_polygon leaves no such tip.
  rows_.clear();
  std::size_t ring = 0;
  for (std::uint32_t e = 0; e + 1 < n; ++e) {
    if (e == polygon.ring_starts[ring + 1]) ++ring;
    const std::uint32_t first = polygon.ring_starts[ring], end = polygon.ring_starts[ring + 1];
    const std::uint32_t start = e + 1 == end ? e + 1 : e + 2;
    rows_.push_back({e, start, e == first ? end - 1 : n, e == first ? end : n, n});
  }
  std::array<std::uint64_t, few_edges_limit / 64> meets;
  rows_meeting(BoxColumns{x0.data(), y0.data(), x1.data(), y1.data()}, rows_, meets);
  // A row is looked at again only when a box meets (2% of the rows of the counties); the exact
  // boxes are made for the exact tests only then.
  std::uint32_t smallest = SmallestViolation::none;
  bool touching = false, indexed = false;
  for (std::uint32_t w = 0; w < meets.size(); ++w) {
    for (std::uint64_t set = meets[w]; set != 0; set &= set - 1) {
      const RowRanges& r = rows_[w * 64 + static_cast<std::uint32_t>(std::countr_zero(set))];
      const auto& boxes = edges_.boxes;
      if (!indexed) {
        edges_.boxes.resize(n);
        const auto& pts = polygon.points;
        for (std::uint32_t i = 0; i < n; ++i)
          edges_.boxes[i] = edge_box(pts[i], pts[edges_.next[i]]);
        indexed = true;
      }
      const Box& box = boxes[r.row];
      for (const auto& [from, to] : {std::pair(r.from, r.to), std::pair(r.from2, r.to2)})
        for (std::uint32_t f = from; f < to; ++f)
          if (boxes[f].x0 <= box.x1 && box.x0 <= boxes[f].x1)
            visit_pair(edges_, r.row, f, find_crossings, smallest, touching);
    }
  }
  return verdict_of(smallest, touching);
}

/// check_all_pairs on a few edges, without the rows' set-up (their ranges, the columns, the
/// SIMD scan).
Verdict SimplicityCheck::check_pair_by_pair(const CleanPolygon& polygon, bool find_crossings) {
  const auto n = static_cast<std::uint32_t>(polygon.points.size());
  edges_.boxes.resize(n);
  link_edges(polygon, edges_, false, [&](std::uint32_t e, const Point& a, const Point& b) {
    edges_.boxes[e] = edge_box(a, b);
  });
  std::uint32_t smallest = SmallestViolation::none;
  bool touching = false;
  const EdgeBox* boxes = edges_.boxes.data();
  const std::uint32_t* next = edges_.next.data();
  // Neighbours' boxes always meet (they share an end): left out before the boxes are looked at.
  for (std::uint32_t e = 0; e + 1 < n; ++e) {
    const EdgeBox s = boxes[e];
    for (std::uint32_t f = e + 1; f < n; ++f) {
      const EdgeBox& t = boxes[f];
      if ((t.x0 <= s.x1) & (s.x0 <= t.x1) & (t.y0 <= s.y1) & (s.y0 <= t.y1) & (next[e] != f) &
          (next[f] != e))
        visit_pair(edges_, e, f, find_crossings, smallest, touching);
    }
  }
  return verdict_of(smallest, touching);
}

/// Whether the pairs of runs whose boxes meet, at the shorter run's edges a pair (a window
/// walks at least those), stay within `budget` looks: runs wound around each other (a spiral)
/// are found before their edges are walked.
bool SimplicityCheck::chains_within(std::size_t budget) const {
  std::size_t looks = 0;
  for (std::size_t i = 0; i < chains_.size(); ++i) {
    const Chain& chain = chains_[i];
    for (std::size_t j = i + 1; j < chains_.size() && chains_[j].x0 <= chain.x1; ++j) {
      const Chain& other = chains_[j];
      const bool meet = other.y0 <= chain.y1 && chain.y0 <= other.y1;
      looks += 1 + meet * std::min(chain.end - chain.begin, other.end - other.begin);
    }
    if (looks > budget) return false;
  }
  return true;
}

/// Every pair of edges of two runs whose x-ranges meet, to visit(e, f): for each edge of the
/// run that starts first, a window of the other's (both in increasing x). Along a run both ends
/// of the edges' x-ranges only grow: its edges that end before the other run starts are
/// skipped by a binary search, and those that start after it ends are not looked at. Returns
/// the looks taken.
template <class Visit>
std::size_t SimplicityCheck::walk_chain_pair(const Chain& chain, const Chain& other,
                                             Visit&& visit) const {
  const EdgeBox* boxes = chain_boxes_.data();  // in run order: the walk reads them in turn
  std::uint32_t window = other.begin;
  std::size_t looks = 1;
  std::uint32_t i = static_cast<std::uint32_t>(
      std::partition_point(boxes + chain.begin, boxes + chain.end,
                           [&](const EdgeBox& box) { return box.x1 < other.x0; }) -
      boxes);
  for (; i < chain.end && boxes[i].x0 <= other.x1; ++i) {
    const EdgeBox& s = boxes[i];
    while (window < other.end && boxes[window].x1 < s.x0) ++window;
    std::uint32_t m = window;
    for (; m < other.end && boxes[m].x0 <= s.x1; ++m)
      if ((boxes[m].y0 <= s.y1) & (s.y0 <= boxes[m].y1)) visit(chain_order_[i], chain_order_[m]);
    looks += 1 + (m - window);
  }
  return looks;
}

/// The edges' boxes, directions and runs monotone in x. Returns the smallest edge of a ring
/// folding back (when `find_crossings`; else or without one, none), or nothing where the runs
/// are not worth walking (too short, or long ones wound round each other past `budget` looks).
std::optional<std::uint32_t> SimplicityCheck::prepare_runs(const CleanPolygon& polygon,
                                                           bool find_crossings,
                                                           std::size_t budget) {
  const auto n = static_cast<std::uint32_t>(polygon.points.size());
  const bool limited = budget != every_pair;
  edges_.boxes.resize(n);
  direction_.resize(n);
  const std::uint32_t fold = link_edges(polygon, edges_, find_crossings,
                                        [&](std::uint32_t e, const Point& a, const Point& b) {
                                          edges_.boxes[e] = edge_box(a, b);
                                          direction_[e] = x_direction(a, b);
                                        });
  if (!monotone_chains(polygon, limited ? 3 : 0)) return std::nullopt;
  // Long runs may wind around each other (a spiral): then a look at their pairs first, which
  // short runs (coasts: 5-7 edges) would pay as much for as for the walk.
  if (limited && chains_.size() * 64 < n && !chains_within(budget)) return std::nullopt;
  return fold;
}

/// The pairs of runs from `from` up to `to` (not included): each run against the runs after it
/// that start before it ends. The looks are added to `spent`, shared by all walks of one check,
/// every few thousand: a walk stops once the sum passes `budget`. A sum only grows, so whether
/// some walk stops does not depend on how the walks interleave: exactly when all of them
/// together would pass the budget.
SimplicityCheck::RunWalk SimplicityCheck::walk_runs(PairAt from, PairAt to, bool find_crossings,
                                                    std::size_t budget,
                                                    std::atomic<std::size_t>& spent) const {
  RunWalk walk;
  const auto visit = [&](std::uint32_t e, std::uint32_t f) {
    visit_pair(edges_, e, f, find_crossings, walk.smallest, walk.touching);
  };
  constexpr std::size_t flush_every = 4096;
  const bool limited = budget != every_pair;
  std::size_t looks = 0;
  const auto over_budget = [&] {
    const std::size_t added = std::exchange(looks, 0);
    return spent.fetch_add(added, std::memory_order_relaxed) + added > budget;
  };
  const std::size_t runs = chains_.size();
  for (std::size_t i = from.run; i < runs && i <= to.run; ++i) {
    const Chain& chain = chains_[i];
    const std::size_t stop = i == to.run ? to.other : runs;
    for (std::size_t j = i == from.run ? from.other : i + 1; j < stop && chains_[j].x0 <= chain.x1;
         ++j) {
      const Chain& other = chains_[j];
      // Runs apart in y are not looked into at all (one branch for both sides).
      const bool apart = (other.y0 > chain.y1) | (chain.y0 > other.y1);
      looks += apart ? 1 : walk_chain_pair(chain, other, visit);
    }
    if (limited && looks >= flush_every && over_budget()) {
      walk.over_budget = true;
      return walk;
    }
  }
  walk.over_budget = limited && over_budget();
  return walk;
}

/// Chains_ are sorted by x0: run i's pairs are the runs after it up to the first that starts
/// past its end, found by galloping from i (most runs have a few pairs: a binary search over
/// all the runs cost Australia's check 0.7 ms of work).
void SimplicityCheck::count_run_pairs(const RunContext& ctx) {
  const std::size_t runs = chains_.size();
  pairs_before_.resize(runs + 1);
  pairs_before_[0] = 0;
  const auto pairs_of = [&](std::size_t i) {
    const double end = chains_[i].x1;
    std::size_t below = i, step = 1;  // chains_[below] starts at or before `end`
    while (below + step < runs && chains_[below + step].x0 <= end) below += step, step *= 2;
    const auto first = chains_.begin() + static_cast<long>(below) + 1;
    const auto last = chains_.begin() + static_cast<long>(std::min(runs, below + step));
    const auto after =
        std::partition_point(first, last, [end](const Chain& c) { return c.x0 <= end; });
    return static_cast<std::size_t>(after - chains_.begin()) - i - 1;
  };
  const std::size_t tasks = ctx.tasks_for(runs, 256);  // a few binary searches a run
  ctx.run_tasks("check simplicity: pair counts", tasks, [&](std::size_t t) {
    for (std::size_t i = part_begin(runs, tasks, t); i < part_begin(runs, tasks, t + 1); ++i)
      pairs_before_[i + 1] = pairs_of(i);
  });
  ctx.run_serial("check simplicity: pair sums", [&] {
    for (std::size_t i = 0; i < runs; ++i) pairs_before_[i + 1] += pairs_before_[i];
  });
}

/// Where the walk is at its `pair`-th pair (pairs_before_ counted): past the last, at the end.
SimplicityCheck::PairAt SimplicityCheck::pair_at(std::size_t pair) const {
  const std::size_t runs = chains_.size();
  if (pair >= pairs_before_[runs]) return {runs, 0};
  // The last run whose pairs start at or before `pair`: it has pairs, so `pair` is one of them.
  const auto run =
      static_cast<std::size_t>(std::upper_bound(pairs_before_.begin(), pairs_before_.end(), pair) -
                               pairs_before_.begin() - 1);
  return {run, run + 1 + (pair - pairs_before_[run])};
}

/// Every pair of edges from two runs monotone in x whose boxes meet, sequentially (at most
/// chains_limit edges: every pair, no budget).
Verdict SimplicityCheck::check_few_chains(const CleanPolygon& polygon, bool find_crossings) {
  const auto n = static_cast<std::uint32_t>(polygon.points.size());
  const std::uint32_t fold = *prepare_runs(polygon, find_crossings, every_pair);
  std::atomic<std::size_t> spent{0};
  RunWalk walk = walk_runs({0, 1}, {chains_.size(), 0}, find_crossings, every_pair, spent);
  // Without a fold, every pair that can conflict was looked at: `smallest` is the smallest
  // edge in any conflict. A run may hide a conflict behind a vertical fold-back within it (a
  // neighbour conflict, found by link_edges): then every pair.
  if (find_crossings && fold != SmallestViolation::none) {
    walk.smallest = std::min(walk.smallest, fold);
    const auto& boxes = edges_.boxes;
    for (std::uint32_t e = 0; e + 1 < n; ++e)
      for (std::uint32_t f = e + 1; f < n; ++f)
        if (boxes[f].x0 <= boxes[e].x1 && boxes[e].x0 <= boxes[f].x1)
          visit_pair(edges_, e, f, find_crossings, walk.smallest, walk.touching);
  }
  return verdict_of(walk.smallest, walk.touching);
}

/// The runs of a large polygon, within chains_budget looks an edge: the set-up sequentially,
/// the pairs of runs in tasks (a run's pairs are read-only; the smallest conflict and whether
/// any edges touch do not depend on the order). None where the grid is the better index, or
/// where a ring folds back (a run may hide a conflict behind it: the grid finds it).
std::optional<Verdict> SimplicityCheck::check_chains(const CleanPolygon& polygon,
                                                     const RunContext& ctx) {
  const std::size_t n = polygon.points.size(), budget = chains_budget * n;
  bool ready = false;
  if (const std::size_t tasks = runs_preparation_tasks(n, ctx); tasks > 1) {
    reversals_ = x_reversals(polygon, ctx, tasks);
    ready = runs_worth_trying(*reversals_, n) &&
            prepare_runs_in_parts(polygon, budget, ctx, tasks) == SmallestViolation::none;
  } else {
    ctx.run_serial("check simplicity", [&] {
      reversals_ = x_reversals(polygon);
      ready = runs_worth_trying(*reversals_, n) &&
              prepare_runs(polygon, true, budget) == SmallestViolation::none;
    });
  }
  if (!ready) return std::nullopt;
  // Tasks of equal pair counts, a few a partition so that stealing evens out their work: by
  // runs, the first task took most of them where long runs (an outer ring's) span the others
  // (a random polygon with 12,499 holes: 1.29 of 2.7 ms).
  // On one partition, one walk (nothing to even out).
  const bool in_parts = PEAR_HAS_THREADS && ctx.partitions > 1;
  if (in_parts) count_run_pairs(ctx);
  const std::size_t pairs = in_parts ? pairs_before_.back() : 0;
  const std::size_t tasks = std::clamp<std::size_t>(pairs / 1024, 1, 16 * ctx.partitions);
  std::vector<RunWalk> walks(tasks);
  std::atomic<std::size_t> spent{0};
  ctx.run_tasks("check simplicity: run pairs", tasks, [&](std::size_t t) {
    const PairAt from = tasks == 1 ? PairAt{0, 1} : pair_at(pairs * t / tasks);
    const PairAt to = tasks == 1 ? PairAt{chains_.size(), 0} : pair_at(pairs * (t + 1) / tasks);
    walks[t] = walk_runs(from, to, true, budget, spent);
  });
  RunWalk all;
  for (const RunWalk& walk : walks) {
    if (walk.over_budget) return std::nullopt;
    all.smallest = std::min(all.smallest, walk.smallest);
    all.touching |= walk.touching;
  }
  return verdict_of(all.smallest, all.touching);
}

/// clean_polygon leaves no point equal to the next, so two edges that are not neighbours share
/// an end exactly when two vertices share a position: sorted, they are next to each other.
bool SimplicityCheck::repeats_a_position(const CleanPolygon& polygon) {
  sorted_points_.assign(polygon.points.begin(), polygon.points.end());
  detail::sort(sorted_points_.begin(), sorted_points_.end(),
               [](const Point& p, const Point& q) { return lexicographic_less(p, q); });
  return std::adjacent_find(sorted_points_.begin(), sorted_points_.end()) != sorted_points_.end();
}

Verdict SimplicityCheck::check(const CleanPolygon& polygon, const RunContext& ctx,
                               bool find_crossings) {
  const auto n = static_cast<std::uint32_t>(polygon.points.size());
  reversals_.reset();
  Verdict verdict;
  // Without the check, past the few edges whose box rows are quickest (a sort of a county's
  // 18 points mispredicts more than its rows cost), whether a position repeats.
  if (!find_crossings && n > few_edges_limit && n <= chains_limit) {
    verdict.touching = repeats_a_position(polygon) ? Verdict::Touching::yes : Verdict::Touching::no;
    return verdict;
  }
  if (n > chains_limit) {
    if (!find_crossings) return verdict;
    // Runs of edges monotone in x first, while they stay near linear (a comb, countries,
    // coasts: Australia's check 70M instructions against the grid's 206M); the grid where they
    // would not (fractals, spirals) or where a ring folds back. At every partition count: the
    // runs' preparation and pairs are tasks too, and at 4 and 16 partitions their work (11.6
    // ms on Australia) is two thirds of the grid's (17.1 ms), their span as short. Where the
    // grid gives up (edges long against its cells: a comb's teeth), the sweep in slabs.
    if (auto decided = check_chains(polygon, ctx)) return *decided;
    index_edges(polygon, ctx);  // find_violation's steps, with the runs before the sweep
    SmallestViolation found;
    if (!check_on_grid(edges_, GridLimits{}, ctx, root_, found, &verdict.touching))
      sweep_in_slabs(edges_, slab_count(edges_.size(), ctx.partitions), ctx, found);
    if (found.get() != SmallestViolation::none) verdict.violation = found.get();
    return verdict;
  }
  ctx.run_serial("check simplicity", [&] {
    verdict = n <= few_edges_limit ? check_all_pairs(polygon, find_crossings)
                                   : check_few_chains(polygon, find_crossings);
  });
  // With few edges a hole that is not where a hole may be is cheap to find at once.
  if (find_crossings && !verdict.violation && verdict.touching == Verdict::Touching::no &&
      polygon.ring_count() > 1)
    verdict.misplaced = find_misplaced_hole_among_few(polygon);
  return verdict;
}

}  // namespace pear::detail
