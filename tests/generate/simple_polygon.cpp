#include "simple_polygon.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "pear/predicates.hpp"

namespace pear::testing {
namespace {

struct Edge {
  std::uint32_t ring;
  std::uint32_t index;  // from vertex `index` to the next one, cyclically
};

int sign(double v) {
  return (v > 0) - (v < 0);
}

/// p lies on the closed segment ab, given that a, b, p are collinear.
bool on_segment(const Point& a, const Point& b, const Point& p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

/// The closed segments ab and cd share a point.
bool segments_meet(const Point& a, const Point& b, const Point& c, const Point& d) {
  const int o1 = sign(orient2d(a, b, c));
  const int o2 = sign(orient2d(a, b, d));
  const int o3 = sign(orient2d(c, d, a));
  const int o4 = sign(orient2d(c, d, b));
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
         (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

/// A uniform grid of buckets over the bounding box; each edge is listed in every bucket its
/// bounding box overlaps. Bucket indices are monotone in the coordinates, so two edges that meet
/// share the bucket of their meeting point.
class EdgeGrid {
 public:
  /// With `boxes`, each edge stands for its bounding box and is listed in all of it.
  EdgeGrid(const Polygon& polygon, const std::vector<Edge>& edges, bool boxes = false)
      : polygon_(polygon), boxes_(boxes) {
    min_ = max_ = polygon[0][0];
    for (const Ring& ring : polygon) {
      for (const Point& p : ring) {
        min_ = {std::min(min_.x, p.x), std::min(min_.y, p.y)};
        max_ = {std::max(max_.x, p.x), std::max(max_.y, p.y)};
      }
    }
    const double width = std::max(max_.x - min_.x, 1e-300);
    const double height = std::max(max_.y - min_.y, 1e-300);
    const double cell = std::sqrt(width * height / static_cast<double>(edges.size()));
    columns_ = std::clamp<std::size_t>(static_cast<std::size_t>(width / cell), 1, 1 << 16);
    rows_ = std::clamp<std::size_t>(static_cast<std::size_t>(height / cell), 1, 1 << 16);
    cell_width_ = width / static_cast<double>(columns_);
    cell_height_ = height / static_cast<double>(rows_);
    fill(edges);
  }

  std::size_t column(double x) const {
    return std::min(columns_ - 1, static_cast<std::size_t>((x - min_.x) / cell_width_));
  }
  std::size_t row(double y) const {
    return std::min(rows_ - 1, static_cast<std::size_t>((y - min_.y) / cell_height_));
  }
  std::size_t columns() const { return columns_; }
  std::size_t rows() const { return rows_; }
  /// Edge numbers listed in bucket (column, row).
  std::span<const std::uint32_t> bucket(std::size_t c, std::size_t r) const {
    const std::size_t b = r * columns_ + c;
    return {entries_.data() + starts_[b], entries_.data() + starts_[b + 1]};
  }

 private:
  /// Visits the buckets an edge passes through: per row, the columns the segment spans within
  /// that row widened by half a row and one column on each side, so rounding cannot leave out
  /// a bucket (a cell is far wider than the rounding). Boxes cover their whole bounding box.
  template <class Visit>
  void for_buckets(const Edge& e, Visit visit) const {
    const Ring& ring = polygon_[e.ring];
    const Point& a = ring[e.index];
    const Point& b = ring[(e.index + 1) % ring.size()];
    const Point low = {std::min(a.x, b.x), std::min(a.y, b.y)};
    const Point high = {std::max(a.x, b.x), std::max(a.y, b.y)};
    const std::size_t r0 = row(low.y);
    const std::size_t r1 = row(high.y);
    for (std::size_t r = r0; r <= r1; ++r) {
      std::size_t c0 = column(low.x);
      std::size_t c1 = column(high.x);
      if (!boxes_ && r0 != r1) {
        const auto along = [&](double y) {
          y = std::clamp(y, low.y, high.y);
          return a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y);
        };
        const double x0 = along(min_.y + (static_cast<double>(r) - 0.5) * cell_height_);
        const double x1 = along(min_.y + (static_cast<double>(r) + 1.5) * cell_height_);
        c0 = std::max(
            c0, column(std::min(x0, x1)) - std::min<std::size_t>(1, column(std::min(x0, x1))));
        c1 = std::min(c1, column(std::max(x0, x1)) + 1);
      }
      for (std::size_t c = c0; c <= c1; ++c) visit(r * columns_ + c);
    }
  }
  void fill(const std::vector<Edge>& edges) {
    starts_.assign(columns_ * rows_ + 1, 0);
    for (const Edge& e : edges) for_buckets(e, [&](std::size_t b) { ++starts_[b + 1]; });
    for (std::size_t b = 0; b + 1 < starts_.size(); ++b) starts_[b + 1] += starts_[b];
    entries_.resize(starts_.back());
    std::vector<std::size_t> next(starts_.begin(), starts_.end() - 1);
    for (std::size_t i = 0; i < edges.size(); ++i)
      for_buckets(edges[i],
                  [&](std::size_t b) { entries_[next[b]++] = static_cast<std::uint32_t>(i); });
  }

  const Polygon& polygon_;
  bool boxes_;
  Point min_{};
  Point max_{};
  std::size_t columns_ = 1;
  std::size_t rows_ = 1;
  double cell_width_ = 1;
  double cell_height_ = 1;
  std::vector<std::size_t> starts_;
  std::vector<std::uint32_t> entries_;
};

std::string where(const Edge& e) {
  return "ring " + std::to_string(e.ring) + " edge " + std::to_string(e.index);
}

/// Consecutive edges (a, b), (b, c) overlap when they fold back onto each other.
bool folds_back(const Point& a, const Point& b, const Point& c) {
  if (orient2d(a, b, c) != 0) return false;
  return sign(a.x - b.x) == sign(c.x - b.x) && sign(a.y - b.y) == sign(c.y - b.y);
}

std::string check_rings(const Polygon& polygon) {
  if (polygon.empty()) return "no rings";
  for (std::size_t r = 0; r < polygon.size(); ++r) {
    const Ring& ring = polygon[r];
    if (ring.size() < 3) return "ring " + std::to_string(r) + " has fewer than 3 points";
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point& p = ring[i];
      if (!std::isfinite(p.x) || !std::isfinite(p.y))
        return "ring " + std::to_string(r) + " vertex " + std::to_string(i) + " is not finite";
      if (p == ring[(i + 1) % ring.size()])
        return "ring " + std::to_string(r) + " repeats vertex " + std::to_string(i);
    }
  }
  return {};
}

/// No point appears twice, in any ring.
std::string check_distinct(const Polygon& polygon, const std::vector<Edge>& edges) {
  std::vector<std::uint32_t> order(edges.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  auto point = [&](std::uint32_t i) { return polygon[edges[i].ring][edges[i].index]; };
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const Point p = point(a);
    const Point q = point(b);
    return p.x < q.x || (p.x == q.x && p.y < q.y);
  });
  for (std::size_t i = 0; i + 1 < order.size(); ++i)
    if (point(order[i]) == point(order[i + 1]))
      return "vertex " + std::to_string(edges[order[i]].index) + " of " + where(edges[order[i]]) +
             " repeats in " + where(edges[order[i + 1]]);
  return {};
}

bool before(const Point& p, const Point& q) {
  return p.x < q.x || (p.x == q.x && p.y < q.y);
}

/// Shamos and Hoey's sweep (1976): segments ordered bottom to top along a vertical sweep line;
/// any two that meet are neighbours in that order just before the leftmost meeting point, so it
/// is enough to test new neighbours at each insertion and removal. With all points distinct,
/// consecutive edges share only their common vertex (folds are checked apart).
class EdgeSweep {
 public:
  EdgeSweep(const Polygon& polygon, const std::vector<Edge>& edges)
      : polygon_(polygon), edges_(edges), active_(Below{this}) {
    for (const Edge& e : edges) {
      auto [a, b] = endpoints(e);
      if (before(b, a)) std::swap(a, b);
      left_.push_back(a);
      right_.push_back(b);
    }
  }

  std::string run() {
    struct Event {
      Point at;
      bool insert;
      std::uint32_t edge;
    };
    std::vector<Event> events;
    for (std::uint32_t i = 0; i < edges_.size(); ++i) {
      events.push_back({left_[i], true, i});
      events.push_back({right_[i], false, i});
    }
    std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
      if (a.at != b.at) return before(a.at, b.at);
      return a.insert < b.insert;  // removals first at a shared point
    });
    for (const Event& event : events) {
      std::string problem = event.insert ? insert(event.edge) : remove(event.edge);
      if (!problem.empty()) return problem;
    }
    return {};
  }

 private:
  struct Below {
    const EdgeSweep* sweep;
    bool operator()(std::uint32_t s, std::uint32_t t) const { return sweep->below(s, t); }
  };

  std::pair<Point, Point> endpoints(const Edge& e) const {
    const Ring& ring = polygon_[e.ring];
    return {ring[e.index], ring[(e.index + 1) % ring.size()]};
  }

  /// s lies below t where both cross the sweep line; judged at the later left endpoint.
  bool below(std::uint32_t s, std::uint32_t t) const {
    if (s == t) return false;
    if (before(left_[s], left_[t])) return !below_at(t, s);
    return below_at(s, t);
  }
  /// For s starting at or after t: is s's left endpoint (or, from a shared one, s) below t.
  bool below_at(std::uint32_t s, std::uint32_t t) const {
    const double side = orient2d(left_[t], right_[t], left_[s]);
    if (side != 0) return side < 0;
    if (left_[s] != left_[t]) touching_ = {s, t};  // s starts on t
    const double turn = orient2d(left_[t], right_[t], right_[s]);
    if (turn == 0) touching_ = {s, t};
    return turn < 0 || (turn == 0 && s < t);
  }

  bool consecutive(std::uint32_t s, std::uint32_t t) const {
    const Edge& e = edges_[s];
    const Edge& f = edges_[t];
    const std::size_t n = polygon_[e.ring].size();
    return e.ring == f.ring && ((e.index + 1) % n == f.index || (f.index + 1) % n == e.index);
  }

  std::string meet(std::uint32_t s, std::uint32_t t) const {
    if (consecutive(s, t)) return {};
    if (segments_meet(left_[s], right_[s], left_[t], right_[t]))
      return where(edges_[s]) + " meets " + where(edges_[t]);
    return {};
  }

  std::string insert(std::uint32_t s) {
    const auto it = active_.insert(s).first;
    if (touching_) {
      const auto [a, b] = *touching_;
      if (!consecutive(a, b) && segments_meet(left_[a], right_[a], left_[b], right_[b]))
        return where(edges_[a]) + " touches " + where(edges_[b]);
      touching_.reset();
    }
    if (it != active_.begin())
      if (std::string problem = meet(s, *std::prev(it)); !problem.empty()) return problem;
    if (std::next(it) != active_.end())
      if (std::string problem = meet(s, *std::next(it)); !problem.empty()) return problem;
    return {};
  }

  std::string remove(std::uint32_t s) {
    const auto it = active_.find(s);
    if (it == active_.end()) return where(edges_[s]) + " lost in the sweep (edges cross)";
    const auto next = active_.erase(it);
    if (next != active_.begin() && next != active_.end()) return meet(*std::prev(next), *next);
    return {};
  }

  const Polygon& polygon_;
  const std::vector<Edge>& edges_;
  std::vector<Point> left_;
  std::vector<Point> right_;
  std::set<std::uint32_t, Below> active_;
  mutable std::optional<std::pair<std::uint32_t, std::uint32_t>> touching_;
};

/// Whether p is inside the ring: the parity of crossings of a rightward ray from p with the
/// ring's edges, exactly. p is known not to lie on the ring.
bool inside_ring(const Ring& ring, const Point& p) {
  bool inside = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point& a = ring[i];
    const Point& b = ring[(i + 1) % ring.size()];
    if ((a.y > p.y) == (b.y > p.y)) continue;
    // The edge spans p's height; the crossing is right of p when p is left of the upward edge.
    if (sign(orient2d(a, b, p)) * (b.y > a.y ? 1 : -1) > 0) inside = !inside;
  }
  return inside;
}

/// Every hole inside the outer ring and outside every other hole. Rings are already known to be
/// disjoint, so one vertex of each hole decides. The outer ring is tested by a ray through a
/// grid of its own edges; other holes only when their bounding box holds the vertex.
std::string check_nesting(const Polygon& polygon) {
  if (polygon.size() < 2) return {};
  std::vector<Edge> outer_edges;
  for (std::uint32_t i = 0; i < polygon[0].size(); ++i) outer_edges.push_back({0, i});
  const EdgeGrid outer(polygon, outer_edges);
  std::vector<std::uint32_t> seen(outer_edges.size(), 0);
  for (std::uint32_t h = 1; h < polygon.size(); ++h) {
    const Point p = polygon[h][0];
    bool inside = false;
    for (std::size_t c = outer.column(p.x); c < outer.columns(); ++c) {
      for (std::uint32_t id : outer.bucket(c, outer.row(p.y))) {
        if (seen[id] == h) continue;
        seen[id] = h;
        const Ring& ring = polygon[0];
        const Point& a = ring[id];
        const Point& b = ring[(id + 1) % ring.size()];
        if ((a.y > p.y) == (b.y > p.y)) continue;
        if (sign(orient2d(a, b, p)) * (b.y > a.y ? 1 : -1) > 0) inside = !inside;
      }
    }
    if (!inside) return "hole " + std::to_string(h) + " is outside the outer ring";
  }
  // Holes by bounding box, in a grid of about one bucket per hole.
  std::vector<Edge> boxes;  // one "edge" per hole: the diagonal of its bounding box
  Polygon diagonals(polygon.size());
  for (std::uint32_t h = 1; h < polygon.size(); ++h) {
    Point low = polygon[h][0];
    Point high = low;
    for (const Point& q : polygon[h]) {
      low = {std::min(low.x, q.x), std::min(low.y, q.y)};
      high = {std::max(high.x, q.x), std::max(high.y, q.y)};
    }
    diagonals[h] = {low, high};
    boxes.push_back({h, 0});
  }
  diagonals[0] = polygon[0];  // the grid spans the whole polygon
  const EdgeGrid holes(diagonals, boxes, true);
  for (std::uint32_t h = 1; h < polygon.size(); ++h) {
    const Point p = polygon[h][0];
    for (std::uint32_t id : holes.bucket(holes.column(p.x), holes.row(p.y))) {
      const std::uint32_t g = boxes[id].ring;
      const Point& low = diagonals[g][0];
      const Point& high = diagonals[g][1];
      if (g == h || p.x < low.x || p.x > high.x || p.y < low.y || p.y > high.y) continue;
      if (inside_ring(polygon[g], p))
        return "hole " + std::to_string(h) + " is inside hole " + std::to_string(g);
    }
  }
  return {};
}

}  // namespace

std::string simplicity_problem(const Polygon& polygon) {
  if (std::string problem = check_rings(polygon); !problem.empty()) return problem;
  std::vector<Edge> edges;
  for (std::uint32_t r = 0; r < polygon.size(); ++r)
    for (std::uint32_t i = 0; i < polygon[r].size(); ++i) edges.push_back({r, i});
  if (std::string problem = check_distinct(polygon, edges); !problem.empty()) return problem;
  for (const Edge& e : edges) {
    const Ring& ring = polygon[e.ring];
    const std::size_t n = ring.size();
    if (folds_back(ring[e.index], ring[(e.index + 1) % n], ring[(e.index + 2) % n]))
      return where(e) + " folds back onto the next edge";
  }
  if (std::string problem = EdgeSweep(polygon, edges).run(); !problem.empty()) return problem;
  return check_nesting(polygon);
}

int ring_orientation(const Ring& ring) {
  const auto lowest = std::min_element(
      ring.begin(), ring.end(),
      [](const Point& a, const Point& b) { return a.y < b.y || (a.y == b.y && a.x < b.x); });
  const std::size_t i = static_cast<std::size_t>(lowest - ring.begin());
  const Point& prev = ring[(i + ring.size() - 1) % ring.size()];
  const Point& next = ring[(i + 1) % ring.size()];
  return sign(orient2d(prev, *lowest, next));
}

long double twice_signed_area(const Ring& ring) {
  long double sum = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point& a = ring[i];
    const Point& b = ring[(i + 1) % ring.size()];
    sum += static_cast<long double>(a.x) * b.y - static_cast<long double>(b.x) * a.y;
  }
  return sum;
}

}  // namespace pear::testing
