// orient2d: every sign must equal the exact sign computed with GMP rationals.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "pear/predicates.hpp"
#include "support.hpp"

namespace pear::test {
namespace {

using Triple = std::array<Point, 3>;

void check_orient2d(const Point& a, const Point& b, const Point& c) {
  ASSERT_TRUE(in_domain(a) && in_domain(b) && in_domain(c)) << "test input outside the domain";
  const int expected = exact_orient2d_sign(a, b, c);
  const double value = orient2d(a, b, c);
  EXPECT_EQ(sign_of(value), expected)
      << std::hexfloat << "orient2d((" << a.x << ", " << a.y << "), (" << b.x << ", " << b.y
      << "), (" << c.x << ", " << c.y << ")) = " << value;
}

// Three points on the segment p..q (the third rounded onto it), in a box where every coordinate
// is in [0.5, 2], so power-of-two scaling to 2^-199 stays inside the domain.
Triple near_collinear_triple(Random& random) {
  const Point p{random.uniform(0.5, 2.0), random.uniform(0.5, 2.0)};
  const Point q{random.uniform(0.5, 2.0), random.uniform(0.5, 2.0)};
  const double t = random.unit();
  const Point r{p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)};
  return {p, q, r};
}

// The triple itself and every single-coordinate perturbation by 1, 2 or 3 ulps either way.
std::vector<Triple> ulp_perturbations(const Triple& triple) {
  std::vector<Triple> cases{triple};
  for (std::size_t point = 0; point < 3; ++point) {
    for (int steps : {-3, -2, -1, 1, 2, 3}) {
      Triple moved_x = triple;
      moved_x[point].x = ulps(moved_x[point].x, steps);
      Triple moved_y = triple;
      moved_y[point].y = ulps(moved_y[point].y, steps);
      cases.push_back(moved_x);
      cases.push_back(moved_y);
    }
  }
  return cases;
}

TEST(Orient2d, ConventionCounterclockwiseIsPositive) {
  EXPECT_GT(orient2d({0, 0}, {1, 0}, {0, 1}), 0.0);
  EXPECT_LT(orient2d({0, 0}, {0, 1}, {1, 0}), 0.0);
  EXPECT_EQ(orient2d({0, 0}, {1, 1}, {2, 2}), 0.0);
}

// Outside the domain nothing is promised but the absence of undefined behaviour; NaN stays NaN.
TEST(Orient2d, NanCoordinateGivesNan) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int slot = 0; slot < 6; ++slot) {
    std::array<double, 6> v{0.5, 0.25, 1.0, 0.75, 0.125, 2.0};
    v[slot] = nan;
    EXPECT_TRUE(std::isnan(orient2d({v[0], v[1]}, {v[2], v[3]}, {v[4], v[5]}))) << "slot " << slot;
  }
}

TEST(Orient2d, RandomPointsMatchReference) {
  Random random(1);
  for (int i = 0; i < 4000; ++i) {
    const Point a{random.uniform(-1, 1), random.uniform(-1, 1)};
    const Point b{random.uniform(-1, 1), random.uniform(-1, 1)};
    const Point c{random.uniform(-1, 1), random.uniform(-1, 1)};
    check_orient2d(a, b, c);
  }
}

TEST(Orient2d, MixedSignsAndMagnitudesMatchReference) {
  Random random(2);
  auto coordinate = [&]() {
    return random.integer(0, 15) == 0 ? 0.0 : random.with_exponent(random.integer(-200, 199));
  };
  for (int i = 0; i < 4000; ++i) {
    check_orient2d({coordinate(), coordinate()}, {coordinate(), coordinate()},
                   {coordinate(), coordinate()});
  }
}

TEST(Orient2d, NearCollinearUlpPerturbationsMatchReference) {
  Random random(3);
  // Unit scale, huge (coordinates up to 2^199) and tiny (down to 2^-200).
  for (int exponent : {0, 198, -199}) {
    for (int line = 0; line < 150; ++line) {
      const Transform transform = random_transform(random, exponent);
      for (const Triple& t : ulp_perturbations(near_collinear_triple(random))) {
        check_orient2d(transform(t[0]), transform(t[1]), transform(t[2]));
        check_orient2d(transform(t[2]), transform(t[0]), transform(t[1]));
      }
    }
  }
}

TEST(Orient2d, ExactlyCollinearIntegersGiveZero) {
  Random random(4);
  for (int exponent : {0, 150, -150}) {
    for (int i = 0; i < 500; ++i) {
      const Transform transform = random_transform(random, exponent);
      const Point a{double(random.integer(-1000, 1000)), double(random.integer(-1000, 1000))};
      const Point b{double(random.integer(-1000, 1000)), double(random.integer(-1000, 1000))};
      const int k = random.integer(-5, 5);
      const Point c{a.x + k * (b.x - a.x), a.y + k * (b.y - a.y)};
      ASSERT_EQ(exact_orient2d_sign(a, b, c), 0);
      EXPECT_EQ(orient2d(transform(a), transform(b), transform(c)), 0.0);
      EXPECT_EQ(orient2d(transform(a), transform(a), transform(c)), 0.0);
    }
  }
}

// Points on y = x, y = -x or y = 2x with coordinates of unrelated magnitudes: exactly collinear,
// yet their differences are not representable, so the exact last stage must decide. Their ulp
// perturbations are the hardest inputs for the adaptive stages.
TEST(Orient2d, MixedMagnitudeCollinearAndPerturbedMatchReference) {
  Random random(5);
  for (int i = 0; i < 300; ++i) {
    const double slope = std::array{1.0, -1.0, 2.0}[random.integer(0, 2)];
    Triple triple;
    for (Point& p : triple) {
      const double x = random.with_exponent(random.integer(-190, 190));
      p = {x, slope * x};
    }
    EXPECT_EQ(orient2d(triple[0], triple[1], triple[2]), 0.0);
    for (const Triple& t : ulp_perturbations(triple)) check_orient2d(t[0], t[1], t[2]);
  }
}

// Kettner, Mehlhorn, Pion, Schirra, Yap, "Classroom examples of robustness problems in geometric
// computations": p on a 2^-53 grid near (0.5, 0.5) against a line through two far points.
TEST(Orient2d, ClassroomGridMatchesReference) {
  const double u = 0x1p-53;
  const std::array<std::array<Point, 2>, 3> lines{{
      {Point{12.0, 12.0}, Point{24.0, 24.0}},
      {Point{17.300000000000001, 17.300000000000001},
       Point{24.000000000000068, 24.000000000000071}},
      {Point{8.8000000000000007, 7.7000000000000002}, Point{12.1, 12.1}},
  }};
  for (const auto& [q, r] : lines) {
    for (int i = 0; i < 128; ++i) {
      for (int j = 0; j < 128; ++j) {
        const Point p{0.5 + i * u, 0.5 + j * u};
        check_orient2d(p, q, r);
        check_orient2d(q, r, p);
      }
    }
  }
}

TEST(Orient2d, SwappingTwoPointsFlipsTheSign) {
  Random random(6);
  for (int line = 0; line < 100; ++line) {
    for (const Triple& t : ulp_perturbations(near_collinear_triple(random))) {
      const auto& [a, b, c] = t;
      const int s = sign_of(orient2d(a, b, c));
      EXPECT_EQ(sign_of(orient2d(b, a, c)), -s);
      EXPECT_EQ(sign_of(orient2d(a, c, b)), -s);
      EXPECT_EQ(sign_of(orient2d(c, b, a)), -s);
      EXPECT_EQ(sign_of(orient2d(b, c, a)), s);
      EXPECT_EQ(sign_of(orient2d(c, a, b)), s);
    }
  }
}

}  // namespace
}  // namespace pear::test
