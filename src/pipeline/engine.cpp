#include "engine.hpp"

#include <algorithm>

#include "cdt/delaunay.hpp"
#include "core/link_runs.hpp"
#include "geometry/sort.hpp"
#include "parallel/variants.hpp"
#include "pear/config.hpp"
#include "simplicity/simplicity.hpp"

namespace pear::detail {
namespace {

/// Below this many boundary nodes the parallel variants do not pay (measured: docs/benchmarks.md),
/// and no stage asks for threads unless the caller chose a parallel algorithm.
constexpr std::size_t parallel_threshold = 20'000;

/// What `automatic` and the CDT's start read from the outline: its size and how often its rings
/// turn back in x (x_reversals: about the runs of edges monotone in x), counted once, only
/// when asked.
class Outline {
 public:
  /// `runs`: x_reversals(clean) where the simplicity check counted them (in parts), else
  /// counted here when first asked.
  Outline(const CleanPolygon& clean, std::optional<std::size_t> runs)
      : clean_(clean), runs_(runs.value_or(unknown)) {}
  std::size_t nodes() const { return clean_.points.size(); }
  std::size_t runs() {
    if (runs_ == unknown) runs_ = x_reversals(clean_);
    return runs_;
  }
  /// Runs of 3 to 64 edges: coastlines (5-15), random polygons with holes (4).
  bool coast_like() { return runs() * 3 <= nodes() && !long_runs(); }
  /// More than 16 long runs: walls wound round each other (a spiral: 82 runs of 1,220 edges;
  /// fractals, stars and hole grids have runs of 1.5-2.3 edges).
  bool corridors() { return long_runs() && runs() > 16; }
  /// At most 16 long runs: a comb (2 runs), an outline convex or nearly so.
  bool few_long_runs() { return long_runs() && runs() <= 16; }
  /// A hole for every 16 nodes or fewer: grids of holes (runs of 2 edges), random polygons
  /// with holes (runs of 4: coast-like).
  bool many_holes() const { return (clean_.ring_count() - 1) * 16 >= nodes(); }

 private:
  /// Runs of over 64 edges on average.
  bool long_runs() { return runs() * 64 < nodes(); }
  static constexpr std::size_t unknown = SIZE_MAX;
  const CleanPolygon& clean_;
  std::size_t runs_ = unknown;
};

/// What `automatic` runs: the algorithm, and the parts it cuts the work into.
struct Choice {
  Algorithm algorithm;
  std::uint32_t parts;
};

/// Divide-and-conquer's parts on a large coast-like outline: more than the partitions. Its
/// parts are clipped by the sequential engine, whose queue on a boundary of hundreds of
/// thousands of nodes waits for memory: parts a few times smaller clip faster (Eurasia in 8
/// parts: 737 ms of work against the sequential engine's 1,033), and more parts than threads
/// let the scheduler even out parts of unequal work (one large piece clips slower than many
/// small ones: South America's two halves 137 and 61 ms). Work/span bound at 2 partitions,
/// 2 parts -> 4 or 8 (docs/parallel.md, "What automatic picks"): Australia 1.77 -> 1.92x,
/// Greenland 1.80 -> 1.99x, South America 1.66 -> 2.23x, Eurasia 1.68 -> 2.62x.
constexpr std::size_t more_parts_from = 100'000;  ///< nodes: 2 parts a partition
constexpr std::size_t most_parts_from = 300'000;  ///< nodes: 4 a partition, and on one partition

std::uint32_t divide_and_conquer_parts(std::uint32_t partitions, Outline& outline) {
  if (outline.nodes() < more_parts_from || !outline.coast_like()) return partitions;
  return std::max(partitions, 2u) * (outline.nodes() < most_parts_from ? 2 : 4);
}

/// `automatic` depends on the outline and the partitions, never on the threads: the output does
/// not change with the machine. Up to four partitions divide-and-conquer keeps `top`'s quality
/// and its split lines halve the work; on large coast-like outlines in more parts than
/// partitions (divide_and_conquer_parts), also on one partition from 300,000 nodes. With two
/// partitions otherwise too: it measured fastest at 2 threads on every family but the comb.
/// With more, its recursion costs work on stars and combs while partition-and-cut's chains keep
/// scaling, except along corridors, whose two walls fall in different chains: there
/// divide-and-conquer's slabs (the spiral on 16 cores at 4-16 threads: 21-26 ms against 45-54;
/// docs/parallel.md, "What automatic picks"). And on grids of holes (a hole every 16 nodes,
/// runs too short to be coast-like), whose bridges zigzag through every row: partition-and-cut's
/// chains block each other there and left most of the clip to their sequential finish (the
/// holes grid at 16 partitions: 13.9 ms projected against divide-and-conquer's 6.7).
///
/// Where the outline has only a few long runs (a comb; an outline convex or nearly so),
/// mark-and-cut at any partition count: divide-and-conquer's repair of the comb's base strip
/// and partition-and-cut's chains along its teeth cost more than they save (16 cores, 2026-11-26
/// 17:45: mark-and-cut 1.03-1.19x the sequential engine at 2-16 threads, divide-and-conquer 0.80x
/// at 2, partition-and-cut 0.93-1.03x at 4-16; a 100,000-point ellipse on 2 cores: 2.0x against
/// 0.9x, and its CDT 0.75x against 0.5x).
///
/// A polygon found not simple gets the sequential engine's best effort: the parallel variants
/// need a simple boundary and, after clipping their parts, fall back to it (a 84k-vertex
/// country: 26 ms of parts thrown away, slower at 2 threads than at 1).
Choice resolve(Algorithm requested, std::size_t nodes, std::uint32_t partitions, bool not_simple,
               Outline& outline) {
  if (requested != Algorithm::automatic) return {requested, partitions};
  if (nodes < parallel_threshold || not_simple) return {Algorithm::sequential, partitions};
  const std::uint32_t dc_parts = divide_and_conquer_parts(partitions, outline);
  if (partitions < 2) {
    if (nodes >= most_parts_from && dc_parts > partitions)
      return {Algorithm::divide_and_conquer, dc_parts};
    return {Algorithm::sequential, partitions};
  }
  if (outline.few_long_runs()) return {Algorithm::mark_and_cut, partitions};
  if (partitions == 2 || outline.corridors()) return {Algorithm::divide_and_conquer, dc_parts};
  if (partitions <= 4 && dc_parts > partitions) return {Algorithm::divide_and_conquer, dc_parts};
  if (outline.many_holes()) return {Algorithm::divide_and_conquer, dc_parts};
  return {Algorithm::partition_and_cut, partitions};
}

/// With `delaunay` the clip only makes the triangulation the flips start from, and the CDT is
/// the same from any (up to cocircular ties). `top`'s queue jumps across large coastlines
/// (Australia: 116 ms against `fast`'s 70) for fewer flips than that saves; outlines of short
/// runs monotone in x (fractals, stars, grids of holes: under 3 edges a run) or of a few long
/// ones (spirals, combs) flip far more from `fast` (the spiral 2.3x the CDT's time). So `fast`
/// from 20,000 nodes where the outline is coast-like, for the clips whose `fast` is the walk
/// (the sequential engine, divide-and-conquer's parts): the sequential CDT on Australia 1.60x,
/// Greenland 1.54x, random holes 1.32x faster; divide-and-conquer's at 2 partitions Greenland
/// 171 -> 146 ms of work. Partition-and-cut's chains queue their ears either way, and from
/// `fast` left Greenland's CDT at 2 partitions 176 -> 251 ms: they keep the heuristic asked for.
EarHeuristic start_of_flips(const Options& options, Algorithm algorithm, Outline& outline) {
  if (!options.delaunay || options.heuristic != EarHeuristic::top) return options.heuristic;
  const bool walks =
      algorithm == Algorithm::sequential || algorithm == Algorithm::divide_and_conquer;
  if (!walks || outline.nodes() < parallel_threshold) return options.heuristic;
  return outline.coast_like() ? EarHeuristic::fast : options.heuristic;
}

bool sequential(Algorithm algorithm) {
  return algorithm == Algorithm::automatic || algorithm == Algorithm::sequential;
}

Issue misplaced_issue(const MisplacedHole& hole) {
  return hole.outside_outer ? Issue::hole_outside_outer_ring : Issue::hole_inside_hole;
}

}  // namespace

bool Engine::found_not_simple() const {
  return std::any_of(findings_.begin(), findings_.end(),
                     [](const Finding& f) { return Diagnostic{f.issue}.is_not_simple(); });
}

std::span<const Point> Engine::caller_points(const InputPolygon& input, const RunContext& ctx) {
  if (input.points != nullptr) return {input.points, input.size()};
  const std::size_t n = input.size();
  caller_points_.resize(n);
  const std::size_t tasks = ctx.tasks_for(n, std::size_t{1} << 14);
  ctx.run_tasks("cdt caller's points", tasks, [&](std::size_t t) {
    const std::size_t from = part_begin(n, tasks, t), to = part_begin(n, tasks, t + 1);
    const auto& offsets = input.ring_offsets;
    for (std::size_t i = from, r = input.ring_of(from); i < to; ++r) {
      const InputPolygon::Ring ring = input.ring(r);
      for (const std::size_t end = std::min<std::size_t>(to, offsets[r + 1]); i < end; ++i)
        caller_points_[i] = ring[i - offsets[r]];
    }
  });
  return caller_points_;
}

Status Engine::report(const InputPolygon& input, std::vector<Diagnostic>& diagnostics) const {
  Status status = Status::ok;
  for (const Finding& f : findings_) {
    const auto ring_end =
        std::upper_bound(input.ring_offsets.begin(), input.ring_offsets.end(), f.vertex);
    const auto ring = static_cast<std::size_t>(ring_end - input.ring_offsets.begin()) - 1;
    diagnostics.push_back({f.issue, ring, f.vertex - input.ring_offsets[ring]});
    if (diagnostics.back().is_not_simple()) status = Status::not_simple;
  }
  return status;
}

void Engine::check(bool find_crossings, const RunContext& ctx) {
  // Parallel on ctx's runner for large polygons; records its phases in the profile.
  verdict_ = simplicity_.check(clean_, ctx, find_crossings);
  if (!verdict_.violation) return;
  // A crossing at the smallest edge in conflict: no split makes the polygon simple, and the
  // T-junction sweep (most of a not-simple polygon's check) is not needed to say so.
  const auto left = simplicity_.unresolvable_conflict_at(clean_, *verdict_.violation, ctx)
                        ? verdict_.violation
                        : split_t_junctions(ctx, *verdict_.violation);
  if (left) {
    found(Issue::not_simple, clean_.original[*left]);
    verdict_.touching = Verdict::Touching::unknown;  // a crossing may hide a touching pair
    return;
  }
  // Split vertices are used by two rings (or twice by one): the rings touch there.
  verdict_ = {std::nullopt, Verdict::Touching::yes, std::nullopt};
}

std::optional<std::uint32_t> Engine::split_t_junctions(const RunContext& ctx,
                                                       std::uint32_t violation) {
  const TJunctionSearch search = simplicity_.find_t_junctions(clean_, ctx);
  if (search.conflict) return search.conflict;
  if (search.junctions.empty()) return violation;
  for (const TJunction& t : search.junctions)
    found(Issue::t_junction_split, clean_.original[t.vertex]);
  ctx.run_serial("split t-junctions", [&] {
    split_at_t_junctions(clean_, search.junctions, split_);
    std::swap(clean_, split_);
  });
  // The split polygon is checked again: what is left is a conflict of its own.
  return simplicity_.find_violation(clean_, ctx);
}

std::vector<std::uint32_t> Engine::bridge_holes(const RunContext& ctx, bool in_parts) {
  const std::size_t n = clean_.points.size();
  // Room for the two nodes each bridge adds and for what splits add later: splicing never
  // moves the arrays (on Eurasia's first call that was 42 MB copied and faulted in on one
  // thread), and pages never written cost nothing.
  boundary_.reserve(2 * (n + clean_.ring_count()));
  // One node per clean vertex, each ring a cycle: copied and linked in whole arrays (a county
  // is a few dozen nodes, and this is a tenth of its run if done node by node).
  if (in_parts) {
    boundary_.pos.resize(n);
    boundary_.vertex.resize(n);
  } else {
    boundary_.pos.assign(clean_.points.begin(), clean_.points.end());
    boundary_.vertex.assign(clean_.original.begin(), clean_.original.end());
  }
  boundary_.prev.resize(n);
  boundary_.next.resize(n);
  std::uint32_t* prev = boundary_.prev.data();
  std::uint32_t* next = boundary_.next.data();
  if (in_parts) {
    const std::size_t tasks = ctx.tasks_for(n, 4096);
    ctx.run_tasks("bridge: boundary", tasks, [&](std::size_t t) {
      const auto first = static_cast<std::uint32_t>(n * t / tasks);
      const auto end = static_cast<std::uint32_t>(n * (t + 1) / tasks);
      std::copy(clean_.points.begin() + first, clean_.points.begin() + end,
                boundary_.pos.begin() + first);
      std::copy(clean_.original.begin() + first, clean_.original.begin() + end,
                boundary_.vertex.begin() + first);
      for (std::uint32_t i = first; i < end; ++i) prev[i] = i - 1, next[i] = i + 1;
    });
  }
  for (std::size_t r = 0; r < clean_.ring_count(); ++r) {
    const std::uint32_t first = clean_.ring_starts[r], last = clean_.ring_starts[r + 1] - 1;
    if (!in_parts)
      for (std::uint32_t i = first; i <= last; ++i) prev[i] = i - 1, next[i] = i + 1;
    prev[first] = last;
    next[last] = first;
  }
  // No repeated position (the check's verdict): up to 64 holes are joined without a grid.
  return bridger_.join(clean_, boundary_, ctx, in_parts,
                       verdict_.touching == Verdict::Touching::no);
}

void Engine::bridge(bool checked, const RunContext& ctx) {
  // Where the check found that no two rings touch, only bridge ends repeat a position, and the
  // passes through them are in order: nothing to untangle, one cycle, and no repeated position
  // at all without holes.
  const bool touching = verdict_.touching != Verdict::Touching::no;
  // In parts when the run is (the parallel variants, or automatic on a large polygon): the
  // same bridges and links either way, so the threads never change the triangles (and a build
  // without threads leaves the parts' code out). The bridger and the untangling record their
  // own phases: in parts, most of their work is tasks.
  const bool in_parts =
      PEAR_HAS_THREADS && ctx.partitions > 1 && clean_.points.size() >= parallel_threshold;
  const std::vector<std::uint32_t> unjoined = bridge_holes(ctx, in_parts);
  std::uint32_t overlapping = UINT32_MAX;
  if (touching) {
    const std::size_t tasks = in_parts ? ctx.tasks_for(boundary_.size(), 4096) : 1;
    overlapping = touching_.untangle(boundary_, ctx, tasks);
    cycles_ = touching_.cycles(boundary_, 0, unjoined, ctx,
                               in_parts ? link_tasks(boundary_.size(), ctx.partitions) : 1);
    shared_ = {&touching_.shared_positions(), false};
  } else {
    cycles_.assign(1, 0);
    shared_ = {nullptr, clean_.ring_count() == 1};
    // The bridges' ends are the repeated positions: marked here, not hashed by the clipper.
    if (clean_.ring_count() > 1) {
      bridge_ends_.assign(boundary_.size(), 0);
      for (std::uint32_t v : bridger_.repeated_nodes()) bridge_ends_[v] = 1;
      shared_ = {&bridge_ends_, false};
    }
  }
  // Nothing lies to the left of the hole's leftmost vertex: it is outside the outer ring.
  for (std::uint32_t hole : unjoined) found(Issue::hole_outside_outer_ring, boundary_.vertex[hole]);
  if (found_not_simple()) return;
  if (verdict_.misplaced) {
    found(misplaced_issue(*verdict_.misplaced), clean_.original[verdict_.misplaced->vertex]);
    return;
  }
  // Edges that meet only where they end may still bound overlapping wedges at a point the
  // boundary passes twice (a lobe inside a lobe of the same orientation): not a polygon.
  if (checked && overlapping != UINT32_MAX) {
    findings_.push_back(why_not_valid(true, boundary_.vertex[overlapping]));
    return;
  }
  // A hole that passes a point twice has lobes, and a lobe can lie outside the outer ring (or
  // in another hole) while the rest of the hole lies right: clipping would take it for an
  // island. Asked only then (rare), since it sorts every vertex.
  if (checked && touching && hole_touches_itself())
    if (const auto hole = find_misplaced_hole(clean_))
      found(misplaced_issue(*hole), clean_.original[hole->vertex]);
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
  detail::sort(positions_.begin(), positions_.end(), [](const auto& a, const auto& b) {
    return lexicographic_less(a.first, b.first) || (a.first == b.first && a.second < b.second);
  });
  for (std::size_t k = 1; k < positions_.size(); ++k)
    if (positions_[k].first == positions_[k - 1].first &&
        positions_[k].second == positions_[k - 1].second)
      return true;
  return false;
}

Engine::Finding Engine::why_not_valid(bool checked, std::uint32_t vertex) const {
  // The check found no conflict, so the rings meet only at shared vertices: a hole in the wrong
  // place is named exactly; else the boundary overlaps itself at a point, or the engine stopped.
  if (checked)
    if (const auto hole = find_misplaced_hole(clean_))
      return {misplaced_issue(*hole), clean_.original[hole->vertex]};
  return {Issue::not_simple, vertex};
}

/// The cycle of boundary_ through `entry` into part_ (linked as a cycle from node 0), unless it
/// has more than `most` nodes (then part_ holds its first ones, and false is returned).
[[gnu::noinline]] bool Engine::copy_cycle(std::uint32_t entry, std::size_t most) {
  part_.clear();
  std::uint32_t v = entry;
  do {
    if (part_.size() >= most) return false;
    part_.add(boundary_.pos[v], boundary_.vertex[v]);
    v = boundary_.next[v];
  } while (v != entry);
  for (std::uint32_t i = 0; i + 1 < part_.size(); ++i) part_.link(i, i + 1);
  part_.link(part_.size() - 1, 0);
  return true;
}

bool Engine::clip(Algorithm algorithm, const Options& options, const RunContext& ctx,
                  TriangleList& out, std::uint32_t& best_effort_vertex) {
  if (cycles_.empty()) return true;
  bool complete = clip_main(algorithm, options, ctx, out, best_effort_vertex);
  // Regions that touch the rest only at points (see touching.hpp): small, copied out so that
  // each costs its own size, clipped sequentially.
  for (std::size_t c = 1; c < cycles_.size(); ++c) {
    copy_cycle(cycles_[c], boundary_.size());
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
      // Part after part, each a slab: runs of this order are the CDT's flip sets.
      // Holes are bridged to the left, so the slabs left of the last line are cut into strips
      // by the bridges crossing both their lines, but the rightmost slab stays one piece, which
      // costs the clipper 2.5-2.9x as much a node (random-holes-100k at 16 partitions: 2.0 ms
      // against the others' 0.75 with a whole share, 1.16 against 0.81 with half): with a hole
      // every 64 nodes or more, a third of a share there (0.78-0.82 against 0.80; at 4, 8
      // parts, 1.7-1.8 ms each).
      return divide_and_conquer(boundary_, entry, options.heuristic, make_ear_clipper, ctx, out,
                                best_effort_vertex, clip_order_.region_ordered, variant_scratch_,
                                shared_,
                                (clean_.ring_count() - 1) * 64 >= boundary_.size() ? 0.35 : 1);
    case Algorithm::partition_and_cut:
      rest = partition_and_cut(boundary_, entry, options.heuristic, ctx, out, variant_scratch_,
                               shared_, options.delaunay);
      clip_order_.region_ordered = out.size();  // chain after chain: each chain's ears lie together
      break;
    case Algorithm::mark_and_cut:
      rest = mark_and_cut(boundary_, entry, ctx, out, variant_scratch_, shared_);
      break;
    default:
      break;
  }
  if (rest == no_node) return true;
  bool complete = true;
  ctx.run_serial("clip sequentially", [&] {
    // What the parallel variants leave is often a cycle of a few hundred nodes on a boundary
    // of hundreds of thousands, whose arrays the clipper would size and scan (0.1-0.5 ms on
    // the coasts at 16 partitions, serial): copied out, it costs its own size, and the bit
    // sets take it up to their limit. Its nodes that share a position are hashed there (as in
    // the touching regions' copies below); where they share one with a node off the cycle, no
    // ear test of the cycle is touched.
    if (algorithm != Algorithm::sequential && copy_cycle(rest, boundary_.size() / 4))
      complete = clipper_.run(part_, 0, options.heuristic, out);
    else
      complete = clipper_.run(boundary_, rest, options.heuristic, out, shared_);
  });
  best_effort_vertex = clipper_.best_effort_vertex();
  return complete;
}

Status Engine::run(const InputPolygon& input, const Options& options, TriangleList& out,
                   std::vector<Diagnostic>& diagnostics, DelaunayStatistics& delaunay) {
  out.clear();
  findings_.clear();
  clip_order_ = {};
  if (options.threads > max_threads) {
    diagnostics.push_back({Issue::invalid_options, 0, 0});
    return Status::invalid_input;
  }
  RunContext ctx;
  ctx.profile = options.profile;
  // Clamped before any stage sizes its work by it (a million parts once meant a million queues).
  ctx.partitions = std::min(options.partitions ? options.partitions : Workers::concurrency(options),
                            max_partitions);
  if (input.size() >= parallel_threshold || !sequential(options.algorithm))
    ctx.runner = workers_.runner(options);
  const Status cleaned = clean_polygon(input, clean_, diagnostics, ctx);
  if (cleaned != Status::ok) return cleaned;
  check(options.check_simplicity, ctx);
  bridge(options.check_simplicity, ctx);
  out.reserve(boundary_.size());
  Outline outline(clean_, simplicity_.x_reversals_counted());
  const Choice choice =
      resolve(options.algorithm, boundary_.size(), ctx.partitions, found_not_simple(), outline);
  const Algorithm algorithm = choice.algorithm;
  RunContext clip_ctx = ctx;
  clip_ctx.partitions = choice.parts;
  std::uint32_t best_effort_vertex = 0;
  Options clip_options = options;
  clip_options.heuristic = start_of_flips(options, algorithm, outline);
  if (!clip(algorithm, clip_options, clip_ctx, out, best_effort_vertex) && !found_not_simple())
    findings_.push_back(why_not_valid(options.check_simplicity, best_effort_vertex));
  // Divide-and-conquer's slabs make good flip sets (Greenland's CDT at 2 threads 110 -> 93 ms,
  // no serial walk) but where corridors wind through every slab: the 100k spiral's at 4 and 16
  // partitions took 76 and 105 ms against the walk's sets' 47 and 51.
  if (algorithm == Algorithm::divide_and_conquer)
    clip_order_ = outline.corridors() ? ClipOrder{} : ClipOrder{clip_order_.region_ordered, true};
  const Status status = report(input, diagnostics);
  // Flipping needs a valid triangulation to end in the CDT; a best effort is left as it is.
  if (options.delaunay && status == Status::ok) {
    // Where the outline has a few long runs (a comb, an outline convex or nearly so) the flips
    // go on one partition, whichever clip came first: at 2 threads the 100k comb's CDT
    // 0.77-0.99x the sequential CDT with sets, 0.99-1.02x on one thread. Points in convex
    // position have long Delaunay edges that cross any sets, and each set's own CDT is far from
    // the whole one: on a 100k ellipse the flips across the sets' borders were 462,000 after
    // the sequential clip at 2 partitions and 35 million at 16 (1.6 s against 64 ms on one
    // partition), 16.7 and 64 million after divide-and-conquer's at 2 and 16.
    RunContext flip_ctx = ctx;
    if (flip_ctx.partitions > 1 && outline.few_long_runs()) flip_ctx.partitions = 1;
    make_delaunay(caller_points(input, flip_ctx), clean_, out, flip_ctx, delaunay,
                  delaunay_scratch_, clip_order_);
  }
  return status;
}

EarStatistics Engine::statistics(const InputPolygon& input) {
  std::vector<Diagnostic> ignored;
  if (clean_polygon(input, clean_, ignored) != Status::ok) return {};
  findings_.clear();
  verdict_ = {};
  bridge(false, RunContext{});
  if (cycles_.empty()) return {};
  return clipper_.statistics(boundary_, cycles_.front());
}

}  // namespace pear::detail
