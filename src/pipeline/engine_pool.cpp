#include "engine_pool.hpp"

#include <vector>

#include "threading.hpp"

namespace pear::detail {
namespace {

/// Engines whose buffers were sized for more vertices than this are large: the pool keeps one.
constexpr std::size_t kept_footprint = 1 << 16;
constexpr std::size_t kept_engines = 64;

struct Pool {
  // Room for every engine kept, made once: keeping one then never allocates; only a lock that
  // fails can throw in release_engine (caught where exceptions exist; WebAssembly has none).
  Pool() { engines.reserve(kept_engines); }
  std::vector<std::unique_ptr<Engine>> engines;  ///< small
  std::unique_ptr<Engine> large;                 ///< the last large engine released
};

Pool& pool() {
  static Pool instance;
  return instance;
}

/// Keeps `engine` (under the pool's lock); what it replaces or cannot keep is left in `engine`,
/// to be freed after the lock.
void keep(Pool& p, std::unique_ptr<Engine>& engine) {
  if (engine->footprint() > kept_footprint)
    std::swap(p.large, engine);  // the last large one: the next large call is likely its size
  else if (p.engines.size() < kept_engines)
    p.engines.push_back(std::move(engine));
}

}  // namespace

std::unique_ptr<Engine> acquire_engine(std::size_t vertices) {
  Pool& p = pool();
  {
    const PoolLock lock;
    // By the measure keep() sorts by: a polygon of 22,000 to 65,536 vertices leaves a large
    // engine, and took a new one at every call while the test was the vertex count (Borneo's
    // 53,410 through pear::triangulate: 0.5 ms a call building and freeing one).
    if (Engine::footprint_after(vertices) > kept_footprint && p.large) return std::move(p.large);
    if (!p.engines.empty()) {
      std::unique_ptr<Engine> engine = std::move(p.engines.back());
      p.engines.pop_back();
      return engine;
    }
  }
  return std::make_unique<Engine>();
}

void release_engine(std::unique_ptr<Engine> engine) noexcept {
  if (!engine) return;
  engine->workers().release();  // no threads kept in the pool
  Pool& p = pool();
#if defined(__cpp_exceptions)
  try {
    const PoolLock lock;
    keep(p, engine);
  } catch (...) {
    // The lock failed (std::system_error): the engine is freed, which is all keeping saves.
  }
#else
  const PoolLock lock;
  keep(p, engine);
#endif
}

void release_pooled_engines() noexcept {
  // Freed after the lock (locals go in reverse order: the lock first).
  std::vector<std::unique_ptr<Engine>> freed;
  std::unique_ptr<Engine> large;
  Pool& p = pool();
  const auto take_all = [&] {
    for (std::unique_ptr<Engine>& engine : p.engines) freed.push_back(std::move(engine));
    p.engines.clear();  // keeps its room: keeping an engine later still never allocates
    large = std::move(p.large);
  };
#if defined(__cpp_exceptions)
  try {
    freed.reserve(kept_engines);  // before the lock: moving the engines out cannot throw
    const PoolLock lock;
    take_all();
  } catch (...) {
    // No room or no lock: nothing is freed.
  }
#else
  freed.reserve(kept_engines);
  const PoolLock lock;
  take_all();
#endif
}

}  // namespace pear::detail
