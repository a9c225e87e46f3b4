// Engines kept for reuse, so that a Triangulator made for one call (pear::triangulate) or a
// batch worker costs what a reused one does: no allocation once the pool is warm.
#pragma once

#include <memory>

#include "engine.hpp"

namespace pear::detail {

/// An engine from the pool, or a new one.
std::unique_ptr<Engine> acquire_engine();
/// Back to the pool; engines sized for large polygons are freed instead (the pool never
/// holds more than a few megabytes of buffers), as are engines beyond the pool's size.
void release_engine(std::unique_ptr<Engine> engine) noexcept;

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
