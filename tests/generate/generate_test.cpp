// The synthetic families: valid simple polygons of the documented sizes and areas, deterministic.
#include <cmath>
#include <cstddef>
#include <numbers>
#include <stdexcept>
#include <string>
#include <tuple>

#include <gtest/gtest.h>

#include "pear/generate.hpp"
#include "simple_polygon.hpp"
#include "sizes.hpp"

namespace {

using pear::Polygon;
using pear::testing::ring_orientation;
using pear::testing::simplicity_problem;
using pear::testing::twice_signed_area;
using pear::testing::vertex_count;

long double area(const Polygon& polygon) {
  long double sum = 0;
  for (const auto& ring : polygon) sum += twice_signed_area(ring);
  return sum / 2;
}

/// The vertex count each family documents for a requested size.
std::size_t documented_count(const std::string& kind, std::size_t n) {
  if (kind == "koch") {  // 3 * 4^d, nearest to n
    std::size_t best = 3;
    for (std::size_t c = 12; c < 100'000'000; c *= 4)
      if (std::llabs(static_cast<long long>(c) - static_cast<long long>(n)) <
          std::llabs(static_cast<long long>(best) - static_cast<long long>(n)))
        best = c;
    return best;
  }
  if (kind == "comb") return 4 * ((n + 2) / 4);
  if (kind == "holes") {
    const auto k = std::llround(std::sqrt((static_cast<double>(n) - 4) / 4));
    return static_cast<std::size_t>(4 + 4 * k * k);
  }
  if (kind == "hilbert") {
    // The path of order k has 4^k cells and floor(4^(k+1) / 5) - (k odd) turns; 2 outline
    // vertices per turn and 2 per end. Nearest to n.
    std::size_t best = 0;
    for (std::size_t k = 1; k <= 11; ++k) {
      const std::size_t turns = (std::size_t{4} << (2 * k)) / 5 - (k % 2);
      const std::size_t count = 4 + 2 * turns;
      if (best == 0 || std::llabs(static_cast<long long>(count) - static_cast<long long>(n)) <
                           std::llabs(static_cast<long long>(best) - static_cast<long long>(n)))
        best = count;
    }
    return best;
  }
  return n;  // star, spiral, random, random-holes: exact
}

class EveryFamily : public ::testing::TestWithParam<std::tuple<std::string, std::size_t>> {};

TEST_P(EveryFamily, IsSimpleOrientedAndOfTheDocumentedSize) {
  const auto& [kind, n] = GetParam();
  const Polygon polygon = pear::generate_polygon(kind, n, 7);
  EXPECT_EQ(vertex_count(polygon), documented_count(kind, n));
  EXPECT_EQ(simplicity_problem(polygon), "");
  EXPECT_EQ(ring_orientation(polygon[0]), 1) << "outer ring must be counterclockwise";
  EXPECT_GT(twice_signed_area(polygon[0]), 0);
  for (std::size_t h = 1; h < polygon.size(); ++h) {
    ASSERT_EQ(ring_orientation(polygon[h]), -1) << "hole " << h << " must be clockwise";
    ASSERT_LT(twice_signed_area(polygon[h]), 0) << "hole " << h;
  }
  EXPECT_GT(area(polygon), 0);
}

std::string name(const ::testing::TestParamInfo<EveryFamily::ParamType>& info) {
  std::string kind = std::get<0>(info.param);
  for (char& c : kind)
    if (c == '-') c = '_';
  return kind + "_" + std::to_string(std::get<1>(info.param));
}

INSTANTIATE_TEST_SUITE_P(
    Sizes, EveryFamily,
    ::testing::Combine(::testing::Values("star", "comb", "spiral", "koch", "hilbert", "random",
                                         "holes", "random-holes"),
                       ::testing::Values(std::size_t{1000}, std::size_t{10'000},
                                         std::size_t{150'000})),
    name);

TEST(Generate, KnowsItsKinds) {
  const auto kinds = pear::generator_kinds();
  EXPECT_EQ(kinds.size(), 8u);
  for (std::string_view kind : kinds) EXPECT_NO_THROW(pear::generate_polygon(kind, 2000));
}

TEST(Generate, IsDeterministicInTheSeed) {
  for (std::string_view kind : pear::generator_kinds()) {
    EXPECT_EQ(pear::generate_polygon(kind, 2000, 3), pear::generate_polygon(kind, 2000, 3)) << kind;
    const bool random = kind == "star" || kind == "random" || kind == "random-holes";
    EXPECT_EQ(pear::generate_polygon(kind, 2000, 3) == pear::generate_polygon(kind, 2000, 4),
              !random)
        << kind;
  }
}

TEST(Generate, UnknownKindOrImpossibleSizeThrows) {
  EXPECT_THROW(pear::generate_polygon("circle", 1000), std::invalid_argument);
  EXPECT_THROW(pear::generate_polygon("spiral", 639), std::invalid_argument);
  EXPECT_THROW(pear::generate_polygon("star", 2), std::invalid_argument);
  EXPECT_THROW(pear::generate_polygon("random", 7), std::invalid_argument);
  EXPECT_THROW(pear::generate_polygon("random-holes", 6), std::invalid_argument);
  EXPECT_THROW(pear::generate_polygon("holes", 5), std::invalid_argument);
}

TEST(Generate, SmallestSizesAreStillSimple) {
  for (const auto& [kind, n] : {std::pair{"spiral", 640},
                                {"star", 3},
                                {"random", 8},
                                {"random-holes", 7},
                                {"holes", 8},
                                {"koch", 3},
                                {"comb", 4},
                                {"hilbert", 8}}) {
    const Polygon polygon = pear::generate_polygon(kind, n);
    EXPECT_EQ(simplicity_problem(polygon), "") << kind;
    EXPECT_EQ(vertex_count(polygon), documented_count(kind, n)) << kind;
  }
}

TEST(Generate, HolesHaveTheExactArea) {
  // [0, 300]^2 minus 10,000 unit squares.
  const Polygon polygon = pear::generate_polygon("holes", 40'004);
  EXPECT_EQ(polygon.size(), 10'001u);
  EXPECT_EQ(area(polygon), 300.0L * 300.0L - 10'000.0L);
}

TEST(Generate, KochHasTheClosedFormArea) {
  // Side 1: each depth adds 3 * 4^(k-1) triangles of area A0 / 9^k, so
  // A_d = A0 * (1 + 3/5 * (1 - (4/9)^d)) with A0 = sqrt(3) / 4.
  for (const auto& [n, depth] : {std::pair{3, 0}, {12, 1}, {768, 4}, {196'608, 8}}) {
    const long double a0 = std::sqrt(3.0L) / 4;
    const long double expected = a0 * (1 + 0.6L * (1 - std::pow(4.0L / 9, depth)));
    EXPECT_NEAR(static_cast<double>(area(pear::generate_polygon("koch", n))),
                static_cast<double>(expected), 1e-12)
        << "depth " << depth;
  }
}

TEST(Generate, CombHasTheExactArea) {
  // 25,000 teeth: a base 49,999 x 1 and teeth 1 x 10.
  EXPECT_EQ(area(pear::generate_polygon("comb", 100'000)), 49'999.0L + 250'000.0L);
}

TEST(Generate, HilbertHasTheExactArea) {
  // 4^k cells of 0.5 x 0.5 and 4^k - 1 joints of 0.5 x 0.5 between them; order 8 has 104,860
  // vertices.
  const Polygon polygon = pear::generate_polygon("hilbert", 104'860);
  ASSERT_EQ(vertex_count(polygon), 104'860u);
  EXPECT_EQ(area(polygon), 0.25L * (2 * 65'536 - 1));
}

TEST(Generate, SpiralIsCloseToTheBandArea) {
  // The band between r = 1 + t and 1.5 + t, angle 2*pi*t, t in [0, 20], has area 225*pi; chords
  // cut off a little.
  const long double a = area(pear::generate_polygon("spiral", 100'000));
  EXPECT_LT(a, 225 * std::numbers::pi_v<long double>);
  EXPECT_NEAR(static_cast<double>(a), 225 * std::numbers::pi, 0.01);
}

TEST(Generate, RandomHolesCountsHoles) {
  EXPECT_EQ(pear::generate_polygon("random-holes", 8004).size(), 1001u);
  // At most 100,000 holes: larger sizes get more vertices per hole.
  const Polygon most = pear::generate_polygon("random-holes", 1'000'004);
  EXPECT_EQ(most.size(), 100'001u);
  EXPECT_EQ(vertex_count(most), 1'000'004u);
  EXPECT_EQ(simplicity_problem(most), "");
}

}  // namespace
