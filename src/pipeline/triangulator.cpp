// pear::Triangulator: the public face of the engine. Keeps every buffer between calls.
#include "engine.hpp"
#include "pear/pear.hpp"
#include "pear/scheduler.hpp"

namespace pear {

Triangulator::Triangulator() : engine_(std::make_unique<detail::Engine>()) {}
Triangulator::~Triangulator() = default;
Triangulator::Triangulator(Triangulator&&) noexcept = default;
Triangulator& Triangulator::operator=(Triangulator&&) noexcept = default;

Status Triangulator::run(const Options& options, std::vector<Diagnostic>& diagnostics,
                         DelaunayStatistics& delaunay) {
  detail::RunContext ctx;
  ctx.profile = options.profile;
  if (options.profile) options.profile->phases.clear();
  if (options.executor) {
    ctx.executor = options.executor;
  } else if (options.threads == 0 || options.threads == default_executor().concurrency()) {
    ctx.executor = &default_executor();
  } else if (options.threads > 1) {
    if (!private_executor_ || private_executor_->concurrency() != options.threads)
      private_executor_ = std::make_unique<Executor>(options.threads);
    ctx.executor = private_executor_.get();
  }
  const std::size_t threads = ctx.executor ? ctx.executor->concurrency() : 1;
  ctx.partitions = static_cast<std::uint32_t>(options.partitions ? options.partitions : threads);
  return engine_->triangulate(PolygonView{flat_.points, flat_.ring_starts}, options, ctx,
                              triangles_, diagnostics, delaunay);
}

EarStatistics Triangulator::run_statistics() {
  return engine_->statistics(PolygonView{flat_.points, flat_.ring_starts});
}

}  // namespace pear
