// Engines kept for reuse, so that a Triangulator made for one call (pear::triangulate) or a
// batch worker costs what a reused one does: no allocation once the pool is warm.
#pragma once

#include <memory>

#include "engine.hpp"

namespace pear::detail {

/// An engine from the pool, or a new one. `vertices`, the polygon's size where it is known:
/// a polygon whose run leaves a large engine (Engine::footprint_after) takes the pool's large
/// engine first, a small one never takes it.
std::unique_ptr<Engine> acquire_engine(std::size_t vertices = 0);
/// Back to the pool: up to 64 engines sized for small polygons, and the last engine sized for a
/// large one (without it, pear::triangulate on large polygons one after another built and freed
/// all of an engine's memory at every call: Eurasia at 16 threads 219 against 155 ms a call).
/// Engines beyond those are freed.
void release_engine(std::unique_ptr<Engine> engine) noexcept;
/// Frees every engine the pool keeps (pear::release_cached_engines).
void release_pooled_engines() noexcept;

/// Takes an engine for a scope.
class PooledEngine {
 public:
  PooledEngine() : engine_(acquire_engine()) {}
  ~PooledEngine() { release_engine(std::move(engine_)); }
  PooledEngine(const PooledEngine&) = delete;
  PooledEngine& operator=(const PooledEngine&) = delete;
  Engine& operator*() { return *engine_; }
  Engine* operator->() { return engine_.get(); }

 private:
  std::unique_ptr<Engine> engine_;
};

}  // namespace pear::detail
