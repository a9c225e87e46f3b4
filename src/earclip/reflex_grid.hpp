// Geometric hashing of reflex nodes (FIST §1.2): a uniform grid built once over the nodes that are
// strictly reflex. Nodes only ever turn from reflex to convex while ears are clipped, so the grid
// never grows; a node that stops being reflex is swapped out of its cell at once, so queries see
// only live reflex nodes (a stale entry would cost every later query that touches its cell).
#pragma once

#include <cstdint>
#include <vector>

#include "boundary.hpp"
#include "uniform_grid.hpp"

namespace pear::detail {

class ReflexGrid {
 public:
  /// An entry keeps the position next to the node, so the box test needs no other memory.
  struct Entry {
    Point pos;
    std::uint32_t node;
  };

  /// Builds the grid over `nodes` (all strictly reflex).
  void build(const Boundary& b, const std::vector<std::uint32_t>& nodes) {
    slot_.resize(b.size());
    if (nodes.empty()) {
      frame_ = GridFrame{};
      cell_start_.assign(2, 0);
      cell_end_.assign(1, 0);
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
    cell_start_.assign(frame_.cell_count() + 1, 0);
    for (std::uint32_t v : nodes) ++cell_start_[cell_of(b.pos[v]) + 1];
    for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
    items_.resize(nodes.size());
    cell_end_.assign(cell_start_.begin(), cell_start_.end() - 1);
    for (std::uint32_t v : nodes) {
      const std::uint32_t slot = cell_end_[cell_of(b.pos[v])]++;
      items_[slot] = {b.pos[v], v};
      slot_[v] = slot;
    }
  }

  /// Takes a node out of the grid (it turned convex or was clipped).
  void remove(std::uint32_t node, const Point& pos) {
    const std::size_t cell = cell_of(pos);
    const std::uint32_t slot = slot_[node], last = --cell_end_[cell];
    items_[slot] = items_[last];
    slot_[items_[slot].node] = slot;
  }

  /// Calls visit(entry) for every node in a cell that the box [lo, hi] touches, until visit
  /// returns true; returns whether it did.
  template <class Visit>
  bool any_in_box(Point lo, Point hi, Visit&& visit) const {
    const int c0 = frame_.column(lo.x), c1 = frame_.column(hi.x);
    const int r0 = frame_.row(lo.y), r1 = frame_.row(hi.y);
    for (int r = r0; r <= r1; ++r) {
      for (std::size_t cell = frame_.cell(c0, r), last = frame_.cell(c1, r); cell <= last; ++cell)
        for (std::uint32_t i = cell_start_[cell]; i < cell_end_[cell]; ++i)
          if (visit(items_[i])) return true;
    }
    return false;
  }

 private:
  std::size_t cell_of(const Point& p) const {
    return frame_.cell(frame_.column(p.x), frame_.row(p.y));
  }

  GridFrame frame_;
  std::vector<std::uint32_t> cell_start_;  ///< first slot of each cell (+ one past the end)
  std::vector<std::uint32_t> cell_end_;    ///< one past the last live slot of each cell
  std::vector<Entry> items_;
  std::vector<std::uint32_t> slot_;  ///< node -> its slot in items_, while it is in the grid
};

}  // namespace pear::detail
