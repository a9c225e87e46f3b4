#include "rings.hpp"

#include <algorithm>
#include <cmath>

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

BoxGrid::BoxGrid(std::span<const Box> boxes) {
  if (boxes.empty()) return;
  bounds_ = boxes.front();
  for (const Box& b : boxes) {
    bounds_.min_x = std::min(bounds_.min_x, b.min_x),
    bounds_.max_x = std::max(bounds_.max_x, b.max_x);
    bounds_.min_y = std::min(bounds_.min_y, b.min_y),
    bounds_.max_y = std::max(bounds_.max_y, b.max_y);
  }
  side_ = static_cast<std::size_t>(std::ceil(std::sqrt(static_cast<double>(boxes.size()))));
  const std::size_t cell_count = side_ * side_;
  std::vector<std::size_t> counts(cell_count + 1, 0);
  auto each_cell = [&](const Box& b, auto visit) {
    for (std::size_t r = row(b.min_y); r <= row(b.max_y); ++r)
      for (std::size_t c = column(b.min_x); c <= column(b.max_x); ++c) visit(r * side_ + c);
  };
  auto is_large = [&](const Box& b) {
    return (row(b.max_y) - row(b.min_y) + 1) * (column(b.max_x) - column(b.min_x) + 1) >
           std::max<std::size_t>(16, cell_count / 8);
  };
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    if (is_large(boxes[i])) {
      large_.push_back(i);
      continue;
    }
    each_cell(boxes[i], [&](std::size_t cell) { ++counts[cell + 1]; });
  }
  for (std::size_t c = 0; c < cell_count; ++c) counts[c + 1] += counts[c];
  starts_ = counts;
  cells_.resize(counts[cell_count]);
  for (std::size_t i = 0; i < boxes.size(); ++i)
    if (!is_large(boxes[i]))
      each_cell(boxes[i], [&](std::size_t cell) { cells_[counts[cell]++] = i; });
}

std::size_t BoxGrid::column(double x) const {
  const double width = bounds_.max_x - bounds_.min_x;
  if (!(width > 0)) return 0;
  const double f = (x - bounds_.min_x) / width * static_cast<double>(side_);
  return std::min(side_ - 1, static_cast<std::size_t>(std::max(0.0, f)));
}

std::size_t BoxGrid::row(double y) const {
  const double height = bounds_.max_y - bounds_.min_y;
  if (!(height > 0)) return 0;
  const double f = (y - bounds_.min_y) / height * static_cast<double>(side_);
  return std::min(side_ - 1, static_cast<std::size_t>(std::max(0.0, f)));
}

std::size_t containing_count(std::span<const Ring> rings, const BoxGrid& grid, const Point& p) {
  std::size_t count = 0;
  grid.candidates(p, [&](std::size_t r) {
    if (inside(rings[r], p)) ++count;
  });
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

bool interior_point(const Ring& hole, std::span<const Ring> others, std::span<const Box> boxes,
                    Point& point) {
  if (hole.size() < 3) return false;
  const double y = scan_height(hole);
  std::vector<double> own;
  crossings(hole, y, own);
  std::sort(own.begin(), own.end());
  std::vector<double> islands;
  const Box hole_box = bounding_box(hole);
  for (std::size_t k = 0; k < others.size(); ++k) {
    const Box& b = boxes[k];
    const bool overlaps =
        b.min_y <= y && y <= b.max_y && b.min_x <= hole_box.max_x && hole_box.min_x <= b.max_x;
    if (overlaps && others[k].size() >= 3 && &others[k] != &hole) crossings(others[k], y, islands);
  }
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
