// The expansion arithmetic under the predicates: every result must be exact (equal to the GMP
// value), nonoverlapping and free of zero components.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "predicates/expansion.hpp"
#include "support.hpp"

namespace pear::test {
namespace {

using Components = std::vector<double>;

mpq_class exact_sum(std::span<const double> e) {
  mpq_class sum = 0;
  for (double component : e) sum += exact(component);
  return sum;
}

// The value of the least significant set bit of v's significand.
double lowest_bit(double v) {
  int exponent;
  const double fraction = std::frexp(std::fabs(v), &exponent);  // in [0.5, 1)
  const auto significand = static_cast<std::uint64_t>(std::ldexp(fraction, 53));
  return std::ldexp(1.0, exponent - 53 + std::countr_zero(significand));
}

// Increasing magnitude, no zeros, and each component below the lowest bit of the next.
void expect_well_formed(std::span<const double> e) {
  for (std::size_t i = 0; i < e.size(); ++i) {
    EXPECT_NE(e[i], 0.0) << "component " << i;
    if (i + 1 < e.size()) {
      EXPECT_LT(std::fabs(e[i]), lowest_bit(e[i + 1]))
          << std::hexfloat << e[i] << " overlaps " << e[i + 1];
    }
  }
}

// Nonadjacent (paper §2.2): besides not overlapping, no component overlaps twice the one below.
void expect_nonadjacent(std::span<const double> e) {
  expect_well_formed(e);
  for (std::size_t i = 0; i + 1 < e.size(); ++i) {
    EXPECT_LT(2 * std::fabs(e[i]), lowest_bit(e[i + 1]))
        << std::hexfloat << e[i] << " is adjacent to " << e[i + 1];
  }
}

Components sum(const Components& e, const Components& f) {
  Components h(e.size() + f.size());
  h.resize(detail::expansion_sum(e, f, h.data()));
  return h;
}

Components scale(const Components& e, double b) {
  Components h(2 * e.size());
  h.resize(detail::scale_expansion(e, b, h.data()));
  return h;
}

// An expansion equal to the sum of a few random doubles of spread-out magnitudes.
Components random_expansion(Random& random, int terms, int exponent_spread) {
  Components e;
  for (int i = 0; i < terms; ++i) {
    e = sum(e, Components{random.with_exponent(random.integer(-exponent_spread, exponent_spread))});
  }
  return e;
}

TEST(Expansion, TwoSumAndTwoProductAreExact) {
  Random random(21);
  for (int i = 0; i < 5000; ++i) {
    const double a = random.with_exponent(random.integer(-400, 400));
    const double b = random.with_exponent(random.integer(-400, 400));
    double s, s_error, d, d_error, p, p_error;
    detail::two_sum(a, b, s, s_error);
    detail::two_diff(a, b, d, d_error);
    detail::two_product(a, b, p, p_error);
    ASSERT_EQ(exact(s) + exact(s_error), exact(a) + exact(b));
    ASSERT_EQ(exact(d) + exact(d_error), exact(a) - exact(b));
    ASSERT_EQ(detail::two_diff_tail(a, b, d), d_error);
    ASSERT_EQ(exact(p) + exact(p_error), exact(a) * exact(b));
  }
}

TEST(Expansion, SumScaleAndProductAreExact) {
  Random random(22);
  for (int i = 0; i < 1000; ++i) {
    const Components e = random_expansion(random, random.integer(1, 6), 120);
    const Components f = random_expansion(random, random.integer(1, 6), 120);
    const double b = random.with_exponent(random.integer(-100, 100));
    expect_well_formed(e);
    ASSERT_EQ(exact_sum(sum(e, f)), exact_sum(e) + exact_sum(f));
    expect_well_formed(sum(e, f));
    ASSERT_EQ(exact_sum(scale(e, b)), exact_sum(e) * exact(b));
    expect_well_formed(scale(e, b));
    EXPECT_EQ(detail::expansion_sign(e), sgn(exact_sum(e)));
    EXPECT_EQ(sign_of(detail::expansion_value(e)), sgn(exact_sum(e)));
  }
}

// The chain of incircle's stage B: a cross product grown into a nonadjacent expansion, scaled
// twice (still nonadjacent, paper Theorem 19), then summed (strongly nonoverlapping, Theorem 13).
TEST(Expansion, CrossScaleAndSumKeepTheirStructure) {
  Random random(23);
  for (int i = 0; i < 2000; ++i) {
    double v[6];
    for (double& x : v) x = random.with_exponent(random.integer(-60, 60));
    const detail::Expansion<4> cross = detail::exact_cross(v[0], v[1], v[2], v[3]);
    ASSERT_EQ(exact_sum(cross.view()), exact(v[0]) * exact(v[1]) - exact(v[2]) * exact(v[3]));
    expect_nonadjacent(cross.view());
    const detail::Expansion<16> scaled = (cross * v[4]) * v[5];
    ASSERT_EQ(exact_sum(scaled.view()), exact_sum(cross.view()) * exact(v[4]) * exact(v[5]));
    expect_nonadjacent(scaled.view());
    const detail::Expansion<32> total = scaled + (cross * v[5]) * v[4];
    ASSERT_EQ(exact_sum(total.view()), 2 * exact_sum(scaled.view()));
    expect_well_formed(total.view());
  }
}

// Products of general expansions: the value is exact whatever the components' structure.
TEST(Expansion, ProductOfExpansionsIsExact) {
  Random random(24);
  for (int i = 0; i < 300; ++i) {
    detail::Expansion<4> e;
    detail::Expansion<4> f;
    for (auto* x : {&e, &f}) {
      const Components c = random_expansion(random, 4, 60);
      std::copy(c.begin(), c.end(), x->term.begin());
      x->size = c.size();
    }
    const detail::Expansion<32> product = e * f;
    ASSERT_EQ(exact_sum(product.view()), exact_sum(e.view()) * exact_sum(f.view()));
  }
}

TEST(Expansion, CancellationToZeroLeavesNoComponents) {
  const Components e = sum({0x1p-60, 1.0}, {-0x1p-60, -1.0});
  EXPECT_TRUE(e.empty());
  EXPECT_EQ(detail::expansion_sign(e), 0);
  EXPECT_EQ(detail::expansion_value(e), 0.0);
}

// The rounded sum of -5*2^-56 and -(1 - 2^-53) is -1, which cancels the leading 1 exactly, although
// the expansion's value is +3*2^-56: the estimate loses the sign, expansion_value must not.
TEST(Expansion, ValueKeepsTheSignWhenTheEstimateLosesIt) {
  const Components e{-5 * 0x1p-56, -(1.0 - 0x1p-53), 1.0};
  expect_well_formed(e);
  ASSERT_EQ(exact_sum(e), mpq_class(3) / mpq_class(mpz_class(1) << 56));
  EXPECT_EQ(detail::expansion_estimate(e), 0.0);
  EXPECT_EQ(detail::expansion_sign(e), 1);
  EXPECT_GT(detail::expansion_value(e), 0.0);
}

}  // namespace
}  // namespace pear::test
