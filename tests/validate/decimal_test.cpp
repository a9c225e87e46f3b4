// validate/decimal.hpp's format_g17 (the validator's numbers without printf) against the C
// library's snprintf "%.17g", which rounds the exact value the same way.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

#include "validate/decimal.hpp"

namespace {

using pear::detail::format_g17;

std::string printf_g17(double value) {
  char text[40];
  std::snprintf(text, sizeof text, "%.17g", value);
  return text;
}

TEST(FormatG17, EdgeValuesAsPrintf) {
  using limits = std::numeric_limits<double>;
  // 1125899906842624.25 and .75: 18 digits that end in 5, ties at the 17th (2^50 < v < 2^51).
  const double values[] = {0.0,
                           -0.0,
                           1.0,
                           -1.0,
                           0.1,
                           0.5,
                           2.5,
                           2.0 / 3,
                           0.3,
                           1e16,
                           1e17,
                           1e-4,
                           1e-5,
                           9.99999999999999999e-5,
                           0.000123456789,
                           123456789012345678.0,
                           99999999999999999.0,
                           9007199254740993.0,
                           4503599627370496.5,
                           1125899906842624.25,
                           1125899906842624.75,
                           1125899906842625.25,
                           1e300,
                           1e-300,
                           limits::max(),
                           limits::min(),
                           limits::denorm_min(),
                           -limits::denorm_min(),
                           limits::infinity(),
                           -limits::infinity()};
  for (const double v : values) EXPECT_EQ(format_g17(v), printf_g17(v)) << printf_g17(v);
  EXPECT_EQ(format_g17(limits::quiet_NaN()), "nan");
}

/// Random bit patterns cover every exponent, subnormals included; short decimals, the
/// carries through nines; the edge values above, ties to even.
TEST(FormatG17, RandomDoublesAsPrintf) {
  std::mt19937_64 random(17);
  int compared = 0;
  for (int i = 0; i < 3000; ++i) {
    const double v = std::bit_cast<double>(random());
    if (v != v || v - v != 0) continue;
    ++compared;
    ASSERT_EQ(format_g17(v), printf_g17(v));
  }
  EXPECT_GT(compared, 2900);
  for (int i = 0; i < 3000; ++i) {
    const double v = static_cast<double>(random() % 2000001) / 1000 - 1000;
    ASSERT_EQ(format_g17(v), printf_g17(v));
    ASSERT_EQ(format_g17(v * 1e-7), printf_g17(v * 1e-7));
  }
}

}  // namespace
