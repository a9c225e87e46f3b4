// Holes that are not where a hole may be. With no two edges in conflict (after T-junctions are
// split), rings meet only at shared vertices, so a hole lies inside or outside each other ring
// as a whole: one of its vertices that no other ring shares decides, by an exact ray test.
#include <algorithm>
#include <utility>

#include "geometry/sort.hpp"
#include "geometry/uniform_grid.hpp"
#include "pear/predicates.hpp"
#include "simplicity.hpp"

namespace pear::detail {
namespace {

/// Whether edge a-b crosses the ray from p to the right (p on no edge): the lower end counts
/// as in, the upper as out, and the side is an exact orientation.
bool crosses_ray_right(const Point& a, const Point& b, const Point& p) {
  if ((a.y <= p.y) == (b.y <= p.y)) return false;
  const double side = orient2d(a, b, p);
  return a.y < b.y ? side > 0 : side < 0;
}

/// Horizontal bands of the edges' y-ranges, each edge listed in every band it meets, so that a
/// ray needs only its band's edges. Fewer bands where edges are tall against their spacing:
/// the entries stay under 8 per edge.
class Bands {
 public:
  explicit Bands(const CleanPolygon& polygon) : polygon_(polygon) {
    const auto& pts = polygon.points;
    const auto n = static_cast<std::uint32_t>(pts.size());
    ring_.resize(n);
    next_.resize(n);
    for (std::uint32_t r = 0; r < polygon.ring_count(); ++r) {
      const std::uint32_t first = polygon.ring_starts[r], end = polygon.ring_starts[r + 1];
      for (std::uint32_t i = first; i < end; ++i) ring_[i] = r, next_[i] = i + 1;
      next_[end - 1] = first;
    }
    double y0 = pts[0].y, y1 = pts[0].y;
    for (const Point& p : pts) y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    for (std::size_t bands = n / 4 + 1;; bands = bands / 2 + 1) {
      frame_.fit({0, y0}, {0, y1}, bands);
      std::size_t entries = 0;
      for (std::uint32_t e = 0; e < n; ++e) entries += rows(e).second - rows(e).first + 1;
      if (entries <= 8 * std::size_t{n} || frame_.ny <= 1) break;
    }
    start_.assign(static_cast<std::size_t>(frame_.ny) + 1, 0);
    for (std::uint32_t e = 0; e < n; ++e)
      for (int r = rows(e).first; r <= rows(e).second; ++r) ++start_[r + 1];
    for (std::size_t r = 1; r < start_.size(); ++r) start_[r] += start_[r - 1];
    edges_.resize(start_.back());
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::uint32_t e = 0; e < n; ++e)
      for (int r = rows(e).first; r <= rows(e).second; ++r) edges_[fill[r]++] = e;
  }

  /// For p on no edge: the rings p lies inside, as odd entries of `parity` (all zero before),
  /// listed in `rings`. Crossings of the ray to the right of p, each edge counted with its
  /// lower end in and its upper end out, every decision an exact orientation.
  void rings_around(const Point& p, std::vector<std::uint8_t>& parity,
                    std::vector<std::uint32_t>& rings) const {
    const int r = frame_.row(p.y);
    for (std::uint32_t k = start_[r]; k < start_[r + 1]; ++k) {
      const std::uint32_t e = edges_[k];
      if (!crosses_ray_right(polygon_.points[e], polygon_.points[next_[e]], p)) continue;
      if (parity[ring_[e]] == 0 && (rings.empty() || rings.back() != ring_[e]))
        rings.push_back(ring_[e]);
      parity[ring_[e]] ^= 1;
    }
  }

 private:
  std::pair<int, int> rows(std::uint32_t e) const {
    const double a = polygon_.points[e].y, b = polygon_.points[next_[e]].y;
    return {frame_.row(std::min(a, b)), frame_.row(std::max(a, b))};
  }

  const CleanPolygon& polygon_;
  std::vector<std::uint32_t> ring_, next_;
  GridFrame frame_;
  std::vector<std::uint32_t> start_, edges_;
};

/// Each vertex's witness status (false where another ring has a vertex at the same point), and
/// whether each ring passes a point twice itself.
struct Witnesses {
  std::vector<std::uint8_t> unshared;
  std::vector<std::uint8_t> self_touching;
};

Witnesses find_witnesses(const CleanPolygon& polygon) {
  std::vector<std::pair<Point, std::uint32_t>> at;  // (position, ring)
  for (std::uint32_t r = 0; r < polygon.ring_count(); ++r)
    for (std::uint32_t i = polygon.ring_starts[r]; i < polygon.ring_starts[r + 1]; ++i)
      at.emplace_back(polygon.points[i], r);
  const auto less = [](const std::pair<Point, std::uint32_t>& s,
                       const std::pair<Point, std::uint32_t>& t) {
    if (s.first.x != t.first.x) return s.first.x < t.first.x;
    if (s.first.y != t.first.y) return s.first.y < t.first.y;
    return s.second < t.second;
  };
  detail::sort(at.begin(), at.end(), less);
  Witnesses w{std::vector<std::uint8_t>(polygon.points.size(), 1),
              std::vector<std::uint8_t>(polygon.ring_count(), 0)};
  std::vector<std::pair<Point, std::uint32_t>> shared;  // positions of two rings or more
  for (std::size_t i = 1; i < at.size(); ++i) {
    if (!(at[i].first == at[i - 1].first)) continue;
    if (at[i].second != at[i - 1].second)
      shared.push_back(at[i]);
    else
      w.self_touching[at[i].second] = 1;
  }
  for (std::uint32_t i = 0; i < polygon.points.size(); ++i)
    w.unshared[i] = !std::binary_search(
        shared.begin(), shared.end(), std::pair(polygon.points[i], 0u),
        [](const auto& s, const auto& t) {
          return s.first.x < t.first.x || (s.first.x == t.first.x && s.first.y < t.first.y);
        });
  return w;
}

}  // namespace

std::optional<MisplacedHole> find_misplaced_hole(const CleanPolygon& polygon) {
  const std::size_t rings = polygon.ring_count();
  if (rings < 2) return std::nullopt;
  const Witnesses witnesses = find_witnesses(polygon);
  const Bands bands(polygon);
  std::vector<std::uint8_t> parity(rings, 0);
  std::vector<std::uint32_t> around;
  for (std::uint32_t hole = 1; hole < rings; ++hole) {
    // One vertex that no other ring shares decides for a hole, which lies inside or outside
    // each other ring as a whole; a hole that passes a point twice has lobes, each of which
    // may lie elsewhere, so every such vertex of it is asked. A hole whose every vertex
    // another ring shares is left undecided (its edges meet the others only there, so the
    // best effort's place names it).
    for (std::uint32_t vertex = polygon.ring_starts[hole]; vertex < polygon.ring_starts[hole + 1];
         ++vertex) {
      if (!witnesses.unshared[vertex]) continue;
      around.clear();
      bands.rings_around(polygon.points[vertex], parity, around);
      bool in_outer = false, in_hole = false;
      for (std::uint32_t r : around) {
        if (parity[r] && r != hole) (r == 0 ? in_outer : in_hole) = true;
        parity[r] = 0;
      }
      if (!in_outer) return MisplacedHole{vertex, true};
      if (in_hole) return MisplacedHole{vertex, false};
      if (!witnesses.self_touching[hole]) break;
    }
  }
  return std::nullopt;
}

std::optional<MisplacedHole> find_misplaced_hole_among_few(const CleanPolygon& polygon) {
  const std::size_t rings = polygon.ring_count();
  const auto& pts = polygon.points;
  for (std::uint32_t hole = 1; hole < rings; ++hole) {
    const std::uint32_t vertex = polygon.ring_starts[hole];
    bool in_outer = false, in_hole = false;
    for (std::uint32_t r = 0; r < rings; ++r) {
      if (r == hole) continue;
      const std::uint32_t first = polygon.ring_starts[r], end = polygon.ring_starts[r + 1];
      bool inside = false;
      for (std::uint32_t e = first; e < end; ++e)
        inside ^= crosses_ray_right(pts[e], pts[e + 1 == end ? first : e + 1], pts[vertex]);
      (r == 0 ? in_outer : in_hole) |= inside;
    }
    if (!in_outer) return MisplacedHole{vertex, true};
    if (in_hole) return MisplacedHole{vertex, false};
  }
  return std::nullopt;
}

}  // namespace pear::detail
