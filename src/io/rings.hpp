// Plane-geometry helpers the .poly reader and writer share: bounding boxes, even-odd point
// location and an interior point of a hole. Floating-point only: they place hole points and sort
// rings into polygons, where an input that needs exact arithmetic is not a simple polygon anyway.
#pragma once

#include <span>
#include <vector>

#include "pear/geometry.hpp"

namespace pear::io::detail {

struct Box {
  double min_x, min_y, max_x, max_y;
  bool contains(const Point& p) const {
    return p.x >= min_x && p.x <= max_x && p.y >= min_y && p.y <= max_y;
  }
};

Box bounding_box(const Ring& ring);

/// Crossing-number test: is p inside the ring? (Points on the boundary go either way.)
bool inside(const Ring& ring, const Point& p);

/// Rings' bounding boxes in a uniform grid, so a point meets only the rings whose box covers
/// its cell: locating many points among many rings stays near linear instead of quadratic.
class BoxGrid {
 public:
  explicit BoxGrid(std::span<const Box> boxes);
  /// Calls visit(r) for every ring r whose box may contain p (a superset of those that do).
  template <class Visit>
  void candidates(const Point& p, Visit visit) const {
    for (const std::size_t r : large_) visit(r);
    if (cells_.empty() || !bounds_.contains(p)) return;
    const std::size_t cell = row(p.y) * side_ + column(p.x);
    for (std::size_t k = starts_[cell]; k < starts_[cell + 1]; ++k) visit(cells_[k]);
  }

 private:
  std::size_t column(double x) const;
  std::size_t row(double y) const;
  Box bounds_{0, 0, 0, 0};
  std::size_t side_ = 0;
  std::vector<std::size_t> starts_;  ///< cell c holds cells_[starts_[c], starts_[c+1])
  std::vector<std::size_t> cells_;
  std::vector<std::size_t> large_;  ///< rings whose box covers much of the grid: always visited
};

/// How many of `rings` contain p.
std::size_t containing_count(std::span<const Ring> rings, const BoxGrid& grid, const Point& p);

/// A point strictly inside `hole` and inside none of `others`' interiors that lie within it,
/// found on a horizontal line through the hole's middle. False if there is none on that line.
/// `boxes` are the others' bounding boxes.
bool interior_point(const Ring& hole, std::span<const Ring> others, std::span<const Box> boxes,
                    Point& point);

}  // namespace pear::io::detail
