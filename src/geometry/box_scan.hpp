// Box tests over columns of coordinates: for each row (a box), whether any box in its ranges
// meets it (the simplicity check of few edges), and which of up to 64 points lie in a box (the
// bit-set clipper's ear test). Most rows meet nothing (2% of the counties' rows do), so the cost
// is the comparisons, all without a branch on the data: the rows in floats (a filter that never
// misses: rounding is monotone, so doubles a <= b give floats a <= b, and boxes that meet in
// doubles meet in floats), eight boxes a step with AVX2 where the processor has it (chosen at
// run time), four with SSE2 (x86-64's baseline) or WebAssembly's SIMD128 (-msimd128), one
// elsewhere; the points in doubles, four or two a step.
// Intrinsics, not GCC's vector types, whose comparison masks GCC 12 takes apart lane by lane.
// The columns are the caller's, sized for its own limits; they must be readable up to a
// multiple of eight entries (rows) or four (points): the lanes past the end are loaded and
// masked off.
#pragma once

#include <array>
#include <cstdint>
#include <span>

namespace pear::detail {

/// An axis-parallel box, closed.
struct Box {
  double x0, y0, x1, y1;
  /// Whether (x, y) lies in the box, sides included. One branch for the caller: which side a
  /// point misses by is a coin toss for the predictor, that it misses is not.
  bool contains(double x, double y) const { return (x >= x0) & (x <= x1) & (y >= y0) & (y <= y1); }
};

/// Boxes as a column per side in floats, each side a double rounded (to nearest, or any
/// monotone rounding: rows_meeting then finds every row whose boxes meet in doubles, and maybe
/// a few more); the caller's arrays, padded by at least seven entries.
struct BoxColumns {
  const float *x0, *y0, *x1, *y1;
};

/// The boxes row `row` is tested against: [from, to) and [from2, to2) (empty ranges allowed).
struct RowRanges {
  std::uint32_t row, from, to, from2, to2;
};

/// Which instructions rows_meeting and points_in_box use: the best the processor has, or one
/// named (for tests).
enum class BoxScan : std::uint8_t { best, sse2, scalar };

/// Sets bit k of `meets` (rows.size() bits, in 64-bit words, cleared first) when the box of
/// rows[k].row meets any box in its ranges (closed boxes, compared as floats).
void rows_meeting(const BoxColumns& columns, std::span<const RowRanges> rows,
                  std::span<std::uint64_t> meets, BoxScan scan = BoxScan::best);

/// Bit i set when point (xs[i], ys[i]) of i in [0, count) (count <= 64) lies in `box`, sides
/// included. xs and ys hold at least count rounded up to a multiple of four values.
std::uint64_t points_in_box(const double* xs, const double* ys, std::uint32_t count, const Box& box,
                            BoxScan scan = BoxScan::best);

/// points_in_box for one instruction set, chosen once: a caller that asks many times (an ear
/// test per step) calls it directly instead of choosing again each time.
using PointsInBox = std::uint64_t (*)(const double* xs, const double* ys, std::uint32_t count,
                                      const Box& box);
PointsInBox points_in_box_function(BoxScan scan = BoxScan::best);

}  // namespace pear::detail
