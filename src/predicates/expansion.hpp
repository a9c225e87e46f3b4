// pear: exact floating-point expansion arithmetic (Shewchuk 1997, "Adaptive Precision
// Floating-Point Arithmetic and Fast Robust Geometric Predicates", sections 2.3-2.8).
//
// An expansion is a sum of doubles, stored in increasing order of magnitude, whose components do
// not overlap: its value is exact. All routines assume IEEE 754 binary64 with round-to-nearest-even
// and no fused multiply-add (the build passes -ffp-contract=off), and no overflow or underflow,
// which the coordinate domain of pear guarantees (see docs/predicates.md).
#pragma once

#include <array>
#include <cstddef>
#include <span>

namespace pear::detail {

// Half an ulp of 1: the relative rounding error of one operation (the paper's epsilon).
inline constexpr double epsilon = 0x1p-53;
// 2^27 + 1: Veltkamp splitting of a 53-bit significand into two 26-bit halves (paper §2.5).
inline constexpr double splitter = 0x1p27 + 1.0;

// a + b = sum + error exactly (paper Theorem 7, Knuth's branch-free two-sum).
inline void two_sum(double a, double b, double& sum, double& error) {
  sum = a + b;
  const double b_virtual = sum - a;
  const double a_virtual = sum - b_virtual;
  const double b_roundoff = b - b_virtual;
  const double a_roundoff = a - a_virtual;
  error = a_roundoff + b_roundoff;
}

// a - b = difference + error exactly.
inline void two_diff(double a, double b, double& difference, double& error) {
  difference = a - b;
  const double b_virtual = a - difference;
  const double a_virtual = difference + b_virtual;
  const double b_roundoff = b_virtual - b;
  const double a_roundoff = a - a_virtual;
  error = a_roundoff + b_roundoff;
}

// The rounding error of a - b, given difference = fl(a - b).
inline double two_diff_tail(double a, double b, double difference) {
  const double b_virtual = a - difference;
  const double a_virtual = difference + b_virtual;
  const double b_roundoff = b_virtual - b;
  const double a_roundoff = a - a_virtual;
  return a_roundoff + b_roundoff;
}

// a = high + low, each half fitting in 26 bits, so products of halves are exact (Theorem 17).
inline void split(double a, double& high, double& low) {
  const double c = splitter * a;
  const double a_big = c - a;
  high = c - a_big;
  low = a - high;
}

// a * b = product + error exactly, without FMA (Dekker's product, paper Theorem 18).
inline void two_product(double a, double b, double& product, double& error) {
  product = a * b;
  double a_high, a_low, b_high, b_low;
  split(a, a_high, a_low);
  split(b, b_high, b_low);
  const double error1 = product - a_high * b_high;
  const double error2 = error1 - a_low * b_high;
  const double error3 = error2 - a_high * b_low;
  error = a_low * b_low - error3;
}

// A fixed-capacity expansion; `size` components are valid, smallest magnitude first.
template <std::size_t Capacity>
struct Expansion {
  std::array<double, Capacity> term;
  std::size_t size = 0;

  std::span<const double> view() const { return {term.data(), size}; }
};

// h = e + f, zero components removed (paper Theorem 13, fast expansion sum: merge by magnitude,
// then one sweep of two-sums). h must have room for e.size() + f.size() components; it may not
// alias e or f. Returns the number of components written. The value is exact for any inputs; the
// result is strongly nonoverlapping when e and f are (nonadjacent ones are), as the theorem needs.
std::size_t expansion_sum(std::span<const double> e, std::span<const double> f, double* h);

// h = e * b, zero components removed (paper Theorem 19). h needs room for 2 * e.size(). The value
// is exact for any e; h is nonoverlapping if e is, and nonadjacent if e is.
std::size_t scale_expansion(std::span<const double> e, double b, double* h);

// The exact sign of an expansion: that of its most significant nonzero component.
int expansion_sign(std::span<const double> e);

// The paper's Estimate: the components summed in increasing order. Its error is what the adaptive
// stages' error bounds account for; its sign may be wrong in rare cases.
double expansion_estimate(std::span<const double> e);

// A double with the exact sign of e and close to its value: the estimate, or the leading
// component should rounding in the estimate have lost the sign. For returning exact results.
double expansion_value(std::span<const double> e);

template <std::size_t N, std::size_t M>
Expansion<N + M> operator+(const Expansion<N>& e, const Expansion<M>& f) {
  Expansion<N + M> h;
  h.size = expansion_sum(e.view(), f.view(), h.term.data());
  return h;
}

template <std::size_t N>
Expansion<2 * N> operator*(const Expansion<N>& e, double b) {
  Expansion<2 * N> h;
  h.size = scale_expansion(e.view(), b, h.term.data());
  return h;
}

template <std::size_t N>
Expansion<N> operator-(const Expansion<N>& e) {
  Expansion<N> h = e;
  for (std::size_t i = 0; i < h.size; ++i) h.term[i] = -h.term[i];
  return h;
}

// The exact product of two expansions: the sum over f's components of e scaled by each. The value
// is exact; the components are well formed only if e is nonadjacent, so read the sign of a product
// of general expansions with LongAccumulator, not expansion_sign.
template <std::size_t N, std::size_t M>
Expansion<2 * N * M> operator*(const Expansion<N>& e, const Expansion<M>& f) {
  std::array<Expansion<2 * N * M>, 2> sums;  // ping-pong: the running sum moves between the two
  sums[0].size = 0;
  std::size_t current = 0;
  Expansion<2 * N> scaled;
  for (std::size_t j = 0; j < f.size; ++j) {
    scaled.size = scale_expansion(e.view(), f.term[j], scaled.term.data());
    Expansion<2 * N* M>& next = sums[1 - current];
    next.size = expansion_sum(sums[current].view(), scaled.view(), next.term.data());
    current = 1 - current;
  }
  return sums[current];
}

// The exact a * b as a two-component expansion.
inline Expansion<2> exact_product(double a, double b) {
  Expansion<2> h;
  two_product(a, b, h.term[1], h.term[0]);
  h.size = 2;
  return h;
}

// The exact a - b as a two-component expansion.
inline Expansion<2> exact_difference(double a, double b) {
  Expansion<2> h;
  two_diff(a, b, h.term[1], h.term[0]);
  h.size = 2;
  return h;
}

// e + b, zeros removed (paper Theorem 10, Grow-Expansion): carry b up through e with two-sums.
// Unlike expansion_sum it keeps a nonadjacent expansion nonadjacent.
template <std::size_t N>
Expansion<N + 1> operator+(const Expansion<N>& e, double b) {
  Expansion<N + 1> h;
  double q = b;
  for (std::size_t i = 0; i < e.size; ++i) {
    double roundoff;
    two_sum(q, e.term[i], q, roundoff);
    if (roundoff != 0.0) h.term[h.size++] = roundoff;
  }
  if (q != 0.0) h.term[h.size++] = q;
  return h;
}

// The exact a*b - c*d (the paper's Two-Two-Diff), zeros removed. Built by growing, so the result is
// nonadjacent: scaling it (Theorem 19) stays nonadjacent, which expansion_sum requires.
inline Expansion<4> exact_cross(double a, double b, double c, double d) {
  double right_high;
  double right_low;
  two_product(c, d, right_high, right_low);
  return (exact_product(a, b) + (-right_low)) + (-right_high);
}

}  // namespace pear::detail
