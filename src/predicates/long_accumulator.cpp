// pear: the long fixed-point accumulator.
#include "long_accumulator.hpp"

#include <cmath>
#include <limits>

namespace pear::detail {

void LongAccumulator::add(double v) {
  if (v == 0.0) return;
  if (!std::isfinite(v)) {
    finite_ = false;
    return;
  }
  int exponent;
  const double fraction = std::frexp(std::fabs(v), &exponent);  // |v| = fraction * 2^exponent
  auto significand = static_cast<std::uint64_t>(std::ldexp(fraction, 53));  // exact, < 2^53
  int position = exponent - 53 - lowest_exponent;  // the weight of the significand's bit 0
  if (position < 0) {                              // a subnormal: the bits shifted out are zero
    significand >>= -position;
    position = 0;
  }
  const auto limb = static_cast<std::size_t>(position / 64);
  const int shift = position % 64;
  const std::uint64_t low = significand << shift;
  const std::uint64_t high = shift == 0 ? 0 : significand >> (64 - shift);
  if (v > 0.0) {
    add_at(limb, low, high);
  } else {
    subtract_at(limb, low, high);
  }
}

void LongAccumulator::add_at(std::size_t limb, std::uint64_t low, std::uint64_t high) {
  std::uint64_t carry = 0;
  for (std::size_t i = limb; i < limb_count; ++i) {
    const std::uint64_t term = i == limb ? low : i == limb + 1 ? high : 0;
    if (i > limb + 1 && carry == 0) break;
    const std::uint64_t partial = limbs_[i] + term;
    const std::uint64_t sum = partial + carry;
    carry = static_cast<std::uint64_t>(partial < term) | static_cast<std::uint64_t>(sum < partial);
    limbs_[i] = sum;
  }
}

void LongAccumulator::subtract_at(std::size_t limb, std::uint64_t low, std::uint64_t high) {
  std::uint64_t borrow = 0;
  for (std::size_t i = limb; i < limb_count; ++i) {
    const std::uint64_t term = i == limb ? low : i == limb + 1 ? high : 0;
    if (i > limb + 1 && borrow == 0) break;
    const std::uint64_t partial = limbs_[i] - term;
    const std::uint64_t difference = partial - borrow;
    borrow =
        static_cast<std::uint64_t>(limbs_[i] < term) | static_cast<std::uint64_t>(partial < borrow);
    limbs_[i] = difference;
  }
}

int LongAccumulator::sign() const {
  if ((limbs_[limb_count - 1] >> 63) != 0) return -1;
  for (std::uint64_t limb : limbs_) {
    if (limb != 0) return 1;
  }
  return 0;
}

double LongAccumulator::value() const {
  if (!finite_) return std::numeric_limits<double>::quiet_NaN();
  const int s = sign();
  if (s == 0) return 0.0;
  std::array<std::uint64_t, limb_count> magnitude = limbs_;
  if (s < 0) {  // two's complement: invert and add one
    std::uint64_t carry = 1;
    for (std::uint64_t& limb : magnitude) {
      limb = ~limb + carry;
      carry = static_cast<std::uint64_t>(carry != 0 && limb == 0);
    }
  }
  std::size_t top = limb_count - 1;
  while (magnitude[top] == 0) --top;
  double result =
      std::ldexp(static_cast<double>(magnitude[top]), 64 * static_cast<int>(top) + lowest_exponent);
  if (top > 0) {
    result += std::ldexp(static_cast<double>(magnitude[top - 1]),
                         64 * static_cast<int>(top - 1) + lowest_exponent);
  }
  if (result == 0.0) result = std::numeric_limits<double>::denorm_min();  // keep the sign visible
  return s > 0 ? result : -result;
}

}  // namespace pear::detail
