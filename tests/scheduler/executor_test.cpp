// Executor, TaskGroup, parallel_for / parallel_reduce: results against serial references,
// exceptions, cancellation, 1 thread, oversubscription, shared use, repeated start and stop.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <numeric>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "pear/scheduler.hpp"
#include "scheduler/work_stealing_deque.hpp"

namespace {

constexpr bool under_tsan = pear::detail::thread_sanitizer;

// fib with a spawn at every level: the deepest nesting of groups and waits we can make.
std::uint64_t spawned_fib(int n) {
  if (n < 2) return static_cast<std::uint64_t>(n);
  std::uint64_t left = 0;
  pear::TaskGroup group;  // the current executor: the one running this task
  group.run([&left, n] { left = spawned_fib(n - 1); });
  const std::uint64_t right = spawned_fib(n - 2);
  group.wait();
  return left + right;
}

std::uint64_t serial_fib(int n) {
  return n < 2 ? static_cast<std::uint64_t>(n) : serial_fib(n - 1) + serial_fib(n - 2);
}

class ExecutorSizes : public ::testing::TestWithParam<std::size_t> {};

TEST_P(ExecutorSizes, SpawnedFibonacciMatchesSerial) {
  pear::Executor executor(GetParam());
  const int n = under_tsan ? 18 : 24;
  std::uint64_t result = 0;
  pear::TaskGroup outer(executor);
  outer.run([&] { result = spawned_fib(n); });
  outer.wait();
  EXPECT_EQ(result, serial_fib(n));
}

TEST_P(ExecutorSizes, ParallelForWritesEveryIndexOnce) {
  pear::Executor executor(GetParam());
  const int n = under_tsan ? 100000 : 1000000;
  std::vector<std::atomic<int>> hits(n);
  pear::parallel_for(executor, 0, n, 100,
                     [&](int i) { hits[i].fetch_add(1, std::memory_order_relaxed); });
  for (int i = 0; i < n; ++i) ASSERT_EQ(hits[i].load(), 1) << "index " << i;
}

TEST_P(ExecutorSizes, ParallelForHandlesOddRanges) {
  pear::Executor executor(GetParam());
  std::vector<int> out(1000, 0);
  pear::parallel_for(executor, -500, 500, 0, [&](int i) { out[i + 500] = i; });  // auto grain
  for (int i = 0; i < 1000; ++i) ASSERT_EQ(out[i], i - 500);
  int calls = 0;
  pear::parallel_for(executor, 7, 7, 1, [&](int) { ++calls; });
  pear::parallel_for(executor, 9, 3, 1, [&](int) { ++calls; });
  EXPECT_EQ(calls, 0);
  pear::parallel_for(executor, std::size_t{0}, std::size_t{3}, 1000, [&](std::size_t) { ++calls; });
  EXPECT_EQ(calls, 3);
}

TEST_P(ExecutorSizes, ParallelReduceSumsExactly) {
  pear::Executor executor(GetParam());
  const std::int64_t n = under_tsan ? 100000 : 3000000;
  const std::int64_t sum = pear::parallel_reduce(
      executor, std::int64_t{0}, n, 1000, std::int64_t{0}, [](std::int64_t i) { return i; },
      [](std::int64_t a, std::int64_t b) { return a + b; });
  EXPECT_EQ(sum, n * (n - 1) / 2);
}

TEST_P(ExecutorSizes, ParallelReduceKeepsIndexOrder) {
  // Concatenation is not commutative: any reordering of chunks or items shows.
  pear::Executor executor(GetParam());
  std::string expected;
  for (int i = 0; i < 2000; ++i) expected += static_cast<char>('a' + i % 26);
  const std::string got = pear::parallel_reduce(
      executor, 0, 2000, 7, std::string(),
      [](int i) { return std::string(1, static_cast<char>('a' + i % 26)); },
      [](std::string a, const std::string& b) { return a + b; });
  EXPECT_EQ(got, expected);
}

TEST_P(ExecutorSizes, ExceptionReachesTheWaiterAndLaterTasksAreSkipped) {
  pear::Executor executor(GetParam());
  pear::TaskGroup group(executor);
  std::atomic<int> ran{0};
  for (int i = 0; i < 100; ++i) {
    group.run([&ran, i] {
      ran.fetch_add(1);
      if (i == 37) throw std::runtime_error("task 37 failed");
    });
  }
  try {
    group.wait();
    FAIL() << "wait() did not rethrow";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "task 37 failed");
  }
  EXPECT_TRUE(group.cancelled());
  EXPECT_GE(ran.load(), 1);
  bool late_ran = false;
  group.run([&] { late_ran = true; });
  EXPECT_NO_THROW(group.wait());  // the exception is rethrown once
  EXPECT_FALSE(late_ran);
}

TEST_P(ExecutorSizes, ParallelForRethrows) {
  pear::Executor executor(GetParam());
  EXPECT_THROW(pear::parallel_for(executor, 0, 10000, 10,
                                  [](int i) {
                                    if (i == 4321) throw std::out_of_range("index 4321");
                                  }),
               std::out_of_range);
}

TEST_P(ExecutorSizes, StopTokenCancelsTheGroup) {
  pear::Executor executor(GetParam());
  std::stop_source stop;
  pear::TaskGroup group(executor, stop.get_token());
  std::atomic<int> ran{0};
  group.run([&] { ran.fetch_add(1); });
  group.wait();
  stop.request_stop();
  EXPECT_TRUE(group.cancelled());
  EXPECT_TRUE(group.stop_token().stop_requested());
  for (int i = 0; i < 50; ++i) group.run([&] { ran.fetch_add(1); });
  group.wait();
  EXPECT_EQ(ran.load(), 1);
}

TEST_P(ExecutorSizes, AnExceptionTriggersSiblingsStopTokens) {
  pear::Executor executor(GetParam());
  pear::TaskGroup group(executor);
  // The watcher is pushed first, so whoever runs it does so only when the thrower is taken
  // or done; it returns once the thrower's exception has requested the stop.
  group.run([&](std::stop_token stop) {
    while (!stop.stop_requested()) std::this_thread::yield();
  });
  group.run([] { throw std::logic_error("stop everybody"); });
  EXPECT_THROW(group.wait(), std::logic_error);
  EXPECT_TRUE(group.stop_token().stop_requested());
  EXPECT_TRUE(group.cancelled());
}

TEST_P(ExecutorSizes, ParallelInvokeRunsEachClosureOnce) {
  pear::Executor executor(GetParam());
  std::vector<int> parts(16, 0);
  for (int round = 0; round < 20; ++round) {
    pear::parallel_invoke(
        executor, [&] { ++parts[0]; }, [&] { ++parts[1]; }, [&] { ++parts[2]; },
        [&] { ++parts[3]; });
    pear::TaskGroup group(executor);
    for (int k = 4; k < 16; ++k) group.run([&parts, k] { ++parts[k]; });
    group.wait();
  }
  for (int k = 0; k < 16; ++k) EXPECT_EQ(parts[k], 20) << "closure " << k;
}

INSTANTIATE_TEST_SUITE_P(Threads, ExecutorSizes, ::testing::Values(1, 2, 3, 16),
                         [](const auto& info) {
                           return "concurrency" + std::to_string(info.param);
                         });

TEST(Executor, OneThreadRunsEverythingOnTheCaller) {
  pear::Executor executor(1);
  EXPECT_EQ(executor.concurrency(), 1u);
  const auto caller = std::this_thread::get_id();
  std::vector<std::thread::id> ids(64);
  pear::TaskGroup group(executor);
  for (int i = 0; i < 64; ++i) {
    group.run([&ids, i] {
      pear::TaskGroup inner;
      inner.run([&ids, i] { ids[i] = std::this_thread::get_id(); });
      inner.wait();
    });
  }
  group.wait();
  for (const auto& id : ids) EXPECT_EQ(id, caller);
}

TEST(Executor, ZeroMeansOneAndHugeIsRejected) {
  pear::Executor executor(0);
  EXPECT_EQ(executor.concurrency(), 1u);
  EXPECT_THROW(pear::Executor(100000), std::invalid_argument);
}

TEST(Executor, UsesSeveralThreadsWhenWorkBlocksOthers) {
  // Two tasks that each wait for the other to start can only finish on two threads at once.
  pear::Executor executor(2);
  std::atomic<int> started{0};
  pear::TaskGroup group(executor);
  for (int i = 0; i < 2; ++i) {
    group.run([&] {
      started.fetch_add(1);
      while (started.load() < 2) std::this_thread::yield();
    });
  }
  group.wait();
  EXPECT_EQ(started.load(), 2);
}

// Lost wake-ups would hang these (and meson's timeout would fail them): between rounds the pool
// idles long enough to fall asleep, so every round needs a sleeper to be woken.
TEST(Executor, SleepingWorkersAreWokenForWorkThatNeedsThem) {
  pear::Executor executor(2);
  for (int round = 0; round < 200; ++round) {
    std::this_thread::sleep_for(std::chrono::microseconds(300));  // let the worker sleep
    std::atomic<int> started{0};
    pear::TaskGroup group(executor);
    for (int i = 0; i < 2; ++i) {
      group.run([&] {
        started.fetch_add(1);
        while (started.load() < 2) std::this_thread::yield();  // needs both threads at once
      });
    }
    group.wait();
    ASSERT_EQ(started.load(), 2) << "round " << round;
  }
}

TEST(Executor, SleepingWaiterIsWokenWhenTheLastTaskEnds) {
  pear::Executor executor(2);
  for (int round = 0; round < 200; ++round) {
    std::atomic<bool> picked_up{false};
    std::atomic<bool> finished{false};
    pear::TaskGroup group(executor);
    group.run([&] {
      picked_up = true;
      std::this_thread::sleep_for(std::chrono::microseconds(300));  // the waiter falls asleep
      finished = true;
    });
    // Not helping yet, the caller lets the worker take the task; then it waits while the task
    // still sleeps, finds nothing to do, sleeps itself and must be woken by the task's end.
    while (!picked_up.load()) std::this_thread::yield();
    group.wait();
    ASSERT_TRUE(picked_up.load() && finished.load()) << "round " << round;
  }
}

TEST(Executor, CurrentExecutorIsTheOneRunningTheTask) {
  pear::Executor executor(3);
  pear::Executor* seen = nullptr;
  {
    pear::TaskGroup group(executor);
    group.run([&] { seen = &pear::current_executor(); });
    group.wait();
  }
  EXPECT_EQ(seen, &executor);
  EXPECT_EQ(&pear::current_executor(), &pear::default_executor());
  EXPECT_EQ(pear::default_executor().concurrency(),
            std::max(1u, std::thread::hardware_concurrency()));
}

TEST(Executor, ManyOutsideThreadsShareOneExecutor) {
  // More outside threads than outside deques: some share the locked queue.
  pear::Executor executor(3);
  const int n = under_tsan ? 2000 : 50000;
  std::vector<std::int64_t> sums(10, 0);
  std::vector<std::thread> users;
  for (int u = 0; u < 10; ++u) {
    users.emplace_back([&, u] {
      sums[u] = pear::parallel_reduce(
          executor, 0, n, 64, std::int64_t{0}, [u](int i) { return std::int64_t{i} * (u + 1); },
          [](std::int64_t a, std::int64_t b) { return a + b; });
    });
  }
  for (auto& user : users) user.join();
  for (int u = 0; u < 10; ++u) EXPECT_EQ(sums[u], std::int64_t{n} * (n - 1) / 2 * (u + 1));
}

TEST(Executor, NestedExecutorsDoNotMixTheirWork) {
  pear::Executor outer(2);
  pear::Executor inner(2);
  std::atomic<int> wrong{0};
  pear::parallel_for(outer, 0, 64, 1, [&](int) {
    pear::parallel_for(inner, 0, 64, 1, [&](int) {
      if (&pear::current_executor() != &inner) wrong.fetch_add(1);
    });
    if (&pear::current_executor() != &outer) wrong.fetch_add(1);
  });
  EXPECT_EQ(wrong.load(), 0);
}

TEST(Executor, RepeatedStartAndStop) {
  const int rounds = under_tsan ? 20 : 200;
  for (int round = 0; round < rounds; ++round) {
    pear::Executor executor(1 + round % 5);
    if (round % 3 == 0) continue;  // some never see work
    std::atomic<int> ran{0};
    pear::TaskGroup group(executor);
    for (int i = 0; i < 20; ++i) group.run([&] { ran.fetch_add(1); });
    group.wait();
    ASSERT_EQ(ran.load(), 20) << "round " << round;
  }
}

TEST(Executor, GroupDestructorCancelsAndWaits) {
  pear::Executor executor(2);
  std::atomic<int> ran{0};
  {
    pear::TaskGroup group(executor);
    group.run([&] { ran.fetch_add(1); });
    group.cancel();
    group.run([&] { ran.fetch_add(1); });  // after cancel: skipped
  }
  EXPECT_LE(ran.load(), 1);
}

}  // namespace
