#include "stage.hpp"

namespace pear::detail {

void RunContext::run_profiled(const char* phase, std::size_t count, TaskFunction task) const {
  using Clock = std::chrono::steady_clock;
  const auto since = [](Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  const std::size_t recorded = profile->phases.size();
  profile->phases.push_back({phase, std::vector<double>(count, 0.0)});
  // The times' buffer, not the vector: a task that records phases of its own (nested runs) may
  // move the vector, never its buffer.
  double* const times = profile->phases.back().task_seconds.data();
  const auto timed = [&](std::size_t i) {
    const auto start = Clock::now();
    task(i);
    times[i] = since(start);
  };
  const auto start = Clock::now();
  if (parallel() && count > 1)
    runner->run(count, timed);
  else
    for (std::size_t i = 0; i < count; ++i) timed(i);
  profile->phases[recorded].wall_seconds = since(start);  // by index, for the same reason
}

void RunContext::run_out_of_line(const char* phase, std::size_t count, TaskFunction task) const {
  if (profile) return run_profiled(phase, count, task);
  if (parallel() && count > 1)
    runner->run(count, task);
  else
    for (std::size_t i = 0; i < count; ++i) task(i);
}

}  // namespace pear::detail
