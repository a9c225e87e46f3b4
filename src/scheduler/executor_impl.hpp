// The executor's insides: per-thread deques, the shared queue, the idle gate.
#pragma once

#include <algorithm>
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
#include "work_stealing_deque.hpp"

namespace pear::detail {

/// Where idle threads sleep without losing a wake-up: prepare (announce), re-check every place
/// work or completion can appear, then commit (sleep until signalled) or cancel. A notifier
/// publishes first, then calls notify: the seq_cst fences on both sides make at least one of
/// them see the other (Dekker), so no sleeper misses work published before it slept.
/// Each sleeper has its own record; a notifier takes records off the list as it signals them,
/// so a burst of pushes wakes each sleeper once rather than signalling the same one again.
class IdleGate {
 public:
  struct Waiter {
    std::condition_variable wake;
    bool signalled = false;  // under the gate's mutex
  };

  void prepare_wait(Waiter& waiter) {
    {
      std::lock_guard lock(mutex_);
      waiter.signalled = false;
      sleepers_.push_back(&waiter);
      waiters_.fetch_add(1, std::memory_order_seq_cst);
    }
    fence(std::memory_order_seq_cst);  // our announcement before our re-check's loads
  }
  void cancel_wait(Waiter& waiter) {
    std::lock_guard lock(mutex_);
    if (waiter.signalled) return;  // a notifier took us off the list already
    sleepers_.erase(std::find(sleepers_.begin(), sleepers_.end(), &waiter));
    waiters_.fetch_sub(1, std::memory_order_relaxed);
  }
  void commit_wait(Waiter& waiter) {
    std::unique_lock lock(mutex_);
    waiter.wake.wait(lock, [&] { return waiter.signalled; });
  }
  /// Wakes up to count sleepers (cheap when none sleeps: a fence and a load).
  void notify(std::size_t count) noexcept {
    fence(std::memory_order_seq_cst);  // the published work before our load of waiters
    if (waiters_.load(order(std::memory_order_relaxed)) == 0) return;
    std::lock_guard lock(mutex_);
    for (; count > 0 && !sleepers_.empty(); --count) {
      Waiter* waiter = sleepers_.back();  // the latest sleeper: its cache is the warmest
      sleepers_.pop_back();
      waiters_.fetch_sub(1, std::memory_order_relaxed);
      waiter->signalled = true;
      waiter->wake.notify_one();  // under the mutex: the waiter may be gone right after
    }
  }
  void notify_all() noexcept { notify(static_cast<std::size_t>(-1)); }

 private:
  alignas(64) std::atomic<std::uint32_t> waiters_{0};
  std::mutex mutex_;
  std::vector<Waiter*> sleepers_;
};

/// A deque and its owner-only stealing state. Worker slots belong to one thread for life;
/// external slots to whichever outside thread claimed them for a ThreadScope.
struct Slot {
  WorkStealingDeque<Job*> deque{256};
  std::atomic<bool> claimed{false};
  std::size_t last_victim = static_cast<std::size_t>(-1);
  IdleGate::Waiter waiter;  // the owner's sleeping record
};

class ExecutorImpl {
 public:
  ExecutorImpl(Executor& self, std::size_t concurrency);
  ExecutorImpl(const ExecutorImpl&) = delete;
  ExecutorImpl& operator=(const ExecutorImpl&) = delete;
  /// Cancels and drains graph runs in flight, then stops and joins the workers.
  void shut_down();

  /// Pushes onto this thread's deque (the shared queue without one); the caller then wakes
  /// sleepers with gate.notify(count), once for a batch. A job that cannot be queued (out of
  /// memory) would leave its group or run waiting forever: that terminates instead.
  void push(Job* job) noexcept;
  /// push, then wake one sleeper.
  void spawn(Job* job) noexcept;
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
