// What the pipeline takes from threads: where a run's tasks go (Options::executor, pear's
// default executor, or a private one for Options::threads) and the engine pool's lock. The
// build's `threads` option picks the implementation: threads_on.cpp on pear's scheduler, or
// threads_off.cpp, with no thread at all (every task on the calling thread, same output as
// threads = 1).
#pragma once

#include <cstdint>
#include <memory>

#include "core/tasks.hpp"
#include "pear/options.hpp"

namespace pear::detail {

class Workers {
 public:
  Workers() noexcept;
  ~Workers();
  Workers(Workers&&) noexcept;
  Workers& operator=(Workers&&) noexcept;

  /// What Options::partitions 0 stands for: the concurrency of the executor a run with these
  /// options would use (nothing is created to find it).
  static std::uint32_t concurrency(const Options& options);
  /// The executor a run with these options uses, created on first use; nullptr for one thread
  /// (and always without threads). A private one, for Options::threads, is kept here.
  Executor* executor(const Options& options);
  /// Where such a run's tasks go: the executor above as a TaskRunner, or nullptr.
  const TaskRunner* runner(const Options& options);
  /// Frees a private executor's threads: an engine kept in the pool holds none.
  void release() noexcept;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// Holds the engine pool's lock for a scope (a mutex with threads, nothing without).
class PoolLock {
 public:
  PoolLock();
  ~PoolLock();
  PoolLock(const PoolLock&) = delete;
  PoolLock& operator=(const PoolLock&) = delete;
};

}  // namespace pear::detail
