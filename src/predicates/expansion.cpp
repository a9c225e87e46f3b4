// pear: the out-of-line expansion routines (Shewchuk 1997, Theorems 13 and 19).
#include "expansion.hpp"

#include <cmath>

namespace pear::detail {

namespace {

// Appends v unless it is zero, without a branch: zeros are rare and unpredictable, and a
// mispredicted branch costs more than the store. The store happens either way, so each call must
// have a slot of its own in h.
inline void append_nonzero(double v, double* h, std::size_t& count) {
  h[count] = v;
  count += static_cast<std::size_t>(v != 0.0);
}

}  // namespace

std::size_t expansion_sum(std::span<const double> e, std::span<const double> f, double* h) {
  // Merge e and f into one sequence of increasing magnitude, carrying a running sum q through it
  // with two-sums; the roundoff of each step is an output component, so at most e.size() +
  // f.size() are written whatever the values (NaN included). Which input holds the next smaller
  // component is a coin toss, so the merge selects by indexing instead of branching.
  std::size_t i = 0;
  std::size_t j = 0;
  auto take_smaller = [&]() {
    const double candidates[2] = {f[j], e[i]};
    const bool take_e = std::fabs(e[i]) < std::fabs(f[j]);
    i += static_cast<std::size_t>(take_e);
    j += static_cast<std::size_t>(!take_e);
    return candidates[take_e];
  };
  if (e.empty() && f.empty()) return 0;
  double q = e.empty() ? f[j++] : f.empty() ? e[i++] : take_smaller();
  std::size_t count = 0;
  double roundoff;
  while (i < e.size() && j < f.size()) {
    two_sum(q, take_smaller(), q, roundoff);
    append_nonzero(roundoff, h, count);
  }
  for (; i < e.size(); ++i) {
    two_sum(q, e[i], q, roundoff);
    append_nonzero(roundoff, h, count);
  }
  for (; j < f.size(); ++j) {
    two_sum(q, f[j], q, roundoff);
    append_nonzero(roundoff, h, count);
  }
  append_nonzero(q, h, count);
  return count;
}

std::size_t scale_expansion(std::span<const double> e, double b, double* h) {
  if (e.empty()) return 0;
  double b_high;
  double b_low;
  split(b, b_high, b_low);  // once, not in every product
  std::size_t count = 0;
  double q;
  double roundoff;
  two_product_presplit(e[0], b, b_high, b_low, q, roundoff);
  append_nonzero(roundoff, h, count);
  for (std::size_t i = 1; i < e.size(); ++i) {
    double product_high;
    double product_low;
    two_product_presplit(e[i], b, b_high, b_low, product_high, product_low);
    double partial;
    two_sum(q, product_low, partial, roundoff);
    append_nonzero(roundoff, h, count);
    // The paper proves |product_high| >= |partial| here, so Fast-Two-Sum would do; two_sum gives
    // the same result without relying on it.
    two_sum(product_high, partial, q, roundoff);
    append_nonzero(roundoff, h, count);
  }
  append_nonzero(q, h, count);
  return count;
}

int expansion_sign(std::span<const double> e) {
  for (std::size_t k = e.size(); k-- > 0;) {
    if (e[k] > 0.0) return 1;
    if (e[k] < 0.0) return -1;
  }
  return 0;
}

double expansion_estimate(std::span<const double> e) {
  double sum = 0.0;
  for (double component : e) sum += component;
  return sum;
}

double expansion_value(std::span<const double> e) {
  const double sum = expansion_estimate(e);
  if (std::isnan(sum)) return sum;  // a NaN input stays visible
  const int sign = expansion_sign(e);
  if ((sum > 0.0 ? 1 : sum < 0.0 ? -1 : 0) == sign) return sum;
  for (std::size_t k = e.size(); k-- > 0;) {
    if (e[k] != 0.0) return e[k];
  }
  return 0.0;
}

}  // namespace pear::detail
