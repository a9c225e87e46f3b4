// A uniform grid over a bounding box that maps coordinates to cells monotonically, so a point
// inside a query box always lies in one of the cells the box covers.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "pear/geometry.hpp"

namespace pear::detail {

struct GridFrame {
  double x0 = 0, y0 = 0, inv_w = 0, inv_h = 0;
  int nx = 1, ny = 1;

  /// About `target_cells` square-ish cells over [min, max].
  void fit(Point min, Point max, std::size_t target_cells) {
    x0 = min.x;
    y0 = min.y;
    const double w = max.x - min.x, h = max.y - min.y;
    const double cells = static_cast<double>(std::max<std::size_t>(1, target_cells));
    double side = std::sqrt(std::max(w * h, 0.0) / cells);
    if (!(side > 0)) side = std::max(w, h) / cells;
    if (!(side > 0)) side = 1;
    nx = static_cast<int>(std::clamp(std::ceil(w / side), 1.0, 16384.0));
    ny = static_cast<int>(std::clamp(std::ceil(h / side), 1.0, 16384.0));
    inv_w = w > 0 ? nx / w : 0;
    inv_h = h > 0 ? ny / h : 0;
    // The products can overflow for huge extents; fall back to one cell per axis then.
    if (!std::isfinite(inv_w)) inv_w = 0, nx = 1;
    if (!std::isfinite(inv_h)) inv_h = 0, ny = 1;
  }
  int column(double x) const {
    return static_cast<int>(std::clamp((x - x0) * inv_w, 0.0, static_cast<double>(nx - 1)));
  }
  int row(double y) const {
    return static_cast<int>(std::clamp((y - y0) * inv_h, 0.0, static_cast<double>(ny - 1)));
  }
  std::size_t cell(int column, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(nx) +
           static_cast<std::size_t>(column);
  }
  std::size_t cell_count() const { return static_cast<std::size_t>(nx) * ny; }

  /// Calls visit(cell) for every cell the segment a-c passes through, and for the neighbouring
  /// cell on each side in its row (a margin for rounding): every point of the segment lies in
  /// one of the visited cells.
  template <class Visit>
  void for_each_cell_on_segment(Point a, Point c, Visit&& visit) const {
    const int r0 = row(std::min(a.y, c.y)), r1 = row(std::max(a.y, c.y));
    for (int r = r0; r <= r1; ++r) {
      double xa = a.x, xc = c.x;
      if (r0 != r1 && inv_h > 0) {  // the part of the segment inside row r's band
        const auto x_at = [&](double y) {
          const double t = std::clamp((y - a.y) / (c.y - a.y), 0.0, 1.0);
          return a.x + t * (c.x - a.x);
        };
        xa = x_at(y0 + r / inv_h);
        xc = x_at(y0 + (r + 1) / inv_h);
      }
      const int c0 = std::max(0, column(std::min(xa, xc)) - 1);
      const int c1 = std::min(nx - 1, column(std::max(xa, xc)) + 1);
      for (int col = c0; col <= c1; ++col) visit(cell(col, r));
    }
  }
};

}  // namespace pear::detail
