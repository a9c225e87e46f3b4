// Workers and PoolLock on pear's scheduler (threaded builds; threading.hpp).
#include <algorithm>
#include <mutex>
#include <thread>

#include "pear/scheduler.hpp"
#include "threading.hpp"

namespace pear::detail {
namespace {

/// The machine's hardware threads, asked once: std::thread::hardware_concurrency reads
/// /sys on Linux, which cost a county's call five times its triangulation.
unsigned hardware_threads() {
  static const unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  return threads;
}

/// The most workers a private executor gets: more than a few per hardware thread give no
/// speed, only context switches (4,096 on 2 cores made a mark-and-cut of a 50,000-vertex star
/// 20x slower than 16 did). The output depends on the partitions, never on the workers.
std::uint32_t worker_limit() {
  return std::max(16u, 4 * hardware_threads());
}

}  // namespace

/// Outside the anonymous namespace: Workers::State, which has external linkage, holds one.
class ExecutorRunner final : public TaskRunner {
 public:
  Executor* executor = nullptr;
  std::size_t concurrency() const override { return executor->concurrency(); }
  void run(std::size_t count, TaskFunction task) const override {
    parallel_for(*executor, std::size_t{0}, count, 1, task);
  }
};

namespace {

std::mutex& pool_mutex() {
  static std::mutex mutex;
  return mutex;
}

}  // namespace

struct Workers::State {
  std::unique_ptr<Executor> private_executor;
  ExecutorRunner runner;
};

Workers::Workers() noexcept = default;
Workers::~Workers() = default;
Workers::Workers(Workers&&) noexcept = default;
Workers& Workers::operator=(Workers&&) noexcept = default;

std::uint32_t Workers::concurrency(const Options& options) {
  if (options.executor) return static_cast<std::uint32_t>(options.executor->concurrency());
  if (options.threads != 0) return options.threads;
  return hardware_threads();
}

Executor* Workers::executor(const Options& options) {
  if (options.executor) return options.executor;
  if (options.threads == 1) return nullptr;
  const std::uint32_t workers = std::min(options.threads, worker_limit());
  if (options.threads == 0 || workers == default_executor().concurrency())
    return &default_executor();
  if (!state_) state_ = std::make_unique<State>();
  std::unique_ptr<Executor>& own = state_->private_executor;
  if (!own || own->concurrency() != workers) own = std::make_unique<Executor>(workers);
  return own.get();
}

const TaskRunner* Workers::runner(const Options& options) {
  Executor* const chosen = executor(options);
  if (!chosen) return nullptr;
  if (!state_) state_ = std::make_unique<State>();
  state_->runner.executor = chosen;
  return &state_->runner;
}

void Workers::release() noexcept {
  state_.reset();
}

PoolLock::PoolLock() {
  pool_mutex().lock();
}
PoolLock::~PoolLock() {
  pool_mutex().unlock();
}

}  // namespace pear::detail
