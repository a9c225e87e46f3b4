// TaskGroup: fork-join over a set of closures, with exception capture and cancellation.
#include <memory>

#include "executor_impl.hpp"

namespace pear {

TaskGroup::TaskGroup(Executor& executor, std::stop_token stop)
    : owner_(executor), executor_(detail::impl_of(executor)), scope_(executor_) {
  if (stop.stop_possible()) link_.emplace(std::move(stop), CancelOnStop{this});
}

void TaskGroup::spawn(Executor& executor, TaskJob* job) noexcept {
  detail::spawn(detail::impl_of(executor), job);
}

void TaskGroup::wake_waiters(Executor& executor) noexcept {
  detail::wake_waiters(detail::impl_of(executor));
}

TaskGroup::~TaskGroup() {
  if (!pending_.done()) {
    cancel();
    executor_.help_until(pending_);
  }
  link_.reset();  // before the stop source its callback may touch
  delete stop_source_.load(std::memory_order_acquire);
}

void TaskGroup::wait() {
  executor_.help_until(pending_);
  if (failed_.load(std::memory_order_acquire)) {
    failed_.store(false, std::memory_order_relaxed);
    std::rethrow_exception(std::exchange(error_, nullptr));
  }
}

void TaskGroup::cancel() noexcept {
  // seq_cst store then load, against stop_token()'s seq_cst CAS then load: one of the two
  // sees the other, so a stop source created concurrently still gets the request.
  cancelled_.store(true, std::memory_order_seq_cst);
  if (auto* source = stop_source_.load(std::memory_order_seq_cst)) source->request_stop();
}

std::stop_token TaskGroup::stop_token() {
  std::stop_source* source = stop_source_.load(std::memory_order_acquire);
  if (source == nullptr) {
    auto fresh = std::make_unique<std::stop_source>();
    if (stop_source_.compare_exchange_strong(source, fresh.get(), std::memory_order_seq_cst,
                                             std::memory_order_acquire)) {
      source = fresh.release();
      if (cancelled_.load(std::memory_order_seq_cst)) source->request_stop();
    }
  }
  return source->get_token();
}

void TaskGroup::fail(std::exception_ptr error) noexcept {
  // The first exception wins; wait() reads error_ after the last arrive(), which orders it.
  if (!failed_.exchange(true, std::memory_order_acq_rel)) error_ = std::move(error);
  cancel();
}

}  // namespace pear
