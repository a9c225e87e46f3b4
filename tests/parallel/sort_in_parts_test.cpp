// sort_in_parts (core/sort_in_parts.hpp): the sort's result at every thread and partition
// count, its merges cut anywhere, and the phases it records (the parallel path must run).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "core/fill_vector.hpp"
#include "core/sort_in_parts.hpp"
#include "pear/config.hpp"
#include "run_contexts.hpp"

namespace pear::detail {
namespace {

/// A key with a payload: elements with equal keys are told apart only by where they end up.
struct Item {
  std::uint32_t key = 0, payload = 0;
  friend bool operator==(const Item&, const Item&) = default;
};
constexpr auto by_key = [](const Item& a, const Item& b) { return a.key < b.key; };

std::vector<Item> random_items(std::size_t n, std::uint32_t keys, unsigned seed) {
  std::mt19937 random(seed);
  std::vector<Item> items(n);
  for (std::uint32_t i = 0; i < n; ++i) items[i] = {static_cast<std::uint32_t>(random() % keys), i};
  return items;
}

std::size_t phases_named(const RunProfile& profile, const std::string& name) {
  return static_cast<std::size_t>(
      std::count_if(profile.phases.begin(), profile.phases.end(),
                    [&](const RunProfile::Phase& p) { return p.name == name; }));
}

TEST(MergeSplit, CutsTheStableMergeAtEveryPosition) {
  std::mt19937 random(7);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Item> a = random_items(random() % 20, 6, random()),
                      b = random_items(random() % 20, 6, random());
    for (Item& x : b) x.payload += 1000;  // b's after a's among equals in the stable merge
    std::sort(a.begin(), a.end(), by_key);
    std::sort(b.begin(), b.end(), by_key);
    std::vector<Item> merged;
    std::merge(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(merged), by_key);
    auto less = by_key;
    for (std::size_t k = 0; k <= merged.size(); ++k) {
      const std::size_t i = merge_split(a.data(), a.size(), b.data(), b.size(), k, less);
      ASSERT_LE(i, a.size());
      ASSERT_LE(k - i, b.size());
      // The first k of the merge are a[0, i) and b[0, k - i).
      std::vector<Item> first(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(i));
      first.insert(first.end(), b.begin(), b.begin() + static_cast<std::ptrdiff_t>(k - i));
      std::sort(first.begin(), first.end(),
                [](const Item& x, const Item& y) { return x.payload < y.payload; });
      std::vector<Item> expected(merged.begin(), merged.begin() + static_cast<std::ptrdiff_t>(k));
      std::sort(expected.begin(), expected.end(),
                [](const Item& x, const Item& y) { return x.payload < y.payload; });
      ASSERT_EQ(first, expected) << "k " << k;
    }
  }
}

TEST(SortInParts, SortsLikeOneSortAtEveryThreadAndPartitionCount) {
  for (const std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{1000}, std::size_t{5000},
                              std::size_t{50'000}, std::size_t{123'457}}) {
    // Keys unique (a total order): the result is exactly one sort's.
    std::vector<std::uint64_t> values(n);
    std::mt19937_64 random(n);
    for (auto& v : values) v = random();
    std::vector<std::uint64_t> expected = values;
    std::sort(expected.begin(), expected.end());
    for_each_context({1, 2, 4}, {1, 2, 3, 4, 7, 16}, [&](const RunContext& ctx, RunProfile& p) {
      std::vector<std::uint64_t> sorted = values;
      sort_in_parts(ctx, "sort", "merge", sorted, std::less<>{});
      ASSERT_EQ(sorted, expected) << "n " << n;
      // Past one task's share it sorts in tasks and merges them (log2 of the tasks rounds).
      const std::size_t tasks = std::min<std::size_t>(ctx.partitions, n / 1024);
      const std::size_t rounds = tasks < 2 ? 0 : std::bit_width(tasks) - 1;
      EXPECT_EQ(phases_named(p, "merge"), PEAR_HAS_THREADS ? rounds : 0) << "n " << n;
      EXPECT_EQ(phases_named(p, "sort"), PEAR_HAS_THREADS ? 1u : 0u);
    });
  }
}

/// max_tasks overrides the partitions (the simplicity check's runs sort in more pieces than
/// partitions), rounded down to a power of two, in a FillVector as well as a std::vector.
TEST(SortInParts, MaxTasksSetsThePiecesWhateverThePartitions) {
  const std::size_t n = 70'001;
  FillVector<std::uint64_t> values(n);
  std::mt19937_64 random(11);
  for (auto& v : values) v = random();
  FillVector<std::uint64_t> expected = values;
  std::sort(expected.begin(), expected.end());
  for (const std::size_t max_tasks :
       {std::size_t{1}, std::size_t{3}, std::size_t{16}, std::size_t{64}, std::size_t{100}}) {
    for_each_context({1, 2}, {1, 2}, [&](const RunContext& ctx, RunProfile& p) {
      FillVector<std::uint64_t> sorted = values;
      sort_in_parts(ctx, "sort", "merge", sorted, std::less<>{}, 1024, max_tasks);
      ASSERT_EQ(sorted, expected) << max_tasks << " tasks";
      const std::size_t tasks = std::min<std::size_t>(max_tasks, n / 1024);
      const std::size_t rounds = tasks < 2 ? 0 : std::bit_width(tasks) - 1;
      EXPECT_EQ(phases_named(p, "merge"), PEAR_HAS_THREADS ? rounds : 0) << max_tasks;
    });
  }
}

TEST(SortInParts, TiesEndTheSameWhateverTheThreads) {
  const std::vector<Item> items = random_items(40'000, 50, 3);
  for (std::uint32_t partitions : {2u, 5u, 8u, 16u}) {
    std::vector<Item> first;
    for_each_context({1, 2, 4}, {partitions}, [&](const RunContext& ctx, RunProfile&) {
      std::vector<Item> sorted = items;
      sort_in_parts(ctx, "sort", "merge", sorted, by_key);
      ASSERT_TRUE(std::is_sorted(sorted.begin(), sorted.end(), by_key));
      std::vector<Item> same = sorted;  // a permutation of the items
      std::sort(same.begin(), same.end(),
                [](const Item& x, const Item& y) { return x.payload < y.payload; });
      ASSERT_EQ(same, items);
      if (first.empty()) first = sorted;
      EXPECT_EQ(sorted, first);  // the ties' order depends on the partitions only
    });
  }
}

}  // namespace
}  // namespace pear::detail
