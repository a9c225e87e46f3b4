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

detail::FlatPolygon& Triangulator::input_buffer() {
  if (!engine_) engine_ = detail::acquire_engine();
  return engine_->input_buffer();
}

std::vector<std::array<std::uint32_t, 3>>& Triangulator::triangle_buffer() {
  if (!engine_) engine_ = detail::acquire_engine();
  return engine_->triangle_buffer();
}

Status Triangulator::run(const PolygonView& polygon, const Options& options,
                         std::vector<std::array<std::uint32_t, 3>>& triangles,
                         std::vector<Diagnostic>& diagnostics, DelaunayStatistics& delaunay) {
  if (!engine_) engine_ = detail::acquire_engine();
  if (options.profile) options.profile->phases.clear();
  return engine_->run(polygon, options, triangles, diagnostics, delaunay);
}

EarStatistics Triangulator::run_statistics(const PolygonView& polygon) {
  if (!engine_) engine_ = detail::acquire_engine();
  return engine_->statistics(polygon);
}

}  // namespace pear
