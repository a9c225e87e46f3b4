#include "polygon_oracle.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "pear/predicates.hpp"
#include "support.hpp"

namespace fuzz {
namespace {

using pear::orient2d;
using pear::Point;
using pear::Ring;

bool accepted_coordinate(double c) {
  if (!std::isfinite(c)) return false;
  const double magnitude = std::fabs(c);
  return c == 0 || (pear::min_nonzero_coordinate <= magnitude && magnitude <= pear::max_coordinate);
}

bool lexicographic_less(const Point& a, const Point& b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

/// p lies on segment ab and is neither endpoint.
bool inside_segment(const Point& a, const Point& b, const Point& p) {
  if (p == a || p == b || orient2d(a, b, p) != 0) return false;
  const auto [low, high] = std::minmax(a, b, lexicographic_less);
  return lexicographic_less(low, p) && lexicographic_less(p, high);
}

struct Edge {
  Point a, b;
  bool boxes_apart(const Edge& o) const {
    return std::max(a.x, b.x) < std::min(o.a.x, o.b.x) ||
           std::max(o.a.x, o.b.x) < std::min(a.x, b.x) ||
           std::max(a.y, b.y) < std::min(o.a.y, o.b.y) ||
           std::max(o.a.y, o.b.y) < std::min(a.y, b.y);
  }
};

int sign(double v) {
  return (v > 0) - (v < 0);
}

/// The two edges cross, overlap, or one's endpoint lies inside the other.
bool edges_conflict(const Edge& e, const Edge& f) {
  if ((e.a == f.a && e.b == f.b) || (e.a == f.b && e.b == f.a)) return true;
  if (inside_segment(e.a, e.b, f.a) || inside_segment(e.a, e.b, f.b) ||
      inside_segment(f.a, f.b, e.a) || inside_segment(f.a, f.b, e.b))
    return true;
  return sign(orient2d(e.a, e.b, f.a)) * sign(orient2d(e.a, e.b, f.b)) < 0 &&
         sign(orient2d(f.a, f.b, e.a)) * sign(orient2d(f.a, f.b, e.b)) < 0;
}

bool any_edges_conflict(const pear::Polygon& rings) {
  std::vector<Edge> edges;
  for (const Ring& ring : rings)
    for (std::size_t i = 0; i < ring.size(); ++i)
      edges.push_back({ring[i], ring[(i + 1) % ring.size()]});
  for (std::size_t i = 0; i < edges.size(); ++i)
    for (std::size_t j = i + 1; j < edges.size(); ++j)
      if (!edges[i].boxes_apart(edges[j]) && edges_conflict(edges[i], edges[j])) return true;
  return false;
}

/// Winding number test; p must not lie on the ring.
bool ring_contains_point(const Ring& ring, const Point& p) {
  int winding = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point& a = ring[i];
    const Point& b = ring[(i + 1) % ring.size()];
    if (a.y <= p.y) {
      if (b.y > p.y && orient2d(a, b, p) > 0) ++winding;
    } else if (b.y <= p.y && orient2d(a, b, p) < 0) {
      --winding;
    }
  }
  return winding != 0;
}

/// Does the segment from ring[i] towards v start into the ring's interior? The interior angle
/// at a vertex is the intersection (convex) or union (reflex) of the two edges' left sides.
bool starts_inside(const Ring& ring, int orientation, std::size_t i, const Point& v) {
  const std::size_t n = ring.size();
  Point before = ring[(i + n - 1) % n];
  Point after = ring[(i + 1) % n];
  if (orientation < 0) std::swap(before, after);
  const Point& u = ring[i];
  const bool left_of_out = orient2d(u, after, v) > 0;
  const bool left_of_in = orient2d(before, u, v) > 0;
  return orient2d(before, u, after) > 0 ? left_of_out && left_of_in : left_of_out || left_of_in;
}

/// Which sides of simple ring `outer` simple ring `inner` has parts on. The two must not cross or
/// overlap, so each point of inner off outer's corners, and each chord of inner between two of
/// outer's corners that is not an edge of outer, lies wholly inside or outside; every edge of
/// inner is one of these or ends at such a point. One of them does not decide: rings touching at
/// two corners can lie on both sides (fuzz: a hole passing out through a corner of the shell).
struct Sides {
  bool inside = false, outside = false;
};

Sides sides_of(const Ring& inner, const Ring& outer, int outer_orientation) {
  std::vector<Point> corners(outer.begin(), outer.end());
  std::sort(corners.begin(), corners.end(), lexicographic_less);
  const auto is_corner = [&](const Point& p) {
    return std::binary_search(corners.begin(), corners.end(), p, lexicographic_less);
  };
  Sides sides;
  for (std::size_t k = 0; k < inner.size(); ++k) {
    const Point& u = inner[k];
    const Point& v = inner[(k + 1) % inner.size()];
    bool inside = false;
    if (!is_corner(u)) {
      inside = ring_contains_point(outer, u);
    } else if (!is_corner(v)) {
      continue;  // the edge lies on v's side, which v's own test decides
    } else {
      const std::size_t i = std::find(outer.begin(), outer.end(), u) - outer.begin();
      const std::size_t n = outer.size();
      if (outer[(i + 1) % n] == v || outer[(i + n - 1) % n] == v) continue;  // a shared edge
      inside = starts_inside(outer, outer_orientation, i, v);
    }
    (inside ? sides.inside : sides.outside) = true;
  }
  return sides;
}

bool visits_a_point_twice(const Ring& ring) {
  std::vector<Point> sorted(ring.begin(), ring.end());
  std::sort(sorted.begin(), sorted.end(), lexicographic_less);
  return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

/// Holes inside the outer ring and outside each other.
bool holes_nest_correctly(const pear::Polygon& rings, const std::vector<int>& orientation) {
  for (std::size_t h = 1; h < rings.size(); ++h) {
    if (sides_of(rings[h], rings[0], orientation[0]).outside) return false;
    for (std::size_t g = 1; g < h; ++g)
      if (sides_of(rings[h], rings[g], orientation[g]).inside ||
          sides_of(rings[g], rings[h], orientation[h]).inside)
        return false;
  }
  return true;
}

}  // namespace

pear::Polygon drop_repeated_points(const pear::Polygon& polygon) {
  pear::Polygon rings;
  for (const Ring& ring : polygon) {
    Ring& kept = rings.emplace_back();
    for (const Point& p : ring)
      if (kept.empty() || !(kept.back() == p)) kept.push_back(p);
    while (kept.size() > 1 && kept.back() == kept.front()) kept.pop_back();
  }
  return rings;
}

namespace {

/// The ring turns straight back at b (a != b != c): collinear, b not strictly between.
bool turns_back(const Point& a, const Point& b, const Point& c) {
  return orient2d(a, b, c) == 0 && !inside_segment(a, c, b);
}

/// In rounds, as the README says: all tips of the ring at once, then repeats merged, again.
void dissolve_spikes(Ring& ring) {
  while (ring.size() >= 3) {
    const std::size_t n = ring.size();
    Ring kept;
    for (std::size_t i = 0; i < n; ++i)
      if (!turns_back(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n])) kept.push_back(ring[i]);
    if (kept.size() == n) return;
    ring.clear();
    for (const Point& p : kept)
      if (ring.empty() || !(ring.back() == p)) ring.push_back(p);
    while (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
  }
}

}  // namespace

pear::Polygon repair(const pear::Polygon& polygon) {
  pear::Polygon rings = drop_repeated_points(polygon);
  for (Ring& ring : rings) dissolve_spikes(ring);
  std::vector<Point> all;
  for (const Ring& ring : rings) all.insert(all.end(), ring.begin(), ring.end());
  std::sort(all.begin(), all.end(), lexicographic_less);
  all.erase(std::unique(all.begin(), all.end()), all.end());
  pear::Polygon split;
  for (const Ring& ring : rings) {
    Ring& out = split.emplace_back();
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point &a = ring[i], &b = ring[(i + 1) % ring.size()];
      out.push_back(a);
      std::vector<Point> inside;
      for (const Point& p : all)
        if (inside_segment(a, b, p)) inside.push_back(p);
      // Sorted from a towards b: by x then y, reversed when b comes first.
      std::sort(inside.begin(), inside.end(), lexicographic_less);
      if (lexicographic_less(b, a)) std::reverse(inside.begin(), inside.end());
      out.insert(out.end(), inside.begin(), inside.end());
    }
  }
  return split;
}

PolygonFacts examine(const pear::Polygon& polygon) {
  PolygonFacts facts;
  for (const Ring& ring : polygon)
    for (const Point& p : ring)
      if (!accepted_coordinate(p.x) || !accepted_coordinate(p.y))
        facts.coordinates_in_range = false;
  if (!facts.coordinates_in_range || polygon.empty()) return facts;
  const pear::Polygon rings = repair(polygon);
  facts.holes = rings.size() - 1;
  std::vector<Point> all;
  for (const Ring& ring : rings) {
    if (ring.size() < 3 || visits_a_point_twice(ring)) return facts;
    all.insert(all.end(), ring.begin(), ring.end());
  }
  facts.vertices = all.size();
  std::sort(all.begin(), all.end(), lexicographic_less);
  facts.repeated_points = all.size() - (std::unique(all.begin(), all.end()) - all.begin());
  if (any_edges_conflict(rings)) return facts;
  std::vector<int> orientation;
  std::vector<mpq_class> areas;
  for (const Ring& ring : rings) {
    areas.push_back(twice_ring_area(ring));
    orientation.push_back(sgn(areas.back()));
  }
  if (!holes_nest_correctly(rings, orientation)) return facts;
  facts.twice_area = abs(areas[0]);
  for (std::size_t h = 1; h < areas.size(); ++h) facts.twice_area -= abs(areas[h]);
  facts.valid = true;
  return facts;
}

}  // namespace fuzz
