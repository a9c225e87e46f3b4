#include "engine_pool.hpp"

#include <vector>

#include "threading.hpp"

namespace pear::detail {
namespace {

/// Engines whose buffers were sized for more vertices than this are not kept.
constexpr std::size_t kept_footprint = 1 << 16;
constexpr std::size_t kept_engines = 64;

struct Pool {
  // Room for every engine kept, made once: keeping one then never allocates; only a lock that
  // fails can throw in release_engine (caught where exceptions exist; WebAssembly has none).
  Pool() { engines.reserve(kept_engines); }
  std::vector<std::unique_ptr<Engine>> engines;
};

Pool& pool() {
  static Pool instance;
  return instance;
}

}  // namespace

std::unique_ptr<Engine> acquire_engine() {
  Pool& p = pool();
  {
    const PoolLock lock;
    if (!p.engines.empty()) {
      std::unique_ptr<Engine> engine = std::move(p.engines.back());
      p.engines.pop_back();
      return engine;
    }
  }
  return std::make_unique<Engine>();
}

void release_engine(std::unique_ptr<Engine> engine) noexcept {
  if (!engine || engine->footprint() > kept_footprint) return;
  engine->workers().release();  // no threads kept in the pool
  Pool& p = pool();
#if defined(__cpp_exceptions)
  try {
    const PoolLock lock;
    if (p.engines.size() < kept_engines) p.engines.push_back(std::move(engine));
  } catch (...) {
    // The lock failed (std::system_error): the engine is freed, which is all keeping saves.
  }
#else
  const PoolLock lock;
  if (p.engines.size() < kept_engines) p.engines.push_back(std::move(engine));
#endif
}

}  // namespace pear::detail
