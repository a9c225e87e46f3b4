// Box tests over columns of coordinates for the small polygons' simplicity check: for each row
// (an edge's box), whether any box in its ranges meets it. Most rows meet nothing (2% of the
// counties' rows do), so the cost is the comparisons: four boxes a step with AVX2 where the
// processor has it (chosen at run time), two with SSE2 (x86-64's baseline), one elsewhere, all
// without a branch on the data. Intrinsics, not GCC's vector types, whose comparison masks
// GCC 12 takes apart lane by lane. The small clipper's ear test asks the same of points: which
// of up to 64 lie in the ear's box.
#pragma once

#include <array>
#include <cstdint>
#include <span>

namespace pear::detail {

/// An axis-parallel box, closed.
struct Box {
  double x0, y0, x1, y1;
};

/// Boxes as a column per side, padded so that a four-wide load past the last box stays inside.
struct BoxColumns {
  static constexpr std::uint32_t capacity = 128;
  std::array<double, capacity + 4> x0{}, y0{}, x1{}, y1{};
  Box box(std::uint32_t i) const { return {x0[i], y0[i], x1[i], y1[i]}; }
};

/// The boxes row `row` is tested against: [from, to) and [from2, to2) (empty ranges allowed).
struct RowRanges {
  std::uint32_t row, from, to, from2, to2;
};

/// Up to 64 points as a column per coordinate, padded so that a four-wide load stays inside.
struct PointColumns {
  static constexpr std::uint32_t capacity = 64;
  std::array<double, capacity + 4> x{}, y{};
};

/// Which instructions rows_meeting and points_in_box use: the best the processor has, or one
/// named (for tests).
enum class BoxScan : std::uint8_t { best, sse2, scalar };

/// Sets bit k of `meets` (rows.size() bits, in 64-bit words, cleared first) when the box of
/// rows[k].row meets any box in its ranges.
void rows_meeting(const BoxColumns& columns, std::span<const RowRanges> rows,
                  std::span<std::uint64_t> meets, BoxScan scan = BoxScan::best);

/// Bit i set when point i of [0, count) (count <= 64) lies in `box`, sides included.
std::uint64_t points_in_box(const PointColumns& points, std::uint32_t count, const Box& box,
                            BoxScan scan = BoxScan::best);

}  // namespace pear::detail
