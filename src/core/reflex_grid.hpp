// Geometric hashing of reflex nodes (FIST §1.2): a uniform grid built once over the nodes that are
// strictly reflex. Nodes only ever turn from reflex to convex while ears are clipped, so the grid
// never grows; a node that stops being reflex is swapped out of its cell at once, so queries see
// only live reflex nodes (a stale entry would cost every later query that touches its cell).
// The positions are columns, cell after cell: where cells are crowded (a coastline's occupied
// cells hold 22 reflex nodes on average), the ear test's query takes a cell's nodes in its box
// by a SIMD scan (geometry/box_scan), not one branch a node.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "boundary.hpp"
#include "fill_vector.hpp"
#include "geometry/box_scan.hpp"
#include "geometry/uniform_grid.hpp"

namespace pear::detail {

class ReflexGrid {
 public:
  /// An entry keeps the position next to the node, so the box test needs no other memory.
  struct Entry {
    Point pos;
    std::uint32_t node;
  };

  /// Builds the grid over `nodes` (all strictly reflex). A grid built without `removable`
  /// cannot remove nodes but needs no memory per boundary node. A removable grid's slot array
  /// spans every boundary node but is written only at its own nodes: left unwritten by resize,
  /// it costs a chain's grid the pages of its own nodes only (zeroed, the 16 chains of Eurasia
  /// wrote 16 arrays of 1.5M slots at every call).
  void build(const Boundary& b, const std::vector<std::uint32_t>& nodes, bool removable = true) {
    if (removable) slot_.resize(b.size());
    extra_.clear();
    live_ = nodes.size();
    if (nodes.empty()) {
      frame_ = GridFrame{};
      lo_ = {INFINITY, INFINITY};
      hi_ = {-INFINITY, -INFINITY};
      cell_start_.assign(2, 0);
      cell_end_.assign(1, 0);
      occupied_.reset(1);
      resize_columns(0);
      scan_cells_ = false;
      return;
    }
    Point lo = b.pos[nodes[0]], hi = lo;
    for (std::uint32_t v : nodes) {
      const Point& p = b.pos[v];
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    frame_.fit(lo, hi, nodes.size());
    lo_ = lo;
    hi_ = hi;
    cell_start_.assign(frame_.cell_count() + 1, 0);
    for (std::uint32_t v : nodes) ++cell_start_[cell_of(b.pos[v]) + 1];
    for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
    resize_columns(nodes.size());
    std::size_t occupied = 0;
    for (std::size_t c = 0; c + 1 < cell_start_.size(); ++c)
      occupied += cell_start_[c + 1] != cell_start_[c];
    scan_cells_ = 2 * nodes.size() >= 7 * occupied;
    cell_end_.assign(cell_start_.begin(), cell_start_.end() - 1);
    occupied_.reset(frame_.cell_count());
    for (std::uint32_t v : nodes) {
      const std::size_t cell = cell_of(b.pos[v]);
      const std::uint32_t slot = cell_end_[cell]++;
      xs_[slot] = b.pos[v].x;
      ys_[slot] = b.pos[v].y;
      node_[slot] = v;
      if (removable) slot_[v] = slot;
      occupied_.set(cell);
    }
  }

  /// Adds a node after the build (the copies a split makes): kept in a short list that every
  /// query visits, since splits are rare.
  void add(std::uint32_t node, const Point& pos) {
    if (slot_.size() <= node) slot_.resize(node + 1);
    slot_[node] = static_cast<std::uint32_t>(extra_.size()) | extra_bit;
    extra_.push_back({pos, node});
    ++live_;
  }

  /// Takes a node out of the grid (it turned convex or was clipped).
  void remove(std::uint32_t node, const Point& pos) {
    --live_;
    if (slot_[node] & extra_bit) {
      const std::uint32_t slot = slot_[node] & ~extra_bit;
      extra_[slot] = extra_.back();
      slot_[extra_[slot].node] = slot | extra_bit;
      extra_.pop_back();
      return;
    }
    const std::size_t cell = cell_of(pos);
    const std::uint32_t slot = slot_[node], last = --cell_end_[cell];
    xs_[slot] = xs_[last];
    ys_[slot] = ys_[last];
    node_[slot] = node_[last];
    slot_[node_[slot]] = slot;
    if (cell_end_[cell] == cell_start_[cell]) occupied_.clear(cell);
  }

  /// Calls visit(entry) for every node in the grid (the built ones and the added) within the
  /// box [lo, hi].
  template <class Visit>
  void for_each_in_box(const Point& lo, const Point& hi, Visit&& visit) const {
    const auto inside = [&](const Point& p) {
      return p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y;
    };
    if (live_ == 0) return;
    if (hi.x >= lo_.x && lo.x <= hi_.x && hi.y >= lo_.y && lo.y <= hi_.y) {
      const int c0 = frame_.column(lo.x), c1 = frame_.column(hi.x);
      for (int r = frame_.row(lo.y); r <= frame_.row(hi.y); ++r)
        for (int c = c0; c <= c1; ++c) {
          const std::size_t cell = frame_.cell(c, r);
          for (std::uint32_t i = cell_start_[cell]; i < cell_end_[cell]; ++i)
            if (inside({xs_[i], ys_[i]})) visit(entry(i));
        }
    }
    for (const Entry& e : extra_)
      if (inside(e.pos)) visit(e);
  }

  /// The nodes in the grid.
  std::size_t live() const { return live_; }

  /// Calls visit(entry) for every node in a cell that triangle (a, b, c) may touch, until visit
  /// returns true; returns whether it did. Per row, only the columns the triangle spans within
  /// the row's band (plus one on each side for rounding), and only cells that hold nodes; none
  /// once every node has left (what is left of a comb is a strip whose ears span it: each
  /// walked every row of the grid's empty cells).
  template <class Visit>
  [[gnu::always_inline]] bool any_near_triangle(const Point& a, const Point& b, const Point& c,
                                                Visit&& visit) const {
    if (live_ == 0) return false;
    const auto visit_row = [&](std::size_t first, std::size_t last) {
      return visit_cells(first, last, visit);
    };
    const bool apart = std::max({a.x, b.x, c.x}) < lo_.x || std::min({a.x, b.x, c.x}) > hi_.x ||
                       std::max({a.y, b.y, c.y}) < lo_.y || std::min({a.y, b.y, c.y}) > hi_.y;
    if (!apart && frame_.any_row_span_of_triangle(a, b, c, visit_row)) return true;
    for (const Entry& e : extra_)
      if (visit(e)) return true;
    return false;
  }

  /// Whether the occupied cells hold 3.5 nodes or more on average (a coastline's 22, Koch-8's
  /// 25, the countries' 3.6-9.3): there any_in_box_near_triangle<true> leaves a cell's nodes
  /// outside the box out by a SIMD scan of its columns, one call a cell. Elsewhere (the comb's
  /// 3.1, the holes grid's 1.8, a random polygon's 1.7) <false>, a test a node, is faster (the
  /// holes grid 7-13% slower by the scan). Callers instantiate both and ask this once a query,
  /// so that each is inlined whole (GCC left a query with both ways inside out of line: the
  /// holes grid 5% slower).
  bool scans_cells() const { return scan_cells_; }

  /// any_near_triangle for the nodes within `box` (the triangle's bounding box) only, in the
  /// same order; `scanned` as scans_cells() says.
  template <bool scanned, class Visit>
  [[gnu::always_inline]] bool any_in_box_near_triangle(const Point& a, const Point& b,
                                                       const Point& c, const Box& box,
                                                       Visit&& visit) const {
    if constexpr (!scanned) {
      return any_near_triangle(
          a, b, c, [&](const Entry& e) { return box.contains(e.pos.x, e.pos.y) && visit(e); });
    } else {
      if (live_ == 0) return false;
      const auto visit_row = [&](std::size_t first, std::size_t last) {
        return occupied_.any_in(first, last, [&](std::size_t cell) {
          for (std::uint32_t from = cell_start_[cell], end = cell_end_[cell]; from < end;
               from += 64) {
            const std::uint32_t count = std::min<std::uint32_t>(end - from, 64);
            for (std::uint64_t in = in_box_(&xs_[from], &ys_[from], count, box); in != 0;
                 in &= in - 1)
              if (visit(entry(from + static_cast<std::uint32_t>(std::countr_zero(in)))))
                return true;
          }
          return false;
        });
      };
      const bool apart = box.x1 < lo_.x || box.x0 > hi_.x || box.y1 < lo_.y || box.y0 > hi_.y;
      if (!apart && frame_.any_row_span_of_triangle(a, b, c, visit_row)) return true;
      for (const Entry& e : extra_)
        if (box.contains(e.pos.x, e.pos.y) && visit(e)) return true;
      return false;
    }
  }

  /// any_in_box_near_triangle the way scans_cells() says.
  template <class Visit>
  bool any_in_box_near_triangle(const Point& a, const Point& b, const Point& c, const Box& box,
                                Visit&& visit) const {
    return scan_cells_ ? any_in_box_near_triangle<true>(a, b, c, box, visit)
                       : any_in_box_near_triangle<false>(a, b, c, box, visit);
  }

 private:
  /// Visits the nodes of the occupied cells in [first, last].
  template <class Visit>
  bool visit_cells(std::size_t first, std::size_t last, Visit& visit) const {
    return occupied_.any_in(first, last, [&](std::size_t cell) {
      for (std::uint32_t i = cell_start_[cell]; i < cell_end_[cell]; ++i)
        if (visit(entry(i))) return true;
      return false;
    });
  }

  std::size_t cell_of(const Point& p) const { return frame_.cell_of(p); }
  Entry entry(std::uint32_t slot) const { return {{xs_[slot], ys_[slot]}, node_[slot]}; }
  /// The columns for `count` nodes, readable four past the last (points_in_box's lanes).
  void resize_columns(std::size_t count) {
    xs_.resize(count + 4);
    ys_.resize(count + 4);
    node_.resize(count);
  }

  GridFrame frame_;
  Point lo_{INFINITY, INFINITY}, hi_{-INFINITY, -INFINITY};  ///< the built nodes' bounding box
  std::vector<std::uint32_t> cell_start_;  ///< first slot of each cell (+ one past the end)
  std::vector<std::uint32_t> cell_end_;    ///< one past the last live slot of each cell
  std::vector<double> xs_, ys_;            ///< the nodes' positions, cell after cell
  std::vector<std::uint32_t> node_;        ///< the nodes, in the same slots
  bool scan_cells_ = false;                ///< see scans_cells()
  PointsInBox in_box_ = points_in_box_function();
  FillVector<std::uint32_t> slot_;  ///< node -> its slot in the columns, while it is in the grid
  Occupancy occupied_;              ///< which cells hold a live node
  std::vector<Entry> extra_;        ///< nodes added after the build
  std::size_t live_ = 0;            ///< nodes in the grid (cells and extra_)
  static constexpr std::uint32_t extra_bit = 0x80000000u;
};

}  // namespace pear::detail
