// The sequential engine on small hand-made polygons: every case checked by the validator.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "pear/generate.hpp"
#include "pear/pear.hpp"
#include "pear/validate.hpp"
#include "support.hpp"

namespace pear {
namespace {

using testing::expect_valid;

Ring square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}
Ring reversed(Ring r) {
  return {r.rbegin(), r.rend()};
}

class Engine : public ::testing::TestWithParam<EarHeuristic> {};

TEST_P(Engine, SquareGivesTwoTriangles) {
  const Polygon p = {square(0, 0, 1)};
  expect_valid(p, GetParam(), "square");
  EXPECT_EQ(triangulate(p, {.heuristic = GetParam()}).triangles.size(), 2u);
}

TEST_P(Engine, SquareWithHoleGivesEightTriangles) {
  const Polygon p = {square(0, 0, 10), reversed(square(4, 4, 2))};
  expect_valid(p, GetParam(), "square with hole");
  EXPECT_EQ(triangulate(p, {.heuristic = GetParam()}).triangles.size(), 8u);
}

TEST_P(Engine, ClockwiseOuterAndCounterclockwiseHoleAreReoriented) {
  const Polygon p = {reversed(square(0, 0, 10)), square(4, 4, 2)};
  expect_valid(p, GetParam(), "reversed rings");
}

TEST_P(Engine, ClosingPointAndRepeatedPointsAreDropped) {
  Ring r = {{0, 0}, {0, 0}, {4, 0}, {4, 0}, {4, 0}, {4, 3}, {0, 3}, {0, 0}};
  const auto result = triangulate(Polygon{r}, {.heuristic = GetParam()});
  ASSERT_EQ(result.status, Status::ok);
  EXPECT_EQ(result.triangles.size(), 2u);
  for (const auto& t : result.triangles)
    for (auto i : t) EXPECT_TRUE(i == 0 || i == 2 || i == 5 || i == 6) << i;  // first occurrences
  expect_valid(Polygon{r}, GetParam(), "duplicates");
}

TEST_P(Engine, CollinearRunsUseEveryVertex) {
  Ring r;
  for (int i = 0; i < 10; ++i) r.push_back({double(i), 0});
  for (int i = 0; i < 10; ++i) r.push_back({10, double(i)});
  for (int i = 10; i > 0; --i) r.push_back({double(i), 10});
  for (int i = 10; i > 0; --i) r.push_back({0, double(i)});
  expect_valid(Polygon{r}, GetParam(), "collinear runs");
}

TEST_P(Engine, HoleTouchingOuterRingAtAVertex) {
  const Polygon p = {square(0, 0, 4), {{0, 0}, {1, 2}, {2, 1}}};
  expect_valid(p, GetParam(), "hole touching outer vertex");
}

TEST_P(Engine, HoleVertexInsideOuterEdgeSplitsTheEdge) {
  // The hole's vertex (0, 2) lies inside the outer edge x = 0 (a T-junction): the edge is split
  // there, the vertex used by both rings, and a warning names it.
  const Polygon p = {square(0, 0, 4), {{0, 2}, {2, 1}, {2, 3}}};
  expect_valid(p, GetParam(), "hole vertex inside outer edge");
  const auto result = triangulate(p, {.heuristic = GetParam()});
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].issue, Issue::t_junction_split);
  EXPECT_EQ(result.diagnostics[0].ring, 1u);
  EXPECT_EQ(result.diagnostics[0].vertex, 0u);
}

TEST_P(Engine, CrossingHolesAreReportedNotSimple) {
  const Polygon p = {square(0, 0, 10), reversed(square(2, 2, 3)), reversed(square(4, 4, 3))};
  const auto result = triangulate(p, {.heuristic = GetParam()});
  EXPECT_EQ(result.status, Status::not_simple);
}

TEST_P(Engine, SimplicityCheckCanBeSwitchedOff) {
  // Two edges of the ring cross at (2, 2).
  const Ring r = {{0, 0}, {4, 4}, {4, 0}, {0, 4}, {-1, 2}};
  EXPECT_EQ(triangulate(Polygon{r}, {.heuristic = GetParam()}).status, Status::not_simple);
  const auto unchecked =
      triangulate(Polygon{r}, {.heuristic = GetParam(), .check_simplicity = false});
  EXPECT_NE(unchecked.status, Status::invalid_input);
}

TEST_P(Engine, HolesTouchingEachOther) {
  // Three holes in a diagonal chain, each touching the next at one corner.
  const Polygon p = {square(0, 0, 10), reversed(square(2, 2, 2)), reversed(square(4, 4, 2)),
                     reversed(square(6, 6, 2))};
  expect_valid(p, GetParam(), "touching holes");
}

TEST_P(Engine, RegressionFanOfHolesTouchingAtOnePoint) {
  // earcut's touching-holes4: 26 thin triangular holes meeting at one point left lobes chained
  // at that point whose local sectors overlap; the ear test then blocked every ear.
  Polygon p = {{{-20, 0}, {20, 0}, {20, 25}, {-20, 25}}};
  for (int k = 0; k < 9; ++k) p.push_back({{2, 12}, {-1.0 - 2 * k, 23}, {-2.0 * k, 23}});
  expect_valid(p, GetParam(), "fan of touching holes");
}

TEST_P(Engine, TwoHolesTouchingEachOtherInside) {
  const Polygon p = {
      {{0, 0}, {10, 0}, {10, 10}}, {{1, 0.5}, {3, 1.5}, {4, 1}}, {{1, 0.5}, {5, 4}, {6, 5.5}}};
  expect_valid(p, GetParam(), "two holes touching inside");
}

TEST_P(Engine, SelfTouchingRingFigureEight) {
  // Two lobes meeting at (2, 2): the ring visits that point twice.
  const Ring r = {{0, 0}, {2, 2}, {4, 0}, {4, 4}, {2, 2}, {0, 4}};
  expect_valid(Polygon{r}, GetParam(), "figure eight");
}

TEST_P(Engine, SelfTouchingHoleWithLobesAlike) {
  // A hole that visits (5, 5) twice, both lobes clockwise, inside a square: a valid polygon.
  const Polygon p = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                     {{5, 5}, {3, 6}, {3, 4}, {5, 5}, {7, 4}, {7, 6}}};
  const auto result = triangulate(p, {.heuristic = GetParam()});
  EXPECT_EQ(result.status, Status::ok);
  EXPECT_TRUE(validate(p, result.triangles).valid);
}

/// A hole that passes (4, -4) twice with lobes wound oppositely, its pinch inside an outer edge
/// (split there: a T-junction), one lobe outside the outer ring. Once the clipper took that lobe
/// for an island: status ok and a triangulation the validator rejected. It is not a polygon.
TEST_P(Engine, SelfTouchingHoleWithALobeOutsideIsNotSimple) {
  const Polygon p = {
      {{6, 3}, {0, 4}, {-7, 1}, {-2, -1}, {-6, -2}, {-5, -2}, {0, -7}, {1, -7}, {7, -1}},
      {{0, -2}, {-1.5, -2}, {-0.5, -0.5}, {0.5, -0.5}},
      {{4, -4}, {4.5, -4}, {4, -4.5}, {4, -4}, {3.5, -4}, {3, -4.5}}};
  for (const Algorithm algorithm : {Algorithm::automatic, Algorithm::partition_and_cut}) {
    const auto result = triangulate(p, {.algorithm = algorithm, .heuristic = GetParam()});
    EXPECT_EQ(result.status, Status::not_simple);
    ASSERT_FALSE(result.diagnostics.empty());
    EXPECT_EQ(result.diagnostics.back().issue, Issue::hole_outside_outer_ring);
    EXPECT_EQ(result.diagnostics.back().ring, 2u);
  }
}

TEST_P(Engine, ZeroWidthAntennaIsDissolved) {
  // A spike out and back along the same segment covers no area: cleaning drops its tip (2, 8)
  // and the repeated (2, 4), leaving the square with a collinear vertex: 3 triangles.
  const Ring r = {{0, 0}, {4, 0}, {4, 4}, {2, 4}, {2, 8}, {2, 4}, {0, 4}};
  expect_valid(Polygon{r}, GetParam(), "antenna");
  const auto result = triangulate(Polygon{r}, {.heuristic = GetParam()});
  EXPECT_EQ(result.triangles.size(), 3u);
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].issue, Issue::spike_dissolved);
  EXPECT_EQ(result.diagnostics[0].vertex, 4u);
}

TEST_P(Engine, ManyHolesInAGrid) {
  Polygon p = {square(0, 0, 60)};
  for (int i = 0; i < 20; ++i)
    for (int j = 0; j < 20; ++j) p.push_back(reversed(square(1 + 3 * i, 1 + 3 * j, 1)));
  expect_valid(p, GetParam(), "20x20 holes");
}

TEST_P(Engine, SelfIntersectingBowtieIsReportedNotSimple) {
  const Ring r = {{0, 0}, {4, 4}, {4, 0}, {0, 4}, {-1, 2}};
  const auto result = triangulate(Polygon{r}, {.heuristic = GetParam()});
  EXPECT_EQ(result.status, Status::not_simple);
  ASSERT_FALSE(result.diagnostics.empty());
  EXPECT_EQ(result.diagnostics.back().issue, Issue::not_simple);
  for (const auto& t : result.triangles)
    for (auto i : t) EXPECT_LT(i, r.size());
}

TEST_P(Engine, HoleOutsideOuterIsReportedNotSimple) {
  const Polygon p = {square(0, 0, 1), reversed(square(-5, -5, 1))};
  const auto result = triangulate(p, {.heuristic = GetParam()});
  EXPECT_EQ(result.status, Status::not_simple);
  ASSERT_FALSE(result.diagnostics.empty());
  EXPECT_EQ(result.diagnostics.back().ring, 1u);
  EXPECT_EQ(result.diagnostics.back().issue, Issue::hole_outside_outer_ring);
}

INSTANTIATE_TEST_SUITE_P(Heuristics, Engine,
                         ::testing::Values(EarHeuristic::top, EarHeuristic::fast),
                         [](const auto& info) {
                           return std::string(testing::heuristic_name(info.param));
                         });

TEST(EngineInput, EmptyInputIsAnError) {
  const auto result = triangulate(Polygon{});
  EXPECT_EQ(result.status, Status::invalid_input);
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].issue, Issue::empty_input);
}

TEST(EngineInput, NaNIsAnErrorNamingRingAndVertex) {
  Polygon p = {square(0, 0, 10), reversed(square(4, 4, 2))};
  p[1][2].y = std::numeric_limits<double>::quiet_NaN();
  const auto result = triangulate(p);
  EXPECT_EQ(result.status, Status::invalid_input);
  ASSERT_FALSE(result.diagnostics.empty());
  EXPECT_EQ(result.diagnostics[0].issue, Issue::non_finite_coordinate);
  EXPECT_EQ(result.diagnostics[0].ring, 1u);
  EXPECT_EQ(result.diagnostics[0].vertex, 2u);
  EXPECT_NE(describe(result.diagnostics[0]).find("ring 1, vertex 2"), std::string::npos);
  EXPECT_TRUE(result.triangles.empty());
}

// Cleaning tests each ring's coordinates as it copies it: a bad coordinate in a later ring must
// still be the one error reported, without the warnings of the rings cleaned before it.
TEST(EngineInput, ABadCoordinateIsTheOnlyDiagnosticWhereverItIs) {
  Polygon spiked = {{{0, 0}, {10, 0}, {10, 10}, {5, 10}, {5, 12}, {5, 10}, {0, 10}},
                    reversed(square(4, 4, 2)),
                    {{1, 1}, {1, 1}, {1, 1}}};
  spiked[2][1].x = std::numeric_limits<double>::infinity();
  for (const Polygon& p : {spiked, Polygon{{{0, 0}, {1, 0}}, spiked[2]}}) {
    const auto result = triangulate(p);
    EXPECT_EQ(result.status, Status::invalid_input);
    ASSERT_EQ(result.diagnostics.size(), 1u);
    EXPECT_EQ(result.diagnostics[0].issue, Issue::non_finite_coordinate);
    EXPECT_EQ(result.diagnostics[0].ring, p.size() - 1);
    EXPECT_EQ(result.diagnostics[0].vertex, 1u);
  }
}

TEST(EngineInput, HugeAndTinyCoordinatesAreErrors) {
  Polygon p = {square(0, 0, 1)};
  p[0][3].x = 1e61;  // 2^200 is about 1.6e60
  EXPECT_EQ(triangulate(p).diagnostics.at(0).issue, Issue::coordinate_out_of_range);
  p[0][3].x = 1e-61;
  EXPECT_EQ(triangulate(p).status, Status::invalid_input);
  p[0][3].x = 0;
  p[0][2] = {0x1p199, 0x1p199};
  EXPECT_EQ(triangulate(p).status, Status::ok);
}

// The range's ends belong to it, the doubles just past them do not, and so on either side of 0
// (cleaning compares the coordinates' bits, without their sign).
TEST(EngineInput, TheRangeOfCoordinatesEndsExactlyAtTwoToThe200AndMinus200) {
  const auto out_of_range = [](double v) {
    Polygon p = {square(0, 0, 1)};
    p[0][3].x = v;
    const auto result = triangulate(p);
    const bool named = !result.diagnostics.empty() &&
                       (result.diagnostics[0].issue == Issue::coordinate_out_of_range ||
                        result.diagnostics[0].issue == Issue::non_finite_coordinate);
    EXPECT_EQ(named, result.status == Status::invalid_input) << v;
    return named;
  };
  for (const double v : {0x1p200, 0x1p-200, 0.0, 1.0})
    for (const double sign : {1.0, -1.0}) EXPECT_FALSE(out_of_range(sign * v)) << sign * v;
  const double past[] = {std::nextafter(0x1p200, INFINITY),
                         std::nextafter(0x1p-200, 0.0),
                         std::numeric_limits<double>::denorm_min(),
                         std::numeric_limits<double>::max(),
                         INFINITY,
                         std::numeric_limits<double>::quiet_NaN()};
  for (const double v : past)
    for (const double sign : {1.0, -1.0}) EXPECT_TRUE(out_of_range(sign * v)) << sign * v;
}

TEST(EngineInput, OuterRingTooSmallIsAnError) {
  const auto result = triangulate(Polygon{{{0, 0}, {1, 1}, {0, 0}, {1, 1}}});
  EXPECT_EQ(result.status, Status::invalid_input);
  EXPECT_EQ(result.diagnostics.at(0).issue, Issue::outer_ring_too_small);
  EXPECT_EQ(triangulate(Polygon{{{0, 0}, {1, 1}, {2, 2}}}).status, Status::invalid_input);
}

TEST(EngineInput, DegenerateHolesAreDroppedAndReported) {
  const Polygon p = {square(0, 0, 10), {{1, 1}, {2, 2}}, {{3, 3}, {4, 4}, {5, 5}}};
  const auto result = triangulate(p);
  EXPECT_EQ(result.status, Status::ok);
  ASSERT_EQ(result.diagnostics.size(), 2u);
  EXPECT_EQ(result.diagnostics[0].issue, Issue::hole_dropped_too_small);
  EXPECT_EQ(result.diagnostics[0].ring, 1u);
  EXPECT_EQ(result.diagnostics[1].issue, Issue::hole_dropped_zero_area);
  EXPECT_EQ(result.diagnostics[1].ring, 2u);
  EXPECT_EQ(result.triangles.size(), 2u);
}

TEST(EngineInput, IndexOverflowIsAnErrorNotAWrap) {
  Ring circle;
  for (int i = 0; i < 300; ++i)
    circle.push_back({std::cos(i * 2 * M_PI / 300), std::sin(i * 2 * M_PI / 300)});
  const auto narrow = triangulate<std::uint8_t>(Polygon{circle});
  EXPECT_EQ(narrow.status, Status::index_overflow);
  EXPECT_TRUE(narrow.triangles.empty());
  const auto wide = triangulate<std::uint16_t>(Polygon{circle});
  EXPECT_EQ(wide.status, Status::ok);
  EXPECT_EQ(wide.triangles.size(), 298u);
}

struct Vec2 {
  float x, y;
};

TEST(EngineInput, UserPointTypesWithoutCopying) {
  const std::vector<std::vector<Vec2>> rings = {{{0, 0}, {2, 0}, {2, 2}, {0, 2}}};
  EXPECT_EQ(triangulate(rings).triangles.size(), 2u);
  const std::vector<std::vector<std::array<double, 2>>> arrays = {{{0, 0}, {2, 0}, {1, 1}}};
  EXPECT_EQ(triangulate(arrays).triangles.size(), 1u);
}

/// The same result as from the points copied into one array (what every ring range was read as
/// before): status, triangles and diagnostics alike.
void expect_as_flat(const Polygon& polygon, const Options& options) {
  std::vector<Point> points;
  std::vector<std::uint32_t> offsets{0};
  for (const Ring& ring : polygon) {
    points.insert(points.end(), ring.begin(), ring.end());
    offsets.push_back(static_cast<std::uint32_t>(points.size()));
  }
  Triangulator triangulator;
  Triangulation<> flat;
  triangulator.triangulate_into(PolygonView{points, offsets}, options, flat);
  const Triangulation<> rings = triangulator.triangulate(polygon, options);
  EXPECT_EQ(rings.status, flat.status);
  EXPECT_EQ(rings.triangles, flat.triangles);
  ASSERT_EQ(rings.diagnostics.size(), flat.diagnostics.size());
  for (std::size_t i = 0; i < flat.diagnostics.size(); ++i) {
    EXPECT_EQ(rings.diagnostics[i].issue, flat.diagnostics[i].issue);
    EXPECT_EQ(rings.diagnostics[i].ring, flat.diagnostics[i].ring);
    EXPECT_EQ(rings.diagnostics[i].vertex, flat.diagnostics[i].vertex);
  }
  // A vector of spans is read in place too.
  std::vector<std::span<const Point>> spans(polygon.begin(), polygon.end());
  EXPECT_EQ(triangulator.triangulate(spans, options).triangles, flat.triangles);
}

/// pear::Polygon's rings are read where they are (no copy into one array first): dirty rings,
/// bad ones named by ring and vertex, and a large polygon cleaned in parallel passes and
/// flipped to its CDT (whose copy of the caller's points then comes from the rings).
TEST(EngineInput, PolygonRingsAreReadWhereTheyAre) {
  static_assert(detail::point_array_rings<Polygon>);
  static_assert(!detail::point_array_rings<std::vector<std::vector<Vec2>>>);
  Ring closed = square(0, 0, 10);
  closed.insert(closed.begin() + 2, closed[1]);  // a repeated point
  closed.push_back(closed.front());              // and the closing one
  const Ring hole = reversed(square(2, 2, 3)), other = reversed(square(6, 6, 2));
  Ring nan_hole = other;
  nan_hole[1].y = std::numeric_limits<double>::quiet_NaN();
  Ring crossing = other;
  std::swap(crossing[1], crossing[2]);
  const std::vector<std::pair<const char*, Polygon>> cases = {
      {"holes", {closed, hole, other}},
      {"an empty ring", {closed, {}, hole}},
      {"a hole of two points", {closed, hole, {{7, 7}, {8, 8}}}},
      {"NaN in ring 2", {closed, hole, nan_hole}},
      {"a crossing hole", {closed, crossing}},
      {"no ring", {}},
  };
  for (const auto& [name, polygon] : cases)
    for (const Options& options :
         {Options{}, Options{.heuristic = EarHeuristic::fast}, Options{.delaunay = true}}) {
      SCOPED_TRACE(name);
      expect_as_flat(polygon, options);
    }
  const Polygon large = generate_polygon("random-holes", 40000, 5);
  for (unsigned threads : {1u, 2u}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    const Options options{.algorithm = Algorithm::partition_and_cut,
                          .delaunay = true,
                          .threads = threads,
                          .partitions = 4};
    expect_as_flat(large, options);
    const Triangulation<> cdt = triangulate(large, options);
    ASSERT_EQ(cdt.status, Status::ok);
    EXPECT_TRUE(validate(large, cdt.triangles).valid);
  }
}

TEST(EngineInput, TriangulatorIsReusable) {
  Triangulator triangulator;
  for (int i = 3; i < 50; ++i) {
    Ring r;
    for (int k = 0; k < i; ++k)
      r.push_back({std::cos(k * 2 * M_PI / i), std::sin(k * 2 * M_PI / i)});
    const auto result = triangulator.triangulate(Polygon{r});
    ASSERT_EQ(result.status, Status::ok);
    EXPECT_EQ(result.triangles.size(), static_cast<std::size_t>(i - 2));
  }
}

/// triangulate_into replaces the result it is given: after a polygon with warnings and many
/// triangles, an error, then a square, nothing of the earlier calls is left.
TEST(EngineInput, TriangulateIntoReplacesTheResult) {
  Triangulator triangulator;
  Triangulation<> result;
  const std::vector<Point> spiky = {{0, 0}, {4, 0}, {4, 4}, {2, 4}, {2, 6}, {2, 4}, {0, 4}};
  const std::vector<std::uint32_t> one_ring = {0, 7};
  triangulator.triangulate_into(PolygonView{spiky, one_ring}, {}, result);
  ASSERT_EQ(result.status, Status::ok);
  // The spike to (2, 6) is dissolved, with a warning; 5 vertices are left (one collinear).
  EXPECT_EQ(result.triangles.size(), 3u);
  ASSERT_FALSE(result.diagnostics.empty());
  const std::vector<Point> bad = {{0, 0}, {NAN, 0}, {1, 1}};
  const std::vector<std::uint32_t> three = {0, 3};
  triangulator.triangulate_into(PolygonView{bad, three}, {}, result);
  EXPECT_EQ(result.status, Status::invalid_input);
  EXPECT_TRUE(result.triangles.empty());
  ASSERT_EQ(result.diagnostics.size(), 1u);
  EXPECT_EQ(result.diagnostics[0].issue, Issue::non_finite_coordinate);
  const std::vector<Point> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<std::uint32_t> four = {0, 4};
  Options delaunay;
  delaunay.delaunay = true;
  triangulator.triangulate_into(PolygonView{square, four}, delaunay, result);
  EXPECT_EQ(result.status, Status::ok);
  EXPECT_EQ(result.triangles.size(), 2u);
  EXPECT_TRUE(result.diagnostics.empty());
  EXPECT_TRUE(validate(Polygon{square}, result.triangles).valid);
}

/// Interleaved coordinates (numpy's (N, 2), GeoArrow's layout) give what the same points
/// give, for both heuristics and the CDT; half a point at the end is refused.
TEST(EngineInput, CoordinateViewGivesWhatPolygonViewGives) {
  const Polygon p = {square(0, 0, 10), reversed(square(2, 2, 3)), reversed(square(6, 6, 2))};
  std::vector<Point> points;
  std::vector<std::uint32_t> offsets{0};
  for (const Ring& ring : p) {
    points.insert(points.end(), ring.begin(), ring.end());
    offsets.push_back(static_cast<std::uint32_t>(points.size()));
  }
  std::vector<double> xy;
  for (const Point& q : points) xy.insert(xy.end(), {q.x, q.y});
  Triangulator triangulator;
  for (const Options& options :
       {Options{}, Options{.heuristic = EarHeuristic::fast}, Options{.delaunay = true}}) {
    Triangulation<> from_points, from_xy;
    triangulator.triangulate_into(PolygonView{points, offsets}, options, from_points);
    triangulator.triangulate_into(CoordinateView{xy, offsets}, options, from_xy);
    ASSERT_EQ(from_points.status, Status::ok);
    EXPECT_EQ(from_xy.status, Status::ok);
    EXPECT_EQ(from_xy.triangles, from_points.triangles);
    EXPECT_TRUE(validate(p, from_xy.triangles).valid);
  }
  xy.push_back(1.0);  // an x without its y
  Triangulation<> odd;
  triangulator.triangulate_into(CoordinateView{xy, offsets}, {}, odd);
  EXPECT_EQ(odd.status, Status::invalid_input);
  ASSERT_EQ(odd.diagnostics.size(), 1u);
  EXPECT_EQ(odd.diagnostics[0].issue, Issue::invalid_offsets);
}

TEST(EngineStatistics, ConvexPolygonIsAllEars) {
  Ring hexagon;
  for (int k = 0; k < 6; ++k) hexagon.push_back({std::cos(k * M_PI / 3), std::sin(k * M_PI / 3)});
  Triangulator triangulator;
  const EarStatistics stats = triangulator.ear_statistics(Polygon{hexagon});
  EXPECT_EQ(stats.vertices, 6u);
  EXPECT_EQ(stats.convex, 6u);
  EXPECT_EQ(stats.reflex, 0u);
  EXPECT_EQ(stats.ears, 6u);
}

TEST(EngineStatistics, ReflexVertexBlocksEars) {
  // An arrow: (2,1) is reflex; the ears at (0,0) and (4,0)... are checked by hand below.
  const Ring arrow = {{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}};
  Triangulator triangulator;
  const EarStatistics stats = triangulator.ear_statistics(Polygon{arrow});
  EXPECT_EQ(stats.reflex, 1u);
  EXPECT_EQ(stats.convex, 4u);
  // (0,4)-(0,0)-(4,0) contains (2,1): not an ear; same for (0,0)-(4,0)-(4,4).
  // (4,0)-(4,4)-(2,1) and (2,1)-(0,4)-(0,0) are ears.
  EXPECT_EQ(stats.ears, 2u);
}

// Found by fuzz/bridged (corpus/fuzz/bridged/crash-hole-touching-three-vertices): a square hole
// whose corners touch the outer ring at three vertices came back not_simple.
TEST_P(Engine, HoleTouchingOuterRingAtThreeVertices) {
  const Ring outer = {{1, 3}, {1, 2}, {0, 2}, {0, 1}, {0, 0}, {1, 0},
                      {2, 0}, {2, 1}, {3, 1}, {3, 2}, {2, 2}, {2, 3}};
  const Ring hole = {{2, 1}, {1, 1}, {1, 2}, {2, 2}};
  expect_valid(Polygon{outer, hole}, GetParam(), "hole touching at three vertices");
}

// Found by fuzz/bridged (crash-plus-with-center-hole): the hole fills a plus sign's centre and
// touches the outer ring at four vertices, cutting the polygon into four arms; the result was
// Status::ok with a gap.
TEST_P(Engine, HoleTouchingOuterRingAtFourVerticesSplitsThePolygon) {
  const Ring outer = {{3, 3}, {3, 2}, {3, 1}, {2, 1}, {2, 0}, {1, 0}, {1, 1},
                      {0, 1}, {0, 2}, {0, 3}, {1, 3}, {1, 4}, {2, 4}, {2, 3}};
  const Ring hole = {{2, 2}, {2, 3}, {1, 3}, {1, 2}, {1, 1}, {2, 1}};
  expect_valid(Polygon{outer, hole}, GetParam(), "plus with centre hole");
}

// Found by fuzz/bridged (crash-chain-of-lobes): one ring of three lobes touching at two vertices
// came back Status::ok with 15 triangles instead of 16 and an uncovered edge.
TEST_P(Engine, RingTouchingItselfInAChainOfThreeLobes) {
  const Ring r = {{1, 2}, {0, 2}, {0, 3}, {0, 4}, {1, 4}, {1, 5}, {2, 5}, {3, 5},
                  {3, 4}, {3, 3}, {2, 3}, {2, 4}, {1, 4}, {1, 3}, {1, 2}, {2, 2},
                  {2, 1}, {3, 1}, {3, 0}, {2, 0}, {1, 0}, {1, 1}};
  expect_valid(Polygon{r}, GetParam(), "chain of lobes");
}

// Found in earcut's water-huge3 (1,443 holes): two holes touch at (3083, 948), and the bridges
// of two other holes end there too. Each bridge's two copies run along one direction, which the
// relinking at touching points took for overlapping edges, so it left the point tangled and
// the clipper ended in the best effort (not_simple for a valid polygon).
TEST_P(Engine, TwoBridgesEndAtAPointWhereHolesTouch) {
  const Ring outer = {{3040, 900}, {3160, 900}, {3160, 990}, {3040, 990}};
  const Polygon polygon = {outer,
                           {{3099, 918}, {3079, 933}, {3067, 931}, {3082, 938}, {3083, 948}},
                           {{3091, 967}, {3094, 978}, {3104, 973}},
                           {{3083, 948}, {3071, 963}, {3076, 974}},
                           {{3125, 932}, {3111, 948}, {3124, 943}},
                           {{3055, 926}, {3057, 940}, {3067, 931}},
                           {{3142, 919}, {3125, 928}, {3138, 931}}};
  expect_valid(polygon, GetParam(), "bridges ending at a touching point");
}

// Found by the benchmark's ear-prevalence run on earcut's empty-square.json: a hole that repeats
// the outer ring dissolves completely as spikes, the statistics loop started from a removed node
// and never returned.
TEST(EarStatisticsRegression, HoleRepeatingTheOuterRingDoesNotHang) {
  const Ring outer = {{0, 0}, {4000, 0}, {4000, 4000}, {0, 4000}};
  const Ring hole = {{0, 0}, {0, 4000}, {4000, 4000}, {4000, 0}};
  Triangulator triangulator;
  const EarStatistics stats = triangulator.ear_statistics(Polygon{outer, hole});
  EXPECT_EQ(stats.convex + stats.reflex, stats.vertices);
  EXPECT_LE(stats.vertices, 8u);
  EXPECT_LE(stats.ears, stats.convex);
}

}  // namespace
}  // namespace pear
