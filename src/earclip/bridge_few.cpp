// Joining up to HoleBridger::scanned_holes holes on rings that share no position, without a
// grid: every hole's ray is cast in one pass over the edges and every hole's visible vertex
// found in one pass over the nodes, each edge or node tested only against the holes whose y
// range it meets (tables of buckets by y). The grid cost more than the searches it served
// there: a glyph of ten holes spent 230 instructions a vertex building it. The holes are then
// spliced in order as the serial joining splices them, and the boundary is the same node for
// node: before a hole is spliced the bridges added so far are tested against its ray (one
// nearer than what the pass found, or through its vertex, and that hole is searched for again
// by scanning every edge and node, as are all holes after a hole left out or an edge split),
// and the node at the vertex it sees is the input's or one of the copies splices made of it,
// whichever's sector holds the hole (the order the grid's lists give them).
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>

#include "bridge.hpp"
#include "pear/config.hpp"
#include "ray_crossing.hpp"

namespace pear::detail {
namespace {

/// Buckets of y over [lo, hi], four a hole: monotone in y, so a value in [p, q] falls in a
/// bucket between p's and q's.
struct YBuckets {
  static constexpr std::size_t most = 4 * HoleBridger::scanned_holes;
  double lo = 0, scale = 0, last = 0;
  int count = 1;
  void fit(double low, double high, std::size_t holes) {
    count = static_cast<int>(std::min(most, 4 * std::bit_ceil(holes)));
    last = count - 1;
    lo = low;
    scale = high > low ? count / (high - low) : 0;
    if (!(scale < std::numeric_limits<double>::infinity())) scale = 0;
  }
  int of(double y) const { return static_cast<int>(std::clamp((y - lo) * scale, 0.0, last)); }
};

/// The better of two hits of one ray: the nearest crossing (largest x, then smallest id), and
/// the smallest id of an edge through the hole's vertex (HoleBridger::cast_left's order).
template <class Hit>
void keep_nearer(Hit& hit, const Hit& other) {
  hit.touching_edge = std::min(hit.touching_edge, other.touching_edge);
  if (other.edge != UINT32_MAX && nearer(other.x, other.edge, hit))
    hit.edge = other.edge, hit.x = other.x;
}

}  // namespace

void HoleBridger::Sight::start(const Point& hole, std::uint32_t start_node, const Boundary& b) {
  h = hole;
  const std::uint32_t end_node = b.next[start_node];
  a = b.pos[start_node], c = b.pos[end_node];
  open = false;
  if (a.y == h.y && a.x <= h.x) {
    best = a, best_node = start_node;
    return;
  }
  if (c.y == h.y && c.x <= h.x) {
    best = c, best_node = end_node;
    return;
  }
  // The end with the smaller x: the triangle (h, crossing, M) then lies left of h, where the
  // hole being joined cannot reach.
  const bool a_is_m = a.x < c.x || (a.x == c.x && a.y < c.y);
  m = best = a_is_m ? a : c;
  best_node = a_is_m ? start_node : end_node;
  up = m.y > h.y ? 1 : -1;
  edge_side = orient2d(a, c, h);
  // A candidate on h's side of line a-c between the rows of h and M lies right of the edge.
  x0 = std::min(a.x, c.x), x1 = h.x;
  y0 = std::min(h.y, m.y), y1 = std::max(h.y, m.y);
  open = true;
}

/// Whether v is seen closer to the ray than the best so far. Every decision is an exact
/// orientation or comparison.
bool HoleBridger::Sight::better(const Point& v) const {
  const double turn = orient2d(h, best, v) * up;  // > 0: v is closer to the ray
  if (turn != 0) return turn > 0;
  return std::abs(v.x - h.x) + std::abs(v.y - h.y) <
         std::abs(best.x - h.x) + std::abs(best.y - h.y);
}

void HoleBridger::Sight::consider(const Point& v, std::uint32_t node) {
  if (v == h || v.x > h.x || (v.y - h.y) * up < 0 || (v.y - m.y) * up > 0) return;
  const double es = orient2d(a, c, v);
  if (es != 0 && (es > 0) != (edge_side > 0)) return;  // beyond the hit edge
  if (orient2d(h, m, v) * up < 0) return;              // on the far side of segment h-M
  if (better(v)) best = v, best_node = node;
}

void HoleBridger::join_scanned(const CleanPolygon& polygon, const RunContext& ctx, bool in_parts,
                               std::vector<std::uint32_t>& unjoined) {
  const auto nodes = static_cast<std::uint32_t>(polygon.points.size());
  const bool parallel = PEAR_HAS_THREADS && in_parts;
  const std::size_t tasks = parallel ? ctx.tasks_for(nodes, 4096) : 1;
  // Serially, one phase: the passes' steps run as plain calls (a context without phases).
  const auto passes = [&](const RunContext& steps) {
    order_holes(polygon, steps, parallel);
    edge_start_.reserve(most_ids());
    out_edge_.reserve(most_ids());
    regrow_unfilled(edge_start_, nodes);
    regrow_unfilled(out_edge_, nodes);
    regrow_unfilled(copy_head_, nodes);
    cast_all(steps, tasks);
    sight_all(steps, tasks);
  };
  const auto splices = [&] {
    reserve_for_splices();
    gridded_ = false;
    added_edges_.clear();
    first_copy_ = b_->size();
    regrow_unfilled(copy_input_, 2 * holes_.size());  // each entry written before it is read
    regrow_unfilled(copy_next_, 2 * holes_.size());
    bool passes_hold = true;  // what the passes found still stands but for added edges
    for (std::size_t k = 0; k < holes_.size(); ++k) {
      const std::uint32_t hole = holes_[k].leftmost, rank = static_cast<std::uint32_t>(k + 1);
      if (!attach(hole, find_scanned(static_cast<std::uint32_t>(k), passes_hold), rank, true,
                  UINT32_MAX)) {
        unjoined.push_back(hole);
        leave_out(polygon, holes_[k].ring);
        passes_hold = false;  // the passes counted its ring for the holes after it
      }
      passes_hold = passes_hold && !edges_split_;
    }
    gridded_ = true;
  };
  if (parallel) {
    passes(ctx);
    ctx.run_serial("bridge: splice", splices);
  } else {
    ctx.run_serial("bridge holes", [&] { passes(RunContext{}), splices(); });
  }
}

/// Every hole's ray against every edge of the rings (edge v from node v, nothing spliced yet)
/// ranked below it, in one pass: the holes by y, and for each edge the run of them whose y
/// lies in its y range. In tasks of edges, each keeping its own hits, merged in order.
void HoleBridger::cast_all(const RunContext& ctx, std::size_t tasks) {
  const std::size_t holes = holes_.size();
  const Boundary& b = *b_;
  std::array<std::uint32_t, YBuckets::most + 1> first_in;
  std::vector<std::pair<double, std::uint32_t>> by_y(holes);
  for (std::size_t k = 0; k < holes; ++k) {  // by insertion: at most 64, and little code
    const std::pair<double, std::uint32_t> hole{b.pos[holes_[k].leftmost].y, k};
    std::size_t at = k;
    for (; at > 0 && hole < by_y[at - 1]; --at) by_y[at] = by_y[at - 1];
    by_y[at] = hole;
  }
  YBuckets buckets;
  buckets.fit(by_y.front().first, by_y.back().first, holes);
  std::fill_n(first_in.begin(), buckets.count + 1, 0u);
  for (const auto& [y, k] : by_y) ++first_in[buckets.of(y) + 1];
  for (int i = 0; i < buckets.count; ++i) first_in[i + 1] += first_in[i];
  const double low = by_y.front().first, high = by_y.back().first;
  const auto nodes = static_cast<std::uint32_t>(edge_start_.size());
  RayHit none;
  none.x = -std::numeric_limits<double>::infinity();
  scanned_hits_.assign(tasks * holes, none);
  ctx.run_tasks_if_threads("bridge: rays", tasks, [&](std::size_t t) {
    RayHit* hits = &scanned_hits_[t * holes];
    const auto end = static_cast<std::uint32_t>(part_begin(nodes, tasks, t + 1));
    for (auto v = static_cast<std::uint32_t>(part_begin(nodes, tasks, t)); v < end; ++v) {
      edge_start_[v] = out_edge_[v] = v;
      copy_head_[v] = UINT32_MAX;  // no copy yet
      const Point &p = b.pos[v], &q = b.pos[b.next[v]];
      const double lo = std::min(p.y, q.y), hi = std::max(p.y, q.y);
      if (hi < low || lo > high) continue;
      for (std::uint32_t j = first_in[buckets.of(lo)]; j < first_in[buckets.of(hi) + 1]; ++j) {
        const auto [y, k] = by_y[j];
        if (y < lo || y > hi || !merged(v, k + 1)) continue;
        visit_edge(hits[k], b.pos[holes_[k].leftmost], v, p, q);
      }
    }
  });
  if constexpr (PEAR_HAS_THREADS)
    for (std::size_t t = 1; t < tasks; ++t)
      for (std::size_t k = 0; k < holes; ++k)
        keep_nearer(scanned_hits_[k], scanned_hits_[t * holes + k]);
  scanned_hits_.resize(holes);
}

/// Every hole's visible vertex among the nodes ranked below it, in one pass: each node tested
/// against the holes whose box (Sight) its bucket of y meets, a bit each. In tasks of nodes,
/// each with its own sights, merged in order (the best is the same in any order).
void HoleBridger::sight_all(const RunContext& ctx, std::size_t tasks) {
  const std::size_t holes = holes_.size();
  const Boundary& b = *b_;
  seen_node_.assign(holes, UINT32_MAX);
  sights_.assign(tasks * holes, Sight{});
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (std::size_t k = 0; k < holes; ++k) {
    if (scanned_hits_[k].edge == UINT32_MAX || scanned_hits_[k].touching_edge != UINT32_MAX)
      continue;
    Sight& sight = sights_[k];
    sight.start(b.pos[holes_[k].leftmost], scanned_hits_[k].edge, b);
    seen_node_[k] = sight.best_node;
    if (sight.open) low = std::min(low, sight.y0), high = std::max(high, sight.y1);
  }
  if (!(low <= high)) return;
  YBuckets buckets;
  buckets.fit(low, high, holes);
  std::array<std::uint64_t, YBuckets::most> in_bucket;
  std::fill_n(in_bucket.begin(), buckets.count, 0u);
  static_assert(scanned_holes <= 64, "a bit a hole");
  for (std::size_t k = 0; k < holes; ++k)
    if (sights_[k].open)
      for (int i = buckets.of(sights_[k].y0); i <= buckets.of(sights_[k].y1); ++i)
        in_bucket[i] |= std::uint64_t{1} << k;
  if constexpr (PEAR_HAS_THREADS)
    for (std::size_t t = 1; t < tasks; ++t)
      std::copy(sights_.begin(), sights_.begin() + holes, sights_.begin() + t * holes);
  const auto nodes = static_cast<std::uint32_t>(b.size());
  ctx.run_tasks_if_threads("bridge: sights", tasks, [&](std::size_t t) {
    Sight* sights = &sights_[t * holes];
    const auto end = static_cast<std::uint32_t>(part_begin(nodes, tasks, t + 1));
    for (auto u = static_cast<std::uint32_t>(part_begin(nodes, tasks, t)); u < end; ++u) {
      const Point& v = b.pos[u];
      if (v.y < low || v.y > high) continue;
      for (std::uint64_t set = in_bucket[buckets.of(v.y)]; set != 0; set &= set - 1) {
        const auto k = static_cast<std::uint32_t>(std::countr_zero(set));
        Sight& sight = sights[k];
        if ((v.x >= sight.x0) & (v.x <= sight.x1) & (v.y >= sight.y0) & (v.y <= sight.y1) &&
            merged(u, k + 1))
          sight.consider(v, u);
      }
    }
  });
  for (std::size_t k = 0; k < holes; ++k) {
    Sight& sight = sights_[k];
    if constexpr (PEAR_HAS_THREADS)
      for (std::size_t t = 1; t < tasks; ++t) {
        const Sight& other = sights_[t * holes + k];
        if (other.best_node != sight.best_node && sight.better(other.best))
          sight.best = other.best, sight.best_node = other.best_node;
      }
    if (sight.open) seen_node_[k] = sight.best_node;
  }
}

/// Hole k's attachment: the passes' while they hold and no bridge added since is nearer on its
/// ray or runs through its vertex, else a search by scans.
HoleBridger::Attachment HoleBridger::find_scanned(std::uint32_t k, bool passes_hold) {
  const std::uint32_t hole = holes_[k].leftmost, rank = k + 1;
  if (!passes_hold) return find_by_scan(hole, rank);
  const Point h = b_->pos[hole];
  Attachment at;
  at.hit = scanned_hits_[k];
  for (const std::uint32_t id : added_edges_) {
    RayHit added;
    const std::uint32_t s = edge_start_[id];
    visit_edge(added, h, id, b_->pos[s], b_->pos[b_->next[s]]);
    if (added.touching_edge != UINT32_MAX ||
        (added.edge != UINT32_MAX && nearer(added.x, id, at.hit)))
      return find_by_scan(hole, rank);
  }
  at.hit.x = std::min(at.hit.x, h.x);  // rounding may put a crossing a hair right of h
  if (at.hit.touching_edge != UINT32_MAX || at.hit.edge == UINT32_MAX) return at;
  at.target = b_->pos[seen_node_[k]];
  at.node = node_holding(seen_node_[k], h, false);
  return at;
}

/// find() without a grid: every edge and node, the merged ones only. No node lies at the
/// hole's vertex (the rings are apart, and a splice copies only nodes at other holes' vertices
/// or at targets).
HoleBridger::Attachment HoleBridger::find_by_scan(std::uint32_t hole, std::uint32_t rank) {
  const Point h = b_->pos[hole];
  Attachment at;
  at.hit.x = -std::numeric_limits<double>::infinity();
  for (std::uint32_t id = 0; id < edge_start_.size(); ++id) {
    if (!merged(id, rank)) continue;
    const std::uint32_t s = edge_start_[id];
    visit_edge(at.hit, h, id, b_->pos[s], b_->pos[b_->next[s]]);
  }
  at.hit.x = std::min(at.hit.x, h.x);
  if (at.hit.touching_edge != UINT32_MAX || at.hit.edge == UINT32_MAX) return at;
  Sight sight;
  sight.start(h, edge_start_[at.hit.edge], *b_);
  for (std::uint32_t node = 0; sight.open && node < b_->size(); ++node)
    if (merged(node, rank)) sight.consider(b_->pos[node], node);
  at.target = sight.best;
  at.node = node_holding(input_node(sight.best_node), h, false);
  return at;
}

}  // namespace pear::detail
