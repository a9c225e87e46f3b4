// TaskGraph: random DAGs run every task exactly once and after all its predecessors, run after
// run; exceptions, cancellation, cycles, and an executor destroyed with a run in flight.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <memory>
#include <numeric>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "pear/scheduler.hpp"
#include "scheduler/work_stealing_deque.hpp"

namespace {

constexpr bool under_tsan = pear::detail::thread_sanitizer;

/// A random DAG whose tasks record when they start and finish (one global clock).
struct Recorder {
  explicit Recorder(std::size_t n) : runs(n), start(n), finish(n) {}
  std::vector<std::atomic<int>> runs;
  std::vector<std::atomic<std::uint64_t>> start;
  std::vector<std::atomic<std::uint64_t>> finish;
  std::atomic<std::uint64_t> clock{0};
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
};

void build_random_dag(pear::TaskGraph& graph, Recorder& recorder, std::size_t n, unsigned seed) {
  std::mt19937 random(seed);
  // rank[i]: task i's place in a hidden topological order, so edges are not in emplace order.
  std::vector<std::uint32_t> rank(n);
  std::iota(rank.begin(), rank.end(), 0u);
  std::shuffle(rank.begin(), rank.end(), random);
  std::vector<std::uint32_t> by_rank(n);
  for (std::uint32_t i = 0; i < n; ++i) by_rank[rank[i]] = i;
  std::vector<pear::Task> tasks;
  tasks.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    tasks.push_back(graph.emplace([&recorder, i] {
      recorder.start[i] = recorder.clock.fetch_add(1) + 1;
      recorder.runs[i].fetch_add(1);
      recorder.finish[i] = recorder.clock.fetch_add(1) + 1;
    }));
  }
  for (std::uint32_t r = 1; r < n; ++r) {
    const unsigned fan_in = random() % 4;  // some tasks are sources
    for (unsigned k = 0; k < fan_in; ++k) {
      const std::uint32_t window = std::min<std::uint32_t>(r, 64);
      const std::uint32_t from = by_rank[r - 1 - random() % window];
      tasks[from].precede(tasks[by_rank[r]]);
      recorder.edges.emplace_back(from, by_rank[r]);
    }
  }
}

void expect_ran_once_in_order(Recorder& recorder, int expected_runs) {
  for (std::size_t i = 0; i < recorder.runs.size(); ++i) {
    ASSERT_EQ(recorder.runs[i].load(), expected_runs) << "task " << i;
  }
  for (const auto& [from, to] : recorder.edges) {
    ASSERT_LT(recorder.finish[from].load(), recorder.start[to].load())
        << "task " << to << " started before its predecessor " << from << " finished";
  }
}

struct DagCase {
  std::size_t concurrency;
  std::size_t tasks;
};

class RandomDag : public ::testing::TestWithParam<DagCase> {};

TEST_P(RandomDag, EveryTaskRunsOnceAfterItsPredecessors) {
  const std::size_t n = std::max<std::size_t>(1, GetParam().tasks / (under_tsan ? 5 : 1));
  pear::Executor executor(GetParam().concurrency);
  pear::TaskGraph graph;
  Recorder recorder(n);
  build_random_dag(graph, recorder, n, static_cast<unsigned>(n));
  for (int run = 1; run <= 3; ++run) {  // build once, run many times
    executor.run(graph).wait();
    expect_ran_once_in_order(recorder, run);
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, RandomDag,
                         ::testing::Values(DagCase{1, 1}, DagCase{1, 5000}, DagCase{2, 2},
                                           DagCase{2, 100000}, DagCase{3, 30000},
                                           DagCase{16, 100000}),
                         [](const auto& info) {
                           return "concurrency" + std::to_string(info.param.concurrency) +
                                  "_tasks" + std::to_string(info.param.tasks);
                         });

TEST(TaskGraph, OverlappingRunsOfOneGraphEachRunEveryTask) {
  pear::Executor executor(3);
  pear::TaskGraph graph;
  const std::size_t n = under_tsan ? 500 : 5000;
  Recorder recorder(n);
  build_random_dag(graph, recorder, n, 7);
  auto first = executor.run(graph);
  auto second = executor.run(graph);
  first.wait();
  second.wait();
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(recorder.runs[i].load(), 2) << "task " << i;
}

/// A chain 0 -> 1 -> ... -> n-1 whose tasks count their runs.
struct Chain {
  explicit Chain(std::size_t n) : ran(n) {
    for (std::size_t i = 0; i < n; ++i) {
      tasks.push_back(graph.emplace([this, i] { ran[i].fetch_add(1); }));
      if (i > 0) tasks[i - 1].precede(tasks[i]);
    }
  }
  pear::TaskGraph graph;
  std::vector<pear::Task> tasks;
  std::vector<std::atomic<int>> ran;
};

TEST(TaskGraph, ExceptionReachesWaitAndCancelsTheRest) {
  pear::Executor executor(2);
  pear::TaskGraph graph;
  std::vector<std::atomic<int>> ran(100);
  std::vector<pear::Task> tasks;
  for (int i = 0; i < 100; ++i) {
    tasks.push_back(graph.emplace([&ran, i] {
      ran[i].fetch_add(1);
      if (i == 40) throw std::runtime_error("task 40 broke");
    }));
    if (i > 0) tasks[i - 1].precede(tasks[i]);
  }
  auto future = executor.run(graph);
  try {
    future.wait();
    FAIL() << "wait() did not rethrow";
  } catch (const std::runtime_error& error) {
    EXPECT_STREQ(error.what(), "task 40 broke");
  }
  EXPECT_TRUE(future.ready());
  EXPECT_TRUE(future.cancelled());
  for (int i = 0; i <= 40; ++i) EXPECT_EQ(ran[i].load(), 1) << "task " << i;
  for (int i = 41; i < 100; ++i) EXPECT_EQ(ran[i].load(), 0) << "task " << i;
  EXPECT_THROW(future.wait(), std::runtime_error);  // every wait() rethrows
}

TEST(TaskGraph, StopTokenStopsRemainingWork) {
  pear::Executor executor(2);
  Chain chain(100);
  std::stop_source stop;
  chain.tasks[10] = chain.graph.emplace([&] { stop.request_stop(); });  // a side task
  chain.tasks[9].precede(chain.tasks[10]);
  chain.tasks[10].precede(chain.tasks[11]);
  auto future = executor.run(chain.graph, stop.get_token());
  EXPECT_NO_THROW(future.wait());
  EXPECT_TRUE(future.cancelled());
  for (int i = 0; i < 10; ++i) EXPECT_EQ(chain.ran[i].load(), 1) << "task " << i;
  for (int i = 11; i < 100; ++i) EXPECT_EQ(chain.ran[i].load(), 0) << "task " << i;
}

TEST(TaskGraph, FutureCancelSkipsWhatHasNotStarted) {
  pear::Executor executor(2);
  pear::TaskGraph graph;
  std::atomic<bool> release{false};
  std::atomic<int> after{0};
  auto gate = graph.emplace([&](std::stop_token stop) {
    while (!release.load() && !stop.stop_requested()) std::this_thread::yield();
  });
  for (int i = 0; i < 50; ++i) gate.precede(graph.emplace([&] { after.fetch_add(1); }));
  auto future = executor.run(graph);
  future.cancel();
  release = true;
  future.wait();
  EXPECT_EQ(after.load(), 0);
  EXPECT_TRUE(future.cancelled());
}

TEST(TaskGraph, TasksSpawnAndWaitForSubtasks) {
  for (std::size_t concurrency : {1u, 2u, 4u}) {
    pear::Executor executor(concurrency);
    pear::TaskGraph graph;
    std::vector<std::int64_t> partial(8, 0);
    std::int64_t total = 0;
    auto sum = graph.emplace(
        [&] { total = std::accumulate(partial.begin(), partial.end(), std::int64_t{0}); });
    for (int part = 0; part < 8; ++part) {
      auto task = graph.emplace([&partial, part] {
        partial[part] = pear::parallel_reduce(
            0, 10000, 100, std::int64_t{0}, [](int i) { return std::int64_t{i}; },
            [](std::int64_t a, std::int64_t b) { return a + b; });
      });
      task.precede(sum);
    }
    executor.run(graph).wait();
    EXPECT_EQ(total, 8 * (std::int64_t{10000} * 9999 / 2)) << "concurrency " << concurrency;
  }
}

TEST(TaskGraph, CycleIsRejectedNamingATaskOnIt) {
  pear::Executor executor(2);
  pear::TaskGraph graph;
  auto a = graph.emplace([] {});
  auto b = graph.emplace([] {});
  auto c = graph.emplace([] {});
  auto d = graph.emplace([] {});
  a.precede(b);
  b.precede(c);
  c.precede(d, b);  // b -> c -> b
  try {
    executor.run(graph);
    FAIL() << "a cyclic graph ran";
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    EXPECT_TRUE(message.find("task 1 ") != std::string::npos ||
                message.find("task 2 ") != std::string::npos)
        << message;
  }
  pear::TaskGraph loop;
  auto self = loop.emplace([] {});
  self.precede(self);
  EXPECT_THROW(executor.run(loop), std::invalid_argument);
}

TEST(TaskGraph, EdgesAcrossGraphsAreRejected) {
  pear::TaskGraph one;
  pear::TaskGraph two;
  auto a = one.emplace([] {});
  auto b = two.emplace([] {});
  EXPECT_THROW(a.precede(b), std::invalid_argument);
}

TEST(TaskGraph, EmptyGraphIsReadyAtOnce) {
  pear::Executor executor(1);
  pear::TaskGraph graph;
  auto future = executor.run(graph);
  EXPECT_TRUE(future.ready());
  EXPECT_NO_THROW(future.wait());
  EXPECT_FALSE(future.cancelled());
}

TEST(TaskGraph, MoveOnlyTaskBodiesWork) {
  pear::Executor executor(2);
  pear::TaskGraph graph;
  int seen = 0;
  auto value = std::make_unique<int>(42);
  graph.emplace([&seen, value = std::move(value)] { seen = *value; });
  executor.run(graph).wait();
  EXPECT_EQ(seen, 42);
}

TEST(TaskGraph, DroppedFutureWaitsForItsRun) {
  pear::Executor executor(2);
  Chain chain(under_tsan ? 200 : 2000);
  { auto future = executor.run(chain.graph); }
  for (const auto& ran : chain.ran) ASSERT_EQ(ran.load(), 1);
}

TEST(TaskGraph, ExecutorDestroyedWithARunInFlight) {
  // The run is cancelled and drained: what ran is a prefix of the chain, the rest skipped.
  for (std::size_t concurrency : {1u, 2u, 8u}) {
    Chain chain(under_tsan ? 300 : 3000);
    pear::Future future;
    {
      pear::Executor executor(concurrency);
      future = executor.run(chain.graph);
    }
    EXPECT_TRUE(future.ready());
    std::size_t prefix = 0;
    while (prefix < chain.ran.size() && chain.ran[prefix].load() == 1) ++prefix;
    for (std::size_t i = prefix; i < chain.ran.size(); ++i) ASSERT_EQ(chain.ran[i].load(), 0);
    EXPECT_EQ(future.cancelled(), prefix < chain.ran.size());
  }
}

}  // namespace
