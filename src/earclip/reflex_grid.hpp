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
    extra_.clear();
    if (nodes.empty()) {
      frame_ = GridFrame{};
      cell_start_.assign(2, 0);
      cell_end_.assign(1, 0);
      occupied_.assign(1, 0);
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
    occupied_.assign(frame_.cell_count() / 64 + 1, 0);
    for (std::uint32_t v : nodes) {
      const std::size_t cell = cell_of(b.pos[v]);
      const std::uint32_t slot = cell_end_[cell]++;
      items_[slot] = {b.pos[v], v};
      slot_[v] = slot;
      occupied_[cell / 64] |= std::uint64_t{1} << (cell % 64);
    }
  }

  /// Adds a node after the build (the copies a split makes): kept in a short list that every
  /// query visits, since splits are rare.
  void add(std::uint32_t node, const Point& pos) {
    if (slot_.size() <= node) slot_.resize(node + 1);
    slot_[node] = static_cast<std::uint32_t>(extra_.size()) | extra_bit;
    extra_.push_back({pos, node});
  }

  /// Takes a node out of the grid (it turned convex or was clipped).
  void remove(std::uint32_t node, const Point& pos) {
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
    if (cell_end_[cell] == cell_start_[cell])
      occupied_[cell / 64] &= ~(std::uint64_t{1} << (cell % 64));
  }

  /// Calls visit(entry) for every node in a cell that triangle (a, b, c) may touch, until visit
  /// returns true; returns whether it did. Per row, only the columns the triangle spans within
  /// the row's band (plus one on each side for rounding), and only cells that hold nodes.
  template <class Visit>
  bool any_near_triangle(const Point& a, const Point& b, const Point& c, Visit&& visit) const {
    const double lo_y = std::min({a.y, b.y, c.y}), hi_y = std::max({a.y, b.y, c.y});
    const int r0 = frame_.row(lo_y), r1 = frame_.row(hi_y);
    for (int r = r0; r <= r1; ++r) {
      double band_lo = lo_y, band_hi = hi_y;
      if (r0 != r1 && frame_.inv_h > 0) {
        band_lo = std::max(lo_y, frame_.y0 + r / frame_.inv_h);
        band_hi = std::min(hi_y, frame_.y0 + (r + 1) / frame_.inv_h);
      }
      double x_lo = INFINITY, x_hi = -INFINITY;
      for (const auto& [p, q] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}})
        clip_to_band(p, q, band_lo, band_hi, x_lo, x_hi);
      if (!(x_lo <= x_hi)) x_lo = std::min({a.x, b.x, c.x}), x_hi = std::max({a.x, b.x, c.x});
      const int c0 = std::max(0, frame_.column(x_lo) - 1);
      const int c1 = std::min(frame_.nx - 1, frame_.column(x_hi) + 1);
      if (visit_cells(frame_.cell(c0, r), frame_.cell(c1, r), visit)) return true;
    }
    for (const Entry& e : extra_)
      if (visit(e)) return true;
    return false;
  }

 private:
  /// Widens [x_lo, x_hi] by the x-range of segment p-q within y in [band_lo, band_hi].
  static void clip_to_band(const Point& p, const Point& q, double band_lo, double band_hi,
                           double& x_lo, double& x_hi) {
    const double y_min = std::min(p.y, q.y), y_max = std::max(p.y, q.y);
    if (y_max < band_lo || y_min > band_hi) return;
    const auto x_at = [&](double y) {
      if (p.y == q.y) return p.x;
      const double t = std::clamp((y - p.y) / (q.y - p.y), 0.0, 1.0);
      return p.x + t * (q.x - p.x);
    };
    if (p.y == q.y) {
      x_lo = std::min({x_lo, p.x, q.x});
      x_hi = std::max({x_hi, p.x, q.x});
      return;
    }
    const double xa = x_at(std::max(band_lo, y_min)), xb = x_at(std::min(band_hi, y_max));
    x_lo = std::min({x_lo, xa, xb});
    x_hi = std::max({x_hi, xa, xb});
  }

  /// Visits the nodes of the occupied cells in [first, last], skipping empty cells 64 at a time.
  template <class Visit>
  bool visit_cells(std::size_t first, std::size_t last, Visit& visit) const {
    std::size_t cell = first;
    while (cell <= last) {
      const std::uint64_t word = occupied_[cell / 64] >> (cell % 64);
      if (word == 0) {
        cell = (cell / 64 + 1) * 64;
        continue;
      }
      cell += static_cast<std::size_t>(std::countr_zero(word));
      if (cell > last) break;
      for (std::uint32_t i = cell_start_[cell]; i < cell_end_[cell]; ++i)
        if (visit(items_[i])) return true;
      ++cell;
    }
    return false;
  }

  std::size_t cell_of(const Point& p) const {
    return frame_.cell(frame_.column(p.x), frame_.row(p.y));
  }

  GridFrame frame_;
  std::vector<std::uint32_t> cell_start_;  ///< first slot of each cell (+ one past the end)
  std::vector<std::uint32_t> cell_end_;    ///< one past the last live slot of each cell
  std::vector<Entry> items_;
  std::vector<std::uint32_t> slot_;      ///< node -> its slot in items_, while it is in the grid
  std::vector<std::uint64_t> occupied_;  ///< one bit per cell: holds a live node
  std::vector<Entry> extra_;             ///< nodes added after the build
  static constexpr std::uint32_t extra_bit = 0x80000000u;
};

}  // namespace pear::detail
