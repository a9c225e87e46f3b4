// Exact helpers on points and segments that several algorithms share.
#pragma once

#include <algorithm>

#include "pear/geometry.hpp"

namespace pear::detail {

/// x first, then y: the sweep order of the bridges and the simplicity check.
inline bool lexicographic_less(const Point& a, const Point& b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

/// For p collinear with segment a-b: whether p lies strictly between its endpoints.
inline bool on_open_segment(const Point& p, const Point& a, const Point& b) {
  if (p == a || p == b) return false;
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

}  // namespace pear::detail
