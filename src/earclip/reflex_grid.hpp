// Geometric hashing of reflex nodes (FIST §1.2): a uniform grid built once over the nodes that are
// not strictly convex. Nodes only ever turn from reflex to convex while ears are clipped, so the
// grid never grows: a flag per node says whether it still counts.
#pragma once

#include <cstdint>
#include <vector>

#include "boundary.hpp"
#include "uniform_grid.hpp"

namespace pear::detail {

class ReflexGrid {
 public:
  /// Builds the grid over `nodes` (those with reflex[node] set).
  void build(const Boundary& b, const std::vector<std::uint32_t>& nodes) {
    if (nodes.empty()) {
      frame_ = GridFrame{};
      cell_start_.assign(2, 0);
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
    fill_.assign(cell_start_.begin(), cell_start_.end() - 1);
    for (std::uint32_t v : nodes) items_[fill_[cell_of(b.pos[v])]++] = v;
  }

  /// Calls visit(node) for every node hashed into a cell that the box [lo, hi] touches, until
  /// visit returns true; returns whether it did.
  template <class Visit>
  bool any_in_box(Point lo, Point hi, Visit&& visit) const {
    const int c0 = frame_.column(lo.x), c1 = frame_.column(hi.x);
    const int r0 = frame_.row(lo.y), r1 = frame_.row(hi.y);
    for (int r = r0; r <= r1; ++r) {
      const std::size_t first = frame_.cell(c0, r), last = frame_.cell(c1, r);
      for (std::uint32_t i = cell_start_[first]; i < cell_start_[last + 1]; ++i)
        if (visit(items_[i])) return true;
    }
    return false;
  }

 private:
  std::size_t cell_of(const Point& p) const {
    return frame_.cell(frame_.column(p.x), frame_.row(p.y));
  }

  GridFrame frame_;
  std::vector<std::uint32_t> cell_start_;
  std::vector<std::uint32_t> items_;
  std::vector<std::uint32_t> fill_;
};

}  // namespace pear::detail
