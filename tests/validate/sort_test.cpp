// geometry/sort.hpp's compact_sort (the WebAssembly build's sort of the validator, the CDT and
// the parallel variants), natively: the same sequence as std::sort, bounded on bad comparators.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <utility>
#include <vector>

#include "geometry/sort.hpp"

namespace {

using pear::detail::compact_sort;

/// Sizes around the insertion-sort cutoff (16) and a few larger ones; keys drawn from `range`
/// values, so small ranges give long runs of equal keys.
TEST(CompactSort, SortsLikeStdSort) {
  std::mt19937 random(29);
  for (const std::size_t size : {0u, 1u, 2u, 3u, 16u, 17u, 18u, 100u, 1000u, 20000u})
    for (const std::uint32_t range : {1u, 2u, 7u, 1000u, 4000000000u}) {
      std::vector<std::uint32_t> keys(size);
      for (auto& k : keys) k = random() % range;
      std::vector<std::uint32_t> expected = keys;
      std::sort(expected.begin(), expected.end());
      compact_sort(keys.begin(), keys.end(), std::less<>());
      EXPECT_EQ(keys, expected) << "size " << size << ", range " << range;
    }
}

/// Ordered, reversed and organ-pipe input, by a comparator on one field of a pair: the other
/// field travels with its key.
TEST(CompactSort, KeepsRecordsWholeOnPatternedInput) {
  for (int pattern = 0; pattern < 3; ++pattern) {
    std::vector<std::pair<int, int>> records;
    for (int i = 0; i < 5000; ++i) {
      const int key = pattern == 0 ? i : pattern == 1 ? 5000 - i : std::min(i, 5000 - i);
      records.push_back({key, 3 * key + 1});
    }
    compact_sort(records.begin(), records.end(),
                 [](const auto& a, const auto& b) { return a.first < b.first; });
    for (std::size_t i = 0; i < records.size(); ++i) {
      EXPECT_EQ(records[i].second, 3 * records[i].first + 1);
      if (i > 0) {
        EXPECT_LE(records[i - 1].first, records[i].first) << "pattern " << pattern;
      }
    }
  }
}

/// The heap sort that compact_sort falls back to after too many bad splits.
TEST(CompactSort, HeapSortSorts) {
  std::mt19937 random(7);
  for (const std::size_t size : {0u, 1u, 2u, 5u, 64u, 3001u}) {
    std::vector<int> keys(size);
    for (auto& k : keys) k = static_cast<int>(random() % 50);
    std::vector<int> expected = keys;
    std::sort(expected.begin(), expected.end());
    std::less<> less;
    pear::detail::heap_sort(keys.begin(), keys.end(), less);
    EXPECT_EQ(keys, expected) << "size " << size;
  }
}

/// NaN makes `<` no strict weak order: still a permutation of the input, found within it
/// (a scan past the range would read the guard values around it, or crash).
TEST(CompactSort, StaysInRangeWithNaN) {
  std::mt19937 random(3);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> storage(2 + 3000, -1e300);
  const auto first = storage.begin() + 1, last = storage.end() - 1;
  for (auto it = first; it != last; ++it) *it = random() % 4 == 0 ? nan : random() % 100;
  std::vector<double> before(first, last);
  compact_sort(first, last, std::less<>());
  EXPECT_EQ(storage.front(), -1e300);
  EXPECT_EQ(storage.back(), -1e300);
  const auto count_nan = [](auto a, auto b) {
    return std::count_if(a, b, [](double v) { return std::isnan(v); });
  };
  EXPECT_EQ(count_nan(first, last), count_nan(before.begin(), before.end()));
  std::vector<double> numbers, numbers_before;
  std::copy_if(first, last, std::back_inserter(numbers), [](double v) { return !std::isnan(v); });
  std::copy_if(before.begin(), before.end(), std::back_inserter(numbers_before),
               [](double v) { return !std::isnan(v); });
  std::sort(numbers.begin(), numbers.end());
  std::sort(numbers_before.begin(), numbers_before.end());
  EXPECT_EQ(numbers, numbers_before);
}

}  // namespace
