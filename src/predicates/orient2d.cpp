// pear: exact orientation test, Shewchuk's adaptive scheme (1997, section 4.3): a floating-point
// filter (stage A), then the exact determinant of the rounded differences (B), a first-order
// correction for the differences' roundoff (C), and finally the exact determinant (D). Each stage
// returns as soon as its error bound proves the sign.
#include <cmath>

#include "expansion.hpp"
#include "pear/predicates.hpp"

namespace pear {
namespace {

using detail::epsilon;
using detail::Expansion;

// Error bound coefficients from the paper's analysis of this exact sequence of operations.
static_assert(detail::orient2d_filter_bound == (3.0 + 16.0 * epsilon) * epsilon);
constexpr double ccw_bound_b = (2.0 + 12.0 * epsilon) * epsilon;
constexpr double ccw_bound_c = (9.0 + 64.0 * epsilon) * epsilon * epsilon;
constexpr double result_bound = (3.0 + 8.0 * epsilon) * epsilon;

}  // namespace

// Stages B to D, reached only when the filter cannot decide (near-collinear input).
double orient2d_adaptive(const Point& a, const Point& b, const Point& c, double det_sum) {
  const double acx = a.x - c.x;
  const double bcx = b.x - c.x;
  const double acy = a.y - c.y;
  const double bcy = b.y - c.y;

  // Stage B: the rounded differences multiplied out exactly.
  const Expansion<4> head = detail::exact_cross(acx, bcy, acy, bcx);
  double det = detail::expansion_estimate(head.view());
  double bound = ccw_bound_b * det_sum;
  if (det >= bound || -det >= bound) return det;

  const double acx_tail = detail::two_diff_tail(a.x, c.x, acx);
  const double bcx_tail = detail::two_diff_tail(b.x, c.x, bcx);
  const double acy_tail = detail::two_diff_tail(a.y, c.y, acy);
  const double bcy_tail = detail::two_diff_tail(b.y, c.y, bcy);
  if (acx_tail == 0.0 && acy_tail == 0.0 && bcx_tail == 0.0 && bcy_tail == 0.0) {
    return detail::expansion_value(head.view());  // the differences were exact, so B is too
  }

  // Stage C: add the terms linear in the tails, in floating point.
  bound = ccw_bound_c * det_sum + result_bound * std::fabs(det);
  det += (acx * bcy_tail + bcy * acx_tail) - (acy * bcx_tail + bcx * acy_tail);
  if (det >= bound || -det >= bound) return det;

  // Stage D: (acx + acx_tail)(bcy + bcy_tail) - (acy + acy_tail)(bcx + bcx_tail), all exact.
  const Expansion<4> tail_head = detail::exact_cross(acx_tail, bcy, acy_tail, bcx);
  const Expansion<4> head_tail = detail::exact_cross(acx, bcy_tail, acy, bcx_tail);
  const Expansion<4> tail_tail = detail::exact_cross(acx_tail, bcy_tail, acy_tail, bcx_tail);
  const Expansion<16> exact = ((head + tail_head) + head_tail) + tail_tail;
  return detail::expansion_value(exact.view());
}

}  // namespace pear
