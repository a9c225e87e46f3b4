// pear (internal): an exact accumulator for sums of doubles and of products of doubles.
//
// The validator compares the polygon's area with the triangles' total area. Shoelace terms of
// far-away, thin polygons cancel catastrophically in floating point, so we sum them exactly: a
// fixed-point number of 32-bit limbs spanning 2^-544 .. 2^480, each limb kept in an int64 so
// additions need no carry propagation until about 2^30 of them have piled up. A product is split
// exactly into two doubles (Dekker's TwoProduct; no FMA needed), both added. Every set bit of
// the validator's terms lies in [2^-506, 2^441) because coordinates are checked to be zero or
// within [2^-200, 2^200] first; a term outside the span sets out_of_range() instead of being lost.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

namespace pear::detail {

class ExactSum {
 public:
  static constexpr int limb_bits = 32;
  static constexpr int limb_count = 32;
  static constexpr int base_exponent = -544;  // value of limb 0's lowest bit: 2^-544

  void add(double value) { add_signed(value, false); }
  void subtract(double value) { add_signed(value, true); }

  /// Adds (or subtracts) a * b exactly.
  void add_product(double a, double b, bool negate = false) {
    double high = a * b;
    double low = two_product_error(a, b, high);
    add_signed(high, negate);
    add_signed(low, negate);
  }

  void add(const ExactSum& other) { combine(other, 1); }
  void subtract(const ExactSum& other) { combine(other, -1); }

  /// -1, 0 or +1: the exact sign of the sum.
  int sign() {
    normalize();
    if (limbs_[limb_count - 1] < 0) return -1;
    for (int i = limb_count - 1; i >= 0; --i)
      if (limbs_[i] != 0) return 1;
    return 0;
  }

  /// The sum rounded to a double (within a few units in the last place): the limbs from the top
  /// down, each exact as a double, so only the additions round. In doubles, not long doubles:
  /// WebAssembly's are 128-bit soft floats (4 KB of code in pear.wasm).
  double to_double() {
    normalize();
    double value = 0;
    for (int i = limb_count - 1; i >= 0; --i)
      value += std::ldexp(static_cast<double>(limbs_[i]), limb_bits * i + base_exponent);
    return value;
  }

  bool out_of_range() const { return out_of_range_; }

 private:
  // Dekker's split: a = high + low with both halves of at most 26 significant bits.
  static void split(double a, double& high, double& low) {
    double c = 134217729.0 * a;  // 2^27 + 1
    high = c - (c - a);
    low = a - high;
  }

  // The exact rounding error of product = fl(a * b) (Dekker 1971, TwoProduct).
  static double two_product_error(double a, double b, double product) {
    double a_high, a_low, b_high, b_low;
    split(a, a_high, a_low);
    split(b, b_high, b_low);
    double error = product - a_high * b_high;
    error -= a_low * b_high;
    error -= a_high * b_low;
    return a_low * b_low - error;
  }

  void add_signed(double value, bool negate) {
    if (value == 0) return;
    const auto bits = std::bit_cast<std::uint64_t>(value);
    const int exponent_field = static_cast<int>((bits >> 52) & 0x7ff);
    std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
    int exponent = -1074;  // subnormal
    if (exponent_field != 0) {
      mantissa |= std::uint64_t{1} << 52;
      exponent = exponent_field - 1075;
    }
    // Only the set bits must lie in the span: 2^-500 is 1 * 2^-500, not 2^52 * 2^-552.
    const int trailing_zeros = std::countr_zero(mantissa);
    mantissa >>= trailing_zeros;
    exponent += trailing_zeros;
    const int shift = exponent - base_exponent;
    if (exponent_field == 0x7ff || shift < 0 || shift / limb_bits + 2 >= limb_count) {
      out_of_range_ = true;
      return;
    }
    const int limb = shift / limb_bits;
    const int offset = shift % limb_bits;
    const std::uint64_t mask = 0xffffffffu;
    // mantissa * 2^offset spans at most 53 + 31 bits: three limbs.
    std::int64_t pieces[3] = {
        static_cast<std::int64_t>((mantissa << offset) & mask),
        static_cast<std::int64_t>((mantissa >> (limb_bits - offset)) & mask),
        offset == 0 ? 0 : static_cast<std::int64_t>(mantissa >> (2 * limb_bits - offset))};
    const bool negative = (bits >> 63) != negate;
    for (int k = 0; k < 3; ++k) limbs_[limb + k] += negative ? -pieces[k] : pieces[k];
    if (++pending_ >= max_pending) normalize();
  }

  void combine(const ExactSum& other, int factor) {
    ExactSum copy = other;
    copy.normalize();
    normalize();
    for (int i = 0; i < limb_count; ++i) limbs_[i] += factor * copy.limbs_[i];
    out_of_range_ = out_of_range_ || other.out_of_range_;
    normalize();
  }

  // Carries upward so limbs 0 .. count-2 lie in [0, 2^32) and the top limb holds the sign.
  void normalize() {
    for (int i = 0; i + 1 < limb_count; ++i) {
      const std::int64_t carry = limbs_[i] >> limb_bits;  // arithmetic shift: floor division
      limbs_[i] -= carry * (std::int64_t{1} << limb_bits);
      limbs_[i + 1] += carry;
    }
    pending_ = 0;
  }

  static constexpr std::uint32_t max_pending = 1u << 28;
  std::array<std::int64_t, limb_count> limbs_{};
  std::uint32_t pending_ = 0;
  bool out_of_range_ = false;
};

}  // namespace pear::detail
