// A uniform grid over a bounding box that maps coordinates to cells monotonically, so a point
// inside a query box always lies in one of the cells the box covers.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "pear/geometry.hpp"

namespace pear::detail {

struct GridFrame {
  double x0 = 0, y0 = 0, inv_w = 0, inv_h = 0;
  double y_slack = 0;  ///< bounds the rounding of a row's band edges (y0 + r / inv_h)
  int nx = 1, ny = 1;

  /// About `target_cells` square-ish cells over [min, max]; exactly one for 1.
  void fit(Point min, Point max, std::size_t target_cells) {
    x0 = min.x;
    y0 = min.y;
    const double w = max.x - min.x, h = max.y - min.y;
    y_slack = 32 * std::numeric_limits<double>::epsilon() * (std::abs(min.y) + std::abs(max.y));
    const double cells = static_cast<double>(std::max<std::size_t>(1, target_cells));
    double side = target_cells <= 1 ? std::max(w, h) : std::sqrt(std::max(w * h, 0.0) / cells);
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
  /// The cell p lies in (clamped to the grid).
  std::size_t cell_of(const Point& p) const { return cell(column(p.x), row(p.y)); }
  std::size_t cell_count() const { return static_cast<std::size_t>(nx) * ny; }

  /// Calls visit(first_cell, last_cell) for the cells of each row that triangle (a, b, c) may
  /// touch: per row, only the columns the triangle spans within the row's band. Rounding is
  /// covered by slack, not by extra columns (three cells a row instead of one for a thin
  /// triangle): the band is widened by y_slack, and x by a bound on the error of interpolating
  /// an edge at an exact y (a few ulps of the largest |x|); column() is monotone, so every
  /// point of the triangle lies in a visited cell. Stops and returns true when visit does.
  template <class VisitRow>
  [[gnu::always_inline]] bool any_row_span_of_triangle(const Point& a, const Point& b,
                                                       const Point& c, VisitRow&& visit) const {
    const double lo_y = std::min({a.y, b.y, c.y}), hi_y = std::max({a.y, b.y, c.y});
    const double lo_x = std::min({a.x, b.x, c.x}), hi_x = std::max({a.x, b.x, c.x});
    const double x_slack =
        64 * std::numeric_limits<double>::epsilon() * std::max(std::abs(lo_x), std::abs(hi_x));
    const int r0 = row(lo_y), r1 = row(hi_y);
    if (r0 == r1)  // most ears: one band, the box is the span (always so when inv_h is 0)
      return visit(cell(column(lo_x - x_slack), r0), cell(column(hi_x + x_slack), r1));
    const EdgeInBands edges[3] = {{a, b}, {b, c}, {c, a}};
    for (int r = r0; r <= r1; ++r) {
      const double band_lo = std::max(lo_y, y0 + r / inv_h - y_slack);
      const double band_hi = std::min(hi_y, y0 + (r + 1) / inv_h + y_slack);
      double x_lo = INFINITY, x_hi = -INFINITY;
      for (const EdgeInBands& edge : edges) edge.widen(band_lo, band_hi, x_lo, x_hi);
      if (!(x_lo <= x_hi)) x_lo = lo_x, x_hi = hi_x;
      if (visit(cell(column(x_lo - x_slack), r), cell(column(x_hi + x_slack), r))) return true;
    }
    return false;
  }

  /// An edge prepared for clipping to many bands: its slope is divided out once.
  struct EdgeInBands {
    Point low, high;  ///< by y
    double dx_dy;     ///< 0 for a horizontal edge
    EdgeInBands(const Point& p, const Point& q)
        : low(p.y <= q.y ? p : q),
          high(p.y <= q.y ? q : p),
          dx_dy(p.y == q.y ? 0 : (high.x - low.x) / (high.y - low.y)) {}
    /// Widens [x_lo, x_hi] by the x-range of the edge within y in [band_lo, band_hi].
    void widen(double band_lo, double band_hi, double& x_lo, double& x_hi) const {
      if (high.y < band_lo || low.y > band_hi) return;
      if (low.y == high.y) {
        x_lo = std::min({x_lo, low.x, high.x});
        x_hi = std::max({x_hi, low.x, high.x});
        return;
      }
      const double xa = low.x + (std::max(band_lo, low.y) - low.y) * dx_dy;
      const double xb = low.x + (std::min(band_hi, high.y) - low.y) * dx_dy;
      x_lo = std::min({x_lo, xa, xb});
      x_hi = std::max({x_hi, xa, xb});
    }
  };

  /// Calls visit(cell) for every cell the segment a-c passes through, and, where it crosses
  /// rows, for the neighbouring cell on each side in each row (a margin for the rounding of
  /// where it enters and leaves the row): every point of the segment lies in one of the
  /// visited cells. Within one row the ends' own columns bound it exactly (column() is
  /// monotone), so a short edge enters one or two cells, not three or four.
  template <class Visit>
  void for_each_cell_on_segment(Point a, Point c, Visit&& visit) const {
    const int r0 = row(std::min(a.y, c.y)), r1 = row(std::max(a.y, c.y));
    const int margin = r0 != r1;
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
      const int c0 = std::max(0, column(std::min(xa, xc)) - margin);
      const int c1 = std::min(nx - 1, column(std::max(xa, xc)) + margin);
      for (int col = c0; col <= c1; ++col) visit(cell(col, r));
    }
  }
};

/// One bit per cell saying whether it holds a node, with a summary bit per 64 cells, so a scan
/// over a long run of empty cells (a thin triangle across a sparse grid) skips 4096 at a time.
class Occupancy {
 public:
  void reset(std::size_t cells) {
    words_.assign(cells / 64 + 1, 0);
    summary_.assign(words_.size() / 64 + 1, 0);
  }
  void set(std::size_t cell) {
    words_[cell / 64] |= std::uint64_t{1} << (cell % 64);
    summary_[cell / 4096] |= std::uint64_t{1} << (cell / 64 % 64);
  }
  void clear(std::size_t cell) {
    std::uint64_t& word = words_[cell / 64];
    word &= ~(std::uint64_t{1} << (cell % 64));
    if (word == 0) summary_[cell / 4096] &= ~(std::uint64_t{1} << (cell / 64 % 64));
  }
  /// Calls visit(cell) for the occupied cells in [first, last] in order, until it returns true.
  template <class Visit>
  bool any_in(std::size_t first, std::size_t last, Visit&& visit) const {
    std::size_t cell = first;
    while (cell <= last) {
      const std::size_t word_index = cell / 64;
      if ((summary_[word_index / 64] >> (word_index % 64)) == 0) {
        cell = (word_index / 64 + 1) * 4096;  // no occupied word left in this summary word
        continue;
      }
      const std::uint64_t word = words_[word_index] >> (cell % 64);
      if (word == 0) {
        cell = (word_index + 1) * 64;
        continue;
      }
      cell += static_cast<std::size_t>(std::countr_zero(word));
      if (cell > last) break;
      if (visit(cell)) return true;
      ++cell;
    }
    return false;
  }

 private:
  std::vector<std::uint64_t> words_;
  std::vector<std::uint64_t> summary_;
};

}  // namespace pear::detail
