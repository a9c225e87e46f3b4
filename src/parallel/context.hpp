// What the parallel variants share: where tasks run, into how many parts the work is cut, and
// the profile that records every task's time for the work/span analysis.
#pragma once

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "pear/pear.hpp"
#include "pear/scheduler.hpp"

namespace pear::detail {

struct ParallelContext {
  Executor* executor = nullptr;  ///< nullptr: tasks run one after another on this thread
  std::uint32_t partitions = 1;  ///< decides the output; the thread count never does
  EarHeuristic heuristic = EarHeuristic::top;
  RunProfile* profile = nullptr;

  bool parallel() const { return executor != nullptr && executor->concurrency() > 1; }

  /// Runs task(i) for i in [0, count) in parallel and waits; records the phase when profiling.
  template <class Task>
  void run_tasks(const char* phase, std::size_t count, Task&& task) const {
    std::vector<double>* times = nullptr;
    if (profile) {
      profile->phases.push_back({phase, std::vector<double>(count, 0.0)});
      times = &profile->phases.back().task_seconds;
    }
    const auto timed = [&](std::size_t i) {
      if (!times) return task(i);
      const auto start = std::chrono::steady_clock::now();
      task(i);
      (*times)[i] = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    if (parallel() && count > 1)
      parallel_for(*executor, std::size_t{0}, count, 1, timed);
    else
      for (std::size_t i = 0; i < count; ++i) timed(i);
  }

  /// Runs a sequential step, recorded as a phase of one task when profiling.
  template <class Step>
  void run_serial(const char* phase, Step&& step) const {
    run_tasks(phase, 1, [&](std::size_t) { step(); });
  }
};

}  // namespace pear::detail
