// Constrained Delaunay triangulation by exact edge flips (paper §2.4): Lawson's flips on the
// whole triangulation, or first inside triangle sets in parallel tasks (pieces of a
// breadth-first walk, or runs of the clipper's order), then across the sets' borders.
#include "delaunay.hpp"

#include <algorithm>
#include <limits>

#include "borders.hpp"
#include "geometry/sort.hpp"
#include "mesh.hpp"
#include "partition.hpp"
#include "pear/config.hpp"

namespace pear::detail {

struct DelaunayScratch {
  Mesh mesh;
  TrianglePartition partition;
  FillVector<std::uint8_t> queued;  ///< a flag per half-edge: on the flip loops' stacks
  TriangleList clipped;             ///< the triangles before the flips in sets
  BorderFlipMarks border_marks;
};

void DelaunayScratchDeleter::operator()(DelaunayScratch* scratch) const noexcept {
  delete scratch;
}

namespace {

/// Below this many triangles per set the parallel tasks cost more than they save.
constexpr std::size_t min_triangles_per_set = 256;

/// The flips across the sets' borders took at most 1.4 an interior edge on the inputs measured
/// (random-holes-100k at 16 sets; the coasts 0.01-0.5), and fewer than the flips inside the
/// sets but on random holes. Where points lie in convex position the Delaunay edges are long
/// and cross every set, and each set's own CDT leads far from the whole one: a 100,000-point
/// ellipse took 35 million flips across 16 sets' borders (1.6 s) against 142,266 on one
/// partition (64 ms), an ellipse with a row of small holes 4.7 million at 2 sets after 22,265
/// inside them. Past this many flips an edge (or a flip inside the sets, if more) the border
/// flips stop, the clip's triangles come back and are flipped on one partition.
constexpr std::size_t border_flips_per_edge = 4;

/// Lawson's algorithm needs at most n(n-1)/2 flips on n vertices (an edge, once flipped away,
/// never comes back); a budget of that many keeps garbage from looping forever.
/// Counted in 64 bits and saturated: size_t has 32 on wasm32.
std::size_t flip_budget(std::size_t vertices) {
  const auto n = static_cast<std::uint64_t>(vertices);
  if (n > (std::uint64_t{1} << 32)) return std::numeric_limits<std::size_t>::max();
  const std::uint64_t flips = n * (n - 1) / 2 + 1;
  return static_cast<std::size_t>(
      std::min<std::uint64_t>(flips, std::numeric_limits<std::size_t>::max()));
}

/// Every interior edge once, in triangle order (the stack pops them in reverse).
void push_interior_edges(const Mesh& mesh, std::vector<std::uint32_t>& stack,
                         std::span<std::uint8_t> queued) {
  for (std::uint32_t h = 0; h < mesh.twin.size(); ++h) {
    if (mesh.twin[h] == no_twin || mesh.twin[h] < h) continue;
    stack.push_back(h);
    queued[h] = 1;
  }
}

void flip_sequentially(DelaunayScratch& scratch, std::size_t budget, const RunContext& ctx,
                       DelaunayStatistics& stats) {
  Mesh& mesh = scratch.mesh;
  FillVector<std::uint8_t>& queued = scratch.queued;
  ctx.run_serial("cdt flip", [&] {
    std::vector<std::uint32_t> stack;
    queued.assign(mesh.twin.size(), 0);
    push_interior_edges(mesh, stack, queued);
    stats.flips = flip_until_delaunay(mesh, stack, queued, FlipScope{}, budget);
  });
}

/// A copy of the triangles, by ctx's tasks (a build without threads copies them in one go: the
/// WebAssembly module's size).
void copy_in_tasks(const TriangleList& from, TriangleList& to, const RunContext& ctx) {
  if constexpr (!PEAR_HAS_THREADS) {
    to = from;
    return;
  }
  if (to.capacity() < from.size()) to.clear();  // growing: nothing old to copy
  to.resize(from.size());
  const std::size_t tasks = ctx.tasks_for(from.size(), std::size_t{1} << 16);
  ctx.run_tasks("cdt clip's triangles", tasks, [&](std::size_t t) {
    const auto first =
        from.begin() + static_cast<std::ptrdiff_t>(part_begin(from.size(), tasks, t));
    const auto last =
        from.begin() + static_cast<std::ptrdiff_t>(part_begin(from.size(), tasks, t + 1));
    std::copy(first, last, to.begin() + (first - from.begin()));
  });
}

/// Flips in sets, then across their borders; false, with the border flips cut short, where
/// those passed border_flips_per_edge. scratch.clipped: the triangles before any flip.
bool flip_in_sets(DelaunayScratch& scratch, std::uint32_t sets, std::size_t budget,
                  const RunContext& ctx, DelaunayStatistics& stats, ClipOrder order) {
  Mesh& mesh = scratch.mesh;
  TrianglePartition& partition = scratch.partition;
  const std::size_t count = mesh.triangles->size();
  if (runs_make_sets(order, count, sets))
    partition_in_runs(mesh, order, sets, ctx, partition);
  else
    ctx.run_serial("cdt partition", [&] { partition_triangles(mesh, sets, partition); });
  FillVector<std::uint8_t>& queued = scratch.queued;
  const std::size_t halves = mesh.twin.size();
  regrow_unfilled(queued, halves);  // the tasks below clear it
  const std::size_t queue_tasks = ctx.tasks_for(halves, std::size_t{1} << 16);
  ctx.run_tasks("cdt flip sets: queue", queue_tasks, [&](std::size_t t) {
    std::fill(queued.begin() + static_cast<std::ptrdiff_t>(part_begin(halves, queue_tasks, t)),
              queued.begin() + static_cast<std::ptrdiff_t>(part_begin(halves, queue_tasks, t + 1)),
              std::uint8_t{0});
  });
  copy_in_tasks(*mesh.triangles, scratch.clipped, ctx);
  std::vector<std::size_t> flips(sets, 0);
  std::vector<std::vector<std::uint32_t>> borders(sets);
  ctx.run_tasks("cdt flip sets", sets, [&](std::size_t s) {
    const FlipScope scope{partition.part.data(), static_cast<std::uint32_t>(s)};
    // Triangle order, as in the sequential loop: the stack then pops the last clipped ears
    // first, which needed fewer flips than walk order (spiral: 1.5 against 3.5 per edge).
    const auto first = partition.order.begin() + static_cast<std::ptrdiff_t>(partition.begin[s]);
    const auto last = partition.order.begin() + static_cast<std::ptrdiff_t>(partition.begin[s + 1]);
    if (!std::is_sorted(first, last)) detail::sort(first, last);  // runs come sorted
    std::vector<std::uint32_t> stack;
    for (auto it = first; it != last; ++it) {
      const std::uint32_t t = *it;
      for (std::uint32_t h = 3 * t; h < 3 * t + 3; ++h) {
        const std::uint32_t g = mesh.twin[h];
        if (g == no_twin || g < h || !scope.contains(g)) continue;
        stack.push_back(h);
        queued[h] = 1;
      }
    }
    flips[s] = flip_until_delaunay(mesh, stack, queued, scope, budget);
    collect_borders(mesh, partition, static_cast<std::uint32_t>(s), borders[s]);
  });
  for (std::size_t f : flips) stats.flips_in_partitions += f;
  // Records its own phases ("cdt relink borders: ...").
  std::vector<std::uint32_t> suspects = relink_borders(mesh, borders, ctx);
  const std::size_t left = budget - std::min(budget, stats.flips_in_partitions);
  const std::size_t border_budget = std::min(
      left, border_flips_per_edge * std::max(mesh.interior_edges, stats.flips_in_partitions));
  stats.flips_on_borders =
      flip_borders(mesh, std::move(suspects), queued, scratch.border_marks, ctx, border_budget);
  stats.flips = stats.flips_in_partitions + stats.flips_on_borders;
  return stats.flips_on_borders < border_budget;
}

}  // namespace

void make_delaunay(std::span<const Point> points, const CleanPolygon& polygon,
                   TriangleList& triangles, const RunContext& ctx, DelaunayStatistics& stats,
                   DelaunayScratchPtr& scratch, ClipOrder order) {
  stats = {};
  if (!scratch) scratch.reset(new DelaunayScratch);
  Mesh& mesh = scratch->mesh;
  // Its phases are recorded as "cdt adjacency: ...".
  if (!build_mesh(points, polygon, triangles, mesh, ctx))
    return;  // not a triangulation: flipping could only make it worse
  stats.edges = mesh.interior_edges;
  const std::size_t budget = flip_budget(points.size());
  const std::size_t sets =
      std::min<std::size_t>(ctx.partitions, triangles.size() / min_triangles_per_set);
  if (sets > 1) {
    if (flip_in_sets(*scratch, static_cast<std::uint32_t>(sets), budget, ctx, stats, order)) return;
    copy_in_tasks(scratch->clipped, triangles, ctx);
    build_mesh(points, polygon, triangles, mesh, ctx);  // the same edges: `edges` stays
    stats.flips_in_partitions = stats.flips_on_borders = 0;
  }
  flip_sequentially(*scratch, budget, ctx, stats);
}

}  // namespace pear::detail
