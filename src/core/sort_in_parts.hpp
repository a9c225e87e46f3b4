// A sort of a large array in tasks: its pieces sorted each in a task, then merged pairwise in
// rounds, each merge cut at equal output positions (a binary search per cut finds where the
// two sorted runs split), so no step is serial but those searches. With a strict total order
// the result is the one sort gives, whatever the number of tasks.
#pragma once

#include <algorithm>
#include <bit>
#include <vector>

#include "core/fill_vector.hpp"
#include "core/stage.hpp"
#include "geometry/sort.hpp"
#include "pear/config.hpp"

namespace pear::detail {

/// Where the first k elements of the stable merge of sorted a[0, na) and b[0, nb) (a's before
/// b's among equals) split them: a[0, i) and b[0, k - i); returns i.
template <class T, class Less>
std::size_t merge_split(const T* a, std::size_t na, const T* b, std::size_t nb, std::size_t k,
                        Less& less) {
  std::size_t lo = k > nb ? k - nb : 0, hi = std::min(k, na);
  while (lo < hi) {
    const std::size_t i = lo + (hi - lo) / 2;
    // a[i] goes out before b[k - i - 1]: the split takes more of a.
    if (!less(b[k - i - 1], a[i]))
      lo = i + 1;
    else
      hi = i;
  }
  return lo;
}

/// Merges sorted a[0, na) and b[0, nb) into out[from, to) of their merge.
template <class T, class Less>
void merge_range(const T* a, std::size_t na, const T* b, std::size_t nb, std::size_t from,
                 std::size_t to, T* out, Less& less) {
  std::size_t i = merge_split(a, na, b, nb, from, less), j = from - i;
  const std::size_t i_end = merge_split(a, na, b, nb, to, less), j_end = to - i_end;
  T* o = out + from;
  while (i < i_end && j < j_end) *o++ = less(b[j], a[i]) ? b[j++] : a[i++];
  o = std::copy(a + i, a + i_end, o);
  std::copy(b + j, b + j_end, o);
}

/// Sorts v by `less` in ctx.partitions tasks, or `max_tasks` when given (a power of two of
/// them, each at least `min_per_task` elements), recorded as the phases `sort_phase` and
/// `merge_phase`; in one serial phase when that leaves one task, and without threads in none
/// (the caller's).
template <class T, class Alloc, class Less>
void sort_in_parts(const RunContext& ctx, const char* sort_phase, const char* merge_phase,
                   std::vector<T, Alloc>& v, Less less, std::size_t min_per_task = 1024,
                   std::size_t max_tasks = 0) {
  const std::size_t n = v.size();
  const std::size_t most = std::min<std::size_t>(max_tasks ? max_tasks : ctx.partitions,
                                                 n / std::max<std::size_t>(1, min_per_task));
  const std::size_t tasks = !PEAR_HAS_THREADS || most < 2 ? 1 : std::bit_floor(most);
  if (tasks < 2) {
    ctx.run_serial_if_threads(sort_phase, [&] { detail::sort(v.begin(), v.end(), less); });
    return;
  }
  const auto cut = [&](std::size_t piece, std::size_t pieces) { return n * piece / pieces; };
  // The merges alternate between v and `other`; with an odd number of rounds the pieces are
  // sorted in `other` (each task copies its own), so that the last round writes v. `other` is
  // not zeroed: the merges write every element (zeroing it was a serial gap between the
  // phases, 0.03 ms for each of the repair's sorts of random holes at 16 partitions).
  FillVector<T> other(n);
  const bool odd_rounds = std::countr_zero(tasks) % 2 == 1;
  T *from = odd_rounds ? other.data() : v.data(), *to = odd_rounds ? v.data() : other.data();
  ctx.run_tasks(sort_phase, tasks, [&](std::size_t t) {
    if (odd_rounds)
      std::copy(v.data() + cut(t, tasks), v.data() + cut(t + 1, tasks), from + cut(t, tasks));
    detail::sort(from + cut(t, tasks), from + cut(t + 1, tasks), less);
  });
  // Round r merges runs of 2^r pieces in pairs; each pair's output in 2^(r + 1) parts.
  for (std::size_t width = 1; width < tasks; width *= 2) {
    ctx.run_tasks(merge_phase, tasks, [&](std::size_t t) {
      const std::size_t pair = t / (2 * width), part = t % (2 * width);
      const std::size_t begin = cut(2 * width * pair, tasks),
                        middle = cut(2 * width * pair + width, tasks),
                        end = cut(2 * width * (pair + 1), tasks);
      const std::size_t size = end - begin;
      merge_range(from + begin, middle - begin, from + middle, end - middle,
                  size * part / (2 * width), size * (part + 1) / (2 * width), to + begin, less);
    });
    std::swap(from, to);
  }
}

}  // namespace pear::detail
