// Box tests over columns of coordinates, two at a time with SSE2 (x86-64's baseline; other
// targets take the scalar loop), for the small polygons' simplicity check: whether any of a run
// of boxes meets a box, without a branch on the data. Intrinsics, not GCC's vector types, whose
// comparison masks GCC 12 takes apart lane by lane.
#pragma once

#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace pear::detail {

/// An axis-parallel box, closed.
struct Box {
  double x0, y0, x1, y1;
};

/// Whether any of the boxes [first, end) meets `box`; boxes as columns of their sides.
inline bool any_box_meets(const double* x0, const double* y0, const double* x1, const double* y1,
                          std::uint32_t first, std::uint32_t end, const Box& box) {
  std::uint32_t f = first;
  bool met = false;
#if defined(__SSE2__)
  const __m128d bx0 = _mm_set1_pd(box.x0), bx1 = _mm_set1_pd(box.x1);
  const __m128d by0 = _mm_set1_pd(box.y0), by1 = _mm_set1_pd(box.y1);
  __m128d any = _mm_setzero_pd();
  for (; f + 2 <= end; f += 2) {
    const __m128d in_x = _mm_and_pd(_mm_cmple_pd(_mm_loadu_pd(x0 + f), bx1),
                                    _mm_cmple_pd(bx0, _mm_loadu_pd(x1 + f)));
    const __m128d in_y = _mm_and_pd(_mm_cmple_pd(_mm_loadu_pd(y0 + f), by1),
                                    _mm_cmple_pd(by0, _mm_loadu_pd(y1 + f)));
    any = _mm_or_pd(any, _mm_and_pd(in_x, in_y));
  }
  met = _mm_movemask_pd(any) != 0;
#endif
  for (; f < end; ++f)
    met |= (x0[f] <= box.x1) & (box.x0 <= x1[f]) & (y0[f] <= box.y1) & (box.y0 <= y1[f]);
  return met;
}

}  // namespace pear::detail
