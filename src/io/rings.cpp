#include "rings.hpp"

#include <algorithm>

namespace pear::io::detail {

Box bounding_box(const Ring& ring) {
  Box box{ring.front().x, ring.front().y, ring.front().x, ring.front().y};
  for (const Point& p : ring) {
    box.min_x = std::min(box.min_x, p.x);
    box.max_x = std::max(box.max_x, p.x);
    box.min_y = std::min(box.min_y, p.y);
    box.max_y = std::max(box.max_y, p.y);
  }
  return box;
}

bool inside(const Ring& ring, const Point& p) {
  bool in = false;
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Point& a = ring[i];
    const Point& b = ring[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x)) in = !in;
  }
  return in;
}

std::size_t containing_count(std::span<const Ring> rings, std::span<const Box> boxes,
                             const Point& p) {
  std::size_t count = 0;
  for (std::size_t r = 0; r < rings.size(); ++r)
    if (boxes[r].contains(p) && inside(rings[r], p)) ++count;
  return count;
}

namespace {
// x of every edge of `ring` crossing the line at height y (half-open in y, so a vertex on the
// line counts once).
void crossings(const Ring& ring, double y, std::vector<double>& xs) {
  for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
    const Point& a = ring[i];
    const Point& b = ring[j];
    if ((a.y > y) != (b.y > y)) xs.push_back(a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x));
  }
}

// A height between two of the ring's vertex heights, in the widest gap.
double scan_height(const Ring& ring) {
  std::vector<double> ys;
  ys.reserve(ring.size());
  for (const Point& p : ring) ys.push_back(p.y);
  std::sort(ys.begin(), ys.end());
  double best = ys.front();
  double best_gap = -1;
  for (std::size_t i = 1; i < ys.size(); ++i) {
    if (ys[i] - ys[i - 1] > best_gap) {
      best_gap = ys[i] - ys[i - 1];
      best = ys[i - 1] + best_gap / 2;
    }
  }
  return best;
}
}  // namespace

bool interior_point(const Ring& hole, std::span<const Ring> others, Point& point) {
  if (hole.size() < 3) return false;
  const double y = scan_height(hole);
  std::vector<double> own;
  crossings(hole, y, own);
  std::sort(own.begin(), own.end());
  std::vector<double> islands;
  for (const Ring& other : others)
    if (other.size() >= 3 && &other != &hole) crossings(other, y, islands);
  std::sort(islands.begin(), islands.end());
  double best_width = 0;
  for (std::size_t k = 0; k + 1 < own.size(); k += 2) {  // [own[k], own[k+1]] is inside the hole
    const auto first = std::upper_bound(islands.begin(), islands.end(), own[k]);
    const auto last = std::lower_bound(islands.begin(), islands.end(), own[k + 1]);
    if (!(own[k] < own[k + 1]) || first > last) continue;
    // Sub-intervals between island crossings; an even number of crossings to the left means
    // the sub-interval is not inside an island.
    double left = own[k];
    bool in_island = false;
    for (auto it = first;; ++it) {
      const double right = it == last ? own[k + 1] : *it;
      if (!in_island && right - left > best_width && left + (right - left) / 2 > left) {
        best_width = right - left;
        point = Point{left + best_width / 2, y};
      }
      if (it == last) break;
      left = right;
      in_island = !in_island;
    }
  }
  return best_width > 0;
}

}  // namespace pear::io::detail
