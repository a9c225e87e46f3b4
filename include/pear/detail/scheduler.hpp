// pear internals behind the scheduler's templates (pear/scheduler.hpp): the job record the
// deques hold, the wait counter, the thread's executor scope and the type-erased task body.
// Not API: names and layout may change in any release.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <stop_token>
#include <type_traits>
#include <utility>

#include "pear/export.hpp"

namespace pear {

class Executor;

/// What a deque holds: one function pointer, no virtual table. execute() owns the job. (In
/// pear, not pear::detail: TaskGroup's exported members name it.)
struct TaskJob {
  void (*execute)(TaskJob*);
};

namespace detail {
class ExecutorImpl;
struct RunState;
using Job = TaskJob;

/// Outstanding work of a group or run, times two; bit 0 says "a waiter may be asleep".
class WaitCounter {
 public:
  void add(std::size_t n) noexcept { state_.fetch_add(2 * n, std::memory_order_relaxed); }
  bool done() const noexcept { return state_.load(std::memory_order_acquire) < 2; }
  /// One unit done. True when it was the last one and a waiter may sleep: wake it.
  bool arrive() noexcept { return state_.fetch_sub(2, std::memory_order_seq_cst) == 3; }
  /// Before a waiter sleeps. False when already done (no need to sleep).
  bool mark_sleeper() noexcept { return state_.fetch_or(1, std::memory_order_seq_cst) >= 2; }
  void clear_sleeper() noexcept { state_.fetch_and(~std::uint64_t{1}, std::memory_order_relaxed); }

 private:
  std::atomic<std::uint64_t> state_{0};
};

/// The thread's view of an executor for a scope: it owns a deque there (or uses the shared
/// queue when all are taken). Scopes nest strictly (they live on the stack). Made and ended
/// only inside libpear (TaskGroup's constructor and destructor), so not exported.
class ThreadScope {
 public:
  explicit ThreadScope(ExecutorImpl& executor);
  ~ThreadScope();
  ThreadScope(const ThreadScope&) = delete;
  ThreadScope& operator=(const ThreadScope&) = delete;

 private:
  ExecutorImpl* saved_executor_ = nullptr;
  void* saved_slot_ = nullptr;
  bool entered_ = false;
};

// Inside libpear only (the templates reach them through TaskGroup's members): not exported.
void spawn(ExecutorImpl& executor, Job* job) noexcept;
void wake_waiters(ExecutorImpl& executor) noexcept;
ExecutorImpl& impl_of(Executor& executor) noexcept;

template <class F>
void invoke_task(F& task, const std::stop_token& stop) {
  if constexpr (std::is_invocable_v<F&, std::stop_token>) {
    task(stop);
  } else {
    task();
  }
}

/// A move-only type-erased task body (std::function would require copyable closures).
class TaskBody {
 public:
  TaskBody() = default;
  template <class F>
  explicit TaskBody(F&& task)
      : holder_(std::make_unique<Holder<std::decay_t<F>>>(std::forward<F>(task))) {}
  void operator()(const std::stop_token& stop) const {
    if (holder_) holder_->call(stop);
  }

 private:
  struct Base {
    virtual ~Base() = default;
    virtual void call(const std::stop_token& stop) = 0;
  };
  template <class F>
  struct Holder final : Base {
    explicit Holder(F&& f) : task(std::move(f)) {}
    explicit Holder(const F& f) : task(f) {}
    void call(const std::stop_token& stop) override { invoke_task(task, stop); }
    F task;
  };
  std::unique_ptr<Base> holder_;
};
}  // namespace detail

}  // namespace pear
