// The fallbacks for boundaries without an ear: they end, in work linear in the boundary, and
// every node is clipped at most once.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>

#include "earclip/ear_clipper.hpp"
#include "pear/pear.hpp"

namespace pear {
namespace {

/// Issue 30: found by the `degenerate` fuzz target (a timeout). A square with 26 triangular
/// holes fanned around one point, a few apexes a hair off it, so the holes cross. The split
/// search cut the boundary into parts; the last three nodes of a finished part stayed queued
/// as ears, were clipped again inside the next part, and that part's node count wrapped
/// around: 90 s of fallbacks, each removing a node that was already gone.
Polygon fan_of_holes_off_the_grid() {
  Polygon polygon = {{{0, 0}, {20, 0}, {20, 25}, {0, 25}}};
  const Point apex{2, 12};
  const Point tips[26][2] = {{{4, 23}, {5, 23}},
                             {{6, 23}, {7, 23.000000536441803}},
                             {{8, 23}, {9, 23}},
                             {{10, 23}, {11, 23}},
                             {{12, 23}, {13, 23}},
                             {{14, 23}, {15, 23}},
                             {{16, 23}, {17, 23}},
                             {{18, 23}, {18, 22}},
                             {{18, 21}, {18, 20}},
                             {{17, 19}, {18, 18}},
                             {{18, 17}, {18, 16}},
                             {{18, 15}, {18, 14}},
                             {{18, 13}, {18, 12}},
                             {{18, 11}, {18, 10}},
                             {{18, 9}, {18, 8}},
                             {{18, 7}, {18, 6}},
                             {{18, 5}, {18, 4}},
                             {{18, 3}, {18, 2.000000000006594}},
                             {{18, 1}, {17, 1}},
                             {{16, 1}, {15, 1}},
                             {{14, 1.0000000000000009}, {13, 1}},
                             {{12, 1}, {11, 1}},
                             {{10, 1}, {9, 1}},
                             {{8, 1}, {7, 1}},
                             {{6, 1}, {5, 1}},
                             {{4, 1}, {3, 1}}};
  for (const auto& tip : tips) polygon.push_back({apex, tip[0], tip[1], apex});
  polygon[4][0] = polygon[4][3] = {2.000000938773155, 12};
  polygon[14][0] = polygon[14][3] = {2, 12.000991821289062};
  polygon[20][0] = polygon[20][3] = {2.0000016018748283, 12};
  return polygon;
}

struct Case {
  Algorithm algorithm;
  EarHeuristic heuristic;
  bool delaunay;
};

class FanOfHoles : public ::testing::TestWithParam<Case> {};

TEST_P(FanOfHoles, EndsWithABestEffortThatClipsNoNodeTwice) {
  const Polygon polygon = fan_of_holes_off_the_grid();
  Options options{.algorithm = GetParam().algorithm,
                  .heuristic = GetParam().heuristic,
                  .delaunay = GetParam().delaunay,
                  .threads = 2};
  const Triangulation<> result = triangulate(polygon, options);
  EXPECT_EQ(result.status, Status::not_simple);
  // At most one triangle per clipping step, and the bridged boundary has n + 2h nodes.
  std::size_t vertices = 0;
  for (const Ring& ring : polygon) vertices += ring.size() - 1;
  EXPECT_LE(result.triangles.size(), vertices + 2 * (polygon.size() - 1) - 2);
  std::set<std::array<std::uint32_t, 3>> seen;
  for (auto t : result.triangles) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    EXPECT_TRUE(seen.insert(t).second)
        << "triangle " << t[0] << " " << t[1] << " " << t[2] << " twice";
  }
}

INSTANTIATE_TEST_SUITE_P(
    EveryAlgorithm, FanOfHoles,
    ::testing::Values(Case{Algorithm::sequential, EarHeuristic::top, false},
                      Case{Algorithm::sequential, EarHeuristic::fast, false},
                      Case{Algorithm::sequential, EarHeuristic::top, true},
                      Case{Algorithm::partition_and_cut, EarHeuristic::top, false},
                      Case{Algorithm::mark_and_cut, EarHeuristic::top, false},
                      Case{Algorithm::divide_and_conquer, EarHeuristic::top, true}));

/// Random points joined in random order: almost no corner is an ear, so nearly every step is
/// a fallback. Scanning the whole cycle each time was quadratic (20,000 points: 1.8 s).
TEST(Fallback, WorkIsLinearWhenNoCornerIsAnEar) {
  constexpr std::uint32_t n = 20'000;
  std::mt19937 random(30);
  std::uniform_real_distribution<double> coordinate(0, 1000);
  for (const EarHeuristic heuristic : {EarHeuristic::top, EarHeuristic::fast}) {
    detail::Boundary boundary;
    for (std::uint32_t i = 0; i < n; ++i) boundary.add({coordinate(random), coordinate(random)}, i);
    for (std::uint32_t i = 0; i < n; ++i) boundary.link(i, (i + 1) % n);
    detail::EarClipper clipper;
    detail::TriangleList triangles;
    EXPECT_FALSE(clipper.run(boundary, 0, heuristic, triangles));
    EXPECT_LE(triangles.size(), n - 2u);
    EXPECT_LE(clipper.fallback_work(),
              detail::EarClipper::fallback_budget(n) + detail::EarClipper::fallback_window * n);
  }
}

}  // namespace
}  // namespace pear
