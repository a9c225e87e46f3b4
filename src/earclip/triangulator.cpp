// pear::Triangulator: the public face of the engine. Keeps every buffer between calls.
#include "engine.hpp"
#include "pear/pear.hpp"

namespace pear {

Triangulator::Triangulator() : engine_(std::make_unique<detail::Engine>()) {}
Triangulator::~Triangulator() = default;
Triangulator::Triangulator(Triangulator&&) noexcept = default;
Triangulator& Triangulator::operator=(Triangulator&&) noexcept = default;

Status Triangulator::run(const Options& options, std::vector<Diagnostic>& diagnostics) {
  return engine_->triangulate(flat_, options, triangles_, diagnostics);
}

EarStatistics Triangulator::run_statistics() {
  return engine_->statistics(flat_);
}

}  // namespace pear
