// The work-stealing executor: worker threads, victim selection, idling, thread scopes.
#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>

#include "executor_impl.hpp"

namespace pear::detail {
namespace {

/// Which executor this thread works for right now, and its deque there (null: shared queue).
struct ThreadContext {
  ExecutorImpl* executor = nullptr;
  Slot* slot = nullptr;
};
thread_local ThreadContext context;

/// Victim selection only needs cheap, per-thread, well-spread numbers: xorshift64.
std::size_t next_random() {
  thread_local std::uint64_t state =
      std::hash<std::thread::id>{}(std::this_thread::get_id()) * 0x9e3779b97f4a7c15ull | 1;
  state ^= state << 13;
  state ^= state >> 7;
  state ^= state << 17;
  return static_cast<std::size_t>(state);
}

void cpu_relax() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

// Outside threads (those not in the pool) that wait get a deque of their own while they wait,
// as long as one of these is free; the rest share a locked queue.
constexpr std::size_t external_slots = 4;
// Idle rounds before sleeping: a few with pause, a few yielding the core (oversubscription).
constexpr int spin_rounds = 16;
constexpr int pause_rounds = 8;

}  // namespace

ExecutorImpl::ExecutorImpl(Executor& owner, std::size_t threads)
    : self(owner), concurrency(threads), workers_(threads - 1) {
  for (std::size_t i = 0; i < workers_ + external_slots; ++i) {
    slots_.push_back(std::make_unique<Slot>());
  }
  threads_.reserve(workers_);
  try {
    for (std::size_t i = 0; i < workers_; ++i) {
      threads_.emplace_back([this, i] { worker_loop(*slots_[i]); });
    }
  } catch (...) {
    stopping_.store(true, std::memory_order_seq_cst);
    gate.notify_all();
    threads_.clear();
    throw;
  }
}

void ExecutorImpl::shut_down() {
  shutting_down.store(true, std::memory_order_seq_cst);
  {
    ThreadScope scope(*this);
    help_until(runs_in_flight);
  }
  stopping_.store(true, std::memory_order_seq_cst);
  gate.notify_all();
  threads_.clear();  // joins; workers leave only when no work is visible
}

void ExecutorImpl::worker_loop(Slot& own) {
  context = {this, &own};
  for (;;) {
    if (Job* job = find_work(&own)) {
      job->execute(job);
      continue;
    }
    if (spin_for_work(&own, nullptr)) continue;
    gate.prepare_wait(own.waiter);
    if (work_visible()) {
      gate.cancel_wait(own.waiter);
      continue;
    }
    if (stopping_.load(std::memory_order_seq_cst)) {
      gate.cancel_wait(own.waiter);
      return;
    }
    gate.commit_wait(own.waiter);
  }
}

void ExecutorImpl::help_until(WaitCounter& counter) {
  Slot* own = own_slot();
  IdleGate::Waiter waiter;
  while (!counter.done()) {
    if (Job* job = find_work(own)) {
      job->execute(job);
      continue;
    }
    if (spin_for_work(own, &counter)) continue;
    if (!counter.mark_sleeper()) break;
    gate.prepare_wait(waiter);
    if (counter.done() || work_visible()) {
      gate.cancel_wait(waiter);
      continue;
    }
    gate.commit_wait(waiter);
  }
  counter.clear_sleeper();
}

bool ExecutorImpl::spin_for_work(Slot* own, const WaitCounter* counter) {
  for (int round = 0; round < spin_rounds; ++round) {
    if (counter != nullptr && counter->done()) return true;
    if (Job* job = find_work(own)) {
      job->execute(job);
      return true;
    }
    if (round < pause_rounds) {
      for (int i = 0; i < 32; ++i) cpu_relax();
    } else {
      std::this_thread::yield();
    }
  }
  return false;
}

Slot* ExecutorImpl::own_slot() const noexcept {
  return context.executor == this ? context.slot : nullptr;
}

void ExecutorImpl::push(Job* job) noexcept {
  if (Slot* own = own_slot()) {
    own->deque.push(job);
    return;
  }
  std::lock_guard lock(shared_mutex_);
  shared_.push_back(job);
  shared_count_.fetch_add(1, std::memory_order_seq_cst);
}

void ExecutorImpl::spawn(Job* job) noexcept {
  push(job);
  gate.notify(1);
}

Job* ExecutorImpl::find_work(Slot* own) {
  if (own != nullptr) {
    if (auto job = own->deque.pop()) return *job;
  }
  if (Job* job = steal(own)) return job;
  return take_shared();
}

Job* ExecutorImpl::steal(Slot* own) {
  const std::size_t count = slots_.size();
  // The last victim that had work first: work tends to stay where it was spawned.
  if (own != nullptr && own->last_victim < count) {
    if (auto job = slots_[own->last_victim]->deque.steal()) return *job;
  }
  // Then every other deque, from a random start so thieves spread out.
  const std::size_t start = next_random() % count;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t victim = (start + k) % count;
    Slot& slot = *slots_[victim];
    if (&slot == own || slot.deque.empty()) continue;
    if (auto job = slot.deque.steal()) {
      if (own != nullptr) own->last_victim = victim;
      return *job;
    }
  }
  return nullptr;
}

Job* ExecutorImpl::take_shared() {
  if (shared_count_.load(order(std::memory_order_relaxed)) == 0) return nullptr;
  std::lock_guard lock(shared_mutex_);
  if (shared_.empty()) return nullptr;
  Job* job = shared_.front();
  shared_.pop_front();
  shared_count_.fetch_sub(1, std::memory_order_relaxed);
  return job;
}

bool ExecutorImpl::work_visible() const noexcept {
  if (shared_count_.load(std::memory_order_seq_cst) != 0) return true;
  return std::any_of(slots_.begin(), slots_.end(),
                     [](const auto& slot) { return !slot->deque.empty(); });
}

Slot* ExecutorImpl::claim_external_slot() noexcept {
  for (std::size_t i = workers_; i < slots_.size(); ++i) {
    Slot& slot = *slots_[i];
    bool expected = false;
    // acquire: we see everything the previous owner did with this deque.
    if (!slot.claimed.load(std::memory_order_relaxed) &&
        slot.claimed.compare_exchange_strong(expected, true, std::memory_order_acquire)) {
      return &slot;
    }
  }
  return nullptr;
}

void ExecutorImpl::release_external_slot(Slot* slot) noexcept {
  slot->claimed.store(false, std::memory_order_release);
}

ThreadScope::ThreadScope(ExecutorImpl& executor) {
  if (context.executor == &executor) return;
  saved_executor_ = context.executor;
  saved_slot_ = context.slot;
  entered_ = true;
  context = {&executor, executor.claim_external_slot()};
}

ThreadScope::~ThreadScope() {
  if (!entered_) return;
  if (context.slot != nullptr) context.executor->release_external_slot(context.slot);
  context = {saved_executor_, static_cast<Slot*>(saved_slot_)};
}

void spawn(ExecutorImpl& executor, Job* job) noexcept {
  executor.spawn(job);
}
void wake_waiters(ExecutorImpl& executor) noexcept {
  executor.gate.notify_all();
}
ExecutorImpl& impl_of(Executor& executor) noexcept {
  return *executor.impl_;
}

}  // namespace pear::detail

namespace pear {

Executor::Executor(std::size_t concurrency) {
  if (concurrency > 4096) {
    throw std::invalid_argument("pear::Executor: concurrency " + std::to_string(concurrency) +
                                " is above the limit of 4096");
  }
  impl_ = std::make_unique<detail::ExecutorImpl>(*this, std::max<std::size_t>(1, concurrency));
}

Executor::~Executor() {
  impl_->shut_down();
}

std::size_t Executor::concurrency() const noexcept {
  return impl_->concurrency;
}

Executor& default_executor() {
  static Executor executor;
  return executor;
}

Executor& current_executor() {
  return detail::context.executor != nullptr ? detail::context.executor->self : default_executor();
}

}  // namespace pear
