// A sort for code off the per-polygon path, small where code size is what it costs.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <functional>
#include <iterator>
#include <utility>

namespace pear::detail {

/// Heap sort's step: moves first[i] down the max-heap first[0, n).
template <class It, class Less>
void sift_down(It first, std::ptrdiff_t n, std::ptrdiff_t i, Less& less) {
  auto value = std::move(first[i]);
  for (std::ptrdiff_t child = 2 * i + 1; child < n; i = child, child = 2 * i + 1) {
    if (child + 1 < n && less(first[child], first[child + 1])) ++child;
    if (!less(value, first[child])) break;
    first[i] = std::move(first[child]);
  }
  first[i] = std::move(value);
}

/// Heap sort: compact_sort's way out of a quicksort that keeps splitting badly.
template <class It, class Less>
void heap_sort(It first, It last, Less& less) {
  const std::ptrdiff_t n = last - first;
  for (std::ptrdiff_t i = n / 2; i-- > 0;) sift_down(first, n, i, less);
  for (std::ptrdiff_t k = n - 1; k > 0; --k) {
    std::iter_swap(first, first + k);
    sift_down(first, k, 0, less);
  }
}

/// Introsort in one function per comparator: median-of-three quicksort, heap sort past
/// 2 log2(n) levels, insertion sort below 17 elements. A few hundred bytes of WebAssembly per
/// comparator where libc++'s std::sort takes 3-6 KB (sorting networks and two insertion sorts,
/// inlined). Every scan is bounded: a comparator that is not a strict weak order (NaN) gives
/// some permutation, never an access out of the range.
template <class It, class Less>
void compact_sort(It first, It last, Less less) {
  int depth = 2 * std::bit_width(static_cast<std::size_t>(last - first));
  while (last - first > 16) {
    if (depth-- == 0) return heap_sort(first, last, less);
    const It low = first + 1, middle = first + (last - first) / 2, high = last - 1;
    if (less(*middle, *low)) std::iter_swap(low, middle);
    if (less(*high, *middle)) std::iter_swap(middle, high);
    if (less(*middle, *low)) std::iter_swap(low, middle);
    std::iter_swap(first, middle);  // the pivot
    // [first + 1, i) holds no element above the pivot, (j, last) none below it; scans stop
    // at equal elements, so runs of equal keys split evenly.
    It i = low, j = high;
    for (;;) {
      while (i <= j && less(*i, *first)) ++i;
      while (i <= j && less(*first, *j)) --j;
      if (i >= j) break;
      std::iter_swap(i++, j--);
    }
    std::iter_swap(first, j);
    // Recurse into the smaller side: the stack stays within log2(n) frames.
    if (j - first < last - j) {
      compact_sort(first, j, less);
      first = j + 1;
    } else {
      compact_sort(j + 1, last, less);
      last = j;
    }
  }
  if (first == last) return;
  for (It i = std::next(first); i != last; ++i) {
    auto value = std::move(*i);
    It j = i;
    for (; j != first && less(value, *std::prev(j)); --j) *j = std::move(*std::prev(j));
    *j = std::move(value);
  }
}

/// The sort of the stages' cold paths (the CDT, the parallel variants, the validator):
/// std::sort natively; compact_sort in WebAssembly, where each std::sort instantiation is
/// 3-6 KB of the module and these paths hold most of them (docs/javascript.md, "Size").
/// Neither is stable, and no caller depends on the order of equal elements.
template <class It, class Less = std::less<>>
void sort(It first, It last, Less less = {}) {
#if defined(__wasm__)
  compact_sort(first, last, less);
#else
  std::sort(first, last, less);
#endif
}

}  // namespace pear::detail
