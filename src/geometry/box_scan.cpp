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

/// A row's own box, from the float columns.
struct FloatBox {
  float x0, y0, x1, y1;
};

FloatBox row_box(const BoxColumns& c, std::uint32_t i) {
  return {c.x0[i], c.y0[i], c.x1[i], c.y1[i]};
}

bool scalar_meets(const BoxColumns& c, std::uint32_t from, std::uint32_t to, const FloatBox& b) {
  bool met = false;
  for (std::uint32_t f = from; f < to; ++f)
    met |= (c.x0[f] <= b.x1) & (b.x0 <= c.x1[f]) & (c.y0[f] <= b.y1) & (b.y0 <= c.y1[f]);
  return met;
}

#if PEAR_BOX_SCAN_X86
/// Four boxes a step, the lanes past `to` masked off (the columns are padded, so the load stays
/// inside): no tail loop whose length changes from row to row.
bool sse2_meets(const BoxColumns& c, std::uint32_t from, std::uint32_t to, const FloatBox& b) {
  const __m128 x0 = _mm_set1_ps(b.x0), x1 = _mm_set1_ps(b.x1);
  const __m128 y0 = _mm_set1_ps(b.y0), y1 = _mm_set1_ps(b.y1);
  const __m128i lane = _mm_setr_epi32(0, 1, 2, 3);
  __m128 any = _mm_setzero_ps();
  for (std::uint32_t f = from; f < to; f += 4) {
    const __m128 valid =
        _mm_castsi128_ps(_mm_cmpgt_epi32(_mm_set1_epi32(static_cast<int>(to - f)), lane));
    const __m128 in_x = _mm_and_ps(_mm_cmple_ps(_mm_loadu_ps(&c.x0[f]), x1),
                                   _mm_cmple_ps(x0, _mm_loadu_ps(&c.x1[f])));
    const __m128 in_y = _mm_and_ps(_mm_cmple_ps(_mm_loadu_ps(&c.y0[f]), y1),
                                   _mm_cmple_ps(y0, _mm_loadu_ps(&c.y1[f])));
    any = _mm_or_ps(any, _mm_and_ps(valid, _mm_and_ps(in_x, in_y)));
  }
  return _mm_movemask_ps(any) != 0;
}

/// Eight boxes a step, masked as sse2_meets.
__attribute__((target("avx2"))) bool avx2_meets(const BoxColumns& c, std::uint32_t from,
                                                std::uint32_t to, const FloatBox& b) {
  const __m256 x0 = _mm256_set1_ps(b.x0), x1 = _mm256_set1_ps(b.x1);
  const __m256 y0 = _mm256_set1_ps(b.y0), y1 = _mm256_set1_ps(b.y1);
  const __m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
  __m256 any = _mm256_setzero_ps();
  for (std::uint32_t f = from; f < to; f += 8) {
    const __m256 valid =
        _mm256_castsi256_ps(_mm256_cmpgt_epi32(_mm256_set1_epi32(static_cast<int>(to - f)), lane));
    const __m256 in_x = _mm256_and_ps(_mm256_cmp_ps(_mm256_loadu_ps(&c.x0[f]), x1, _CMP_LE_OQ),
                                      _mm256_cmp_ps(x0, _mm256_loadu_ps(&c.x1[f]), _CMP_LE_OQ));
    const __m256 in_y = _mm256_and_ps(_mm256_cmp_ps(_mm256_loadu_ps(&c.y0[f]), y1, _CMP_LE_OQ),
                                      _mm256_cmp_ps(y0, _mm256_loadu_ps(&c.y1[f]), _CMP_LE_OQ));
    any = _mm256_or_ps(any, _mm256_and_ps(valid, _mm256_and_ps(in_x, in_y)));
  }
  return _mm256_movemask_ps(any) != 0;
}
#endif

#if PEAR_BOX_SCAN_WASM
/// WebAssembly's 128-bit SIMD (-msimd128): four boxes a step, masked as sse2_meets.
bool wasm_meets(const BoxColumns& c, std::uint32_t from, std::uint32_t to, const FloatBox& b) {
  const v128_t x0 = wasm_f32x4_splat(b.x0), x1 = wasm_f32x4_splat(b.x1);
  const v128_t y0 = wasm_f32x4_splat(b.y0), y1 = wasm_f32x4_splat(b.y1);
  const v128_t lane = wasm_i32x4_make(0, 1, 2, 3);
  v128_t any = wasm_i32x4_splat(0);
  for (std::uint32_t f = from; f < to; f += 4) {
    const v128_t valid = wasm_i32x4_gt(wasm_i32x4_splat(static_cast<int>(to - f)), lane);
    const v128_t in_x = wasm_v128_and(wasm_f32x4_le(wasm_v128_load(&c.x0[f]), x1),
                                      wasm_f32x4_le(x0, wasm_v128_load(&c.x1[f])));
    const v128_t in_y = wasm_v128_and(wasm_f32x4_le(wasm_v128_load(&c.y0[f]), y1),
                                      wasm_f32x4_le(y0, wasm_v128_load(&c.y1[f])));
    any = wasm_v128_or(any, wasm_v128_and(valid, wasm_v128_and(in_x, in_y)));
  }
  return wasm_v128_any_true(any);
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
    const FloatBox b = row_box(c, r.row);
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
