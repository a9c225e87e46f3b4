// pear: exact geometric predicates (Shewchuk's adaptive-precision scheme, written here from his
// paper "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates", 1997).
#pragma once

#include "pear/geometry.hpp"

namespace pear {

/// Twice the signed area of triangle (a, b, c), with the sign exactly right: positive if a, b, c
/// are in counterclockwise order, negative if clockwise, zero if collinear.
/// Exact for all inputs whose coordinates are zero or between 2^-200 and 2^200 in magnitude.
double orient2d(const Point& a, const Point& b, const Point& c);

/// For a, b, c in counterclockwise order: positive if d lies inside their circumcircle, negative
/// if outside, zero if on it. The sign is exact on the same domain as orient2d.
double incircle(const Point& a, const Point& b, const Point& c, const Point& d);

/// The plain floating-point orientation determinant, no guarantee on its sign. For quick
/// rejections where an error is harmless; never for decisions.
inline double orient2d_inexact(const Point& a, const Point& b, const Point& c) {
  return (a.x - c.x) * (b.y - c.y) - (a.y - c.y) * (b.x - c.x);
}

}  // namespace pear
