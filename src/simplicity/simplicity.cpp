#include "simplicity.hpp"

#include <algorithm>
#include <limits>

#include "geometry/segments.hpp"
#include "pear/predicates.hpp"

namespace pear::detail {
namespace {

bool opposite(double s, double t) {
  return (s > 0 && t < 0) || (s < 0 && t > 0);
}

/// Slabs for the sweep when the grid gives up: enough for two to four threads, few enough that
/// the edges crossing slab borders (swept twice) stay a small part. Depends on n only.
std::uint32_t slab_count(std::uint32_t n) {
  return std::clamp<std::uint32_t>(n / 16384, 1, 2);
}

}  // namespace

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

void SimplicityCheck::index_edges(const CleanPolygon& polygon, const RunContext& ctx) {
  const auto n = static_cast<std::uint32_t>(polygon.points.size());
  edges_.points = &polygon.points;
  edges_.next.resize(n);
  edges_.boxes.resize(n);
  for (std::size_t r = 0; r < polygon.ring_count(); ++r) {
    const std::uint32_t first = polygon.ring_starts[r], last = polygon.ring_starts[r + 1] - 1;
    for (std::uint32_t i = first; i < last; ++i) edges_.next[i] = i + 1;
    edges_.next[last] = first;
  }
  const std::size_t chunk = 1 << 16, chunks = (n + chunk - 1) / chunk;
  std::vector<EdgeBox> bounds(chunks);
  ctx.run_tasks("check simplicity: edge boxes", chunks, [&](std::size_t i) {
    const auto& pts = polygon.points;
    const std::size_t end = std::min<std::size_t>(n, (i + 1) * chunk);
    EdgeBox all = {pts[i * chunk].x, pts[i * chunk].y, pts[i * chunk].x, pts[i * chunk].y};
    for (std::size_t e = i * chunk; e < end; ++e) {
      const Point &a = pts[e], &b = pts[edges_.next[e]];
      edges_.boxes[e] = {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x),
                         std::max(a.y, b.y)};
      all = merged(all, edges_.boxes[e]);
    }
    bounds[i] = all;
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
    sweep_in_slabs(edges_, method == Method::sweep_only ? 3 : slab_count(edges_.size()), ctx,
                   found);
  if (found.get() == SmallestViolation::none) return std::nullopt;
  return found.get();
}

}  // namespace pear::detail
