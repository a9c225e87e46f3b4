// An exact check that the cleaned rings form a valid polygon boundary: no two edges cross,
// overlap, or meet where one of them does not end (a vertex inside another edge). Rings may
// touch at shared vertices, which the engine handles.
//
// Method (docs/simplicity.md): an adaptive grid of edge bounding boxes. Cells are processed in
// parallel; a cell holding many edges gets its own finer grid fitted to them, recursively; a
// pair of edges is tested once, in the cell holding the lower-left corner of the intersection
// of their boxes. Where edges are long against their spacing (a random star) no grid separates
// them: a cell, or the whole polygon, is then decided by a Shamos-Hoey sweep, the whole polygon
// in vertical slabs swept in parallel. Every decision depends on counts only, never on timing.
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <vector>

#include "core/fill_vector.hpp"
#include "core/stage.hpp"
#include "geometry/box_scan.hpp"
#include "geometry/uniform_grid.hpp"

namespace pear::detail {

/// The closed bounding box of an edge: exact (min and max of coordinates, no rounding).
using EdgeBox = Box;

inline EdgeBox merged(const EdgeBox& a, const EdgeBox& b) {
  return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

/// The box of the edge from a to b.
inline EdgeBox edge_box(const Point& a, const Point& b) {
  return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
}

/// The direction in x of the edge from a to b: -1, 0 (vertical) or +1.
inline std::int8_t x_direction(const Point& a, const Point& b) {
  return static_cast<std::int8_t>((b.x > a.x) - (b.x < a.x));
}

/// What SimplicityCheck::find_t_junctions found.
struct TJunctionSearch {
  /// Every T-junction, by edge, then from the edge's start to its end; one vertex (the smallest
  /// index) for each point inside an edge. Incomplete when there is a conflict.
  std::vector<TJunction> junctions;
  /// The smaller edge of a crossing, an overlap or a fold: what no split resolves.
  std::optional<std::uint32_t> conflict;
};

/// The rings' edges: edge e runs from vertex e to next[e].
struct RingEdges {
  const FillVector<Point>* points = nullptr;
  // Each written in full after every resize, in tasks on large polygons (fill_vector.hpp).
  FillVector<std::uint32_t> next;
  FillVector<EdgeBox> boxes;
  EdgeBox bounds{};  ///< of all edges

  std::uint32_t size() const { return static_cast<std::uint32_t>(next.size()); }
  /// Whether edges e and f (any two) cross, overlap, or one passes through a vertex of the
  /// other; neighbours in a ring conflict only by folding back over each other.
  bool conflict(std::uint32_t e, std::uint32_t f) const;
  /// For edges e and f that may conflict: false when they cross, overlap or fold back over each
  /// other; otherwise true, appending the T-junction if an end of one lies inside the other.
  bool t_junctions(std::uint32_t e, std::uint32_t f, std::vector<TJunction>& out) const;

 private:
  bool separate_edges_conflict(std::uint32_t e, std::uint32_t f) const;
};

/// The smallest edge index offered by any task: the minimum is the same in any order.
class SmallestViolation {
 public:
  static constexpr std::uint32_t none = UINT32_MAX;
  std::uint32_t get() const { return value_.load(std::memory_order_relaxed); }
  void offer(std::uint32_t edge) {
    std::uint32_t seen = get();
    while (edge < seen && !value_.compare_exchange_weak(seen, edge, std::memory_order_relaxed)) {
    }
  }

 private:
  std::atomic<std::uint32_t> value_{none};
};

/// When the grid subdivides and when it hands a cell to the sweep. Counts only: deterministic.
struct GridLimits {
  std::uint32_t leaf_edges = 24;       ///< cells with at most this many edges test all pairs
  double root_entries_per_edge = 3;    ///< more in a chunk of edges at the root: slabs swept
  double child_entries_per_edge = 3;   ///< more in a finer grid: it does not separate the edges
  std::uint32_t max_depth = 8;         ///< levels of grids, the root included
  std::uint32_t all_pairs_edges = 64;  ///< a cell no finer grid helps: all pairs up to here,
                                       ///< a sweep beyond (unless allow_sweep is false)
  bool allow_sweep = true;
};

/// A hole that lies outside the outer ring, or inside another hole.
struct MisplacedHole {
  std::uint32_t vertex;  ///< a vertex of the hole no other ring shares (into polygon.points)
  bool outside_outer;    ///< else inside another hole
};

/// What SimplicityCheck::check found.
struct Verdict {
  /// The first vertex of an edge in a conflict: the smallest such edge where the runs or the
  /// few-edges strategies decide, else as find_violation gives it.
  std::optional<std::uint32_t> violation;
  /// Whether two edges that are not neighbours share an endpoint position (rings touching at
  /// vertices): the engine then relinks the passes through such points (TouchingPoints).
  /// Known exactly when there is no violation (a ring folding back on itself may hide a
  /// touching pair) for few edges, from the runs, and from the grid where it tested every
  /// pair; unknown from the sweep.
  enum class Touching : std::uint8_t { no, yes, unknown } touching = Touching::unknown;
  /// For few edges that neither conflict nor touch, with holes: the first hole not inside the
  /// outer ring or inside another hole (find_misplaced_hole_among_few). Not asked otherwise:
  /// the engine names such a hole when it cannot clip the polygon (find_misplaced_hole).
  std::optional<MisplacedHole> misplaced;
};

/// The grid over the whole polygon, kept between calls for its buffers.
/// The cells a box covers in a grid: columns c0..c1, rows r0..r1.
struct CellRange {
  int c0, c1, r0, r1;
  std::size_t size() const {
    return static_cast<std::size_t>(c1 - c0 + 1) * static_cast<std::size_t>(r1 - r0 + 1);
  }
};

struct RootGrid {
  GridFrame frame;
  std::vector<std::uint32_t> cell_start, items;
  std::vector<std::uint32_t> chunk_counts;  ///< per chunk of edges and cell, for filling
  /// Each edge's cells: found by the count, read by the fill (written in full before they are
  /// read, in tasks).
  FillVector<CellRange> ranges;
};

/// Checks every pair of edges sharing a cell; offers the smallest edge of each conflict found,
/// and gives (`touching`, when no conflict is found) whether two vertices share a position:
/// unknown where a cell was swept instead. False when the root grid would hold too many
/// entries (nothing was checked then).
bool check_on_grid(const RingEdges& edges, const GridLimits& limits, const RunContext& ctx,
                   RootGrid& root, SmallestViolation& found, Verdict::Touching* touching = nullptr);
/// Shamos-Hoey on a subset of the edges: a conflict among them (its smaller edge), if any.
std::optional<std::uint32_t> sweep_edges(const RingEdges& edges,
                                         std::span<const std::uint32_t> subset);
/// Borders of `slabs` vertical slabs (slab s is x in [borders[s - 1], borders[s])) that give
/// each slab about as many edges, an edge counted in every slab its x-range meets.
/// The sample's reading and sorting are ctx's tasks.
std::vector<double> slab_borders(const RingEdges& edges, std::uint32_t slabs,
                                 const RunContext& ctx = RunContext{});
/// The sweep in `slabs` vertical slabs, in parallel; an edge goes to every slab its box meets.
void sweep_in_slabs(const RingEdges& edges, std::uint32_t slabs, const RunContext& ctx,
                    SmallestViolation& found);

/// The sweep in slabs, recording every T-junction and stopping at a conflict no split resolves.
TJunctionSearch find_t_junctions_in_slabs(const RingEdges& edges, std::uint32_t slabs,
                                          const RunContext& ctx);

/// For rings whose edges do not conflict (they meet only at shared vertices): the first hole,
/// in ring order, that is not inside the outer ring or is inside another hole. Exact; near
/// linear for real data (a ray per hole through horizontal bands of the edges). For polygons
/// the engine could not triangulate, to name why.
std::optional<MisplacedHole> find_misplaced_hole(const CleanPolygon& polygon);
/// find_misplaced_hole for rings that share no vertex position and whose edges do not conflict
/// (the check found none touching): a ray from each hole's first vertex against every edge of
/// the other rings, nothing to set up. For few edges: holes times vertices tests.
std::optional<MisplacedHole> find_misplaced_hole_among_few(const CleanPolygon& polygon);

/// How often the rings turn back in x: about the number of runs of edges monotone in x (n over
/// 1.5-2.3 on fractals, stars and grids of holes, 5-15 on coastlines, a few on combs and spirals).
std::size_t x_reversals(const CleanPolygon& polygon);
/// The same count in `tasks` tasks on ctx (runs_in_parts.cpp).
std::size_t x_reversals(const CleanPolygon& polygon, const RunContext& ctx, std::size_t tasks);

class SimplicityCheck {
 public:
  /// Up to this many edges, every pair is tested by box tests (pair_by_pair_limit); up to
  /// chains_limit, pairs of runs monotone in x; beyond, the grid and the sweep
  /// (find_violation). Measured: docs/engine.md, "Strategies".
  static constexpr std::uint32_t few_edges_limit = 128;
  static_assert(few_edges_limit % 64 == 0, "check_all_pairs keeps a bit a row in whole words");
  static constexpr std::uint32_t chains_limit = 384;
  /// Past chains_limit the runs are tried first (at most two partitions: they are serial),
  /// and given up for the grid after chains_budget looks per edge.
  static constexpr std::size_t chains_budget = 8;

  /// The check, by the strategy that suits the size. `find_crossings` false asks only whether
  /// rings touch (no orientation tests), for runs that skip the check: by the box rows up to
  /// few_edges_limit, then whether a position repeats (a sort); beyond chains_limit that is not
  /// asked at all (unknown).
  Verdict check(const CleanPolygon& polygon, const RunContext& ctx, bool find_crossings);

  /// `grid_only` (never a sweep, tiny cells: every level of the grid is exercised) and
  /// `sweep_only` (three slabs) are for tests that compare the methods on small inputs.
  enum class Method : std::uint8_t { automatic, grid_only, sweep_only };

  /// The index (into polygon.points) of the first vertex of an edge in a conflict, if any: the
  /// smallest such index among the conflicts found. The grid finds them all, so where it alone
  /// decides this is the smallest edge in any conflict; a sweep reports the first it meets. The
  /// same for any thread count.
  std::optional<std::uint32_t> find_violation(const CleanPolygon& polygon, const RunContext& ctx,
                                              Method method = Method::automatic);

  /// Every vertex lying strictly inside an edge, or a conflict that splitting edges at such
  /// vertices cannot resolve. A sweep (in slabs, in parallel): for polygons find_violation has
  /// found not simple, so valid input never pays for it. Deterministic at any thread count.
  /// `sweep_only` sweeps three slabs (for tests: slab borders on small inputs).
  TJunctionSearch find_t_junctions(const CleanPolygon& polygon, const RunContext& ctx,
                                   Method method = Method::automatic);

  /// Whether edge `e` (the first vertex's index, as find_violation gives it) is in a conflict
  /// that no split at a T-junction resolves: it crosses, overlaps or folds back over another
  /// edge. Then the polygon is not simple whatever find_t_junctions would find, and its sweep
  /// need not run. One pass over the edges' boxes.
  bool unresolvable_conflict_at(const CleanPolygon& polygon, std::uint32_t e,
                                const RunContext& ctx);

  /// The runs monotone in x the last check by runs cut the rings into (for tests: serially and
  /// in parts the same).
  std::size_t runs() const { return chains_.size(); }
  /// x_reversals of the last check's polygon where it counted them (the runs tried past
  /// chains_limit), for the engine's choices; T-junction splits do not change them.
  std::optional<std::size_t> x_reversals_counted() const { return reversals_; }

 private:
  void index_edges(const CleanPolygon& polygon, const RunContext& ctx);
  bool repeats_a_position(const CleanPolygon& polygon);
  Verdict check_all_pairs(const CleanPolygon& polygon, bool find_crossings);
  /// Up to this many edges check_all_pairs goes pair by pair: the rows' set-up costs more than
  /// it saves (in node a county of 8 vertices or fewer 1.16x faster; the same instructions
  /// natively; from 17 edges the rows are faster again).
  static constexpr std::uint32_t pair_by_pair_limit = 16;
  Verdict check_pair_by_pair(const CleanPolygon& polygon, bool find_crossings);
  /// Every pair of edges in two runs whose boxes meet; none when that would look at more than
  /// `budget` pairs of runs and edges (the grid is then the better index).
  static constexpr std::size_t every_pair = std::numeric_limits<std::size_t>::max();
  std::optional<std::uint32_t> prepare_runs(const CleanPolygon& polygon, bool find_crossings,
                                            std::size_t budget);
  /// prepare_runs(polygon, true, budget) in `tasks` tasks (runs_in_parts.cpp): the same fold,
  /// runs and order.
  std::optional<std::uint32_t> prepare_runs_in_parts(const CleanPolygon& polygon,
                                                     std::size_t budget, const RunContext& ctx,
                                                     std::size_t tasks);
  std::uint32_t link_edges_in_parts(const CleanPolygon& polygon, const RunContext& ctx,
                                    std::size_t tasks);
  bool cut_runs_in_parts(const CleanPolygon& polygon, const RunContext& ctx, std::size_t tasks);
  void finish_runs_in_parts(const RunContext& ctx, std::size_t tasks);
  void sort_runs_in_parts(const RunContext& ctx, std::size_t tasks);
  /// What a walk over pairs of runs found: the smallest edge in a conflict, touching edges.
  struct RunWalk {
    std::uint32_t smallest = SmallestViolation::none;
    bool touching = false;
    bool over_budget = false;
  };
  /// A pair of runs, `run` before `other` in chains_: where a walk over the pairs starts or ends.
  struct PairAt {
    std::size_t run, other;
  };
  RunWalk walk_runs(PairAt from, PairAt to, bool find_crossings, std::size_t budget,
                    std::atomic<std::size_t>& spent) const;
  /// The pairs a walk over every run looks at, counted in tasks: pairs_before_[i], the pairs of
  /// runs before run i (the last entry all of them).
  void count_run_pairs(const RunContext& ctx);
  PairAt pair_at(std::size_t pair) const;
  Verdict check_few_chains(const CleanPolygon& polygon, bool find_crossings);
  std::optional<Verdict> check_chains(const CleanPolygon& polygon, const RunContext& ctx);
  bool monotone_chains(const CleanPolygon& polygon, std::size_t min_chain_edges);
  bool chains_within(std::size_t budget) const;
  /// Where the ring of edges [first, end) first turns in x (direction_), or first: its runs
  /// start there, so that none wraps around the ring's first point.
  std::uint32_t first_turn(std::uint32_t first, std::uint32_t end) const;
  struct Chain;
  void finish_run(Chain& chain);
  template <class Visit>
  std::size_t walk_chain_pair(const Chain& chain, const Chain& other, Visit&& visit) const;

  RingEdges edges_;
  RootGrid root_;

  /// check_chains' runs of edges along which x never reverses (chain_order_[begin, end), in
  /// increasing x), sorted by where their x-ranges start.
  struct Chain {
    std::uint32_t begin, end;
    bool decreasing;
    double x0, x1, y0, y1;
  };
  /// The order of chains_: by where their x-ranges start, then by position (a total order,
  /// so that runs sorted in parts come out as sorted at once).
  static bool chain_before(const Chain& a, const Chain& b) {
    return a.x0 < b.x0 || (a.x0 == b.x0 && a.begin < b.begin);
  }
  // The runs' FillVectors are written in full after every resize (in tasks on large polygons).
  FillVector<Chain> chains_;
  std::vector<std::uint32_t> run_start_;   ///< each ring's first run's first edge (in parts)
  std::vector<std::size_t> pairs_before_;  ///< count_run_pairs
  std::optional<std::size_t> reversals_;   ///< x_reversals_counted()
  FillVector<std::uint32_t> chain_order_;
  FillVector<EdgeBox> chain_boxes_;    ///< the edges' boxes in chain_order_
  FillVector<std::int8_t> direction_;  ///< each edge's direction in x: -1, 0 or +1
  std::vector<Point> sorted_points_;   ///< repeats_a_position's copy

  /// check_all_pairs' edge boxes in floats, a column per side (padded for eight-wide loads),
  /// and the pairs to test as rows (geometry/box_scan.hpp).
  std::array<std::array<float, few_edges_limit + 8>, 4> float_columns_{};
  std::vector<RowRanges> rows_;
};

}  // namespace pear::detail
