#include "ear_clipper.hpp"

#include <algorithm>
#include <bit>
#include <cmath>

namespace pear::detail {
namespace {

Point min_corner(const Point& a, const Point& b, const Point& c) {
  return {std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y})};
}
Point max_corner(const Point& a, const Point& b, const Point& c) {
  return {std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y})};
}

}  // namespace

void EarClipper::classify(std::uint32_t entry) {
  Boundary& b = *b_;
  reflex_.assign(b.size(), 0);
  grid_built_ = false;
  alive_.assign(b.size(), 0);
  stamp_.assign(b.size(), 0);
  scratch_.clear();
  remaining_ = 0;
  std::uint32_t v = entry;
  do {
    alive_[v] = 1;
    ++remaining_;
    v = b.next[v];
  } while (v != entry);
  // A spike in the input (a ring running out and back along one segment) is a ring
  // self-intersection: it is dissolved, and the result is flagged as a best effort.
  const std::size_t before = remaining_;
  for (std::uint32_t u = 0; u < b.size(); ++u) {
    if (!alive_[u]) continue;
    const std::uint32_t vertex = b.vertex[u];
    dissolve_spikes(u);
    if (remaining_ != before && !best_effort_) best_effort_ = true, best_effort_vertex_ = vertex;
  }
  mark_pinches();
  for (std::uint32_t u = 0; u < b.size(); ++u) {
    if (alive_[u] && (pinch_[u] || b.turn(u) < 0)) {
      reflex_[u] = 1;
      scratch_.push_back(u);
    }
  }
  grid_.build(b, scratch_);
  grid_built_ = true;
}

/// Nodes that share their position with another live node (bridge ends, rings touching at a
/// vertex): they stay hashed whatever their angle, since a convex one at an ear's corner can
/// still reach into the ear (the strictly-reflex argument does not cover a chain that touches
/// a corner). Found with a hash table on the exact coordinates.
void EarClipper::mark_pinches() {
  const Boundary& b = *b_;
  pinch_.assign(b.size(), 0);
  std::size_t capacity = 16;
  while (capacity < 2 * static_cast<std::size_t>(remaining_)) capacity *= 2;
  position_table_.assign(capacity, UINT32_MAX);
  const auto key = [&](const Point& p) {
    const std::uint64_t x = std::bit_cast<std::uint64_t>(p.x + 0.0);  // -0 and +0 alike
    const std::uint64_t y = std::bit_cast<std::uint64_t>(p.y + 0.0);
    // splitmix64's finalizer: integer coordinates have all-zero low mantissa bits, so the
    // table index must depend on every bit.
    std::uint64_t h = x ^ (y * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull);
    h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
    h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
    return h ^ (h >> 31);
  };
  for (std::uint32_t u = 0; u < b.size(); ++u) {
    if (!alive_[u]) continue;
    for (std::size_t slot = key(b.pos[u]) & (capacity - 1);; slot = (slot + 1) & (capacity - 1)) {
      const std::uint32_t other = position_table_[slot];
      if (other == UINT32_MAX) {
        position_table_[slot] = u;
        break;
      }
      if (b.pos[other] == b.pos[u]) {
        pinch_[u] = pinch_[other] = 1;
        break;
      }
    }
  }
}

void EarClipper::remove(std::uint32_t v) {
  if (v == anchor_) anchor_ = b_->next[v];
  b_->unlink(v);
  alive_[v] = 0;
  drop_reflex(v);
  --remaining_;
}

void EarClipper::drop_reflex(std::uint32_t v) {
  if (!reflex_[v]) return;
  reflex_[v] = 0;
  if (grid_built_) grid_.remove(v, b_->pos[v]);
}

/// A node whose neighbours coincide is the tip of a zero-area spike: the remnant of a lobe of
/// a self-touching ring, or an antenna in the input. It and its successor (which duplicates
/// its predecessor) leave without a triangle. Returns a live node where the change happened.
std::uint32_t EarClipper::dissolve_spikes(std::uint32_t v) {
  Boundary& b = *b_;
  while (remaining_ >= 4 && b.pos[b.prev[v]] == b.pos[b.next[v]]) {
    const std::uint32_t p = b.prev[v], n = b.next[v];
    remove(v);
    remove(n);
    v = p;
  }
  return v;
}

/// After a clip next to v: dissolve spikes, refresh the convexity and ear status around v.
std::uint32_t EarClipper::settle(std::uint32_t v, bool queue) {
  if (!alive_[v]) return UINT32_MAX;
  const std::uint32_t u = dissolve_spikes(v);
  if (u != v) {
    for (std::uint32_t w : {b_->prev[u], u, b_->next[u]}) {
      update_neighbour(w);
      if (queue) offer(w);
    }
    return u;
  }
  update_neighbour(v);
  if (queue) offer(v);
  return v;
}

/// Whether reflex node q spoils the ear (p, v, n). Strictly inside always does; on the
/// triangle's boundary it does when its edges reach into the triangle (paper Fig. 1(b), and
/// FIST's handling of the coincident nodes that bridges and touching rings create).
bool EarClipper::blocks(std::uint32_t p, std::uint32_t v, std::uint32_t n, std::uint32_t q) const {
  const Boundary& b = *b_;
  const Point &a = b.pos[p], &t = b.pos[v], &c = b.pos[n], &x = b.pos[q];
  const double o1 = orient2d(a, t, x);
  if (o1 < 0) return false;
  const double o2 = orient2d(t, c, x);
  if (o2 < 0) return false;
  const double o3 = orient2d(c, a, x);
  if (o3 < 0) return false;
  if (o1 > 0 && o2 > 0 && o3 > 0) return true;
  if (x == a) return coincident_blocks(q, t, c);
  if (x == c) return coincident_blocks(q, a, t);
  if (x == t) return coincident_blocks(q, c, a);
  if (o3 == 0) return true;  // on the open diagonal
  const Point &qp = b.pos[b.prev[q]], &qn = b.pos[b.next[q]];
  if (o1 == 0) return orient2d(a, t, qp) > 0 || orient2d(a, t, qn) > 0;
  return orient2d(t, c, qp) > 0 || orient2d(t, c, qn) > 0;
}

/// q sits exactly on a corner of the ear; the corner's wedge is bounded by the rays towards
/// wedge_a and wedge_b. q spoils the ear if one of its edges runs into the wedge. (Whether the
/// diagonal runs into q's own sector need not be asked: in a valid boundary that would put the
/// corner's own edge into the wedge, and a strictly reflex node into the triangle. Asking it
/// blocked every ear of lobes chained at one point, whose local sectors overlap.)
bool EarClipper::coincident_blocks(std::uint32_t q, const Point& wedge_a,
                                   const Point& wedge_b) const {
  const Boundary& b = *b_;
  const Point& corner = b.pos[q];
  const auto in_wedge = [&](const Point& y) {
    return orient2d(corner, wedge_a, y) > 0 && orient2d(wedge_b, corner, y) > 0;
  };
  return in_wedge(b.pos[b.prev[q]]) || in_wedge(b.pos[b.next[q]]);
}

bool EarClipper::is_ear(std::uint32_t v) const {
  const Boundary& b = *b_;
  const std::uint32_t p = b.prev[v], n = b.next[v];
  const Point &a = b.pos[p], &t = b.pos[v], &c = b.pos[n];
  if (!(orient2d(a, t, c) > 0)) return false;
  // A boundary edge running along the diagonal from one of its ends (a collinear chain that
  // the grid does not hold) makes the diagonal touch the boundary.
  const Point &before = b.pos[b.prev[p]], &after = b.pos[b.next[n]];
  if (orient2d(a, c, after) == 0 && on_open_segment(after, a, c)) return false;
  if (orient2d(a, c, before) == 0 && on_open_segment(before, a, c)) return false;
  const Point lo = min_corner(a, t, c), hi = max_corner(a, t, c);
  return !grid_.any_near_triangle(a, t, c, [&](const ReflexGrid::Entry& e) {
    const Point& x = e.pos;
    if (x.x < lo.x || x.x > hi.x || x.y < lo.y || x.y > hi.y) return false;
    if (e.node == p || e.node == v || e.node == n) return false;
    return blocks(p, v, n, e.node);
  });
}

/// FIST's "top": ears closer to equilateral first. Twice the area over the sum of the squared
/// sides is 1/sqrt(3) for an equilateral triangle and tends to 0 for slivers.
double EarClipper::quality(std::uint32_t v) const {
  const Boundary& b = *b_;
  const Point &a = b.pos[b.prev[v]], &t = b.pos[v], &c = b.pos[b.next[v]];
  const auto sq = [](const Point& u, const Point& w) {
    const double dx = u.x - w.x, dy = u.y - w.y;
    return dx * dx + dy * dy;
  };
  const double sides = sq(a, t) + sq(t, c) + sq(c, a);
  return sides > 0 ? orient2d_inexact(a, t, c) / sides : 0;
}

/// Squared length of v's ear diagonal: "fast" clips short diagonals first, which keeps the
/// triangles, and so the ear tests, small.
double EarClipper::diagonal(std::uint32_t v) const {
  const Point &a = b_->pos[b_->prev[v]], &c = b_->pos[b_->next[v]];
  const double dx = a.x - c.x, dy = a.y - c.y;
  return dx * dx + dy * dy;
}

void EarClipper::clip(std::uint32_t v) {
  const Boundary& b = *b_;
  out_->push_back({b.vertex[b.prev[v]], b.vertex[v], b.vertex[b.next[v]]});
  remove(v);
}

/// After a clip: v's angle shrank, so it may have turned convex; its ear status may change.
void EarClipper::update_neighbour(std::uint32_t v) {
  if (reflex_[v] && !pinch_[v] && b_->turn(v) >= 0) drop_reflex(v);
  ++stamp_[v];
}

/// Queues v if it is an ear: by shape for "top", last in first out for "fast" (the newest
/// ears sit next to the last clip, so clipping stays local and cheap).
void EarClipper::offer(std::uint32_t v) {
  if (!is_ear(v)) return;
  const int bucket = heuristic_ == EarHeuristic::top ? EarQueue::shape_bucket(quality(v))
                                                     : EarQueue::length_bucket(diagonal(v));
  queue_.push(bucket, {v, stamp_[v]});
}

bool EarClipper::pop(std::uint32_t& v) {
  EarQueue::Candidate top;
  while (queue_.pop(top)) {
    if (alive_[top.node] && stamp_[top.node] == top.stamp) {
      v = top.node;
      return true;
    }
  }
  return false;
}

void EarClipper::clip_ears(std::uint32_t entry) {
  pending_.clear();
  anchor_ = entry;
  std::uint32_t last = entry;
  std::uint32_t v = entry;
  do {
    offer(v);
    v = b_->next[v];
  } while (v != entry);
  for (;;) {
    while (remaining_ > 3) {
      if (!pop(v)) {
        if (!fall_back(anchor_)) break;
        last = touched_;
        for (std::uint32_t u : {b_->prev[last], last, b_->next[last]})
          update_neighbour(u), offer(u);
        continue;
      }
      const std::uint32_t p = b_->prev[v], n = b_->next[v];
      clip(v);
      const std::uint32_t n_left = settle(n, true), p_left = settle(p, true);
      last = p_left != UINT32_MAX ? p_left : n_left != UINT32_MAX ? n_left : p;
    }
    if (remaining_ == 3) finish(anchor_);
    if (pending_.empty()) return;
    // The next part of a split cycle.
    const PendingCycle part = pending_.back();
    pending_.pop_back();
    remaining_ = part.nodes;
    anchor_ = part.entry;
    last = part.entry;
    v = part.entry;
    do {
      ++stamp_[v];
      offer(v);
      v = b_->next[v];
    } while (v != part.entry);
  }
}

bool EarClipper::run(Boundary& b, std::uint32_t entry, EarHeuristic heuristic, TriangleList& out) {
  b_ = &b;
  out_ = &out;
  heuristic_ = heuristic;
  best_effort_ = false;
  split_budget_ = 4'000'000 + 64 * static_cast<std::size_t>(b.size());
  queue_.clear();
  classify(entry);
  if (remaining_ >= 3) clip_ears(live(entry));
  return !best_effort_;
}

EarStatistics EarClipper::statistics(Boundary& b, std::uint32_t entry) {
  b_ = &b;
  classify(entry);
  EarStatistics stats;
  std::uint32_t v = entry;
  do {
    ++stats.vertices;
    if (b.turn(v) > 0)
      ++stats.convex;
    else
      ++stats.reflex;
    if (remaining_ > 3 && is_ear(v)) ++stats.ears;
    v = b.next[v];
  } while (v != entry);
  if (remaining_ == 3) stats.ears = stats.convex;
  return stats;
}

}  // namespace pear::detail
