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

/// How many of `rings` contain p (with their boxes precomputed to skip most of them).
std::size_t containing_count(std::span<const Ring> rings, std::span<const Box> boxes,
                             const Point& p);

/// A point strictly inside `hole` and inside none of `others`' interiors that lie within it,
/// found on a horizontal line through the hole's middle. False if there is none on that line.
bool interior_point(const Ring& hole, std::span<const Ring> others, Point& point);

}  // namespace pear::io::detail
