// The sequential engine: clean -> boundary with bridges -> ear clipping.
#pragma once

#include <vector>

#include "../parallel/context.hpp"
#include "bridge.hpp"
#include "clean.hpp"
#include "ear_clipper.hpp"
#include "simplicity.hpp"
#include "touching.hpp"

namespace pear::detail {

class Engine {
 public:
  Status triangulate(const FlatPolygon& input, const Options& options, const ParallelContext& ctx,
                     TriangleList& out, std::vector<Diagnostic>& diagnostics,
                     DelaunayStatistics& delaunay);
  EarStatistics statistics(const FlatPolygon& input);

 private:
  /// Cleans and bridges; returns false when nothing can be triangulated.
  bool prepare(const FlatPolygon& input, bool check_simplicity, const ParallelContext& ctx,
               std::vector<Diagnostic>& diagnostics, Status& status);
  /// Clips the prepared boundary with `algorithm`; false when a best-effort fallback acted.
  bool clip(Algorithm algorithm, const Options& options, const ParallelContext& ctx,
            TriangleList& out, std::uint32_t& best_effort_vertex);
  /// The algorithm on the first cycle, the sequential engine on what it leaves.
  bool clip_main(Algorithm algorithm, const Options& options, const ParallelContext& ctx,
                 TriangleList& out, std::uint32_t& best_effort_vertex);
  Diagnostic locate(const FlatPolygon& input, Issue issue, std::uint32_t caller_index) const;

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
