// pear tests: an independent exact reference (GMP rationals) and input generators for the
// predicate tests.
#pragma once

#include <gmpxx.h>

#include <cmath>
#include <cstdint>
#include <random>

#include "pear/geometry.hpp"

namespace pear::test {

inline int sign_of(double v) {
  return (v > 0.0) - (v < 0.0);
}

// Every double is a dyadic rational, so mpq_class holds it exactly.
inline mpq_class exact(double v) {
  return mpq_class(v);
}

inline int exact_orient2d_sign(const Point& a, const Point& b, const Point& c) {
  const mpq_class acx = exact(a.x) - exact(c.x);
  const mpq_class acy = exact(a.y) - exact(c.y);
  const mpq_class bcx = exact(b.x) - exact(c.x);
  const mpq_class bcy = exact(b.y) - exact(c.y);
  return sgn(mpq_class(acx * bcy - acy * bcx));
}

inline int exact_incircle_sign(const Point& a, const Point& b, const Point& c, const Point& d) {
  const mpq_class adx = exact(a.x) - exact(d.x), ady = exact(a.y) - exact(d.y);
  const mpq_class bdx = exact(b.x) - exact(d.x), bdy = exact(b.y) - exact(d.y);
  const mpq_class cdx = exact(c.x) - exact(d.x), cdy = exact(c.y) - exact(d.y);
  const mpq_class det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                        (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                        (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
  return sgn(det);
}

// Whether a coordinate lies in the predicates' documented domain.
inline bool in_domain(double v) {
  const double m = std::fabs(v);
  return m == 0.0 || (m >= min_nonzero_coordinate && m <= max_coordinate);
}
inline bool in_domain(const Point& p) {
  return in_domain(p.x) && in_domain(p.y);
}

// v moved by `steps` ulps (toward +infinity when positive).
inline double ulps(double v, int steps) {
  const double toward = steps > 0 ? INFINITY : -INFINITY;
  for (int i = 0; i < std::abs(steps); ++i) v = std::nextafter(v, toward);
  return v;
}

// Deterministic across platforms: values built from raw 64-bit draws, not <random> distributions.
class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  // Uniform in [0, 1), on a 2^-53 grid.
  double unit() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }
  double uniform(double low, double high) { return low + (high - low) * unit(); }
  int integer(int low, int high) {  // inclusive
    return low + static_cast<int>(engine_() % static_cast<std::uint64_t>(high - low + 1));
  }
  bool coin() { return (engine_() >> 63) != 0; }
  // A random significand in [1, 2), random sign, times 2^exponent.
  double with_exponent(int exponent) {
    const double m = std::ldexp(1.0 + unit(), exponent);
    return coin() ? -m : m;
  }

 private:
  std::mt19937_64 engine_;
};

// An exact symmetry of the plane (reflections, axis swap) followed by an exact power-of-two
// scaling: it preserves collinearity and cocircularity, and the reference says what the sign is.
struct Transform {
  bool flip_x = false;
  bool flip_y = false;
  bool swap_axes = false;
  int exponent = 0;

  Point operator()(const Point& p) const {
    double x = flip_x ? -p.x : p.x;
    double y = flip_y ? -p.y : p.y;
    if (swap_axes) std::swap(x, y);
    return {std::ldexp(x, exponent), std::ldexp(y, exponent)};
  }
};

inline Transform random_transform(Random& random, int exponent) {
  return {random.coin(), random.coin(), random.coin(), exponent};
}

}  // namespace pear::test
