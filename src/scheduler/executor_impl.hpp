// The executor's insides: per-thread deques, the shared queue, the idle gate.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "pear/scheduler.hpp"
#include "pear/work_stealing_deque.hpp"

namespace pear::detail {

/// Where idle threads sleep without losing a wake-up: prepare (announce), re-check every place
/// work or completion can appear, then commit (sleep unless the epoch moved since prepare).
/// A notifier publishes first, then calls notify: the seq_cst fences on both sides make at
/// least one of them see the other (Dekker), so no sleeper misses work published before it.
class IdleGate {
 public:
  std::uint64_t prepare_wait() noexcept {
    waiters_.fetch_add(1, std::memory_order_seq_cst);
    fence(std::memory_order_seq_cst);  // our announcement before our re-check's loads
    return epoch_.load(std::memory_order_seq_cst);
  }
  void cancel_wait() noexcept { waiters_.fetch_sub(1, std::memory_order_relaxed); }
  void commit_wait(std::uint64_t ticket) {
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return epoch_.load(std::memory_order_relaxed) != ticket; });
    }
    waiters_.fetch_sub(1, std::memory_order_relaxed);
  }
  /// Wakes up to count sleepers (cheap when none sleeps: a fence and a load).
  void notify(std::size_t count) {
    fence(std::memory_order_seq_cst);  // the published work before our load of waiters
    const std::uint32_t waiting = waiters_.load(order(std::memory_order_relaxed));
    if (waiting == 0) return;
    {
      // Under the mutex, so a sleeper between its predicate check and its sleep cannot miss it.
      std::lock_guard lock(mutex_);
      epoch_.fetch_add(1, std::memory_order_seq_cst);
    }
    if (count >= waiting) {
      wake_.notify_all();
    } else {
      for (std::size_t i = 0; i < count; ++i) wake_.notify_one();
    }
  }
  void notify_all() { notify(static_cast<std::size_t>(-1)); }

 private:
  alignas(64) std::atomic<std::uint32_t> waiters_{0};
  std::atomic<std::uint64_t> epoch_{0};
  std::mutex mutex_;
  std::condition_variable wake_;
};

/// A deque and its owner-only stealing state. Worker slots belong to one thread for life;
/// external slots to whichever outside thread claimed them for a ThreadScope.
struct Slot {
  WorkStealingDeque<Job*> deque{256};
  std::atomic<bool> claimed{false};
  std::size_t last_victim = static_cast<std::size_t>(-1);
};

class ExecutorImpl {
 public:
  ExecutorImpl(Executor& self, std::size_t concurrency);
  ExecutorImpl(const ExecutorImpl&) = delete;
  ExecutorImpl& operator=(const ExecutorImpl&) = delete;
  /// Cancels and drains graph runs in flight, then stops and joins the workers.
  void shut_down();

  /// Pushes onto this thread's deque (the shared queue without one); the caller then wakes
  /// sleepers with gate.notify(count), once for a batch.
  void push(Job* job);
  /// push, then wake one sleeper.
  void spawn(Job* job);
  void help_until(WaitCounter& counter);

  Slot* claim_external_slot() noexcept;
  void release_external_slot(Slot* slot) noexcept;

  Executor& self;
  const std::size_t concurrency;
  IdleGate gate;
  WaitCounter runs_in_flight;
  std::atomic<bool> shutting_down{false};  // runs skip their tasks from now on

 private:
  void worker_loop(Slot& own);
  Slot* own_slot() const noexcept;
  Job* find_work(Slot* own);
  Job* steal(Slot* own);
  Job* take_shared();
  bool work_visible() const noexcept;
  bool spin_for_work(Slot* own, const WaitCounter* counter);

  std::vector<std::unique_ptr<Slot>> slots_;  // workers' first, then the external ones
  std::size_t workers_;
  std::mutex shared_mutex_;
  std::deque<Job*> shared_;  // from threads without a slot
  std::atomic<std::size_t> shared_count_{0};
  std::atomic<bool> stopping_{false};
  std::vector<std::jthread> threads_;
};

}  // namespace pear::detail
