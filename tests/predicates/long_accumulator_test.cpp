// The long accumulator must give the exact sign of any sum of finite doubles, subnormals and
// cancellations included.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "predicates/long_accumulator.hpp"
#include "support.hpp"

namespace pear::test {
namespace {

TEST(LongAccumulator, SignOfRandomSumsMatchesReference) {
  Random random(31);
  for (int i = 0; i < 2000; ++i) {
    detail::LongAccumulator accumulator;
    mpq_class reference = 0;
    const int terms = random.integer(1, 12);
    for (int k = 0; k < terms; ++k) {
      // Mostly normal numbers across the whole range, some subnormals.
      double v = random.with_exponent(random.integer(-1022, 1022));
      if (random.integer(0, 7) == 0) v = std::ldexp(double(random.integer(-1000, 1000)), -1074);
      accumulator.add(v);
      reference += exact(v);
    }
    ASSERT_EQ(accumulator.sign(), sgn(reference));
    ASSERT_EQ(sign_of(accumulator.value()), sgn(reference));
  }
}

// Terms that cancel except for a tiny residue far below them: the sign is the residue's, and the
// borrow runs through the whole accumulator.
TEST(LongAccumulator, CancellationLeavesTheExactResidue) {
  for (double residue : {0x1p-1074, -0x1p-1074, 0x1p-600, -3.0}) {
    detail::LongAccumulator accumulator;
    accumulator.add(0x1.fffffffffffffp1023);
    accumulator.add(residue);
    accumulator.add(-0x1.fffffffffffffp1023);
    EXPECT_EQ(accumulator.sign(), sign_of(residue));
    EXPECT_EQ(accumulator.value(), residue);
  }
  detail::LongAccumulator zero;
  zero.add(1.5);
  zero.add(-1.5);
  EXPECT_EQ(zero.sign(), 0);
  EXPECT_EQ(zero.value(), 0.0);
}

TEST(LongAccumulator, NonFiniteTermGivesNan) {
  detail::LongAccumulator accumulator;
  accumulator.add(1.0);
  accumulator.add(std::numeric_limits<double>::quiet_NaN());
  EXPECT_TRUE(std::isnan(accumulator.value()));
}

}  // namespace
}  // namespace pear::test
