// FIST's fallback cascade for when no ear is left although more than three nodes remain.
// Each step removes at least one node, so clipping always ends, in at most n steps.
#include <algorithm>
#include <cmath>

#include "ear_clipper.hpp"

namespace pear::detail {
namespace {

bool segments_cross(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  const double o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

}  // namespace

/// Whether segment a-b meets edge u-w other than in a shared endpoint position.
bool diagonal_hits_edge(const Point& a, const Point& b, const Point& u, const Point& w) {
  const double o1 = orient2d(a, b, u), o2 = orient2d(a, b, w);
  const double o3 = orient2d(u, w, a), o4 = orient2d(u, w, b);
  const auto opposite = [](double s, double t) { return (s > 0 && t < 0) || (s < 0 && t > 0); };
  if (opposite(o1, o2) && opposite(o3, o4)) return true;
  return (o1 == 0 && on_open_segment(u, a, b)) || (o2 == 0 && on_open_segment(w, a, b)) ||
         (o3 == 0 && on_open_segment(a, u, w)) || (o4 == 0 && on_open_segment(b, u, w));
}

/// 1. Degenerate remnants of a valid boundary: a spike that returns to its start (the last bit
///    of a lobe of a self-touching ring) or a zero-length edge goes away without a triangle.
/// 2. A local self-crossing (edges before and after an ear cross): clip that ear (best effort).
/// 3. Otherwise clip the best-shaped convex corner (best effort); with none, drop a node.
/// Every call removes a node or splits the cycle. The cycle is scanned from `near` while the
/// run's budget lasts, then only a window after it: linear time in all.
bool EarClipper::fall_back(std::uint32_t near) {
  Boundary& b = *b_;
  std::uint32_t crossing = UINT32_MAX, convex = UINT32_MAX;
  double best_quality = -1;
  const std::size_t scan =
      fallback_budget_ >= remaining_ ? remaining_ : std::min(remaining_, fallback_window);
  fallback_budget_ -= std::min(fallback_budget_, scan);
  fallback_work_ += scan;
  std::uint32_t v = near;
  for (std::size_t k = 0; k < scan; ++k) {
    const std::uint32_t p = b.prev[v], n = b.next[v];
    if (b.pos[p] == b.pos[n] || b.pos[v] == b.pos[n]) {
      const std::uint32_t gone = b.pos[v] == b.pos[n] ? n : v;
      const std::uint32_t also = gone == v ? n : UINT32_MAX;
      for (std::uint32_t u : {gone, also})
        if (u != UINT32_MAX && remaining_ > 2) remove(u);
      touched_ = p;
      return remaining_ >= 3;
    }
    const double turn = b.turn(v);
    if (turn > 0) {
      if (crossing == UINT32_MAX &&
          segments_cross(b.pos[b.prev[p]], b.pos[p], b.pos[n], b.pos[b.next[n]]))
        crossing = v;
      const double q = quality(v);
      if (q > best_quality) best_quality = q, convex = v;
    }
    v = n;
    if (v == near) break;
  }

  if (split_along_diagonal(near)) return true;

  if (!best_effort_) best_effort_vertex_ = b.vertex[near];
  best_effort_ = true;
  const std::uint32_t chosen = crossing != UINT32_MAX ? crossing : convex;
  if (chosen != UINT32_MAX) {
    touched_ = b.prev[chosen];
    clip(chosen);
  } else {
    touched_ = b.prev[near];
    remove(near);
  }
  return remaining_ >= 3;
}

/// FIST's split: when a valid boundary has no ear left (lobes chained at a pinch point can
/// hide every ear), cut it along a diagonal that lies inside at both ends and meets no edge,
/// and clip the two parts one after the other. The search is cubic, so it runs only on cycles
/// of at most split_limit nodes and within the run's fallback budget (every pair of nodes and
/// every edge test counts: bounded time on inputs that are not simple); beyond that the
/// best-effort steps take over.
bool EarClipper::split_along_diagonal(std::uint32_t near) {
  Boundary& b = *b_;
  if (remaining_ > split_limit) return false;
  scratch_.clear();
  std::uint32_t u = near;
  do {
    scratch_.push_back(u);
    u = b.next[u];
  } while (u != near);
  const std::size_t m = scratch_.size();
  for (std::size_t i = 0; i < m; ++i) {
    for (std::size_t j = i + 2; j < m; ++j) {
      if (i == 0 && j == m - 1) continue;  // neighbours
      if (fallback_budget_ == 0) return false;
      --fallback_budget_;
      ++fallback_work_;
      const std::uint32_t a = scratch_[i], c = scratch_[j];
      const Point &pa = b.pos[a], &pc = b.pos[c];
      if (pa == pc || !b.sector_contains(a, pc) || !b.sector_contains(c, pa)) continue;
      if (fallback_budget_ < m) return false;
      fallback_budget_ -= m;
      fallback_work_ += m;
      bool clear = true;
      for (std::size_t k = 0; k < m && clear; ++k)
        clear = !diagonal_hits_edge(pa, pc, b.pos[scratch_[k]], b.pos[b.next[scratch_[k]]]);
      if (!clear) continue;
      split_cycle(a, c, j - i + 1);
      return true;
    }
  }
  return false;
}

/// Cuts the cycle along a-c: a -> ... -> c -> a is clipped now, copies of a and c close the
/// other part, which waits on the pending stack.
void EarClipper::split_cycle(std::uint32_t a, std::uint32_t c, std::size_t first_part) {
  Boundary& b = *b_;
  const std::uint32_t other = remaining_ - first_part + 2;
  const auto [c2, a2] = b.add_diagonal(c, a);
  for (auto* flags : {&alive_, &reflex_, &pinch_}) flags->resize(b.size(), 0);
  stamp_.resize(b.size(), 0);
  alive_[a2] = alive_[c2] = 1;
  for (std::uint32_t node : {a, c, a2, c2}) {
    pinch_[node] = 1;
    if (!reflex_[node]) reflex_[node] = 1, grid_.add(node, b.pos[node]);
  }
  // The waiting part's queued ears must not be popped while the first part is clipped.
  std::uint32_t u = a2;
  do {
    ++stamp_[u];
    u = b.next[u];
  } while (u != a2);
  pending_.push_back({a2, other});
  remaining_ = first_part;
  anchor_ = a;
  touched_ = a;
  u = a;
  do {
    ++stamp_[u];
    offer(u);
    u = b.next[u];
  } while (u != a);
}

/// Ends the cycle being clipped: its last three nodes form its last triangle, unless they are
/// degenerate, and every node left leaves the boundary, so that none of them, still queued, is
/// popped as an ear of the part clipped next (it would be clipped twice and that part's count
/// would go wrong).
void EarClipper::finish(std::uint32_t any) {
  Boundary& b = *b_;
  if (remaining_ == 3 && alive_[any]) {
    const double turn = b.turn(any);
    if (turn > 0)
      out_->push_back({b.vertex[b.prev[any]], b.vertex[any], b.vertex[b.next[any]]});
    else if (turn < 0 && !best_effort_)
      best_effort_ = true, best_effort_vertex_ = b.vertex[any];
  }
  for (std::uint32_t v = any; remaining_ > 0 && alive_[v]; v = b.next[v]) {
    alive_[v] = 0;
    --remaining_;
  }
  remaining_ = 0;
}

}  // namespace pear::detail
