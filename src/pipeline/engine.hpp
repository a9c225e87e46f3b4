// One run of the pipeline, the same for every polygon: clean -> check (-> split T-junctions) ->
// bridge -> untangle touching points -> clip (sequentially or by a parallel variant) -> CDT ->
// report. Each stage picks its own strategy by size (docs/architecture.md); the engine owns
// every stage's buffers, so a reused engine allocates nothing once warm.
#pragma once

#include <memory>
#include <vector>

#include "cdt/delaunay.hpp"
#include "clean/clean.hpp"
#include "core/stage.hpp"
#include "earclip/bridge.hpp"
#include "earclip/ear_clipper.hpp"
#include "earclip/touching.hpp"
#include "parallel/variants.hpp"
#include "pear/detail/flat_polygon.hpp"
#include "simplicity/simplicity.hpp"
#include "threading.hpp"

namespace pear::detail {

class Engine {
 public:
  /// Triangulates `input` into `out` (cleared first), appending to `diagnostics`. Parallel
  /// stages run where Workers::runner(options) says, looked up only when a stage needs
  /// threads: a sequential run, and every small polygon, never touches an executor.
  Status run(const InputPolygon& input, const Options& options, TriangleList& out,
             std::vector<Diagnostic>& diagnostics, DelaunayStatistics& delaunay);
  EarStatistics statistics(const InputPolygon& input);

  /// Where a caller of run() keeps its input and results between runs (the Triangulator's
  /// flattened rings and narrow-index triangles, a batch's per-polygon offsets and results):
  /// every buffer a run needs lives in its engine, and goes back to the pool with it.
  struct Buffers {
    FlatPolygon input;
    TriangleList triangles;
    std::vector<Diagnostic> diagnostics;
  };
  Buffers& buffers() { return buffers_; }
  /// Vertices the buffers were last sized for: what keeping this engine costs.
  std::size_t footprint() const { return clean_.points.capacity() + boundary_.pos.capacity(); }
  /// The least footprint a run on a polygon of `vertices` leaves: its clean points and the
  /// boundary's room for two nodes a bridge (bridge_holes reserves it).
  static std::size_t footprint_after(std::size_t vertices) { return 3 * vertices; }
  Workers& workers() { return workers_; }

 private:
  /// What a stage after cleaning found, at the caller's flat index of a vertex; reported (as
  /// ring and vertex) once, at the end.
  struct Finding {
    Issue issue;
    std::uint32_t vertex;
  };

  /// The check: conflicts, with T-junctions split when that is all that is wrong.
  void check(bool find_crossings, const RunContext& ctx);
  /// After the check found `violation`: splits every edge at the vertices lying inside it,
  /// each named in a warning, when that is all that is wrong. Returns the violation left (an
  /// index into clean_), if any.
  std::optional<std::uint32_t> split_t_junctions(const RunContext& ctx, std::uint32_t violation);
  /// boundary_ from clean_'s rings, the holes joined by bridges; the points where it passes
  /// more than once relinked, unless the check found that no two rings touch; cycles_ set.
  void bridge(bool checked, const RunContext& ctx);
  /// boundary_ from clean_'s rings, joined by the bridger (in parts: as ctx's tasks); returns
  /// the leftmost node of every hole that could not be joined.
  std::vector<std::uint32_t> bridge_holes(const RunContext& ctx, bool in_parts);
  /// After untangling: whether a hole passes one of its points twice.
  bool hole_touches_itself();
  /// Clips every cycle with `algorithm`; false when a best-effort fallback acted.
  bool clip(Algorithm algorithm, const Options& options, const RunContext& ctx, TriangleList& out,
            std::uint32_t& best_effort_vertex);
  /// The cycle through `entry` into part_, unless it has more than `most` nodes.
  bool copy_cycle(std::uint32_t entry, std::size_t most);
  /// The algorithm on the first cycle, the sequential engine on what it leaves.
  bool clip_main(Algorithm algorithm, const Options& options, const RunContext& ctx,
                 TriangleList& out, std::uint32_t& best_effort_vertex);
  /// A misplaced hole, if the check passed (rings meet only at shared vertices), else
  /// not_simple at `vertex`: why a polygon is not valid although no conflict was found.
  Finding why_not_valid(bool checked, std::uint32_t vertex) const;
  void found(Issue issue, std::uint32_t caller_index) {
    findings_.push_back({issue, caller_index});
  }
  bool found_not_simple() const;
  /// The findings as diagnostics in the caller's numbering, and the status they make.
  Status report(const InputPolygon& input, std::vector<Diagnostic>& diagnostics) const;
  /// The caller's points, for the CDT (which reads them by the caller's index): where they
  /// are, or copied (in ctx's tasks) from interleaved coordinates or the rings' arrays.
  std::span<const Point> caller_points(const InputPolygon& input, const RunContext& ctx);

  Workers workers_;  ///< a private executor for Options::threads, kept between runs
  Buffers buffers_;
  CleanPolygon clean_;
  CleanPolygon split_;  ///< clean_ with its T-junctions split, swapped with it
  Boundary boundary_;
  SimplicityCheck simplicity_;
  Verdict verdict_;
  HoleBridger bridger_;
  TouchingPoints touching_;
  SharedPositions shared_;                 ///< what the clipper learns of repeated positions
  std::vector<std::uint8_t> bridge_ends_;  ///< shared_'s marks where no rings touch
  std::vector<std::uint32_t> cycles_;      ///< one node per region to clip, the main one first
  ClipOrder clip_order_;                   ///< the triangles clipped region by region (for the CDT)
  Boundary part_;                          ///< a region copied out of boundary_ (copy_cycle)
  EarClipper clipper_;
  VariantScratchPtr variant_scratch_;    ///< the parallel variants' arrays, made on first use
  DelaunayScratchPtr delaunay_scratch_;  ///< the CDT's arrays, made on first use
  std::vector<Finding> findings_;
  std::vector<std::pair<Point, std::uint32_t>> positions_;  ///< hole_touches_itself's scratch
  FillVector<Point> caller_points_;                         ///< caller_points' copy
};

}  // namespace pear::detail
