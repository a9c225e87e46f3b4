// pear::Triangulator: the public face of the engine. Its engine comes from the pool on first
// use and goes back when the Triangulator goes, so a Triangulator per call is cheap too.
#include "engine.hpp"
#include "engine_pool.hpp"
#include "pear/pear.hpp"

namespace pear {

Triangulator::Triangulator() noexcept = default;
Triangulator::~Triangulator() {
  detail::release_engine(std::move(engine_));
}
Triangulator::Triangulator(Triangulator&&) noexcept = default;
Triangulator& Triangulator::operator=(Triangulator&& other) noexcept {
  if (this != &other) {
    detail::release_engine(std::move(engine_));
    engine_ = std::move(other.engine_);
  }
  return *this;
}

void Triangulator::acquire(std::size_t vertices) {
  engine_ = detail::acquire_engine(vertices);
}

detail::FlatPolygon& Triangulator::input_buffer() {
  if (!engine_) engine_ = detail::acquire_engine();
  return engine_->buffers().input;
}

std::vector<std::array<std::uint32_t, 3>>& Triangulator::triangle_buffer() {
  if (!engine_) engine_ = detail::acquire_engine();
  return engine_->buffers().triangles;
}

namespace {

/// The one run behind every Triangulator call: an engine from the pool, the profile reset.
Status run_engine(std::unique_ptr<detail::Engine>& engine, const detail::InputPolygon& polygon,
                  const Options& options, std::vector<std::array<std::uint32_t, 3>>& triangles,
                  std::vector<Diagnostic>& diagnostics, DelaunayStatistics& delaunay) {
  if (!engine) engine = detail::acquire_engine(polygon.size());
  if (options.profile) options.profile->phases.clear();
  return engine->run(polygon, options, triangles, diagnostics, delaunay);
}

}  // namespace

Status Triangulator::run(const PolygonView& polygon, const Options& options,
                         std::vector<std::array<std::uint32_t, 3>>& triangles,
                         std::vector<Diagnostic>& diagnostics, DelaunayStatistics& delaunay) {
  return run_engine(engine_, polygon, options, triangles, diagnostics, delaunay);
}

Status Triangulator::run(const CoordinateView& polygon, const Options& options,
                         std::vector<std::array<std::uint32_t, 3>>& triangles,
                         std::vector<Diagnostic>& diagnostics, DelaunayStatistics& delaunay) {
  if (polygon.xy.size() % 2 != 0) {  // half a point at the end: no offset can end the rings
    const std::size_t rings = polygon.ring_offsets.empty() ? 0 : polygon.ring_offsets.size() - 1;
    diagnostics.push_back({Issue::invalid_offsets, rings, 0});
    return Status::invalid_input;
  }
  return run_engine(engine_, polygon, options, triangles, diagnostics, delaunay);
}

Status Triangulator::run(const detail::RingSpans& polygon, const Options& options,
                         std::vector<std::array<std::uint32_t, 3>>& triangles,
                         std::vector<Diagnostic>& diagnostics, DelaunayStatistics& delaunay) {
  return run_engine(engine_, polygon, options, triangles, diagnostics, delaunay);
}

EarStatistics Triangulator::run_statistics(const PolygonView& polygon) {
  if (!engine_) engine_ = detail::acquire_engine();
  return engine_->statistics(polygon);
}

void release_cached_engines() noexcept {
  detail::release_pooled_engines();
}

}  // namespace pear
