// The exact accumulator behind the validator's area check: sums that floating point gets wrong.
#include <gtest/gtest.h>

#include "validate/exact_sum.hpp"

namespace pear::test {
namespace {

using detail::ExactSum;

TEST(ExactSum, KeepsSmallTermsBesideLargeOnes) {
  ExactSum sum;
  sum.add(0x1p100);
  sum.add(1);
  sum.subtract(0x1p100);
  EXPECT_EQ(sum.sign(), 1);
  EXPECT_EQ(sum.to_double(), 1.0);
}

TEST(ExactSum, ProductsAreExact) {
  // (1 + 2^-30)^2 = 1 + 2^-29 + 2^-60: the last term is lost by a rounded product.
  ExactSum sum;
  sum.add_product(1 + 0x1p-30, 1 + 0x1p-30);
  sum.subtract(1);
  sum.subtract(0x1p-29);
  EXPECT_EQ(sum.to_double(), 0x1p-60);
  sum.add_product(0x1p-30, 0x1p-30, true);
  EXPECT_EQ(sum.sign(), 0);
}

TEST(ExactSum, SpansTheWholeCoordinateDomain) {
  // Products of coordinates range from 2^-400 to 2^400.
  ExactSum sum;
  sum.add_product(0x1p200, 0x1p200);
  sum.add_product(0x1p-200, 0x1p-200);
  sum.add_product(0x1p200, -0x1p200);
  EXPECT_EQ(sum.to_double(), 0x1p-400);
  EXPECT_FALSE(sum.out_of_range());
}

TEST(ExactSum, BorrowsAcrossLimbs) {
  ExactSum sum;
  sum.add(1);
  sum.subtract(0x1p-500);
  EXPECT_EQ(sum.sign(), 1);
  sum.subtract(1);
  EXPECT_EQ(sum.sign(), -1);
  EXPECT_EQ(sum.to_double(), -0x1p-500);
}

TEST(ExactSum, ManyAdditionsCarryCorrectly) {
  // 2^21 copies of (2^53 - 1) * 2^-21 sum to 2^53 - 1, past the 2^28-addition normalization
  // interval's worth of limb growth for these 32-bit pieces.
  ExactSum sum;
  const double piece = (0x1p53 - 1) * 0x1p-21;
  for (int i = 0; i < (1 << 21); ++i) sum.add(piece);
  EXPECT_EQ(sum.to_double(), 0x1p53 - 1);
  sum.subtract(0x1p53 - 1);
  EXPECT_EQ(sum.sign(), 0);
}

TEST(ExactSum, CombinesSums) {
  ExactSum a, b;
  a.add(3);
  b.add(5);
  a.subtract(b);
  EXPECT_EQ(a.to_double(), -2.0);
  a.add(b);
  a.add(b);
  EXPECT_EQ(a.to_double(), 8.0);
}

TEST(ExactSum, FlagsTermsOutsideItsRange) {
  ExactSum sum;
  sum.add(0x1p-600);
  EXPECT_TRUE(sum.out_of_range());
}

}  // namespace
}  // namespace pear::test
