#include "mesh.hpp"

#include <algorithm>

#include "pear/predicates.hpp"

namespace pear::detail {
namespace {

/// The edges to match: every half-edge, then every ring edge, as (low, high) caller indices.
struct EdgeKeys {
  std::vector<std::uint32_t> low, high;
  std::size_t half_edges = 0;
};

EdgeKeys collect_edges(const CleanPolygon& polygon, const TriangleList& triangles) {
  EdgeKeys keys;
  keys.half_edges = 3 * triangles.size();
  const std::size_t count = keys.half_edges + polygon.points.size();
  keys.low.resize(count);
  keys.high.resize(count);
  const auto put = [&](std::size_t e, std::uint32_t u, std::uint32_t v) {
    keys.low[e] = std::min(u, v);
    keys.high[e] = std::max(u, v);
  };
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k) put(3 * t + k, triangles[t][k], triangles[t][(k + 1) % 3]);
  std::size_t e = keys.half_edges;
  for (std::size_t r = 0; r < polygon.ring_count(); ++r) {
    const std::uint32_t first = polygon.ring_starts[r], end = polygon.ring_starts[r + 1];
    for (std::uint32_t i = first; i < end; ++i)
      put(e++, polygon.original[i], polygon.original[i + 1 < end ? i + 1 : first]);
  }
  return keys;
}

/// Stable counting sort of `in` by key[e] < range into `out`.
void counting_sort(const std::vector<std::uint32_t>& in, const std::vector<std::uint32_t>& key,
                   std::size_t range, std::vector<std::uint32_t>& out) {
  std::vector<std::uint32_t> start(range + 1, 0);
  for (std::uint32_t e : in) ++start[key[e] + 1];
  for (std::size_t v = 0; v < range; ++v) start[v + 1] += start[v];
  out.resize(in.size());
  for (std::uint32_t e : in) out[start[key[e]]++] = e;
}

bool pair(Mesh& mesh, std::uint32_t h, std::uint32_t g) {
  // The same direction: the two triangles overlap.
  if (mesh.points[mesh.origin(h)] == mesh.points[mesh.origin(g)]) return false;
  mesh.twin[h] = g;
  mesh.twin[g] = h;
  ++mesh.interior_edges;
  return true;
}

/// Where rings touch, two caller indices share a point, and the triangles on the two sides of a
/// diagonal there, or a ring edge and its triangle, may use different ones. The edges the index
/// matching left alone are few: they are matched again by their endpoints' positions with a
/// plain sort. A ring edge among them keeps its triangle's edge a constraint.
bool pair_by_position(Mesh& mesh, const EdgeKeys& keys, std::vector<std::uint32_t>& loose) {
  const auto ends = [&](std::uint32_t e) {
    return EdgeEnds(mesh.points[keys.low[e]], mesh.points[keys.high[e]]);
  };
  std::sort(loose.begin(), loose.end(), [&](std::uint32_t h, std::uint32_t g) {
    const EdgeEnds e = ends(h), f = ends(g);
    return e != f ? e < f : h < g;
  });
  for (std::size_t i = 0, j = 0; i < loose.size(); i = j) {
    std::size_t rings = 0;
    for (j = i; j < loose.size() && ends(loose[j]) == ends(loose[i]); ++j)
      rings += loose[j] >= keys.half_edges ? 1 : 0;
    if (j - i - rings > 2) return false;
    if (j - i == 2 && rings == 0 && !pair(mesh, loose[i], loose[i + 1])) return false;
  }
  return true;
}

}  // namespace

EdgeEnds::EdgeEnds(const Point& p, const Point& q) : low(p), high(q) {
  if (lexicographic_less(q, p)) std::swap(low, high);
}

bool build_mesh(std::span<const Point> points, const CleanPolygon& polygon, TriangleList& triangles,
                Mesh& mesh) {
  mesh.points = points;
  mesh.triangles = &triangles;
  mesh.interior_edges = 0;
  mesh.twin.assign(3 * triangles.size(), no_twin);
  const EdgeKeys keys = collect_edges(polygon, triangles);
  for (std::uint32_t v : keys.high)
    if (v >= points.size()) return false;
  // Two counting sorts (by high, then stably by low) put equal edges next to each other.
  std::vector<std::uint32_t> order(keys.low.size()), by_high;
  for (std::size_t e = 0; e < order.size(); ++e) order[e] = static_cast<std::uint32_t>(e);
  counting_sort(order, keys.high, points.size(), by_high);
  counting_sort(by_high, keys.low, points.size(), order);
  std::vector<std::uint32_t> loose;  // matched to nothing by index: see pair_by_position
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i, rings = 0;
    for (; j < order.size() && keys.low[order[j]] == keys.low[order[i]] &&
           keys.high[order[j]] == keys.high[order[i]];
         ++j)
      rings += order[j] >= keys.half_edges ? 1 : 0;
    const std::size_t uses = j - i - rings;
    if (uses > 2) return false;
    if (uses == 2 && rings == 0) {
      if (!pair(mesh, order[i], order[i + 1])) return false;
    } else if (uses + rings == 1) {
      loose.push_back(order[i]);
    }
    i = j;
  }
  return pair_by_position(mesh, keys, loose);
}

bool must_flip(const Mesh& mesh, std::uint32_t h) {
  const std::uint32_t g = mesh.twin[h];
  const Point& a = mesh.points[mesh.corner(h, 0)];
  const Point& b = mesh.points[mesh.corner(h, 1)];
  const Point& c = mesh.points[mesh.corner(h, 2)];
  const Point& d = mesh.points[mesh.corner(g, 2)];
  // The new triangles (a, d, c) and (d, b, c) must both be counterclockwise.
  const auto flippable = [&] { return orient2d(a, d, c) > 0 && orient2d(d, b, c) > 0; };
  const double first = orient2d(a, b, c), second = orient2d(b, a, d);
  if (first < 0 || second < 0) return false;  // not a triangulation: leave it
  if (first == 0 || second == 0) return flippable();
  return incircle(a, b, c, d) > 0 && flippable();
}

void flip(Mesh& mesh, std::uint32_t h, FlipScope scope) {
  const std::uint32_t g = mesh.twin[h];
  auto& triangles = *mesh.triangles;
  const std::uint32_t t = h / 3, u = g / 3, i = h % 3, j = g % 3;
  const std::uint32_t a = triangles[t][i], b = triangles[t][(i + 1) % 3];
  const std::uint32_t c = triangles[t][(i + 2) % 3], d = triangles[u][(j + 2) % 3];
  const std::uint32_t h1 = 3 * t + (i + 1) % 3, h2 = 3 * t + (i + 2) % 3;
  const std::uint32_t g1 = 3 * u + (j + 1) % 3, g2 = 3 * u + (j + 2) % 3;
  const std::uint32_t bc = mesh.twin[h1], ca = mesh.twin[h2];
  const std::uint32_t ad = mesh.twin[g1], db = mesh.twin[g2];
  // t becomes (d, c, a) and u becomes (c, d, b), each starting at slot i resp. j: slot i and
  // slot j hold the new diagonal, the outer edges move one slot on or over to the other side.
  triangles[t][i] = d;
  triangles[t][(i + 1) % 3] = c;
  triangles[t][(i + 2) % 3] = a;
  triangles[u][j] = c;
  triangles[u][(j + 1) % 3] = d;
  triangles[u][(j + 2) % 3] = b;
  const auto link = [&](std::uint32_t slot, std::uint32_t outer) {
    mesh.twin[slot] = outer;
    if (outer != no_twin && scope.contains(outer)) mesh.twin[outer] = slot;
  };
  link(h1, ca);
  link(h2, ad);
  link(g1, db);
  link(g2, bc);
}

std::size_t flip_until_delaunay(Mesh& mesh, std::vector<std::uint32_t>& stack,
                                std::vector<std::uint8_t>& queued, FlipScope scope,
                                std::size_t budget) {
  std::size_t flips = 0;
  const auto push = [&](std::uint32_t h) {
    const std::uint32_t g = mesh.twin[h];
    if (g == no_twin || !scope.contains(g) || queued[h] || queued[g]) return;
    queued[h] = 1;
    stack.push_back(h);
  };
  while (!stack.empty()) {
    const std::uint32_t h = stack.back();
    stack.pop_back();
    queued[h] = 0;
    const std::uint32_t g = mesh.twin[h];
    if (g == no_twin || !scope.contains(g) || flips == budget || !must_flip(mesh, h)) continue;
    flip(mesh, h, scope);
    ++flips;
    push(next_half_edge(h));
    push(next_half_edge(next_half_edge(h)));
    push(next_half_edge(g));
    push(next_half_edge(next_half_edge(g)));
  }
  return flips;
}

}  // namespace pear::detail
