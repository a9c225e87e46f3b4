// The Chase–Lev deque: owner-only semantics against a std::deque model, and owner plus thieves
// consuming exactly the multiset that was pushed (no loss, no duplicate), across growth.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <deque>
#include <random>
#include <thread>
#include <vector>

#include "scheduler/work_stealing_deque.hpp"

namespace {

// ThreadSanitizer slows atomics down a lot: smaller sizes keep the suite short there.
constexpr std::size_t scale_down = pear::detail::thread_sanitizer ? 4 : 1;

TEST(WorkStealingDeque, OwnerPopsLastInFirstOutAcrossGrowth) {
  pear::WorkStealingDeque<int> deque(2);
  for (int i = 0; i < 1000; ++i) deque.push(i);
  EXPECT_GE(deque.capacity(), 1000u);
  EXPECT_EQ(deque.size(), 1000u);
  for (int i = 999; i >= 0; --i) {
    auto item = deque.pop();
    ASSERT_TRUE(item.has_value());
    EXPECT_EQ(*item, i);
  }
  EXPECT_FALSE(deque.pop().has_value());
  EXPECT_FALSE(deque.steal().has_value());
  EXPECT_TRUE(deque.empty());
}

TEST(WorkStealingDeque, StealTakesOldestFirst) {
  pear::WorkStealingDeque<int> deque(4);
  for (int i = 0; i < 100; ++i) deque.push(i);
  for (int i = 0; i < 50; ++i) EXPECT_EQ(deque.steal(), i);
  for (int i = 99; i >= 50; --i) EXPECT_EQ(deque.pop(), i);
  EXPECT_FALSE(deque.pop().has_value());
}

TEST(WorkStealingDeque, RandomOwnerOperationsMatchAModel) {
  pear::WorkStealingDeque<std::uint32_t> deque(2);
  std::deque<std::uint32_t> model;
  std::mt19937 random(12345);
  for (std::uint32_t step = 0; step < 200000; ++step) {
    const unsigned op = random() % 8;
    if (op < 4) {  // pushes outnumber the rest, so the deque grows several times
      deque.push(step);
      model.push_back(step);
    } else if (op < 6) {
      const auto item = deque.pop();
      ASSERT_EQ(item.has_value(), !model.empty()) << "step " << step;
      if (item) {
        EXPECT_EQ(*item, model.back());
        model.pop_back();
      }
    } else {
      const auto item = deque.steal();
      ASSERT_EQ(item.has_value(), !model.empty()) << "step " << step;
      if (item) {
        EXPECT_EQ(*item, model.front());
        model.pop_front();
      }
    }
    ASSERT_EQ(deque.size(), model.size());
  }
}

struct Race {
  std::size_t items;
  int thieves;
};

class DequeRace : public ::testing::TestWithParam<Race> {};

// The owner pushes 0..n-1 in bursts and pops some between bursts; thieves steal all the while.
// Every thread keeps what it took; together they must hold each item exactly once.
TEST_P(DequeRace, ConsumedMultisetEqualsPushed) {
  const std::size_t items = std::max<std::size_t>(1, GetParam().items / scale_down);
  const int thief_count = GetParam().thieves;
  pear::WorkStealingDeque<std::uint32_t> deque(2);  // tiny: growth happens under contention
  std::atomic<bool> owner_done{false};
  std::atomic<int> thieves_ready{0};
  std::vector<std::vector<std::uint32_t>> taken(thief_count + 1);
  std::vector<std::thread> thieves;
  for (int t = 1; t <= thief_count; ++t) {
    thieves.emplace_back([&, t] {
      thieves_ready.fetch_add(1);
      int misses = 0;
      while (!owner_done.load(std::memory_order_acquire)) {
        if (auto item = deque.steal()) {
          taken[t].push_back(*item);
          misses = 0;
        } else if (++misses % 64 == 0) {
          std::this_thread::yield();  // 8 thieves on 2 cores: let the owner run
        }
      }
    });
  }
  while (thieves_ready.load() < thief_count) std::this_thread::yield();  // race from the start
  std::mt19937 random(static_cast<unsigned>(items * 31 + thief_count));
  std::size_t next = 0;
  while (next < items) {
    const std::size_t burst = std::min<std::size_t>(items - next, 1 + random() % 64);
    for (std::size_t i = 0; i < burst; ++i) deque.push(static_cast<std::uint32_t>(next++));
    for (std::size_t pops = random() % 48; pops > 0; --pops) {
      if (auto item = deque.pop()) taken[0].push_back(*item);
    }
  }
  while (!deque.empty()) {
    if (auto item = deque.pop()) taken[0].push_back(*item);
  }
  owner_done.store(true, std::memory_order_release);
  for (auto& thief : thieves) thief.join();

  std::vector<std::uint32_t> seen(items, 0);
  std::size_t total = 0;
  for (const auto& list : taken) {
    for (std::uint32_t item : list) {
      ASSERT_LT(item, items);
      ++seen[item];
    }
    total += list.size();
  }
  EXPECT_EQ(total, items);
  RecordProperty("stolen", std::to_string(items - taken[0].size()));
  for (std::size_t i = 0; i < items; ++i) ASSERT_EQ(seen[i], 1u) << "item " << i;
}

INSTANTIATE_TEST_SUITE_P(OwnerAndThieves, DequeRace,
                         ::testing::Values(Race{1, 1}, Race{2, 8}, Race{1000, 1}, Race{1000, 8},
                                           Race{100000, 2}, Race{100000, 4}, Race{1000000, 1},
                                           Race{1000000, 8}),
                         [](const auto& info) {
                           return "items" + std::to_string(info.param.items) + "_thieves" +
                                  std::to_string(info.param.thieves);
                         });

}  // namespace
