// incircle: every sign must equal the exact sign computed with GMP rationals.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "pear/predicates.hpp"
#include "support.hpp"

namespace pear::test {
namespace {

using Quad = std::array<Point, 4>;

void check_incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
  ASSERT_TRUE(in_domain(a) && in_domain(b) && in_domain(c) && in_domain(d))
      << "test input outside the domain";
  const int expected = exact_incircle_sign(a, b, c, d);
  const double value = incircle(a, b, c, d);
  EXPECT_EQ(sign_of(value), expected)
      << std::hexfloat << "incircle((" << a.x << ", " << a.y << "), (" << b.x << ", " << b.y
      << "), (" << c.x << ", " << c.y << "), (" << d.x << ", " << d.y << ")) = " << value;
}

void check_incircle(const Quad& q) {
  check_incircle(q[0], q[1], q[2], q[3]);
}

// Four points on a circle inside the box [0.5, 2]^2, each rounded to doubles.
Quad near_cocircular_quad(Random& random) {
  const double cx = random.uniform(1.0, 1.5);
  const double cy = random.uniform(1.0, 1.5);
  const double radius = random.uniform(0.1, 0.5);
  Quad quad;
  for (Point& p : quad) {
    const double angle = 2.0 * std::numbers::pi * random.unit();
    p = {cx + radius * std::cos(angle), cy + radius * std::sin(angle)};
  }
  return quad;
}

// The quad itself and every single-coordinate perturbation of d or a by 1, 2 or 3 ulps.
std::vector<Quad> ulp_perturbations(const Quad& quad) {
  std::vector<Quad> cases{quad};
  for (std::size_t point : {std::size_t{0}, std::size_t{3}}) {
    for (int steps : {-3, -2, -1, 1, 2, 3}) {
      Quad moved_x = quad;
      moved_x[point].x = ulps(moved_x[point].x, steps);
      Quad moved_y = quad;
      moved_y[point].y = ulps(moved_y[point].y, steps);
      cases.push_back(moved_x);
      cases.push_back(moved_y);
    }
  }
  return cases;
}

TEST(Incircle, ConventionInsideIsPositive) {
  const Point a{1, 0}, b{0, 1}, c{-1, 0};
  EXPECT_GT(incircle(a, b, c, {0, 0}), 0.0);
  EXPECT_LT(incircle(a, b, c, {2, 2}), 0.0);
  EXPECT_EQ(incircle(a, b, c, {0, -1}), 0.0);
  EXPECT_LT(incircle(c, b, a, {0, 0}), 0.0);  // clockwise a, b, c reverse the sign
}

TEST(Incircle, NanCoordinateGivesNan) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int slot = 0; slot < 8; ++slot) {
    std::array<double, 8> v{1.0, 0.0, 0.0, 1.0, -1.0, 0.0, 0.0, -1.0};  // cocircular: no early exit
    v[slot] = nan;
    EXPECT_TRUE(std::isnan(incircle({v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}, {v[6], v[7]})))
        << "slot " << slot;
  }
}

TEST(Incircle, RandomPointsMatchReference) {
  Random random(11);
  for (int i = 0; i < 3000; ++i) {
    Quad quad;
    for (Point& p : quad) p = {random.uniform(-1, 1), random.uniform(-1, 1)};
    check_incircle(quad);
  }
}

TEST(Incircle, MixedSignsAndMagnitudesMatchReference) {
  Random random(12);
  auto coordinate = [&]() {
    return random.integer(0, 15) == 0 ? 0.0 : random.with_exponent(random.integer(-200, 199));
  };
  for (int i = 0; i < 3000; ++i) {
    Quad quad;
    for (Point& p : quad) p = {coordinate(), coordinate()};
    check_incircle(quad);
  }
}

TEST(Incircle, NearCocircularUlpPerturbationsMatchReference) {
  Random random(13);
  for (int exponent : {0, 198, -199}) {
    for (int circle = 0; circle < 120; ++circle) {
      const Transform transform = random_transform(random, exponent);
      for (const Quad& q : ulp_perturbations(near_cocircular_quad(random))) {
        check_incircle(transform(q[0]), transform(q[1]), transform(q[2]), transform(q[3]));
      }
    }
  }
}

// Integer points on the circle x^2 + y^2 = 65^2 (65^2 is a sum of two squares in four ways),
// translated by integers and scaled by powers of two: exactly cocircular.
TEST(Incircle, ExactlyCocircularIntegersGiveZero) {
  std::vector<Point> circle;
  for (auto [x, y] :
       std::array<std::array<int, 2>, 5>{{{0, 65}, {16, 63}, {25, 60}, {33, 56}, {39, 52}}}) {
    for (int sx : {-1, 1}) {
      for (int sy : {-1, 1}) {
        circle.push_back({double(sx * x), double(sy * y)});
        circle.push_back({double(sy * y), double(sx * x)});
      }
    }
  }
  Random random(14);
  for (int exponent : {0, 150, -150}) {
    for (int i = 0; i < 400; ++i) {
      const Transform transform = random_transform(random, exponent);
      const Point shift{double(random.integer(-1000, 1000)), double(random.integer(-1000, 1000))};
      Quad quad;
      for (Point& p : quad) {
        const Point& on_circle = circle[random.integer(0, int(circle.size()) - 1)];
        p = transform({on_circle.x + shift.x, on_circle.y + shift.y});
      }
      ASSERT_EQ(exact_incircle_sign(quad[0], quad[1], quad[2], quad[3]), 0);
      EXPECT_EQ(incircle(quad[0], quad[1], quad[2], quad[3]), 0.0);
    }
  }
}

// The corners of an axis-parallel rectangle are cocircular. With coordinates of unrelated
// magnitudes the differences are not representable, so the exact last stage must decide; their
// ulp perturbations are the hardest inputs for the adaptive stages.
TEST(Incircle, MixedMagnitudeRectanglesAndPerturbedMatchReference) {
  Random random(15);
  for (int i = 0; i < 300; ++i) {
    const double x0 = random.with_exponent(random.integer(-190, 190));
    const double x1 = random.with_exponent(random.integer(-190, 190));
    const double y0 = random.with_exponent(random.integer(-190, 190));
    const double y1 = random.with_exponent(random.integer(-190, 190));
    Quad quad{Point{x0, y0}, Point{x1, y0}, Point{x1, y1}, Point{x0, y1}};
    std::swap(quad[random.integer(0, 3)], quad[random.integer(0, 3)]);
    EXPECT_EQ(incircle(quad[0], quad[1], quad[2], quad[3]), 0.0);
    for (const Quad& q : ulp_perturbations(quad)) check_incircle(q);
  }
}

// In the style of Kettner et al.'s classroom examples: d on a 2^-53 grid near (0.5, 0.5), a
// corner of the rectangle (or the square) whose other corners are a, b, c.
TEST(Incircle, ClassroomGridMatchesReference) {
  const double u = 0x1p-53;
  const std::array<std::array<Point, 3>, 2> circles{{
      {Point{24.0, 0.5}, Point{24.0, 12.0}, Point{0.5, 12.0}},
      {Point{0.5, -0.5}, Point{-0.5, 0.5}, Point{-0.5, -0.5}},
  }};
  for (const auto& [a, b, c] : circles) {
    for (int i = -32; i < 32; ++i) {
      for (int j = -32; j < 32; ++j) {
        const Point d{0.5 + i * u, 0.5 + j * u};
        check_incircle(a, b, c, d);
      }
    }
  }
}

TEST(Incircle, SwappingTwoPointsFlipsTheSign) {
  Random random(16);
  for (int circle = 0; circle < 60; ++circle) {
    for (const Quad& q : ulp_perturbations(near_cocircular_quad(random))) {
      const auto& [a, b, c, d] = q;
      const int s = sign_of(incircle(a, b, c, d));
      EXPECT_EQ(sign_of(incircle(b, a, c, d)), -s);
      EXPECT_EQ(sign_of(incircle(a, c, b, d)), -s);
      EXPECT_EQ(sign_of(incircle(d, b, c, a)), -s);
      EXPECT_EQ(sign_of(incircle(a, d, c, b)), -s);
      EXPECT_EQ(sign_of(incircle(b, c, a, d)), s);
      EXPECT_EQ(sign_of(incircle(d, a, b, c)), -s);  // a 4-cycle is odd
    }
  }
}

}  // namespace
}  // namespace pear::test
