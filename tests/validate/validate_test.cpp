// The validator: accepts hand-made correct triangulations and rejects hand-made broken ones, each
// for the reason it was broken. All expected values are computed by hand in the comments.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "pear/validate.hpp"

namespace pear::test {
namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

ValidationReport check(const Polygon& polygon, const Triangles& triangles,
                       const ValidateOptions& options = {}) {
  return validate(polygon, std::span<const std::array<std::uint32_t, 3>>(triangles), options);
}

bool has_message(const ValidationReport& report, const std::string& part) {
  for (const auto& message : report.messages)
    if (message.find(part) != std::string::npos) return true;
  return false;
}

std::string messages(const ValidationReport& report) {
  std::string all;
  for (const auto& message : report.messages) all += message + "\n";
  return all;
}

const Polygon unit_square = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
const Triangles unit_square_triangles = {{0, 1, 2}, {0, 2, 3}};

// Outer 4x4 square (0..3), a clockwise 2x2 hole (4..7) in its middle: area 16 - 4 = 12.
const Polygon square_with_hole = {{{0, 0}, {4, 0}, {4, 4}, {0, 4}},
                                  {{1, 1}, {1, 3}, {3, 3}, {3, 1}}};
// One trapezoid between each outer side and the hole side facing it, cut along a diagonal.
// Twice the areas: 4, 2, 4, 2, 4, 2, 4, 2 = 24.
const Triangles square_with_hole_triangles = {{0, 1, 7}, {0, 7, 4}, {1, 2, 6}, {1, 6, 7},
                                              {2, 3, 5}, {2, 5, 6}, {3, 0, 4}, {3, 4, 5}};

TEST(Validate, AcceptsSquare) {
  const auto report = check(unit_square, unit_square_triangles);
  EXPECT_TRUE(report.valid) << messages(report);
  EXPECT_EQ(report.expected_triangles, 2u);
  EXPECT_EQ(report.polygon_area, 1.0);
  EXPECT_EQ(report.triangle_area, 1.0);
  EXPECT_EQ(report.area_rel_error, 0.0);
  EXPECT_TRUE(report.messages.empty());
}

TEST(Validate, AcceptsSquareWithHole) {
  const auto report = check(square_with_hole, square_with_hole_triangles);
  EXPECT_TRUE(report.valid) << messages(report);
  EXPECT_EQ(report.expected_triangles, 8u);  // n + 2h - 2 = 8 + 2 - 2
  EXPECT_EQ(report.polygon_area, 12.0);
  EXPECT_EQ(report.triangle_area, 12.0);
}

TEST(Validate, AcceptsCounterclockwiseHoleAsWell) {
  Polygon polygon = square_with_hole;
  polygon[1] = {{3, 1}, {3, 3}, {1, 3}, {1, 1}};  // the same hole, counterclockwise: 4..7 reversed
  const Triangles triangles = {{0, 1, 4}, {0, 4, 7}, {1, 2, 5}, {1, 5, 4},
                               {2, 3, 6}, {2, 6, 5}, {3, 0, 7}, {3, 7, 6}};
  const auto report = check(polygon, triangles);
  EXPECT_TRUE(report.valid) << messages(report);
}

TEST(Validate, AcceptsLShape) {
  // (0,0) (2,0) (2,1) (1,1) (1,2) (0,2): area 3, a fan from vertex 0 (twice the areas 2, 1, 1, 2).
  const Polygon l_shape = {{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}};
  const auto report = check(l_shape, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 5}});
  EXPECT_TRUE(report.valid) << messages(report);
  EXPECT_EQ(report.expected_triangles, 4u);
  EXPECT_EQ(report.polygon_area, 3.0);
}

TEST(Validate, AcceptsClockwiseOuterRing) {
  const Polygon clockwise = {{{0, 0}, {0, 1}, {1, 1}, {1, 0}}};
  const auto report = check(clockwise, {{0, 3, 2}, {0, 2, 1}});
  EXPECT_TRUE(report.valid) << messages(report);
  EXPECT_EQ(report.polygon_area, 1.0);
}

// A clockwise hole (0,0) (1,2) (2,1) touching the outer square's corner (0,0): indices 0 and 4 are
// one point. The region is simply connected around the hole's pinch: 16 - 3/2 = 14.5, and it
// needs n + 2h - 2 - 2m = 7 + 2 - 2 - 2 = 5 triangles (m = 1 repeated point).
const Polygon touching_hole = {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{0, 0}, {1, 2}, {2, 1}}};

TEST(Validate, AcceptsHoleTouchingOuterRingAtAVertex) {
  // Twice the areas: 4 + 8 + 5 + 8 + 4 = 29. Triangle 4 uses index 4 for the shared point.
  const Triangles triangles = {{0, 1, 6}, {1, 2, 6}, {6, 2, 5}, {5, 2, 3}, {4, 5, 3}};
  const auto report = check(touching_hole, triangles);
  EXPECT_TRUE(report.valid) << messages(report);
  EXPECT_EQ(report.expected_triangles, 5u);
  EXPECT_EQ(report.polygon_area, 14.5);
  EXPECT_EQ(report.triangle_area, 14.5);
}

TEST(Validate, AcceptsEitherCopyOfATouchingPoint) {
  const Triangles triangles = {{4, 1, 6}, {1, 2, 6}, {6, 2, 5}, {5, 2, 3}, {0, 5, 3}};
  const auto report = check(touching_hole, triangles);
  EXPECT_TRUE(report.valid) << messages(report);
}

TEST(Validate, CollapsedTrianglesAreNotCounted) {
  // (0, 4, 5) names the touching point twice: zero area, no boundary, not one of the 5.
  const Triangles triangles = {{0, 1, 6}, {1, 2, 6}, {6, 2, 5}, {5, 2, 3}, {4, 5, 3}, {0, 4, 5}};
  const auto strict = check(touching_hole, triangles);
  EXPECT_FALSE(strict.valid);
  EXPECT_EQ(strict.zero_area_triangles, 1u);
  EXPECT_TRUE(has_message(strict, "triangle 5 (0, 4, 5) has zero area")) << messages(strict);
  const auto relaxed = check(touching_hole, triangles, {.allow_zero_area = true});
  EXPECT_TRUE(relaxed.valid) << messages(relaxed);
}

TEST(Validate, RejectsTouchingHoleTriangulatedAcrossTheHole) {
  // Triangle (0, 1, 5) = (0,0) (4,0) (1,2) covers the hole's vertex region: it replaces
  // (0, 1, 6) and (6, 2, 5) is then wrong as well.
  const Triangles triangles = {{0, 1, 5}, {1, 2, 6}, {6, 2, 5}, {5, 2, 3}, {4, 5, 3}};
  const auto report = check(touching_hole, triangles);
  EXPECT_FALSE(report.valid);
  EXPECT_GT(report.bad_edges, 0u);
}

TEST(Validate, CountsWhereAHoleTouchesTheOuterRing) {
  // No ring passes a point twice, so the count holds with the touching point: a fan around a
  // Steiner point (the dropped one-point hole, index 7) has 2 triangles too many.
  Polygon polygon = touching_hole;
  polygon.push_back({{3, 3}});
  const Triangles triangles = {{0, 1, 6}, {1, 2, 6}, {6, 2, 7}, {2, 3, 7},
                               {3, 5, 7}, {5, 6, 7}, {4, 5, 3}};
  const auto report = check(polygon, triangles);
  EXPECT_FALSE(report.valid);
  EXPECT_EQ(report.expected_triangles, 5u);
  EXPECT_EQ(report.bad_edges, 0u);
  EXPECT_TRUE(has_message(report, "wrong triangle count: 7")) << messages(report);
}

// A 4x4 square (0..3) and a clockwise triangular hole (4..6) whose vertex 4 = (0,2) lies inside
// the outer edge 3 -> 0 (a T-junction): that edge is matched by 3 -> 4 and 4 -> 0.
const Polygon hole_on_edge = {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{0, 2}, {2, 3}, {2, 1}}};

TEST(Validate, AcceptsBoundaryEdgeSplitWhereAHoleVertexLiesInsideIt) {
  // Twice the areas: 4 + 4 + 4 + 8 + 4 + 4 = 28 = 2 * (16 - 2). Counted with the split: n = 8
  // (7 vertices and the split), h = 1, m = 1: 6 triangles.
  const Triangles triangles = {{3, 4, 5}, {3, 5, 2}, {2, 5, 6}, {2, 6, 1}, {1, 6, 0}, {0, 6, 4}};
  const auto report = check(hole_on_edge, triangles);
  EXPECT_TRUE(report.valid) << messages(report);
  EXPECT_EQ(report.expected_triangles, 6u);
  EXPECT_EQ(report.bad_edges, 0u);
}

TEST(Validate, RejectsTriangulationMissingTheSplit) {
  // Triangles 0 and 1 use the outer edge 3 -> 0 whole and cover the hole's corner at (0, 2).
  const Triangles triangles = {{3, 0, 6}, {3, 6, 5}, {3, 5, 2}, {2, 5, 6}, {2, 6, 1}, {1, 6, 0}};
  const auto report = check(hole_on_edge, triangles);
  EXPECT_FALSE(report.valid);
  EXPECT_GT(report.bad_edges, 0u);
}

TEST(Validate, RejectsATriangulationThatFillsAnOverlapOfTheBoundary) {
  // The hole's base (3,0)-(1,0) runs along the outer edge 0 -> 1 the other way: the boundary
  // cancels there as a chain, and the five triangles cover the notched square exactly, but
  // boundary edges that overlap are no polygon (pear calls it not_simple).
  const Polygon notch = {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 0}, {3, 0}, {2, 2}}};
  const auto report = check(notch, {{0, 4, 6}, {0, 6, 3}, {6, 2, 3}, {6, 5, 1}, {6, 1, 2}});
  EXPECT_FALSE(report.valid);
  EXPECT_EQ(report.area_rel_error, 0);
  EXPECT_TRUE(has_message(report, "is not used by any triangle")) << messages(report);
}

TEST(Validate, RejectsTriangleEdgeThroughABoundaryVertex) {
  // Vertex 1 = (2,0) lies on the triangles' edge 0 -> 2: only the boundary's edges may be split.
  const Polygon polygon = {{{0, 0}, {2, 0}, {4, 0}, {4, 4}, {0, 4}}};
  const auto report = check(polygon, {{0, 2, 3}, {0, 3, 4}});
  EXPECT_FALSE(report.valid);
  EXPECT_TRUE(has_message(report, "is not used by any triangle")) << messages(report);
}

TEST(Validate, DissolvesZeroWidthSpikes) {
  // Out to (2, 6) and back along the same segment: no area, and not a vertex of the polygon
  // (vertex 4 repeats vertex 2), so 3 triangles for the 5 kept vertices.
  const Polygon polygon = {{{0, 0}, {4, 0}, {4, 4}, {2, 4}, {2, 6}, {2, 4}, {0, 4}}};
  const auto report = check(polygon, {{0, 1, 2}, {0, 2, 3}, {0, 3, 6}});
  EXPECT_TRUE(report.valid) << messages(report);
  EXPECT_EQ(report.expected_triangles, 3u);
  const auto tip = check(polygon, {{0, 1, 2}, {0, 2, 3}, {0, 3, 6}, {3, 2, 4}});
  EXPECT_FALSE(tip.valid);
  EXPECT_TRUE(has_message(tip, "is not a vertex of the cleaned polygon")) << messages(tip);
}

TEST(Validate, CleansRepeatedAndClosingPoints) {
  // Index 2 repeats index 1 and index 5 closes the ring: kept are 0, 1, 3, 4.
  const Polygon polygon = {{{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}}};
  const auto report = check(polygon, {{0, 1, 3}, {0, 3, 4}});
  EXPECT_TRUE(report.valid) << messages(report);
  EXPECT_EQ(report.expected_triangles, 2u);
}

TEST(Validate, IgnoresDegenerateHoles) {
  // A two-point hole and a zero-area (collinear) hole are dropped: h = 0, their edges are free.
  Polygon polygon = unit_square;
  polygon.push_back({{0.5, 0.5}, {0.6, 0.6}});
  polygon.push_back({{0.2, 0.2}, {0.3, 0.3}, {0.4, 0.4}});
  const auto report = check(polygon, unit_square_triangles);
  EXPECT_TRUE(report.valid) << messages(report);
  EXPECT_EQ(report.expected_triangles, 2u);
}

TEST(Validate, RejectsOverlapWhoseAreasCancel) {
  // (1, 2, 0) is (0, 1, 2) again by rotation and (0, 2, 3) is missing: count and area both match.
  const auto report = check(unit_square, {{0, 1, 2}, {1, 2, 0}});
  EXPECT_FALSE(report.valid);
  EXPECT_EQ(report.area_rel_error, 0.0);
  EXPECT_EQ(report.triangles, report.expected_triangles);
  EXPECT_GT(report.bad_edges, 0u);
  EXPECT_TRUE(has_message(report, "triangle 1 (1, 2, 0) repeats triangle 0 (0, 1, 2)"))
      << messages(report);
}

TEST(Validate, RejectsTwoOverlappingTrianglesOfExactArea) {
  // (0, 1, 2) and (1, 2, 3) both have area 1/2 and overlap around (1, 1/2), leaving (0, 0),
  // (1/2, 1/2), (0, 1) uncovered: both use edge 1 -> 2.
  const auto report = check(unit_square, {{0, 1, 2}, {1, 2, 3}});
  EXPECT_FALSE(report.valid);
  EXPECT_EQ(report.area_rel_error, 0.0);
  EXPECT_EQ(report.bad_orientation, 0u);
  EXPECT_TRUE(has_message(report, "used in the same direction")) << messages(report);
  EXPECT_TRUE(has_message(report, "boundary edge from vertex 3 (ring 0, vertex 3) to vertex 0"))
      << messages(report);
}

TEST(Validate, RejectsMissingBoundaryEdge) {
  Triangles triangles = square_with_hole_triangles;
  triangles.erase(triangles.begin());  // (0, 1, 7): the only user of boundary edge 0 -> 1
  const auto report = check(square_with_hole, triangles);
  EXPECT_FALSE(report.valid);
  EXPECT_TRUE(has_message(report,
                          "boundary edge from vertex 0 (ring 0, vertex 0) to vertex 1 "
                          "(ring 0, vertex 1) is not used by any triangle"))
      << messages(report);
  // The missing triangle's area is 2 of 12: relative error 1/6.
  EXPECT_DOUBLE_EQ(report.area_rel_error, 1.0 / 6.0);
}

TEST(Validate, RejectsFlippedTriangle) {
  const auto report = check(unit_square, {{0, 1, 2}, {0, 3, 2}});
  EXPECT_FALSE(report.valid);
  EXPECT_EQ(report.bad_orientation, 1u);
  EXPECT_TRUE(has_message(report, "triangle 1 (0, 3, 2) is clockwise")) << messages(report);
}

TEST(Validate, RejectsOutOfRangeIndex) {
  const auto report = check(unit_square, {{0, 1, 2}, {0, 2, 4}});
  EXPECT_FALSE(report.valid);
  EXPECT_TRUE(has_message(report, "triangle 1 (0, 2, 4): index 4 is out of range"))
      << messages(report);
}

TEST(Validate, RejectsRepeatedTriangle) {
  const auto report = check(unit_square, {{0, 1, 2}, {0, 2, 3}, {2, 0, 1}});
  EXPECT_FALSE(report.valid);
  EXPECT_TRUE(has_message(report, "triangle 2 (2, 0, 1) repeats triangle 0 (0, 1, 2)"))
      << messages(report);
}

TEST(Validate, RejectsWrongCountWithSteinerPoint) {
  // A one-point "hole" is dropped, but its point (index 4, the centre) can still be named.
  // The fan around it is a valid triangulation with a Steiner point: 4 triangles, not 2.
  Polygon polygon = unit_square;
  polygon.push_back({{0.5, 0.5}});
  const Triangles fan = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
  const auto strict = check(polygon, fan);
  EXPECT_FALSE(strict.valid);
  EXPECT_EQ(strict.expected_triangles, 2u);
  EXPECT_EQ(strict.bad_edges, 0u);
  EXPECT_TRUE(has_message(strict, "wrong triangle count: 4")) << messages(strict);
  EXPECT_TRUE(has_message(strict, "vertex 4 (ring 1, vertex 0) is not a vertex of the cleaned"))
      << messages(strict);

  const auto relaxed = check(polygon, fan, {.check_count = false});
  EXPECT_TRUE(relaxed.valid) << messages(relaxed);
}

TEST(Validate, RejectsWrongCount) {
  const auto report = check(square_with_hole, {{0, 1, 2}, {0, 2, 3}});
  EXPECT_FALSE(report.valid);
  EXPECT_TRUE(has_message(report, "wrong triangle count: 2")) << messages(report);
}

// A rhombus (-3,0) (0,-1) (3,0) (0,1). The circle through 0, 2, 3 has centre (0,-4) and radius 5:
// vertex 1 at distance 3 lies inside, so the long diagonal 0-2 is not locally Delaunay. The circle
// through 1, 2, 3 has centre (4/3, 0) and radius 5/3: vertex 0 at distance 13/3 is outside.
const Polygon rhombus = {{{-3, 0}, {0, -1}, {3, 0}, {0, 1}}};

TEST(Validate, RejectsNonDelaunayEdge) {
  const Triangles long_diagonal = {{0, 1, 2}, {0, 2, 3}};
  const auto report = check(rhombus, long_diagonal, {.check_delaunay = true});
  EXPECT_FALSE(report.valid);
  EXPECT_EQ(report.non_delaunay_edges, 1u);
  EXPECT_TRUE(has_message(report, "is not locally Delaunay")) << messages(report);
  // Still a valid triangulation when the Delaunay property is not asked for.
  EXPECT_TRUE(check(rhombus, long_diagonal).valid);
}

TEST(Validate, AcceptsFlippedDelaunayEdge) {
  const auto report = check(rhombus, {{1, 2, 3}, {1, 3, 0}}, {.check_delaunay = true});
  EXPECT_TRUE(report.valid) << messages(report);
  EXPECT_EQ(report.non_delaunay_edges, 0u);
}

TEST(Validate, ZeroAreaTrianglesOnlyWhenAllowed) {
  // (1,0) lies on the bottom side: the flat "ear" (0, 1, 2) has zero area, then 2 triangles.
  const Polygon polygon = {{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}}};
  const Triangles with_flat_ear = {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}};
  const auto strict = check(polygon, with_flat_ear);
  EXPECT_FALSE(strict.valid);
  EXPECT_EQ(strict.zero_area_triangles, 1u);
  EXPECT_TRUE(check(polygon, with_flat_ear, {.allow_zero_area = true}).valid);
  // Without the flat ear the same polygon is triangulated with 3 proper triangles.
  const auto proper = check(polygon, {{0, 1, 4}, {1, 3, 4}, {1, 2, 3}});
  EXPECT_TRUE(proper.valid) << messages(proper);
  EXPECT_EQ(proper.zero_area_triangles, 0u);
}

TEST(Validate, AreaIsExactFarFromTheOrigin) {
  // The square with hole moved by 2^50: shoelace products reach 2^102, far beyond a double's 53
  // bits, yet the areas stay exactly 12.
  Polygon polygon = square_with_hole;
  for (auto& ring : polygon)
    for (auto& p : ring) p = {p.x + 0x1p50, p.y + 0x1p50};
  const auto report = check(polygon, square_with_hole_triangles);
  EXPECT_TRUE(report.valid) << messages(report);
  EXPECT_EQ(report.polygon_area, 12.0);
  EXPECT_EQ(report.triangle_area, 12.0);
  EXPECT_EQ(report.area_rel_error, 0.0);
}

TEST(Validate, RejectsBadCoordinates) {
  Polygon polygon = square_with_hole;
  polygon[1][2].y = std::numeric_limits<double>::quiet_NaN();
  polygon[0][1].x = 1e300;
  const auto report = check(polygon, square_with_hole_triangles);
  EXPECT_FALSE(report.valid);
  EXPECT_TRUE(has_message(report, "vertex 6 (ring 1, vertex 2): coordinate is NaN"))
      << messages(report);
  EXPECT_TRUE(has_message(report, "vertex 1 (ring 0, vertex 1): coordinate outside"))
      << messages(report);
}

TEST(Validate, RejectsDegenerateOuterRing) {
  const Polygon line = {{{0, 0}, {1, 1}, {2, 2}}};
  const auto report = check(line, {{0, 1, 2}});
  EXPECT_FALSE(report.valid);
  EXPECT_TRUE(has_message(report, "ring 0 (outer)")) << messages(report);
}

TEST(Validate, RejectsEmptyPolygon) {
  EXPECT_FALSE(check(Polygon{}, {}).valid);
}

TEST(Validate, StopsRecordingMessagesAtTheLimit) {
  // Every one of the 8 triangles reversed: 8 clockwise triangles, but only 3 messages kept.
  Triangles reversed = square_with_hole_triangles;
  for (auto& t : reversed) std::swap(t[1], t[2]);
  const auto report = check(square_with_hole, reversed, {.max_messages = 3});
  EXPECT_FALSE(report.valid);
  EXPECT_EQ(report.bad_orientation, 8u);
  EXPECT_EQ(report.messages.size(), 3u);
}

TEST(Validate, AcceptsAnyPointAndIndexType) {
  const std::vector<std::vector<std::array<float, 2>>> rings = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const std::vector<std::array<std::uint16_t, 3>> triangles = {{0, 1, 2}, {0, 2, 3}};
  const auto report = validate(rings, std::span<const std::array<std::uint16_t, 3>>(triangles));
  EXPECT_TRUE(report.valid) << messages(report);
}

}  // namespace
}  // namespace pear::test
