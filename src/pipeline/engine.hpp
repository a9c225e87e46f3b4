// One run of the pipeline: clean -> check -> bridge -> clip (sequential or a parallel
// variant) -> CDT. The stages are functions of the algorithm folders; the engine owns their
// buffers, so a reused engine allocates nothing once warm.
#pragma once

#include <vector>

#include "clean.hpp"
#include "core/stage.hpp"
#include "earclip/bridge.hpp"
#include "earclip/ear_clipper.hpp"
#include "earclip/touching.hpp"
#include "simplicity/simplicity.hpp"

namespace pear::detail {

class Engine {
 public:
  Status triangulate(const PolygonView& input, const Options& options, const RunContext& ctx,
                     TriangleList& out, std::vector<Diagnostic>& diagnostics,
                     DelaunayStatistics& delaunay);
  EarStatistics statistics(const PolygonView& input);

 private:
  /// Cleans and bridges; returns false when nothing can be triangulated.
  bool prepare(const PolygonView& input, bool check_simplicity, const RunContext& ctx,
               std::vector<Diagnostic>& diagnostics, Status& status);
  /// Clips the prepared boundary with `algorithm`; false when a best-effort fallback acted.
  bool clip(Algorithm algorithm, const Options& options, const RunContext& ctx, TriangleList& out,
            std::uint32_t& best_effort_vertex);
  /// The algorithm on the first cycle, the sequential engine on what it leaves.
  bool clip_main(Algorithm algorithm, const Options& options, const RunContext& ctx,
                 TriangleList& out, std::uint32_t& best_effort_vertex);
  Diagnostic locate(const PolygonView& input, Issue issue, std::uint32_t caller_index) const;

  CleanPolygon clean_;
  Boundary boundary_;
  SimplicityCheck simplicity_;
  HoleBridger bridger_;
  TouchingPoints touching_;
  std::vector<std::uint32_t> cycles_;  ///< one node per region to clip, the main one first
  Boundary part_;                      ///< a region copied out of boundary_
  EarClipper clipper_;
};

}  // namespace pear::detail
