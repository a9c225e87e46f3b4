// The Shamos-Hoey sweep for SimplicityCheck: edges enter a status ordered bottom to top when the
// sweep reaches their left end and leave at their right end; only edges that become neighbours
// there are tested. The first conflict in sweep order is always found before the order could
// go wrong, and the search stops at the first conflict found.
#include <algorithm>
#include <set>

#include "boundary.hpp"
#include "pear/predicates.hpp"
#include "simplicity.hpp"

namespace pear::detail {
namespace {

struct Segment {
  Point left, right;
};

/// Orders edges from bottom to top where the later-starting one begins (or, sharing a start,
/// just after it). Collinear overlapping edges compare equal in geometry: that is a conflict,
/// recorded, and ordered by id to stay a strict order.
struct Below {
  const std::vector<Segment>* segments;
  mutable std::uint32_t overlap = UINT32_MAX;

  bool operator()(std::uint32_t s, std::uint32_t t) const {
    if (s == t) return false;
    const Segment &a = (*segments)[s], &b = (*segments)[t];
    const bool a_later = !lexicographic_less(a.left, b.left);
    const Segment &later = a_later ? a : b, &earlier = a_later ? b : a;
    double side =
        later.left == earlier.left ? 0 : orient2d(earlier.left, earlier.right, later.left);
    if (side == 0) side = orient2d(earlier.left, earlier.right, later.right);
    if (side == 0) {
      overlap = std::min(s, t);
      return s < t;
    }
    return a_later ? side < 0 : side > 0;  // is a below b?
  }
};

}  // namespace

std::optional<std::uint32_t> SimplicityCheck::sweep() {
  const auto& pts = polygon_->points;
  const auto n = static_cast<std::uint32_t>(pts.size());
  std::vector<Segment> segments(n);
  for (std::uint32_t e = 0; e < n; ++e) {
    const Point &a = pts[e], &b = pts[next_[e]];
    segments[e] = lexicographic_less(a, b) ? Segment{a, b} : Segment{b, a};
  }
  // Event 2e inserts edge e at its left end, 2e + 1 removes it at its right end. At one point,
  // removals come before insertions, so edges meeting end to end are never both in the status.
  std::vector<std::uint32_t> events(2 * static_cast<std::size_t>(n));
  for (std::uint32_t i = 0; i < events.size(); ++i) events[i] = i;
  const auto where = [&](std::uint32_t event) -> const Point& {
    return event % 2 ? segments[event / 2].right : segments[event / 2].left;
  };
  std::sort(events.begin(), events.end(), [&](std::uint32_t x, std::uint32_t y) {
    const Point &p = where(x), &q = where(y);
    if (!(p == q)) return lexicographic_less(p, q);
    if (x % 2 != y % 2) return x % 2 > y % 2;
    return x < y;
  });

  Below below{&segments};
  std::set<std::uint32_t, Below> status(below);
  std::vector<std::set<std::uint32_t, Below>::iterator> place(n);
  const auto conflict = [&](std::uint32_t e, std::uint32_t f) -> std::optional<std::uint32_t> {
    if (pair_conflicts(e, f)) return std::min(e, f);
    return std::nullopt;
  };
  for (std::uint32_t event : events) {
    const std::uint32_t e = event / 2;
    if (event % 2) {  // removal: its neighbours meet
      const auto it = place[e];
      const auto above = std::next(it);
      const bool has_below = it != status.begin();
      const auto under = has_below ? std::prev(it) : it;
      status.erase(it);
      if (has_below && above != status.end())
        if (const auto found = conflict(*under, *above)) return found;
      continue;
    }
    const auto [it, inserted] = status.insert(e);
    if (status.key_comp().overlap != UINT32_MAX) return status.key_comp().overlap;
    place[e] = it;
    if (it != status.begin())
      if (const auto found = conflict(*std::prev(it), e)) return found;
    if (std::next(it) != status.end())
      if (const auto found = conflict(e, *std::next(it))) return found;
  }
  return std::nullopt;
}

}  // namespace pear::detail
