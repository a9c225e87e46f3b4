// The exact simplicity check: its grid and its sweep must agree with a brute-force reference on
// small polygons full of degeneracies (integer grid: collinear runs, touching, overlaps).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "../../src/earclip/clean.hpp"
#include "../../src/earclip/simplicity.hpp"
#include "pear/generate.hpp"
#include "pear/predicates.hpp"

namespace pear::detail {
namespace {

bool between(const Point& p, const Point& a, const Point& b) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

/// Closed segments a-b and c-d share a point.
bool intersect(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  const double o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
    return true;
  return (o1 == 0 && between(c, a, b)) || (o2 == 0 && between(d, a, b)) ||
         (o3 == 0 && between(a, c, d)) || (o4 == 0 && between(b, c, d));
}

/// Reference: two edges may only meet in endpoints they share, and only in that one point.
bool brute_force_violation(const CleanPolygon& polygon) {
  const auto& pts = polygon.points;
  std::vector<std::uint32_t> next(pts.size());
  for (std::size_t r = 0; r < polygon.ring_count(); ++r)
    for (std::uint32_t i = polygon.ring_starts[r]; i < polygon.ring_starts[r + 1]; ++i)
      next[i] = i + 1 < polygon.ring_starts[r + 1] ? i + 1 : polygon.ring_starts[r];
  for (std::uint32_t e = 0; e < pts.size(); ++e) {
    for (std::uint32_t f = e + 1; f < pts.size(); ++f) {
      const Point &a = pts[e], &b = pts[next[e]], &c = pts[f], &d = pts[next[f]];
      if (!intersect(a, b, c, d)) continue;
      // Meeting is fine only when it is exactly one shared endpoint: then no other endpoint of
      // either lies on the other segment, and they are not collinear overlapping.
      const bool share = a == c || a == d || b == c || b == d;
      if (!share) return true;
      const Point shared = (a == c || a == d) ? a : b;
      const Point other_ab = shared == a ? b : a;
      const Point other_cd = (c == shared) ? d : c;
      if (orient2d(shared, other_ab, other_cd) == 0 &&
          (between(other_cd, shared, other_ab) || between(other_ab, shared, other_cd)))
        return true;                                              // folding back along each other
      if ((a == c || a == d) && (b == c || b == d)) return true;  // the same segment twice
    }
  }
  return false;
}

CleanPolygon random_polygon(std::mt19937& rng, int rings, int max_vertices, int grid) {
  FlatPolygon flat;
  std::uniform_int_distribution<int> coordinate(0, grid), count(3, max_vertices);
  for (int r = 0; r < rings; ++r) {
    flat.ring_starts.push_back(static_cast<std::uint32_t>(flat.points.size()));
    const int k = count(rng);
    for (int i = 0; i < k; ++i)
      flat.points.push_back({double(coordinate(rng)), double(coordinate(rng))});
  }
  flat.ring_starts.push_back(static_cast<std::uint32_t>(flat.points.size()));
  CleanPolygon clean;
  std::vector<Diagnostic> diagnostics;
  clean_polygon(flat, clean, diagnostics);
  return clean;
}

TEST(Simplicity, GridAndSweepAgreeWithBruteForce) {
  std::mt19937 rng(12345);
  SimplicityCheck check;
  int violations = 0, simple = 0;
  for (int round = 0; round < 4000; ++round) {
    const CleanPolygon polygon = random_polygon(rng, 1 + round % 3, 3 + round % 7, 3 + round % 6);
    if (polygon.ring_count() == 0 || polygon.points.size() < 3) continue;
    const bool expected = brute_force_violation(polygon);
    SCOPED_TRACE("round " + std::to_string(round));
    EXPECT_EQ(check.find_violation(polygon, SimplicityCheck::Method::sweep_only).has_value(),
              expected);
    EXPECT_EQ(check.find_violation(polygon, SimplicityCheck::Method::grid_only).has_value(),
              expected);
    (expected ? violations : simple) += 1;
  }
  EXPECT_GT(violations, 100);  // both outcomes were exercised
  EXPECT_GT(simple, 100);
}

TEST(Simplicity, SyntheticFamiliesAreSimpleByBothMethods) {
  SimplicityCheck check;
  for (std::string_view kind : generator_kinds()) {
    const Polygon polygon = generate_polygon(kind, 3000, 3);
    FlatPolygon flat;
    flatten(polygon, flat);
    CleanPolygon clean;
    std::vector<Diagnostic> diagnostics;
    ASSERT_EQ(clean_polygon(flat, clean, diagnostics), Status::ok);
    SCOPED_TRACE(std::string(kind));
    EXPECT_FALSE(check.find_violation(clean, SimplicityCheck::Method::sweep_only));
    EXPECT_FALSE(check.find_violation(clean));
  }
}

TEST(Simplicity, SweepFindsOneCrossingAmongManyEdges) {
  // A random star (long edges packed close: the grid gives up) with two radii swapped.
  Polygon star = generate_polygon("star", 20000, 5);
  std::swap(star[0][100], star[0][9000]);
  FlatPolygon flat;
  flatten(star, flat);
  CleanPolygon clean;
  std::vector<Diagnostic> diagnostics;
  ASSERT_EQ(clean_polygon(flat, clean, diagnostics), Status::ok);
  SimplicityCheck check;
  EXPECT_TRUE(check.find_violation(clean));
  EXPECT_TRUE(check.find_violation(clean, SimplicityCheck::Method::sweep_only));
}

}  // namespace
}  // namespace pear::detail
