// Geometric hashing of reflex nodes (FIST §1.2): a uniform grid built once over the nodes that are
// strictly reflex. Nodes only ever turn from reflex to convex while ears are clipped, so the grid
// never grows; a node that stops being reflex is swapped out of its cell at once, so queries see
// only live reflex nodes (a stale entry would cost every later query that touches its cell).
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include "boundary.hpp"
#include "fill_vector.hpp"
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
      items_.clear();
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
    items_.resize(nodes.size());
    cell_end_.assign(cell_start_.begin(), cell_start_.end() - 1);
    occupied_.reset(frame_.cell_count());
    for (std::uint32_t v : nodes) {
      const std::size_t cell = cell_of(b.pos[v]);
      const std::uint32_t slot = cell_end_[cell]++;
      items_[slot] = {b.pos[v], v};
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
    items_[slot] = items_[last];
    slot_[items_[slot].node] = slot;
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
            if (inside(items_[i].pos)) visit(items_[i]);
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
  bool any_near_triangle(const Point& a, const Point& b, const Point& c, Visit&& visit) const {
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

 private:
  /// Visits the nodes of the occupied cells in [first, last].
  template <class Visit>
  bool visit_cells(std::size_t first, std::size_t last, Visit& visit) const {
    return occupied_.any_in(first, last, [&](std::size_t cell) {
      for (std::uint32_t i = cell_start_[cell]; i < cell_end_[cell]; ++i)
        if (visit(items_[i])) return true;
      return false;
    });
  }

  std::size_t cell_of(const Point& p) const { return frame_.cell_of(p); }

  GridFrame frame_;
  Point lo_{INFINITY, INFINITY}, hi_{-INFINITY, -INFINITY};  ///< the built nodes' bounding box
  std::vector<std::uint32_t> cell_start_;  ///< first slot of each cell (+ one past the end)
  std::vector<std::uint32_t> cell_end_;    ///< one past the last live slot of each cell
  std::vector<Entry> items_;
  FillVector<std::uint32_t> slot_;  ///< node -> its slot in items_, while it is in the grid
  Occupancy occupied_;              ///< which cells hold a live node
  std::vector<Entry> extra_;        ///< nodes added after the build
  std::size_t live_ = 0;            ///< nodes in the grid (cells and extra_)
  static constexpr std::uint32_t extra_bit = 0x80000000u;
};

}  // namespace pear::detail
