#include "simplicity.hpp"

#include <algorithm>

#include "pear/predicates.hpp"

namespace pear::detail {
namespace {

/// p lies on segment a-b (given collinear) strictly between its endpoints.
bool inside_segment(const Point& p, const Point& a, const Point& b) {
  if (p == a || p == b) return false;
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

bool opposite(double s, double t) {
  return (s > 0 && t < 0) || (s < 0 && t > 0);
}

}  // namespace

/// Edge e runs from vertex e to next_[e]. Two edges conflict when they cross properly, when an
/// endpoint of one lies inside the other, or when they are the same segment.
bool SimplicityCheck::edges_conflict(std::uint32_t e, std::uint32_t f) const {
  const auto& pts = polygon_->points;
  const Point &a = pts[e], &b = pts[next_[e]], &c = pts[f], &d = pts[next_[f]];
  const double o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  if (opposite(o1, o2)) {
    const double o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
    if (opposite(o3, o4)) return true;
    if ((o3 == 0 && inside_segment(a, c, d)) || (o4 == 0 && inside_segment(b, c, d))) return true;
    return false;
  }
  if ((o1 == 0 && inside_segment(c, a, b)) || (o2 == 0 && inside_segment(d, a, b))) return true;
  if (o1 == 0 && o2 == 0) {
    if (inside_segment(a, c, d) || inside_segment(b, c, d)) return true;
    return (a == c && b == d) || (a == d && b == c);
  }
  return false;
}

std::optional<std::uint32_t> SimplicityCheck::find_violation(const CleanPolygon& polygon) {
  polygon_ = &polygon;
  const auto& pts = polygon.points;
  const auto n = static_cast<std::uint32_t>(pts.size());
  next_.resize(n);
  for (std::size_t r = 0; r < polygon.ring_count(); ++r) {
    const std::uint32_t first = polygon.ring_starts[r], last = polygon.ring_starts[r + 1] - 1;
    for (std::uint32_t i = first; i < last; ++i) next_[i] = i + 1;
    next_[last] = first;
  }
  Point lo = pts[0], hi = pts[0];
  for (const Point& p : pts) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  frame_.fit(lo, hi, n / 2 + 1);
  // Counting sort of (cell, edge) pairs into a compressed cell table.
  cell_start_.assign(frame_.cell_count() + 1, 0);
  for (std::uint32_t e = 0; e < n; ++e)
    frame_.for_each_cell_on_segment(pts[e], pts[next_[e]],
                                    [&](std::size_t c) { ++cell_start_[c + 1]; });
  for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  items_.resize(cell_start_.back());
  fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
  for (std::uint32_t e = 0; e < n; ++e)
    frame_.for_each_cell_on_segment(pts[e], pts[next_[e]],
                                    [&](std::size_t c) { items_[fill_[c]++] = e; });

  for (std::size_t c = 0; c + 1 < cell_start_.size(); ++c) {
    for (std::uint32_t i = cell_start_[c]; i < cell_start_[c + 1]; ++i) {
      for (std::uint32_t j = i + 1; j < cell_start_[c + 1]; ++j) {
        const std::uint32_t e = items_[i], f = items_[j];
        if (e == f) continue;
        if (next_[e] == f || next_[f] == e) {
          // Neighbours share a vertex: they conflict only by folding back over each other.
          const std::uint32_t shared = next_[e] == f ? f : e;
          const std::uint32_t before = shared == f ? e : f, after = next_[shared];
          if (orient2d(pts[before], pts[shared], pts[after]) == 0 &&
              (inside_segment(pts[before], pts[shared], pts[after]) ||
               inside_segment(pts[after], pts[before], pts[shared]) || pts[before] == pts[after]))
            return std::min(e, f);
          continue;
        }
        if (edges_conflict(e, f)) return std::min(e, f);
      }
    }
  }
  return std::nullopt;
}

}  // namespace pear::detail
