// pear: the out-of-line expansion routines (Shewchuk 1997, Theorems 13 and 19).
#include "expansion.hpp"

#include <cmath>

namespace pear::detail {

std::size_t expansion_sum(std::span<const double> e, std::span<const double> f, double* h) {
  // Merge e and f into one sequence g of increasing magnitude, then carry a running sum Q through
  // g with two-sums; the roundoff of each step is an output component.
  std::size_t i = 0;
  std::size_t j = 0;
  auto next = [&]() {
    if (j == f.size() || (i < e.size() && std::fabs(e[i]) < std::fabs(f[j]))) return e[i++];
    return f[j++];
  };
  const std::size_t total = e.size() + f.size();
  if (total == 0) return 0;
  double q = next();
  std::size_t count = 0;
  for (std::size_t k = 1; k < total; ++k) {
    double roundoff;
    two_sum(q, next(), q, roundoff);
    if (roundoff != 0.0) h[count++] = roundoff;
  }
  if (q != 0.0) h[count++] = q;
  return count;
}

std::size_t scale_expansion(std::span<const double> e, double b, double* h) {
  if (e.empty()) return 0;
  std::size_t count = 0;
  double q;
  double roundoff;
  two_product(e[0], b, q, roundoff);
  if (roundoff != 0.0) h[count++] = roundoff;
  for (std::size_t i = 1; i < e.size(); ++i) {
    double product_high;
    double product_low;
    two_product(e[i], b, product_high, product_low);
    double partial;
    two_sum(q, product_low, partial, roundoff);
    if (roundoff != 0.0) h[count++] = roundoff;
    // The paper proves |product_high| >= |partial| here, so Fast-Two-Sum would do; two_sum gives
    // the same result without relying on it.
    two_sum(product_high, partial, q, roundoff);
    if (roundoff != 0.0) h[count++] = roundoff;
  }
  if (q != 0.0) h[count++] = q;
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
