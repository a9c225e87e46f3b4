// One run of the pipeline: clean -> check (-> split T-junctions) -> bridge -> clip (sequential or a
// parallel variant) -> CDT. The stages are functions of the algorithm folders; the engine owns
// their buffers, so a reused engine allocates nothing once warm.
#pragma once

#include <memory>
#include <vector>

#include "clean/clean.hpp"
#include "core/stage.hpp"
#include "earclip/bridge.hpp"
#include "earclip/ear_clipper.hpp"
#include "earclip/small_clipper.hpp"
#include "earclip/touching.hpp"
#include "pear/detail/flat_polygon.hpp"
#include "simplicity/simplicity.hpp"
#include "threading.hpp"

namespace pear::detail {

class Engine {
 public:
  /// Triangulates `input` into `out` (cleared first).
  /// Parallel stages run where Workers::runner(options) says, looked up only when a stage
  /// needs threads: a sequential run, and every small polygon, never touches an executor.
  Status triangulate(const PolygonView& input, const Options& options, TriangleList& out,
                     std::vector<Diagnostic>& diagnostics, DelaunayStatistics& delaunay);
  EarStatistics statistics(const PolygonView& input);

  /// Buffers a caller may fill and pass back as input (Triangulator's flattened rings).
  FlatPolygon& input_buffer() { return input_; }
  TriangleList& triangle_buffer() { return triangles_; }
  /// Vertices the buffers were last sized for: what keeping this engine costs.
  std::size_t footprint() const { return clean_.points.capacity() + boundary_.pos.capacity(); }
  Workers& workers() { return workers_; }

 private:
  /// The small-polygon path: few vertices, no repeated position; holes are bridged first.
  /// Returns false when it does not apply or finds the polygon not valid; the general path
  /// then runs (and names what is wrong).
  bool triangulate_small(const Options& options, TriangleList& out);
  /// boundary_ from clean_'s rings, the holes joined by bridges; returns the leftmost node of
  /// every hole that could not be joined.
  std::vector<std::uint32_t> bridge_holes();
  /// After untangling: whether a hole passes one of its points twice.
  bool hole_touches_itself();
  /// Cleans and bridges; returns false when nothing can be triangulated.
  bool prepare(const PolygonView& input, bool check_simplicity, const RunContext& ctx,
               std::vector<Diagnostic>& diagnostics, Status& status);
  /// Clips the prepared boundary with `algorithm`; false when a best-effort fallback acted.
  bool clip(Algorithm algorithm, const Options& options, const RunContext& ctx, TriangleList& out,
            std::uint32_t& best_effort_vertex);
  /// The algorithm on the first cycle, the sequential engine on what it leaves.
  bool clip_main(Algorithm algorithm, const Options& options, const RunContext& ctx,
                 TriangleList& out, std::uint32_t& best_effort_vertex);
  /// After find_violation found `violation`: splits every edge at the vertices lying inside it,
  /// each named in a warning, when that is all that is wrong. Returns the violation left (an
  /// index into clean_), if any.
  std::optional<std::uint32_t> split_t_junctions(const PolygonView& input, const RunContext& ctx,
                                                 std::uint32_t violation,
                                                 std::vector<Diagnostic>& diagnostics);
  /// Why a polygon whose check (when `checked`) found no conflict is not valid after all: a
  /// misplaced hole if there is one, else not_simple at `vertex` (where the boundary overlaps
  /// itself, or where clipping stopped short).
  Diagnostic why_not_valid(const PolygonView& input, bool checked, std::uint32_t vertex) const;
  Diagnostic locate(const PolygonView& input, Issue issue, std::uint32_t caller_index) const;

  Workers workers_;  ///< a private executor for Options::threads, kept between runs
  FlatPolygon input_;
  TriangleList triangles_;
  CleanPolygon clean_;
  CleanPolygon split_;  ///< clean_ with its T-junctions split, swapped with it
  Boundary boundary_;
  SimplicityCheck simplicity_;
  HoleBridger bridger_;
  TouchingPoints touching_;
  std::vector<std::uint32_t> cycles_;  ///< one node per region to clip, the main one first
  Boundary part_;                      ///< a region copied out of boundary_
  EarClipper clipper_;
  SmallClipper small_;
  std::vector<Point> ring_points_;  ///< the bridged boundary as one ring, for small_
  std::vector<std::uint32_t> ring_original_;
  std::vector<std::pair<Point, std::uint32_t>> positions_;  ///< hole_touches_itself's scratch
};

}  // namespace pear::detail
