// Angle statistics on triangles whose angles are known by hand.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "pear/quality.hpp"

namespace pear::test {
namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

QualityStatistics measure(const std::vector<Point>& points, const Triangles& triangles) {
  return quality(points, triangles);
}

std::size_t histogram_total(const QualityStatistics& statistics) {
  return std::accumulate(statistics.min_angle_histogram.begin(),
                         statistics.min_angle_histogram.end(), std::size_t{0});
}

TEST(Quality, EquilateralTriangle) {
  const auto statistics = measure({{0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}}, {{0, 1, 2}});
  EXPECT_EQ(statistics.triangles, 1u);
  EXPECT_NEAR(statistics.dev60_avg_deg, 0.0, 1e-9);
  EXPECT_NEAR(statistics.min_angle_avg_deg, 60.0, 1e-9);
  EXPECT_NEAR(statistics.min_angle_deg, 60.0, 1e-9);
  EXPECT_EQ(statistics.min_angle_histogram[11], 1u);  // [55, 60]
}

TEST(Quality, RightIsoscelesTriangle) {
  // Angles 90, 45, 45: deviations 30, 15, 15, average 20; smallest 45.
  const auto statistics = measure({{0, 0}, {1, 0}, {0, 1}}, {{0, 1, 2}});
  EXPECT_NEAR(statistics.dev60_avg_deg, 20.0, 1e-9);
  EXPECT_NEAR(statistics.min_angle_avg_deg, 45.0, 1e-9);
  EXPECT_NEAR(statistics.min_angle_deg, 45.0, 1e-9);
  EXPECT_EQ(histogram_total(statistics), 1u);
}

TEST(Quality, AveragesOverTriangles) {
  // Second triangle (0,0) (2,0) (2,1): angles atan(1/2) = 26.56505117707799, 90 and
  // 63.43494882292201; deviations 33.43494882292201 + 30 + 3.43494882292201 = 66.86989764584402.
  const std::vector<Point> points = {{0, 0}, {1, 0}, {0, 1}, {2, 0}, {2, 1}};
  const auto statistics = measure(points, {{0, 1, 2}, {0, 3, 4}});
  EXPECT_EQ(statistics.triangles, 2u);
  EXPECT_NEAR(statistics.dev60_avg_deg, (60.0 + 66.86989764584402) / 6, 1e-9);
  EXPECT_NEAR(statistics.min_angle_avg_deg, (45.0 + 26.56505117707799) / 2, 1e-9);
  EXPECT_NEAR(statistics.min_angle_deg, 26.56505117707799, 1e-9);
  EXPECT_EQ(statistics.min_angle_histogram[5], 1u);  // [25, 30)
  EXPECT_EQ(histogram_total(statistics), 2u);
}

TEST(Quality, SliverAnglesStayAccurate) {
  // Apex (0.5, 1e-12): the base angles are atan(2e-12) = 2e-12 rad = 1.1459155902616465e-10 deg,
  // which acos of a normalized dot product would round to 0.
  const auto statistics = measure({{0, 0}, {1, 0}, {0.5, 1e-12}}, {{0, 1, 2}});
  EXPECT_NEAR(statistics.min_angle_deg, 1.1459155902616465e-10, 1e-18);
  EXPECT_NEAR(statistics.dev60_avg_deg, 80.0, 1e-9);  // (60 + 60 + 120) / 3
  EXPECT_EQ(statistics.min_angle_histogram[0], 1u);
}

TEST(Quality, SkipsTrianglesWithMissingPoints) {
  const auto statistics = measure({{0, 0}, {1, 0}, {0, 1}}, {{0, 1, 2}, {0, 1, 7}});
  EXPECT_EQ(statistics.triangles, 1u);
  EXPECT_NEAR(statistics.min_angle_avg_deg, 45.0, 1e-9);
}

TEST(Quality, EmptyTriangulation) {
  const auto statistics = measure({{0, 0}}, {});
  EXPECT_EQ(statistics.triangles, 0u);
  EXPECT_EQ(histogram_total(statistics), 0u);
}

}  // namespace
}  // namespace pear::test
