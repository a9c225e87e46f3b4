#include "engine.hpp"

#include <algorithm>

#include "cdt/delaunay.hpp"
#include "parallel/variants.hpp"

namespace pear::detail {
namespace {

/// Below this many boundary nodes the parallel variants do not pay (measured: docs/benchmarks.md),
/// and no stage asks for threads unless the caller chose a parallel algorithm.
constexpr std::size_t parallel_threshold = 20'000;

/// Up to this many vertices a polygon of one ring takes the small path (measured:
/// docs/engine.md, "Small polygons").
constexpr std::size_t small_limit = SmallClipper::max_nodes;

/// `automatic` depends on the size and the partitions, never on the threads: the output does not
/// change with the machine. With two partitions divide-and-conquer's one split line halves the
/// work and keeps `top`'s quality: it measured fastest at 2 threads on every family and was never
/// slower than sequential. With more, its recursion costs work on stars and combs while
/// partition-and-cut's chains keep scaling (docs/parallel.md, "What automatic picks").
/// automatic's choice. A polygon found not simple gets the sequential engine's best effort: the
/// parallel variants need a simple boundary and, after clipping their parts, fall back to it
/// (a 84k-vertex country: 26 ms of parts thrown away, slower at 2 threads than at 1).
Algorithm resolve(Algorithm requested, std::size_t nodes, std::uint32_t partitions,
                  bool not_simple) {
  if (requested != Algorithm::automatic) return requested;
  if (partitions < 2 || nodes < parallel_threshold || not_simple) return Algorithm::sequential;
  return partitions == 2 ? Algorithm::divide_and_conquer : Algorithm::partition_and_cut;
}

bool sequential(Algorithm algorithm) {
  return algorithm == Algorithm::automatic || algorithm == Algorithm::sequential;
}

}  // namespace

Diagnostic Engine::locate(const PolygonView& input, Issue issue, std::uint32_t caller_index) const {
  const auto ring_end =
      std::upper_bound(input.ring_offsets.begin(), input.ring_offsets.end(), caller_index);
  const std::size_t ring = static_cast<std::size_t>(ring_end - input.ring_offsets.begin()) - 1;
  return {issue, ring, caller_index - input.ring_offsets[ring]};
}

std::optional<std::uint32_t> Engine::split_t_junctions(const PolygonView& input,
                                                       const RunContext& ctx,
                                                       std::uint32_t violation,
                                                       std::vector<Diagnostic>& diagnostics) {
  const TJunctionSearch search = simplicity_.find_t_junctions(clean_, ctx);
  if (search.conflict) return search.conflict;
  if (search.junctions.empty()) return violation;
  for (const TJunction& t : search.junctions)
    diagnostics.push_back(locate(input, Issue::t_junction_split, clean_.original[t.vertex]));
  ctx.run_serial("split t-junctions", [&] {
    split_at_t_junctions(clean_, search.junctions, split_);
    std::swap(clean_, split_);
  });
  // The split polygon is checked again: what is left is a conflict of its own.
  return simplicity_.find_violation(clean_, ctx);
}

Diagnostic Engine::why_not_valid(const PolygonView& input, bool checked,
                                 std::uint32_t vertex) const {
  // The check found no conflict, so the rings meet only at shared vertices: a hole in the wrong
  // place is named exactly; else the boundary overlaps itself at a point, or the engine stopped.
  if (checked)
    if (const auto hole = find_misplaced_hole(clean_))
      return locate(input,
                    hole->outside_outer ? Issue::hole_outside_outer_ring : Issue::hole_inside_hole,
                    clean_.original[hole->vertex]);
  return locate(input, Issue::not_simple, vertex);
}

bool Engine::prepare(const PolygonView& input, bool check_simplicity, const RunContext& ctx,
                     std::vector<Diagnostic>& diagnostics, Status& status) {
  if (check_simplicity) {
    // Parallel on ctx's executor; records its own phases in the profile.
    std::optional<std::uint32_t> violation = simplicity_.find_violation(clean_, ctx);
    if (violation) violation = split_t_junctions(input, ctx, *violation, diagnostics);
    if (violation) {
      diagnostics.push_back(locate(input, Issue::not_simple, clean_.original[*violation]));
      status = Status::not_simple;
    }
  }
  std::vector<std::uint32_t> unjoined;
  std::uint32_t overlapping = UINT32_MAX;
  ctx.run_serial("bridge holes", [&] {
    unjoined = bridge_holes();
    overlapping = touching_.untangle(boundary_);
    cycles_ = touching_.cycles(boundary_, 0, unjoined);
  });
  // Nothing lies to the left of the hole's leftmost vertex: it is outside the outer ring.
  for (std::uint32_t hole : unjoined) {
    diagnostics.push_back(locate(input, Issue::hole_outside_outer_ring, boundary_.vertex[hole]));
    status = Status::not_simple;
  }
  // Edges that meet only where they end may still bound overlapping wedges at a point the
  // boundary passes twice (a lobe inside a lobe of the same orientation): not a polygon.
  if (check_simplicity && status == Status::ok && overlapping != UINT32_MAX) {
    diagnostics.push_back(why_not_valid(input, true, boundary_.vertex[overlapping]));
    status = Status::not_simple;
  }
  // A hole that passes a point twice has lobes, and a lobe can lie outside the outer ring (or
  // in another hole) while the rest of the hole lies right: clipping would take it for an
  // island. Asked only then (rare), since it sorts every vertex.
  if (check_simplicity && status == Status::ok && hole_touches_itself())
    if (const auto hole = find_misplaced_hole(clean_)) {
      diagnostics.push_back(locate(
          input, hole->outside_outer ? Issue::hole_outside_outer_ring : Issue::hole_inside_hole,
          clean_.original[hole->vertex]));
      status = Status::not_simple;
    }
  return true;
}

bool Engine::hole_touches_itself() {
  // The nodes of clean_'s vertices come first in boundary_; those at a position another node
  // has are few (bridge ends, touching points).
  if (clean_.ring_count() < 2) return false;
  const std::vector<std::uint8_t>& shared = touching_.shared_positions();
  positions_.clear();
  std::size_t ring = 1;
  for (std::uint32_t i = clean_.ring_starts[1]; i < clean_.points.size(); ++i) {
    while (i >= clean_.ring_starts[ring + 1]) ++ring;
    if (shared[i]) positions_.push_back({clean_.points[i], static_cast<std::uint32_t>(ring)});
  }
  std::sort(positions_.begin(), positions_.end(), [](const auto& a, const auto& b) {
    return lexicographic_less(a.first, b.first) || (a.first == b.first && a.second < b.second);
  });
  for (std::size_t k = 1; k < positions_.size(); ++k)
    if (positions_[k].first == positions_[k - 1].first &&
        positions_[k].second == positions_[k - 1].second)
      return true;
  return false;
}

bool Engine::clip(Algorithm algorithm, const Options& options, const RunContext& ctx,
                  TriangleList& out, std::uint32_t& best_effort_vertex) {
  if (cycles_.empty()) return true;
  bool complete = clip_main(algorithm, options, ctx, out, best_effort_vertex);
  // Regions that touch the rest only at points (see touching.hpp): small, copied out so that
  // each costs its own size, clipped sequentially.
  for (std::size_t c = 1; c < cycles_.size(); ++c) {
    part_.clear();
    std::uint32_t v = cycles_[c];
    do {
      part_.add(boundary_.pos[v], boundary_.vertex[v]);
      v = boundary_.next[v];
    } while (v != cycles_[c]);
    for (std::uint32_t i = 0; i + 1 < part_.size(); ++i) part_.link(i, i + 1);
    part_.link(part_.size() - 1, 0);
    if (!clipper_.run(part_, 0, options.heuristic, out) && complete) {
      complete = false;
      best_effort_vertex = clipper_.best_effort_vertex();
    }
  }
  return complete;
}

bool Engine::clip_main(Algorithm algorithm, const Options& options, const RunContext& ctx,
                       TriangleList& out, std::uint32_t& best_effort_vertex) {
  const std::uint32_t entry = cycles_.front();
  std::uint32_t rest = entry;
  switch (algorithm) {
    case Algorithm::divide_and_conquer:
      return divide_and_conquer(boundary_, entry, options.heuristic, make_ear_clipper, ctx, out,
                                best_effort_vertex);
    case Algorithm::partition_and_cut:
      rest = partition_and_cut(boundary_, entry, options.heuristic, ctx, out);
      break;
    case Algorithm::mark_and_cut:
      rest = mark_and_cut(boundary_, entry, ctx, out);
      break;
    default:
      break;
  }
  if (rest == no_node) return true;
  bool complete = true;
  ctx.run_serial("classify and hash reflex nodes", [&] {
    clipper_.prepare(boundary_, rest, options.heuristic, out, &touching_.shared_positions());
  });
  ctx.run_serial("clip sequentially", [&] { complete = clipper_.clip_prepared(rest); });
  best_effort_vertex = clipper_.best_effort_vertex();
  return complete;
}

std::vector<std::uint32_t> Engine::bridge_holes() {
  boundary_.clear();
  for (std::size_t r = 0; r < clean_.ring_count(); ++r) {
    const std::uint32_t first = clean_.ring_starts[r], last = clean_.ring_starts[r + 1] - 1;
    for (std::uint32_t i = first; i <= last; ++i)
      boundary_.add(clean_.points[i], clean_.original[i]);
    for (std::uint32_t i = first; i < last; ++i) boundary_.link(i, i + 1);
    boundary_.link(last, first);
  }
  return bridger_.join(clean_, boundary_);
}

bool Engine::triangulate_small(const Options& options, TriangleList& out) {
  const SmallVerdict verdict = simplicity_.check_small(clean_, options.check_simplicity);
  // A violation is reported by the general path, which also gives the best effort.
  if (verdict.touching || verdict.violation) return false;
  const std::size_t holes = clean_.ring_count() - 1;
  out.reserve(clean_.points.size() + 2 * holes - 2);
  if (holes == 0) return small_.run(clean_.points, clean_.original, options.heuristic, out);
  // Holes: each must lie in the outer ring and in no other hole (else the general path names
  // it), and be joined by a bridge; the joined boundary is then clipped as one ring.
  if (options.check_simplicity && find_misplaced_hole_among_few(clean_)) return false;
  if (!bridge_holes().empty()) return false;
  ring_points_.clear();
  ring_original_.clear();
  std::uint32_t v = 0;
  do {
    ring_points_.push_back(boundary_.pos[v]);
    ring_original_.push_back(boundary_.vertex[v]);
    v = boundary_.next[v];
  } while (v != 0 && ring_points_.size() < boundary_.size());
  if (ring_points_.size() != boundary_.size()) return false;
  return small_.run(ring_points_, ring_original_, options.heuristic, out, true);
}

Status Engine::triangulate(const PolygonView& input, const Options& options, TriangleList& out,
                           std::vector<Diagnostic>& diagnostics, DelaunayStatistics& delaunay) {
  out.clear();
  if (options.threads > max_threads) {
    diagnostics.push_back({Issue::invalid_options, 0, 0});
    return Status::invalid_input;
  }
  RunContext ctx;
  ctx.profile = options.profile;
  Status status = Status::ok;
  ctx.run_serial("clean", [&] { status = clean_polygon(input, clean_, diagnostics); });
  if (status != Status::ok) return status;
  bool small = false;
  // Bridges add two nodes per hole.
  if (sequential(options.algorithm) &&
      clean_.points.size() + 2 * (clean_.ring_count() - 1) <= small_limit)
    ctx.run_serial("clip small polygon", [&] { small = triangulate_small(options, out); });
  if (small) {
    if (options.delaunay) make_delaunay(input.points, clean_, out, ctx, delaunay);
    return Status::ok;
  }
  // Clamped before any stage sizes its work by it (a million parts once meant a million queues).
  ctx.partitions = std::min(options.partitions ? options.partitions : Workers::concurrency(options),
                            max_partitions);
  if (clean_.points.size() >= parallel_threshold || !sequential(options.algorithm))
    ctx.runner = workers_.runner(options);
  if (!prepare(input, options.check_simplicity, ctx, diagnostics, status)) return status;
  out.reserve(boundary_.size());
  const Algorithm algorithm =
      resolve(options.algorithm, boundary_.size(), ctx.partitions, status == Status::not_simple);
  std::uint32_t best_effort_vertex = 0;
  if (!clip(algorithm, options, ctx, out, best_effort_vertex) && status == Status::ok) {
    diagnostics.push_back(why_not_valid(input, options.check_simplicity, best_effort_vertex));
    status = Status::not_simple;
  }
  // Flipping needs a valid triangulation to end in the CDT; a best effort is left as it is.
  if (options.delaunay && status == Status::ok)
    make_delaunay(input.points, clean_, out, ctx, delaunay);
  return status;
}

EarStatistics Engine::statistics(const PolygonView& input) {
  std::vector<Diagnostic> ignored;
  Status status = clean_polygon(input, clean_, ignored);
  if (status != Status::ok || !prepare(input, false, RunContext{}, ignored, status) ||
      cycles_.empty())
    return {};
  return clipper_.statistics(boundary_, cycles_.front());
}

}  // namespace pear::detail
