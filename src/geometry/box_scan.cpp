#include "box_scan.hpp"

#include <algorithm>

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define PEAR_BOX_SCAN_X86 1
#include <immintrin.h>
#endif
#if defined(__wasm_simd128__)
#define PEAR_BOX_SCAN_WASM 1
#include <wasm_simd128.h>
#endif

namespace pear::detail {
namespace {

bool meets_one(const BoxColumns& c, std::uint32_t f, const Box& b) {
  const double x0 = c.x0[f], y0 = c.y0[f], x1 = c.x1[f], y1 = c.y1[f];
  return (x0 <= b.x1) & (b.x0 <= x1) & (y0 <= b.y1) & (b.y0 <= y1);
}

bool scalar_meets(const BoxColumns& c, std::uint32_t from, std::uint32_t to, const Box& b) {
  bool met = false;
  for (std::uint32_t f = from; f < to; ++f) met |= meets_one(c, f, b);
  return met;
}

#if PEAR_BOX_SCAN_X86
bool sse2_meets(const BoxColumns& c, std::uint32_t from, std::uint32_t to, const Box& b) {
  const __m128d x0 = _mm_set1_pd(b.x0), x1 = _mm_set1_pd(b.x1);
  const __m128d y0 = _mm_set1_pd(b.y0), y1 = _mm_set1_pd(b.y1);
  __m128d any = _mm_setzero_pd();
  std::uint32_t f = from;
  for (; f + 2 <= to; f += 2) {
    const __m128d in_x = _mm_and_pd(_mm_cmple_pd(_mm_loadu_pd(&c.x0[f]), x1),
                                    _mm_cmple_pd(x0, _mm_loadu_pd(&c.x1[f])));
    const __m128d in_y = _mm_and_pd(_mm_cmple_pd(_mm_loadu_pd(&c.y0[f]), y1),
                                    _mm_cmple_pd(y0, _mm_loadu_pd(&c.y1[f])));
    any = _mm_or_pd(any, _mm_and_pd(in_x, in_y));
  }
  const bool tail = scalar_meets(c, f, to, b);  // both ends computed: no branch between them
  return (_mm_movemask_pd(any) != 0) | tail;
}

/// Lanes whose box of columns [f, f + 4) meets the box of sides x0, x1, y0, y1 (broadcast).
__attribute__((target("avx2"))) inline __m256d avx2_step(const BoxColumns& c, std::uint32_t f,
                                                         __m256d x0, __m256d y0, __m256d x1,
                                                         __m256d y1) {
  const __m256d in_x = _mm256_and_pd(_mm256_cmp_pd(_mm256_loadu_pd(&c.x0[f]), x1, _CMP_LE_OQ),
                                     _mm256_cmp_pd(x0, _mm256_loadu_pd(&c.x1[f]), _CMP_LE_OQ));
  const __m256d in_y = _mm256_and_pd(_mm256_cmp_pd(_mm256_loadu_pd(&c.y0[f]), y1, _CMP_LE_OQ),
                                     _mm256_cmp_pd(y0, _mm256_loadu_pd(&c.y1[f]), _CMP_LE_OQ));
  return _mm256_and_pd(in_x, in_y);
}

/// Four boxes a step, the lanes past `to` masked off (the columns are padded, so the load stays
/// inside): no tail loop whose length changes from row to row.
__attribute__((target("avx2"))) bool avx2_meets(const BoxColumns& c, std::uint32_t from,
                                                std::uint32_t to, const Box& b) {
  const __m256d x0 = _mm256_set1_pd(b.x0), x1 = _mm256_set1_pd(b.x1);
  const __m256d y0 = _mm256_set1_pd(b.y0), y1 = _mm256_set1_pd(b.y1);
  const __m256i lane = _mm256_setr_epi64x(0, 1, 2, 3);
  __m256d any = _mm256_setzero_pd();
  for (std::uint32_t f = from; f < to; f += 4) {
    const __m256d valid = _mm256_castsi256_pd(_mm256_cmpgt_epi64(_mm256_set1_epi64x(to - f), lane));
    any = _mm256_or_pd(any, _mm256_and_pd(valid, avx2_step(c, f, x0, y0, x1, y1)));
  }
  return _mm256_movemask_pd(any) != 0;
}

#endif

/// The bits of [0, count), count <= 64.
[[maybe_unused]] std::uint64_t first_bits(std::uint32_t count) {
  return count == 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << count) - 1;
}

std::uint64_t scalar_in_box(const double* xs, const double* ys, std::uint32_t count, const Box& b) {
  std::uint64_t in = 0;
  for (std::uint32_t i = 0; i < count; ++i) {
    const double x = xs[i], y = ys[i];
    in |= static_cast<std::uint64_t>((x >= b.x0) & (x <= b.x1) & (y >= b.y0) & (y <= b.y1)) << i;
  }
  return in;
}

#if PEAR_BOX_SCAN_WASM
/// WebAssembly's 128-bit SIMD (-msimd128): two boxes a step, as SSE2 does.
bool wasm_meets(const BoxColumns& c, std::uint32_t from, std::uint32_t to, const Box& b) {
  const v128_t x0 = wasm_f64x2_splat(b.x0), x1 = wasm_f64x2_splat(b.x1);
  const v128_t y0 = wasm_f64x2_splat(b.y0), y1 = wasm_f64x2_splat(b.y1);
  v128_t any = wasm_f64x2_splat(0.0);
  std::uint32_t f = from;
  for (; f + 2 <= to; f += 2) {
    const v128_t in_x = wasm_v128_and(wasm_f64x2_le(wasm_v128_load(&c.x0[f]), x1),
                                      wasm_f64x2_le(x0, wasm_v128_load(&c.x1[f])));
    const v128_t in_y = wasm_v128_and(wasm_f64x2_le(wasm_v128_load(&c.y0[f]), y1),
                                      wasm_f64x2_le(y0, wasm_v128_load(&c.y1[f])));
    any = wasm_v128_or(any, wasm_v128_and(in_x, in_y));
  }
  const bool tail = scalar_meets(c, f, to, b);
  return wasm_v128_any_true(any) | tail;
}

/// Two points a step; the lanes past `count` read padding and are masked off.
std::uint64_t wasm_in_box(const double* xs, const double* ys, std::uint32_t count, const Box& b) {
  const v128_t x0 = wasm_f64x2_splat(b.x0), x1 = wasm_f64x2_splat(b.x1);
  const v128_t y0 = wasm_f64x2_splat(b.y0), y1 = wasm_f64x2_splat(b.y1);
  std::uint64_t in = 0;
  for (std::uint32_t i = 0; i < count; i += 2) {
    const v128_t x = wasm_v128_load(xs + i), y = wasm_v128_load(ys + i);
    const v128_t in_x = wasm_v128_and(wasm_f64x2_le(x0, x), wasm_f64x2_le(x, x1));
    const v128_t in_y = wasm_v128_and(wasm_f64x2_le(y0, y), wasm_f64x2_le(y, y1));
    in |= static_cast<std::uint64_t>(wasm_i64x2_bitmask(wasm_v128_and(in_x, in_y))) << i;
  }
  return in & first_bits(count);
}
#endif

#if PEAR_BOX_SCAN_X86
/// Whether `scan` asks for the best and the processor has AVX2 (asked once).
bool use_avx2(BoxScan scan) {
  static const bool has_avx2 = __builtin_cpu_supports("avx2");
  return scan == BoxScan::best && has_avx2;
}

/// Two points a step, four with AVX2; the lanes past `count` read padding and are masked off.
std::uint64_t sse2_in_box(const double* xs, const double* ys, std::uint32_t count, const Box& b) {
  const __m128d x0 = _mm_set1_pd(b.x0), x1 = _mm_set1_pd(b.x1);
  const __m128d y0 = _mm_set1_pd(b.y0), y1 = _mm_set1_pd(b.y1);
  std::uint64_t in = 0;
  for (std::uint32_t i = 0; i < count; i += 2) {
    const __m128d x = _mm_loadu_pd(xs + i), y = _mm_loadu_pd(ys + i);
    const __m128d in_x = _mm_and_pd(_mm_cmple_pd(x0, x), _mm_cmple_pd(x, x1));
    const __m128d in_y = _mm_and_pd(_mm_cmple_pd(y0, y), _mm_cmple_pd(y, y1));
    in |= static_cast<std::uint64_t>(_mm_movemask_pd(_mm_and_pd(in_x, in_y))) << i;
  }
  return in & first_bits(count);
}

__attribute__((target("avx2"))) std::uint64_t avx2_in_box(const double* xs, const double* ys,
                                                          std::uint32_t count, const Box& b) {
  const __m256d x0 = _mm256_set1_pd(b.x0), x1 = _mm256_set1_pd(b.x1);
  const __m256d y0 = _mm256_set1_pd(b.y0), y1 = _mm256_set1_pd(b.y1);
  std::uint64_t in = 0;
  for (std::uint32_t i = 0; i < count; i += 4) {
    const __m256d x = _mm256_loadu_pd(xs + i), y = _mm256_loadu_pd(ys + i);
    const __m256d in_x =
        _mm256_and_pd(_mm256_cmp_pd(x0, x, _CMP_LE_OQ), _mm256_cmp_pd(x, x1, _CMP_LE_OQ));
    const __m256d in_y =
        _mm256_and_pd(_mm256_cmp_pd(y0, y, _CMP_LE_OQ), _mm256_cmp_pd(y, y1, _CMP_LE_OQ));
    in |= static_cast<std::uint64_t>(_mm256_movemask_pd(_mm256_and_pd(in_x, in_y))) << i;
  }
  return in & first_bits(count);
}
#endif

/// Sets the bit of every row whose box meets a box of its ranges, by `scan`. Always inlined, so
/// that in avx2_rows the AVX2 scan is inlined too.
template <class Meets>
[[gnu::always_inline]] inline void rows_with(const BoxColumns& c, std::span<const RowRanges> rows,
                                             std::span<std::uint64_t> meets, Meets&& scan) {
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const RowRanges& r = rows[k];
    const Box b = c.box(r.row);
    // The second range is empty but for a ring's first edge (a polygon with holes).
    const bool first = scan(c, r.from, r.to, b);
    const bool second = r.from2 < r.to2 && scan(c, r.from2, r.to2, b);
    meets[k / 64] |= static_cast<std::uint64_t>(first | second) << (k % 64);
  }
}

#if PEAR_BOX_SCAN_X86
__attribute__((target("avx2"))) void avx2_rows(const BoxColumns& c, std::span<const RowRanges> rows,
                                               std::span<std::uint64_t> meets) {
  rows_with(c, rows, meets, avx2_meets);
}
#endif

}  // namespace

void rows_meeting(const BoxColumns& columns, std::span<const RowRanges> rows,
                  std::span<std::uint64_t> meets, [[maybe_unused]] BoxScan scan) {
  std::fill(meets.begin(), meets.end(), 0);
#if PEAR_BOX_SCAN_X86
  if (use_avx2(scan)) return avx2_rows(columns, rows, meets);
  if (scan != BoxScan::scalar) return rows_with(columns, rows, meets, sse2_meets);
#endif
#if PEAR_BOX_SCAN_WASM
  if (scan != BoxScan::scalar) return rows_with(columns, rows, meets, wasm_meets);
#endif
  rows_with(columns, rows, meets, scalar_meets);
}

PointsInBox points_in_box_function([[maybe_unused]] BoxScan scan) {
#if PEAR_BOX_SCAN_X86
  if (use_avx2(scan)) return avx2_in_box;
  if (scan != BoxScan::scalar) return sse2_in_box;
#endif
#if PEAR_BOX_SCAN_WASM
  if (scan != BoxScan::scalar) return wasm_in_box;
#endif
  return scalar_in_box;
}

std::uint64_t points_in_box(const double* xs, const double* ys, std::uint32_t count, const Box& box,
                            BoxScan scan) {
  return points_in_box_function(scan)(xs, ys, count, box);
}

}  // namespace pear::detail
