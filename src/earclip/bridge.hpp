// Holes joined to the outer ring by bridges (FIST §1.2): one weakly simple boundary.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/boundary.hpp"
#include "core/fill_vector.hpp"
#include "core/stage.hpp"
#include "geometry/uniform_grid.hpp"
#include "pear/config.hpp"

namespace pear::detail {

/// Joins the holes one by one, in order of their leftmost vertex, each to a vertex visible to
/// the left of it (Eberly's ray method). Rays and visibility run on a uniform grid of the
/// merged edges and nodes, so the cost stays near-linear with 100,000 holes (with few holes,
/// one cell: scans). Every ring's nodes and edges enter the grid at once, in arrays filled by
/// counting (no allocation per cell); each carries the rank at which it joins the boundary
/// (outer ring 0, the k-th hole in order k), so a hole of rank k sees exactly the rings ranked
/// below it, and the few nodes and edges that bridges add go to per-cell lists beside them.
///
/// In parallel (docs/parallel.md, "Bridges in parts"): every hole's ray and visible vertex are
/// found at once, as tasks, against the rings ranked below it, and so is whether a bridge found
/// for a hole before it may cross its ray; then, in order, each hole is spliced, after a check
/// that no bridge added before it crosses its ray nearer than what it hit (the only way the
/// serial result could differ; then it is found again). The triangles are the same as the
/// serial joining's, whatever the threads or parts.
class HoleBridger {
 public:
  /// Up to this many holes the grid is one cell: each hole scans every edge and node.
  static constexpr std::size_t few_holes = 4;
  /// Up to this many holes on rings that are `apart`, no grid at all: every ray in one pass
  /// over the edges, every visible vertex in one pass over the nodes (bridge_few.cpp).
  static constexpr std::size_t scanned_holes = 64;
  /// `boundary` holds one node per clean vertex, each ring already linked as a cycle.
  /// Returns the leftmost node of every hole it could not join (nothing lies to its left: the
  /// hole is outside the outer ring, so the input is not a valid polygon). `in_parts`: the
  /// caller runs in parts (ctx.partitions > 1, a parallel run): with more than `few_holes`
  /// holes the search then runs as ctx's tasks, ctx.partitions x 4 of them; every phase is
  /// recorded in ctx's profile. `apart`: no two vertices of the polygon share a position (the
  /// simplicity check's verdict); up to scanned_holes holes are then joined without a grid,
  /// to the same boundary.
  std::vector<std::uint32_t> join(const CleanPolygon& polygon, Boundary& boundary,
                                  const RunContext& ctx = RunContext{}, bool in_parts = false,
                                  bool apart = false);

  /// Up to how many holes on rings apart are joined without a grid (scanned_holes; tests
  /// set 0 to take the grid's path there).
  void scan_up_to(std::size_t holes) { scan_limit_ = holes; }

  /// Holes whose attachment the parallel search found and the splice had to find again (an
  /// earlier bridge crossed its ray): for tests and the profile's notes.
  std::size_t redone() const { return redone_; }
  /// The nodes the last join left at a position another node has: both ends of every bridge
  /// and their copies (where no rings touch, the only repeated positions).
  const std::vector<std::uint32_t>& repeated_nodes() const { return repeated_; }

 private:
  struct RayHit {
    std::uint32_t edge = UINT32_MAX;           ///< nearest edge crossed left of the hole, or none
    double x = 0;                              ///< where it crosses (for ranking only)
    std::uint32_t touching_edge = UINT32_MAX;  ///< an edge passing exactly through the hole vertex
  };
  /// Where a hole attaches, as seen from its leftmost vertex.
  struct Attachment {
    bool touches = false;  ///< a merged node lies at the hole's vertex
    RayHit hit;
    /// The visible vertex, when the ray hit an edge; else the origin, never garbage: the
    /// splice reads its cell before it knows nothing was hit (uninitialised, a NaN there made
    /// the cell index wild: a SEGV under ASan in a fresh-clone CI run at e037ab6).
    Point target{};
    /// The merged node to splice at (node_at of the hole's vertex, or of target), as the
    /// search saw it: still right while no splice changed a node in its cell.
    std::uint32_t node = UINT32_MAX;
  };

  /// The grid's contents: the nodes and edges of every ring (ids: the ring's node numbers,
  /// edge v running from v), then per-cell lists of what bridges add.
  struct CellLists {
    FillVector<std::uint32_t> start, items;  ///< cell c holds items[start[c], start[c + 1])
    FillVector<std::uint32_t> head;          ///< added later: a list through `added`
    std::vector<std::pair<std::uint32_t, std::uint32_t>> added;  ///< {item, next in list}
    template <class Visit>
    void for_each(std::size_t cell, Visit&& visit) const {
      for (std::uint32_t i = start[cell]; i < start[cell + 1]; ++i) visit(items[i]);
      for_each_added(cell, visit);
    }
    template <class Visit>
    void for_each_added(std::size_t cell, Visit&& visit) const {
      for (std::uint32_t a = head[cell]; a != UINT32_MAX; a = added[a].second)
        visit(added[a].first);
    }
    void add(std::size_t cell, std::uint32_t item) {
      added.push_back({item, head[cell]});
      head[cell] = static_cast<std::uint32_t>(added.size() - 1);
    }
  };
  struct Hole {
    std::uint32_t leftmost, ring;
  };
  /// The parallel grid build's scratch, per chunk of item ids: its (cell, item) pairs and how
  /// many fall in each band of cells (then where the band's pairs of this chunk go).
  /// {cell, item}, trivial (std::pair's constructor zeroes): resize() leaves it unwritten.
  struct CellPair {
    std::uint32_t first, second;
  };
  struct GridChunk {
    std::vector<CellPair> pairs;
    std::vector<std::uint32_t> in_band;
  };

  using PhaseNames = std::array<const char*, 3>;
  CellLists& cell_lists(std::size_t list) {
    return list == 0 ? node_cells_ : list == 1 ? edge_cells_ : bridge_cells_;
  }
  /// Whether the attachment joins the hole by a bridge from a ray's hit (the search's usual
  /// outcome), not at a shared point or inside an edge.
  static bool adds_bridge(const Attachment& at) {
    return !at.touches && at.hit.touching_edge == UINT32_MAX && at.hit.edge != UINT32_MAX;
  }
  void order_holes(const CleanPolygon& polygon, const RunContext& ctx, bool parallel);
  // Without a grid (bridge_few.cpp).
  /// Eberly's search for the vertex a hole's vertex h sees along its ray's hit edge a-c: M,
  /// the end of a-c with the smaller x, or the vertex in triangle (h, crossing, M) seen at the
  /// smallest angle from the ray (the nearest on ties). Every candidate lies in the box.
  struct Sight {
    Point h, a, c, m, best;
    std::uint32_t best_node = UINT32_MAX;
    double up = 1, edge_side = 0;
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
    bool open = false;  ///< candidates remain to be looked at (M is not on the ray)
    void start(const Point& hole, std::uint32_t start_node, const Boundary& b);
    bool better(const Point& v) const;
    void consider(const Point& v, std::uint32_t node);
  };
  // The splice after the search in parts, on rings apart (bridge_splice.cpp).
  struct WaitingBridge {
    std::uint32_t target, hole;
    std::uint32_t node, edge, repeat;    ///< the first ids it takes (two nodes, two edges, four)
    std::array<std::uint32_t, 5> marks;  ///< the nodes it writes or whose lists it changes
    bool made;
  };
  bool splice_apart(const CleanPolygon& polygon, std::vector<std::uint32_t>& unjoined,
                    std::size_t& k, bool& stale);
  void wait_or_make(std::uint32_t target, std::uint32_t hole, std::uint32_t indexed);
  void make_bridge(WaitingBridge& w);
  void settle(std::uint32_t node);
  void finish_waiting(const RunContext* ctx);
  std::uint32_t input_node(std::uint32_t node) const;
  std::uint32_t node_at_apart(const Point& p, const Point& towards, std::uint32_t rank);
  Attachment find_apart(std::uint32_t hole, std::uint32_t rank);
  void join_scanned(const CleanPolygon& polygon, const RunContext& ctx, bool in_parts,
                    std::vector<std::uint32_t>& unjoined);
  void cast_all(const RunContext& ctx, std::size_t tasks);
  void sight_all(const RunContext& ctx, std::size_t tasks);
  Attachment find_scanned(std::uint32_t k, bool passes_hold);
  Attachment find_by_scan(std::uint32_t hole, std::uint32_t rank);
  std::uint32_t node_holding(std::uint32_t input, const Point& towards, bool settling);
  void list_copy(std::uint32_t copy, std::uint32_t of);
  /// A splice added `copy` at the position of `of` (an input node or a copy): listed with
  /// its input node's copies while joining without a grid (the grid lists it in its cell).
  void note_copy(std::uint32_t copy, std::uint32_t of) {
    if (PEAR_HAS_THREADS && !gridded_) list_copy(copy, of);
  }
  void build_grid(const CleanPolygon& polygon, const RunContext& ctx, bool parallel);
  void fill_cells(std::uint32_t nodes);
  void build_grid_in_parts(const CleanPolygon& polygon, const RunContext& ctx);
  template <class Cells>
  void fill_lists_in_parts(std::size_t first_list, std::size_t count, std::uint32_t items,
                           std::size_t tasks, const RunContext& ctx, const PhaseNames& phases,
                           Cells&& cells);
  void sort_band(std::size_t list, std::size_t band, std::size_t per_band);
  void index_found_bridges(const RunContext& ctx);
  void assign_ranks(const CleanPolygon& polygon, std::size_t from, std::size_t to);
  void find_all(const RunContext& ctx);
  void splice_all(const CleanPolygon& polygon, bool found_in_parallel,
                  std::vector<std::uint32_t>& unjoined);
  bool merged(std::uint32_t item, std::uint32_t rank) const { return rank_[item] < rank; }
  Attachment find(std::uint32_t hole, std::uint32_t rank) const;
  static bool crosses_before_hit(const Point& h, const RayHit& hit, const Point& a, const Point& b);
  template <class Crosses>
  bool any_on_ray(const Point& h, const RayHit& hit, Crosses&& crosses_in_cell) const;
  bool any_found_bridge_crosses(std::uint32_t k) const;
  bool any_added_near_ray(const Point& h, const RayHit& hit) const;
  void list_added_edge(std::size_t cell, std::uint32_t id);
  bool crossed_by_bridge(const Point& h, const RayHit& hit, bool found_bridges) const;
  template <class Visit>
  void for_each_indexed_bridge(std::size_t cell, Visit&& visit) const;
  bool attach(std::uint32_t hole, const Attachment& at, std::uint32_t rank, bool node_known,
              std::uint32_t indexed);
  void mark_changed(std::size_t cell);
  void hand_edge_to_copy(std::uint32_t target, std::uint32_t target_copy);
  std::size_t cell_of(std::uint32_t v) const;
  /// The most node or edge ids a join can end with: a bridge adds two nodes and two edges, a
  /// hole joined inside an edge one of each.
  std::size_t most_ids() const { return b_->size() + 2 * holes_.size(); }
  void reserve_for_splices();
  void leave_out(const CleanPolygon& polygon, std::uint32_t ring);
  void insert_node(std::size_t cell, std::uint32_t node);
  std::uint32_t new_edge(std::uint32_t start);
  void insert_edges(std::uint32_t start, std::uint32_t back);
  std::uint32_t node_at(const Point& p, const Point& towards, std::uint32_t rank) const;
  RayHit cast_left(const Point& h, std::uint32_t rank) const;
  Point visible_target(const Point& h, const RayHit& hit, std::uint32_t rank) const;
  void splice_bridge(std::uint32_t target, std::uint32_t hole,
                     std::uint32_t indexed_hole = UINT32_MAX);
  void splice_touching(std::uint32_t target, std::uint32_t hole);
  void splice_into_edge(std::uint32_t edge, std::uint32_t hole);

  Boundary* b_ = nullptr;
  GridFrame frame_;
  CellLists node_cells_, edge_cells_;
  /// In parts (index_found_bridges): the cells of every hole's bridge as found (items: hole
  /// numbers in holes_). A bridge spliced as found is entered only here (its edges' ids in
  /// bridge_edge_), so edge_cells_' added lists hold only the edges of holes found again.
  CellLists bridge_cells_;
  bool bridges_indexed_ = false;
  /// Per hole spliced as found: its bridge's first edge (the second is the next id).
  std::vector<std::uint32_t> bridge_edge_;
  /// Per hole: whether a bridge found for a hole before it may cross its ray.
  std::vector<std::uint8_t> maybe_crossed_;
  /// Node or edge id -> the rank of its ring (a ring joins when the hole ranked next is
  /// searched), 0 for what bridges add, never (UINT32_MAX) for a hole that could not be joined.
  std::vector<std::uint32_t> rank_;
  FillVector<std::uint32_t> edge_start_;  ///< edge id -> start node (its end is next[start])
  FillVector<std::uint32_t> out_edge_;    ///< node -> id of the edge leaving it
  std::vector<Hole> holes_;               ///< by leftmost vertex: hole k - 1 has rank k
  std::vector<Attachment> found_;         ///< the parallel search's result per hole
  std::vector<CellPair> pairs_;           ///< {cell, item}: build_grid
  std::vector<GridChunk> grid_chunks_;    ///< in parts: the nodes' chunks, then the edges'
  /// In parts, per list (nodes, edges, found bridges): its pairs by band, and where each band
  /// starts.
  FillVector<CellPair> by_band_[3];
  std::vector<std::uint32_t> band_start_[3];
  /// In the parallel splice: the node cells where a splice added a node or turned a node's
  /// sector (a node found there by the search must be looked up again).
  std::vector<std::uint8_t> changed_cells_;
  /// In the splice after the search in parts: per row of the grid, a bit per column whose
  /// cell lists an added edge (row_words_ words a row).
  std::vector<std::uint64_t> added_columns_;
  std::size_t row_words_ = 0;
  bool edges_split_ = false;  ///< a splice ran the boundary through an edge: ids moved
  /// Whether the grid lists what splices add (false while joining without one).
  bool gridded_ = true;
  /// Without a grid: per hole (by rank - 1) its ray's hit on the rings and the vertex it sees,
  /// from the passes; the edges splices added.
  std::size_t scan_limit_ = scanned_holes;
  std::vector<RayHit> scanned_hits_;
  std::vector<Sight> sights_;  ///< per task and hole while the passes run
  std::vector<std::uint32_t> seen_node_;
  std::vector<std::uint32_t> added_edges_;
  /// Where no two input nodes share a position (joined without a grid, or the splice in parts
  /// on rings apart): per input node its newest copy, per copy (ids from first_copy_ on) the
  /// one before and its input node.
  std::uint32_t first_copy_ = 0;
  FillVector<std::uint32_t> copy_head_, copy_next_, copy_input_;
  /// The splice in parts on rings apart: whether it runs; per node the bridge waiting on it
  /// (its index in waiting_), or whether a splice changed it; per bridge made from the search
  /// (edge ids from first_edge_, two a bridge) its entry in waiting_; the next node, edge and
  /// repeated_ ids to hand out.
  bool apart_ = false, bridges_waiting_ = false;
  std::vector<WaitingBridge> waiting_;
  FillVector<std::uint32_t> pending_, edge_bridge_;
  std::uint32_t first_edge_ = 0;
  std::array<std::uint32_t, 3> next_ids_{};
  std::size_t redone_ = 0;
  std::vector<std::uint32_t> repeated_;
};

}  // namespace pear::detail
