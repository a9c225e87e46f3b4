#include "decimal.hpp"

#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

namespace pear::detail {
namespace {

constexpr int significant = 17;

/// A natural number in base 1e9 limbs, least significant first.
struct Natural {
  std::vector<std::uint32_t> limbs;

  void multiply(std::uint32_t factor) {
    std::uint64_t carry = 0;
    for (std::uint32_t& limb : limbs) {
      const std::uint64_t product = std::uint64_t{limb} * factor + carry;
      limb = static_cast<std::uint32_t>(product % 1'000'000'000);
      carry = product / 1'000'000'000;
    }
    if (carry != 0) limbs.push_back(static_cast<std::uint32_t>(carry));
  }

  std::string digits() const {
    std::string text = std::to_string(limbs.back());
    for (std::size_t i = limbs.size() - 1; i-- > 0;) {
      const std::string group = std::to_string(limbs[i]);
      text += std::string(9 - group.size(), '0') + group;
    }
    return text;
  }
};

/// The exact decimal digits of |value| (finite, not zero) and the power of ten of the last one.
std::string exact_digits(double value, int& last_exponent) {
  const auto bits = std::bit_cast<std::uint64_t>(value);
  const int biased = static_cast<int>((bits >> 52) & 0x7ff);
  std::uint64_t mantissa = bits & ((std::uint64_t{1} << 52) - 1);
  if (biased != 0) mantissa |= std::uint64_t{1} << 52;
  int exponent = (biased != 0 ? biased : 1) - 1075;  // |value| = mantissa * 2^exponent
  Natural n{{static_cast<std::uint32_t>(mantissa % 1'000'000'000),
             static_cast<std::uint32_t>(mantissa / 1'000'000'000 % 1'000'000'000),
             static_cast<std::uint32_t>(mantissa / 1'000'000'000'000'000'000)}};
  while (n.limbs.size() > 1 && n.limbs.back() == 0) n.limbs.pop_back();
  // 2^-k = 5^k / 10^k: a negative power of two is a power of five and a shift of the point.
  last_exponent = exponent < 0 ? exponent : 0;
  for (; exponent > 0; --exponent) n.multiply(2);
  for (; exponent < 0; ++exponent) n.multiply(5);
  return n.digits();
}

/// Rounds `digits` to `significant` digits, ties to even; a carry out of the first digit
/// raises `exponent` (the power of ten of the first digit).
std::string rounded(const std::string& digits, int& exponent) {
  std::string kept = digits.substr(0, significant);
  if (digits.size() > significant) {
    const char next = digits[significant];
    const bool rest_zero = digits.find_first_not_of('0', significant + 1) == std::string::npos;
    const bool up = next > '5' || (next == '5' && (!rest_zero || (kept.back() - '0') % 2 == 1));
    std::size_t i = kept.size();
    for (; up && i > 0 && kept[i - 1] == '9'; --i) kept[i - 1] = '0';
    if (up && i == 0) {
      kept.insert(kept.begin(), '1');
      kept.pop_back();
      ++exponent;
    } else if (up) {
      ++kept[i - 1];
    }
  }
  kept.resize(significant, '0');
  return kept;
}

std::string without_trailing_zeros(std::string text) {
  if (text.find('.') == std::string::npos) return text;
  text.erase(text.find_last_not_of('0') + 1);
  if (text.back() == '.') text.pop_back();
  return text;
}

}  // namespace

std::string format_g17(double value) {
  if (value != value) return "nan";
  const std::string sign = std::signbit(value) ? "-" : "";
  if (value == 0) return sign + "0";
  if (value - value != 0) return sign + "inf";
  int last = 0;
  const std::string all = exact_digits(value, last);
  int exponent = static_cast<int>(all.size()) - 1 + last;
  const std::string digits = rounded(all, exponent);
  if (exponent < -4 || exponent >= significant) {
    const std::string power = std::to_string(exponent < 0 ? -exponent : exponent);
    return sign + without_trailing_zeros(digits.substr(0, 1) + "." + digits.substr(1)) + "e" +
           (exponent < 0 ? "-" : "+") + (power.size() < 2 ? "0" : "") + power;
  }
  if (exponent < 0)
    return sign + without_trailing_zeros("0." + std::string(-exponent - 1, '0') + digits);
  return sign +
         without_trailing_zeros(digits.substr(0, exponent + 1) + "." + digits.substr(exponent + 1));
}

}  // namespace pear::detail
