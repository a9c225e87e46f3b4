// Holes joined to the outer ring by bridges (FIST §1.2): one weakly simple boundary.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "core/boundary.hpp"
#include "core/stage.hpp"
#include "geometry/uniform_grid.hpp"

namespace pear::detail {

/// Joins the holes one by one, in order of their leftmost vertex, each to a vertex visible to
/// the left of it (Eberly's ray method). Rays and visibility run on a uniform grid of the
/// merged edges and nodes, so the cost stays near-linear with 100,000 holes (with few holes,
/// one cell: scans). Every ring's
/// nodes and edges enter the grid at once, in arrays filled by counting (no allocation per
/// cell); a hole's only count once it is merged, and the few nodes and edges that bridges add
/// go to per-cell lists beside them.
class HoleBridger {
 public:
  /// Up to this many holes the grid is one cell: each hole scans every edge and node.
  static constexpr std::size_t few_holes = 4;

  /// `boundary` holds one node per clean vertex, each ring already linked as a cycle.
  /// Returns the leftmost node of every hole it could not join (nothing lies to its left: the
  /// hole is outside the outer ring, so the input is not a valid polygon).
  std::vector<std::uint32_t> join(const CleanPolygon& polygon, Boundary& boundary);

 private:
  struct RayHit {
    std::uint32_t edge = UINT32_MAX;           ///< nearest edge crossed left of the hole, or none
    double x = 0;                              ///< where it crosses (for ranking only)
    std::uint32_t touching_edge = UINT32_MAX;  ///< an edge passing exactly through the hole vertex
  };

  /// The grid's contents: the nodes and edges of every ring (ids: the ring's node numbers,
  /// edge v running from v), then per-cell lists of what bridges add.
  struct CellLists {
    std::vector<std::uint32_t> start, items;  ///< cell c holds items[start[c], start[c + 1])
    std::vector<std::uint32_t> head;          ///< added later: a list through `added`
    std::vector<std::pair<std::uint32_t, std::uint32_t>> added;  ///< {item, next in list}
    template <class Visit>
    void for_each(std::size_t cell, Visit&& visit) const {
      for (std::uint32_t i = start[cell]; i < start[cell + 1]; ++i) visit(items[i]);
      for (std::uint32_t a = head[cell]; a != UINT32_MAX; a = added[a].second)
        visit(added[a].first);
    }
    void add(std::size_t cell, std::uint32_t item) {
      added.push_back({item, head[cell]});
      head[cell] = static_cast<std::uint32_t>(added.size() - 1);
    }
  };

  void build_grid(std::uint32_t nodes);
  void fill_cells(std::uint32_t nodes);
  void merge_ring(std::uint32_t first_node);
  void insert_node(std::uint32_t node);
  std::uint32_t insert_edge(std::uint32_t start);
  std::uint32_t leftmost_node(std::uint32_t first_node) const;
  std::uint32_t node_at(const Point& p, const Point& towards) const;
  RayHit cast_left(const Point& h) const;
  Point visible_target(const Point& h, const RayHit& hit) const;
  void splice_bridge(std::uint32_t target, std::uint32_t hole);
  void splice_touching(std::uint32_t target, std::uint32_t hole);
  void splice_into_edge(std::uint32_t edge, std::uint32_t hole);

  Boundary* b_ = nullptr;
  GridFrame frame_;
  CellLists node_cells_, edge_cells_;
  std::vector<std::uint8_t> node_merged_, edge_merged_;  ///< on the joined boundary yet
  std::vector<std::uint32_t> edge_start_;  ///< edge id -> start node (its end is next[start])
  std::vector<std::uint32_t> out_edge_;    ///< node -> id of the edge leaving it
  std::vector<std::uint32_t> order_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs_;  ///< {cell, item}: build_grid
};

}  // namespace pear::detail
