#include "stage.hpp"

namespace pear::detail {

void RunContext::run_profiled(const char* phase, std::size_t count, TaskFunction task) const {
  using Clock = std::chrono::steady_clock;
  const auto since = [](Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  const std::size_t recorded = profile->phases.size();
  profile->phases.push_back({phase, std::vector<double>(count, 0.0)});
  std::vector<double>* times = &profile->phases.back().task_seconds;
  const auto timed = [&](std::size_t i) {
    const auto start = Clock::now();
    task(i);
    (*times)[i] = since(start);
  };
  const auto start = Clock::now();
  if (parallel() && count > 1)
    runner->run(count, timed);
  else
    for (std::size_t i = 0; i < count; ++i) timed(i);
  // By index: a task may record phases of its own (nested runs) and move the vector.
  profile->phases[recorded].wall_seconds = since(start);
}

}  // namespace pear::detail
