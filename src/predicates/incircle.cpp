// pear: exact incircle test, Shewchuk's adaptive scheme (1997, section 4.5): a floating-point
// filter (stage A), the exact determinant of the rounded differences (B), a first-order correction
// for the differences' roundoff (C), and, when even that cannot decide, the determinant of the
// exact differences computed entirely in expansion arithmetic (D).
#include <cmath>

#include "expansion.hpp"
#include "long_accumulator.hpp"
#include "pear/predicates.hpp"

namespace pear {
namespace {

using detail::epsilon;
using detail::Expansion;

// Error bound coefficients from the paper's analysis of this exact sequence of operations.
constexpr double icc_bound_a = (10.0 + 96.0 * epsilon) * epsilon;
constexpr double icc_bound_b = (4.0 + 48.0 * epsilon) * epsilon;
constexpr double icc_bound_c = (44.0 + 576.0 * epsilon) * epsilon * epsilon;
constexpr double result_bound = (3.0 + 8.0 * epsilon) * epsilon;

// The lifted row: (dx^2 + dy^2) * minor, exactly, for a single-double dx, dy.
Expansion<32> lifted_term(const Expansion<4>& minor, double dx, double dy) {
  return ((minor * dx) * dx) + ((minor * dy) * dy);
}

// Stage D: every difference as an exact two-component expansion, the determinant multiplied out.
double incircle_exact(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Expansion<2> adx = detail::exact_difference(a.x, d.x);
  const Expansion<2> ady = detail::exact_difference(a.y, d.y);
  const Expansion<2> bdx = detail::exact_difference(b.x, d.x);
  const Expansion<2> bdy = detail::exact_difference(b.y, d.y);
  const Expansion<2> cdx = detail::exact_difference(c.x, d.x);
  const Expansion<2> cdy = detail::exact_difference(c.y, d.y);
  auto minor = [](const Expansion<2>& px, const Expansion<2>& py, const Expansion<2>& qx,
                  const Expansion<2>& qy) { return px * qy + (-(qx * py)); };
  auto lift = [](const Expansion<2>& px, const Expansion<2>& py) { return px * px + py * py; };
  const Expansion<512> a_term = lift(adx, ady) * minor(bdx, bdy, cdx, cdy);
  const Expansion<512> b_term = lift(bdx, bdy) * minor(cdx, cdy, adx, ady);
  const Expansion<512> c_term = lift(cdx, cdy) * minor(adx, ady, bdx, bdy);
  // The products' values are exact but lift is not nonadjacent, so their components may overlap:
  // the accumulator reads the sign without relying on their structure.
  detail::LongAccumulator sum;
  sum.add(a_term.view());
  sum.add(b_term.view());
  sum.add(c_term.view());
  return sum.value();
}

// Stages B to D, reached only when the filter cannot decide (near-cocircular input).
[[gnu::noinline]] double incircle_adaptive(const Point& a, const Point& b, const Point& c,
                                           const Point& d, double permanent) {
  const double adx = a.x - d.x;
  const double bdx = b.x - d.x;
  const double cdx = c.x - d.x;
  const double ady = a.y - d.y;
  const double bdy = b.y - d.y;
  const double cdy = c.y - d.y;

  // Stage B: the rounded differences multiplied out exactly.
  const Expansion<4> bc = detail::exact_cross(bdx, cdy, cdx, bdy);
  const Expansion<4> ca = detail::exact_cross(cdx, ady, adx, cdy);
  const Expansion<4> ab = detail::exact_cross(adx, bdy, bdx, ady);
  const Expansion<96> head =
      (lifted_term(bc, adx, ady) + lifted_term(ca, bdx, bdy)) + lifted_term(ab, cdx, cdy);
  double det = detail::expansion_estimate(head.view());
  double bound = icc_bound_b * permanent;
  if (det >= bound || -det >= bound) return det;

  const double adx_tail = detail::two_diff_tail(a.x, d.x, adx);
  const double ady_tail = detail::two_diff_tail(a.y, d.y, ady);
  const double bdx_tail = detail::two_diff_tail(b.x, d.x, bdx);
  const double bdy_tail = detail::two_diff_tail(b.y, d.y, bdy);
  const double cdx_tail = detail::two_diff_tail(c.x, d.x, cdx);
  const double cdy_tail = detail::two_diff_tail(c.y, d.y, cdy);
  if (adx_tail == 0.0 && bdx_tail == 0.0 && cdx_tail == 0.0 && ady_tail == 0.0 && bdy_tail == 0.0 &&
      cdy_tail == 0.0) {
    return detail::expansion_value(head.view());  // the differences were exact, so B is too
  }

  // Stage C: add the terms linear in the tails (the derivative of each lifted row), in floating
  // point.
  bound = icc_bound_c * permanent + result_bound * std::fabs(det);
  det += ((adx * adx + ady * ady) *
              ((bdx * cdy_tail + cdy * bdx_tail) - (bdy * cdx_tail + cdx * bdy_tail)) +
          2.0 * (adx * adx_tail + ady * ady_tail) * (bdx * cdy - bdy * cdx)) +
         ((bdx * bdx + bdy * bdy) *
              ((cdx * ady_tail + ady * cdx_tail) - (cdy * adx_tail + adx * cdy_tail)) +
          2.0 * (bdx * bdx_tail + bdy * bdy_tail) * (cdx * ady - cdy * adx)) +
         ((cdx * cdx + cdy * cdy) *
              ((adx * bdy_tail + bdy * adx_tail) - (ady * bdx_tail + bdx * ady_tail)) +
          2.0 * (cdx * cdx_tail + cdy * cdy_tail) * (adx * bdy - ady * bdx));
  if (det >= bound || -det >= bound) return det;

  return incircle_exact(a, b, c, d);
}

}  // namespace

double incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
  // Stage A: the plain 3x3 determinant of the differences, trusted when it exceeds its proven
  // rounding error (a multiple of the permanent, the same sum with every term made positive).
  const double adx = a.x - d.x;
  const double bdx = b.x - d.x;
  const double cdx = c.x - d.x;
  const double ady = a.y - d.y;
  const double bdy = b.y - d.y;
  const double cdy = c.y - d.y;

  const double bdx_cdy = bdx * cdy;
  const double cdx_bdy = cdx * bdy;
  const double a_lift = adx * adx + ady * ady;
  const double cdx_ady = cdx * ady;
  const double adx_cdy = adx * cdy;
  const double b_lift = bdx * bdx + bdy * bdy;
  const double adx_bdy = adx * bdy;
  const double bdx_ady = bdx * ady;
  const double c_lift = cdx * cdx + cdy * cdy;

  const double det =
      a_lift * (bdx_cdy - cdx_bdy) + b_lift * (cdx_ady - adx_cdy) + c_lift * (adx_bdy - bdx_ady);
  const double permanent = (std::fabs(bdx_cdy) + std::fabs(cdx_bdy)) * a_lift +
                           (std::fabs(cdx_ady) + std::fabs(adx_cdy)) * b_lift +
                           (std::fabs(adx_bdy) + std::fabs(bdx_ady)) * c_lift;
  const double bound = icc_bound_a * permanent;
  if (det > bound || -det > bound) return det;
  return incircle_adaptive(a, b, c, d, permanent);
}

}  // namespace pear
