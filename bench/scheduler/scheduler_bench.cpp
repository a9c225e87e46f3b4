// pear's scheduler against oneTBB (when found) and a serial loop, on the same workloads.
// Names are Workload/Runner: bench/scheduler/report.py turns a JSON run into the ratio table.
//   pear2 / tbb2: 2 threads (this machine's cores); pear1 / tbb1: 1 thread; serial: a plain loop.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "pear/scheduler.hpp"

#if defined(PEAR_BENCH_WITH_TBB)
#include <tbb/blocked_range.h>
#include <tbb/flow_graph.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <tbb/task_group.h>
#endif

namespace {

constexpr int empty_tasks = 10000;
constexpr int fib_n = 30;
constexpr std::size_t light_items = 10'000'000;
constexpr std::size_t heavy_items = 10'000;
constexpr int dag_width = 10000;

pear::Executor& pear_executor(int threads) {
  static pear::Executor two(2);
  static pear::Executor one(1);
  return threads == 1 ? one : two;
}

// A light item: a few flops on one float (memory traffic dominates).
inline void light_item(std::vector<float>& data, std::size_t i) {
  data[i] = data[i] * 0.5f + 1.0f;
}

// A heavy item: a few µs of dependent arithmetic, no memory traffic.
inline double heavy_item(std::size_t i) {
  double x = static_cast<double>(i) * 1e-4 + 1.0;
  for (int k = 0; k < 500; ++k) x = std::sqrt(x * 1.000001 + 0.5);
  return x;
}

// A DAG task: about 0.3 µs.
inline double dag_item(int i) {
  double x = i;
  for (int k = 0; k < 100; ++k) x = x * 0.999 + 1.0;
  return x;
}

// ---- per-task overhead: spawn and run empty tasks, then wait ----

void task_overhead_pear(benchmark::State& state) {
  pear::Executor& executor = pear_executor(2);
  for (auto _ : state) {
    pear::TaskGroup group(executor);
    for (int i = 0; i < empty_tasks; ++i) group.run([] {});
    group.wait();
  }
  state.SetItemsProcessed(state.iterations() * empty_tasks);
}
BENCHMARK(task_overhead_pear)->Name("task_overhead/pear2")->UseRealTime();

// ---- recursive spawning: fib with a spawn at every level ----

std::uint64_t fib_pear(int n) {
  if (n < 2) return static_cast<std::uint64_t>(n);
  std::uint64_t left = 0;
  pear::TaskGroup group;
  group.run([&left, n] { left = fib_pear(n - 1); });
  const std::uint64_t right = fib_pear(n - 2);
  group.wait();
  return left + right;
}

std::uint64_t fib_serial(int n) {
  return n < 2 ? static_cast<std::uint64_t>(n) : fib_serial(n - 1) + fib_serial(n - 2);
}

void fib_pear_bench(benchmark::State& state) {
  pear::Executor& executor = pear_executor(2);
  for (auto _ : state) {
    std::uint64_t result = 0;
    pear::TaskGroup group(executor);
    group.run([&] { result = fib_pear(fib_n); });
    group.wait();
    benchmark::DoNotOptimize(result);
  }
}
BENCHMARK(fib_pear_bench)->Name("fib30/pear2")->UseRealTime()->Unit(benchmark::kMillisecond);

void fib_serial_bench(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(fib_serial(fib_n));
}
BENCHMARK(fib_serial_bench)->Name("fib30/serial")->UseRealTime()->Unit(benchmark::kMillisecond);

// ---- parallel_for: 10^7 light items, 10^4 heavy ones ----

void light_pear(benchmark::State& state) {
  pear::Executor& executor = pear_executor(static_cast<int>(state.range(0)));
  std::vector<float> data(light_items, 1.0f);
  for (auto _ : state) {
    pear::parallel_for(executor, std::size_t{0}, light_items, 0,
                       [&](std::size_t i) { light_item(data, i); });
    benchmark::ClobberMemory();
  }
}
BENCHMARK(light_pear)
    ->Name("for_light/pear2")
    ->Arg(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(light_pear)
    ->Name("for_light/pear1")
    ->Arg(1)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

void light_serial(benchmark::State& state) {
  std::vector<float> data(light_items, 1.0f);
  for (auto _ : state) {
    for (std::size_t i = 0; i < light_items; ++i) light_item(data, i);
    benchmark::ClobberMemory();
  }
}
BENCHMARK(light_serial)->Name("for_light/serial")->UseRealTime()->Unit(benchmark::kMillisecond);

void heavy_pear(benchmark::State& state) {
  pear::Executor& executor = pear_executor(static_cast<int>(state.range(0)));
  std::vector<double> out(heavy_items);
  for (auto _ : state) {
    pear::parallel_for(executor, std::size_t{0}, heavy_items, 0,
                       [&](std::size_t i) { out[i] = heavy_item(i); });
    benchmark::ClobberMemory();
  }
}
BENCHMARK(heavy_pear)
    ->Name("for_heavy/pear2")
    ->Arg(2)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(heavy_pear)
    ->Name("for_heavy/pear1")
    ->Arg(1)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

void heavy_serial(benchmark::State& state) {
  std::vector<double> out(heavy_items);
  for (auto _ : state) {
    for (std::size_t i = 0; i < heavy_items; ++i) out[i] = heavy_item(i);
    benchmark::ClobberMemory();
  }
}
BENCHMARK(heavy_serial)->Name("for_heavy/serial")->UseRealTime()->Unit(benchmark::kMillisecond);

// ---- a wide DAG: one source, dag_width independent tasks, one sink; built once ----

void dag_pear(benchmark::State& state) {
  pear::Executor& executor = pear_executor(2);
  std::vector<double> out(dag_width);
  pear::TaskGraph graph;
  auto source = graph.emplace([] {});
  auto sink = graph.emplace([] {});
  for (int i = 0; i < dag_width; ++i) {
    auto task = graph.emplace([&out, i] { out[i] = dag_item(i); });
    source.precede(task);
    task.precede(sink);
  }
  for (auto _ : state) {
    executor.run(graph).wait();
    benchmark::ClobberMemory();
  }
}
BENCHMARK(dag_pear)->Name("wide_dag/pear2")->UseRealTime()->Unit(benchmark::kMillisecond);

void dag_serial(benchmark::State& state) {
  std::vector<double> out(dag_width);
  for (auto _ : state) {
    for (int i = 0; i < dag_width; ++i) out[i] = dag_item(i);
    benchmark::ClobberMemory();
  }
}
BENCHMARK(dag_serial)->Name("wide_dag/serial")->UseRealTime()->Unit(benchmark::kMillisecond);

void task_overhead_serial(benchmark::State& state) {
  // The same closures called in a loop through an opaque pointer: what "no scheduler" costs.
  std::vector<void (*)()> calls(empty_tasks, [] {});
  for (auto _ : state) {
    for (auto* call : calls) {
      benchmark::DoNotOptimize(call);
      call();
    }
  }
  state.SetItemsProcessed(state.iterations() * empty_tasks);
}
BENCHMARK(task_overhead_serial)->Name("task_overhead/serial")->UseRealTime();

#if defined(PEAR_BENCH_WITH_TBB)

tbb::task_arena& tbb_arena(int threads) {
  static tbb::task_arena two(2);
  static tbb::task_arena one(1);
  return threads == 1 ? one : two;
}

void task_overhead_tbb(benchmark::State& state) {
  tbb_arena(2).execute([&] {
    for (auto _ : state) {
      tbb::task_group group;
      for (int i = 0; i < empty_tasks; ++i) group.run([] {});
      group.wait();
    }
  });
  state.SetItemsProcessed(state.iterations() * empty_tasks);
}
BENCHMARK(task_overhead_tbb)->Name("task_overhead/tbb2")->UseRealTime();

std::uint64_t fib_tbb(int n) {
  if (n < 2) return static_cast<std::uint64_t>(n);
  std::uint64_t left = 0;
  tbb::task_group group;
  group.run([&left, n] { left = fib_tbb(n - 1); });
  const std::uint64_t right = fib_tbb(n - 2);
  group.wait();
  return left + right;
}

void fib_tbb_bench(benchmark::State& state) {
  tbb_arena(2).execute([&] {
    for (auto _ : state) benchmark::DoNotOptimize(fib_tbb(fib_n));
  });
}
BENCHMARK(fib_tbb_bench)->Name("fib30/tbb2")->UseRealTime()->Unit(benchmark::kMillisecond);

void light_tbb(benchmark::State& state) {
  std::vector<float> data(light_items, 1.0f);
  tbb_arena(static_cast<int>(state.range(0))).execute([&] {
    for (auto _ : state) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, light_items), [&](const auto& range) {
        for (std::size_t i = range.begin(); i < range.end(); ++i) light_item(data, i);
      });
      benchmark::ClobberMemory();
    }
  });
}
BENCHMARK(light_tbb)->Name("for_light/tbb2")->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(light_tbb)->Name("for_light/tbb1")->Arg(1)->UseRealTime()->Unit(benchmark::kMillisecond);

void heavy_tbb(benchmark::State& state) {
  std::vector<double> out(heavy_items);
  tbb_arena(static_cast<int>(state.range(0))).execute([&] {
    for (auto _ : state) {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, heavy_items), [&](const auto& range) {
        for (std::size_t i = range.begin(); i < range.end(); ++i) out[i] = heavy_item(i);
      });
      benchmark::ClobberMemory();
    }
  });
}
BENCHMARK(heavy_tbb)->Name("for_heavy/tbb2")->Arg(2)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(heavy_tbb)->Name("for_heavy/tbb1")->Arg(1)->UseRealTime()->Unit(benchmark::kMillisecond);

void dag_tbb(benchmark::State& state) {
  // TBB's own build-once graph: a flow graph of continue_nodes.
  using tbb::flow::continue_msg;
  std::vector<double> out(dag_width);
  tbb_arena(2).execute([&] {
    tbb::flow::graph graph;
    tbb::flow::broadcast_node<continue_msg> source(graph);
    tbb::flow::continue_node<continue_msg> sink(graph,
                                                [](const continue_msg&) { return continue_msg(); });
    std::vector<std::unique_ptr<tbb::flow::continue_node<continue_msg>>> tasks;
    for (int i = 0; i < dag_width; ++i) {
      tasks.push_back(std::make_unique<tbb::flow::continue_node<continue_msg>>(
          graph, [&out, i](const continue_msg&) {
            out[i] = dag_item(i);
            return continue_msg();
          }));
      tbb::flow::make_edge(source, *tasks.back());
      tbb::flow::make_edge(*tasks.back(), sink);
    }
    for (auto _ : state) {
      source.try_put(continue_msg());
      graph.wait_for_all();
      benchmark::ClobberMemory();
    }
  });
}
BENCHMARK(dag_tbb)->Name("wide_dag/tbb2")->UseRealTime()->Unit(benchmark::kMillisecond);

#endif

}  // namespace

BENCHMARK_MAIN();
