// Workers and PoolLock without threads (-Dthreads=disabled; threading.hpp): every task runs
// on the calling thread, and the engine pool needs no lock.
#include "threading.hpp"

namespace pear::detail {

struct Workers::State {};

Workers::Workers() noexcept = default;
Workers::~Workers() = default;
Workers::Workers(Workers&&) noexcept = default;
Workers& Workers::operator=(Workers&&) noexcept = default;

/// As the threaded build with that many threads: partitions 0 means Options::threads (one
/// when that is 0), so the output is the threaded build's for the same options.
std::uint32_t Workers::concurrency(const Options& options) {
  return options.threads != 0 ? options.threads : 1;
}

Executor* Workers::executor(const Options&) {
  return nullptr;
}

const TaskRunner* Workers::runner(const Options&) {
  return nullptr;
}

void Workers::release() noexcept {}

PoolLock::PoolLock() = default;
PoolLock::~PoolLock() = default;

}  // namespace pear::detail
