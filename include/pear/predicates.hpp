// pear: exact geometric predicates (Shewchuk's adaptive-precision scheme, written here from his
// paper "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates", 1997).
#pragma once

#include <cmath>

#include "pear/export.hpp"
#include "pear/geometry.hpp"

namespace pear {

namespace detail {
/// Stage A's error bound, (3 + 16e)e with e = 2^-53 (Shewchuk 1997, section 4.3).
inline constexpr double orient2d_filter_bound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;
}  // namespace detail

/// orient2d's stages B to D, for the near-collinear inputs its inline filter cannot decide:
/// the exact sign of the determinant of a, b, c, given det_sum = |(a.x - c.x)(b.y - c.y)| +
/// |(a.y - c.y)(b.x - c.x)|. Call orient2d; this is its out-of-line part.
PEAR_API double orient2d_adaptive(const Point& a, const Point& b, const Point& c, double det_sum);

/// Twice the signed area of triangle (a, b, c), with the sign exactly right: positive if a, b, c
/// are in counterclockwise order, negative if clockwise, zero if collinear.
/// Exact for all inputs whose coordinates are zero or between 2^-200 and 2^200 in magnitude.
/// The floating-point filter is inline, so the easy case costs about a plain determinant.
inline double orient2d(const Point& a, const Point& b, const Point& c) {
  const double det_left = (a.x - c.x) * (b.y - c.y);
  const double det_right = (a.y - c.y) * (b.x - c.x);
  const double det = det_left - det_right;
  // One bound test covers the paper's early return for products of opposite sign as well.
  // std::fabs, not a comparison: signs are coin tosses for the branch predictor.
  const double det_sum = std::fabs(det_left) + std::fabs(det_right);
  if (std::fabs(det) >= detail::orient2d_filter_bound * det_sum) return det;
  return orient2d_adaptive(a, b, c, det_sum);
}

/// For a, b, c in counterclockwise order: positive if d lies inside their circumcircle, negative
/// if outside, zero if on it. The sign is exact on the same domain as orient2d.
PEAR_API double incircle(const Point& a, const Point& b, const Point& c, const Point& d);

/// The plain floating-point orientation determinant, no guarantee on its sign. For quick
/// rejections where an error is harmless; never for decisions.
inline double orient2d_inexact(const Point& a, const Point& b, const Point& c) {
  return (a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x);
}

}  // namespace pear
