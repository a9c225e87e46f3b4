// pear: a long fixed-point accumulator (Kulisch): the exact sum of any doubles as one wide
// two's-complement integer whose bit 0 weighs 2^-1074, the smallest subnormal. Its sign is exact
// whatever the structure of the terms, so it reads the sign of expansions whose components may
// overlap.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace pear::detail {

class LongAccumulator {
 public:
  // Adds v exactly. An infinite or NaN term makes the sum undefined (value() is then NaN).
  void add(double v);
  void add(std::span<const double> terms) {
    for (double v : terms) add(v);
  }

  // -1, 0 or +1: the exact sign of the sum.
  int sign() const;

  // A double close to the sum with its exact sign (NaN after a non-finite term).
  double value() const;

 private:
  static constexpr int lowest_exponent = -1074;
  // 2304 bits: finite doubles reach bit 2098; the rest absorbs the carries of up to 2^200 terms.
  static constexpr std::size_t limb_count = 36;

  void add_at(std::size_t limb, std::uint64_t low, std::uint64_t high);
  void subtract_at(std::size_t limb, std::uint64_t low, std::uint64_t high);

  std::array<std::uint64_t, limb_count> limbs_{};
  bool finite_ = true;
};

}  // namespace pear::detail
