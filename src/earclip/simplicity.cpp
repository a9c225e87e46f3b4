#include "simplicity.hpp"

#include "boundary.hpp"

#include <algorithm>
#include <cmath>

#include "pear/predicates.hpp"

namespace pear::detail {
namespace {

bool opposite(double s, double t) {
  return (s > 0 && t < 0) || (s < 0 && t > 0);
}

}  // namespace

/// Edge e runs from vertex e to next_[e]. Two edges conflict when they cross properly, when an
/// endpoint of one lies inside the other, or when they are the same segment.
bool SimplicityCheck::edges_conflict(std::uint32_t e, std::uint32_t f) const {
  const auto& pts = polygon_->points;
  const Point &a = pts[e], &b = pts[next_[e]], &c = pts[f], &d = pts[next_[f]];
  // Segments whose boxes do not meet cannot touch; most pairs sharing a cell end here.
  if (std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
      std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y))
    return false;
  const double o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  if (opposite(o1, o2)) {
    const double o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
    if (opposite(o3, o4)) return true;
    if ((o3 == 0 && on_open_segment(a, c, d)) || (o4 == 0 && on_open_segment(b, c, d))) return true;
    return false;
  }
  if ((o1 == 0 && on_open_segment(c, a, b)) || (o2 == 0 && on_open_segment(d, a, b))) return true;
  if (o1 == 0 && o2 == 0) {
    if (on_open_segment(a, c, d) || on_open_segment(b, c, d)) return true;
    return (a == c && b == d) || (a == d && b == c);
  }
  return false;
}

/// Any two edges of the rings: neighbours in a ring share a vertex and conflict only by folding
/// back over each other; other pairs by edges_conflict.
bool SimplicityCheck::pair_conflicts(std::uint32_t e, std::uint32_t f) const {
  if (e == f) return false;
  if (next_[e] != f && next_[f] != e) return edges_conflict(e, f);
  const auto& pts = polygon_->points;
  const std::uint32_t shared = next_[e] == f ? f : e;
  const std::uint32_t before = shared == f ? e : f, after = next_[shared];
  return orient2d(pts[before], pts[shared], pts[after]) == 0 &&
         (on_open_segment(pts[before], pts[shared], pts[after]) ||
          on_open_segment(pts[after], pts[before], pts[shared]) || pts[before] == pts[after]);
}

std::optional<std::uint32_t> SimplicityCheck::find_violation(const CleanPolygon& polygon,
                                                             Method method) {
  polygon_ = &polygon;
  const auto n = static_cast<std::uint32_t>(polygon.points.size());
  next_.resize(n);
  for (std::size_t r = 0; r < polygon.ring_count(); ++r) {
    const std::uint32_t first = polygon.ring_starts[r], last = polygon.ring_starts[r + 1] - 1;
    for (std::uint32_t i = first; i < last; ++i) next_[i] = i + 1;
    next_[last] = first;
  }
  if (method != Method::sweep_only) {
    const GridVerdict verdict = check_on_grid();
    if (verdict.decided || method == Method::grid_only) return verdict.violation;
  }
  return sweep();
}

/// Pairs of edges sharing a grid cell. Fast where edges are short against their spacing (real
/// outlines); where the grid would hold or pair up too much (long edges packed close, as in a
/// random star), it gives up and the sweep decides. The limits depend on counts only, so the
/// outcome is deterministic.
SimplicityCheck::GridVerdict SimplicityCheck::check_on_grid() {
  const auto& pts = polygon_->points;
  const auto n = static_cast<std::uint32_t>(pts.size());
  Point lo = pts[0], hi = pts[0];
  double perimeter = 0;
  for (std::uint32_t e = 0; e < n; ++e) {
    const Point& p = pts[e];
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    perimeter += std::abs(pts[next_[e]].x - p.x) + std::abs(pts[next_[e]].y - p.y);
  }
  // Cells about twice the mean edge length, between n/2 and 4n cells.
  const double side = 2 * perimeter / n;
  const double wanted = side > 0 ? (hi.x - lo.x) * (hi.y - lo.y) / (side * side) : 0;
  frame_.fit(lo, hi, static_cast<std::size_t>(std::clamp(wanted, n / 2.0 + 1, 4.0 * n + 1)));

  const std::size_t max_entries = 16 * static_cast<std::size_t>(n) + 64;
  cell_start_.assign(frame_.cell_count() + 1, 0);
  std::size_t entries = 0;
  for (std::uint32_t e = 0; e < n && entries <= max_entries; ++e)
    frame_.for_each_cell_on_segment(pts[e], pts[next_[e]], [&](std::size_t c) {
      ++cell_start_[c + 1];
      ++entries;
    });
  if (entries > max_entries) return {};
  std::size_t pairs = 0;
  for (std::size_t c = 1; c < cell_start_.size(); ++c) {
    const std::size_t k = cell_start_[c];
    pairs += k * (k - 1) / 2;
    cell_start_[c] += cell_start_[c - 1];
  }
  if (pairs > 96 * static_cast<std::size_t>(n) + 1024)
    return {};  // pair tests are ~100x cheaper than a sweep step
  items_.resize(cell_start_.back());
  fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
  for (std::uint32_t e = 0; e < n; ++e)
    frame_.for_each_cell_on_segment(pts[e], pts[next_[e]],
                                    [&](std::size_t c) { items_[fill_[c]++] = e; });
  for (std::size_t c = 0; c + 1 < cell_start_.size(); ++c)
    for (std::uint32_t i = cell_start_[c]; i < cell_start_[c + 1]; ++i)
      for (std::uint32_t j = i + 1; j < cell_start_[c + 1]; ++j)
        if (pair_conflicts(items_[i], items_[j])) return {true, std::min(items_[i], items_[j])};
  return {true, std::nullopt};
}

}  // namespace pear::detail
