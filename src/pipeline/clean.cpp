#include "clean.hpp"

#include <algorithm>
#include <cmath>

#include "pear/predicates.hpp"

namespace pear::detail {
namespace {

bool coordinate_in_range(double c) {
  const double m = std::fabs(c);
  return m == 0.0 || (m >= min_nonzero_coordinate && m <= max_coordinate);
}

/// First error among the coordinates of all rings, if any.
bool check_coordinates(const PolygonView& in, std::vector<Diagnostic>& diagnostics) {
  for (std::size_t r = 0; r + 1 < in.ring_offsets.size(); ++r) {
    for (std::uint32_t i = in.ring_offsets[r]; i < in.ring_offsets[r + 1]; ++i) {
      const Point& p = in.points[i];
      const std::size_t vertex = i - in.ring_offsets[r];
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
        diagnostics.push_back({Issue::non_finite_coordinate, r, vertex});
        return false;
      }
      if (!coordinate_in_range(p.x) || !coordinate_in_range(p.y)) {
        diagnostics.push_back({Issue::coordinate_out_of_range, r, vertex});
        return false;
      }
    }
  }
  return true;
}

/// Appends ring [begin, end) without repeated consecutive points (nor a repeated closing point).
void append_deduplicated(const PolygonView& in, std::uint32_t begin, std::uint32_t end,
                         CleanPolygon& out) {
  const std::size_t first = out.points.size();
  for (std::uint32_t i = begin; i < end; ++i) {
    if (out.points.size() > first && out.points.back() == in.points[i]) continue;
    out.points.push_back(in.points[i]);
    out.original.push_back(i);
  }
  while (out.points.size() > first + 1 && out.points.back() == out.points[first]) {
    out.points.pop_back();
    out.original.pop_back();
  }
}

/// +1 counterclockwise, -1 clockwise, 0 when every point is collinear (zero area).
/// Decided exactly at the lowest-leftmost vertex, which is convex for a simple ring;
/// for non-simple rings whose extreme corner is flat, the shoelace sign decides.
int ring_orientation(const Point* p, std::size_t n) {
  std::size_t lowest = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (p[i].y < p[lowest].y || (p[i].y == p[lowest].y && p[i].x < p[lowest].x)) lowest = i;
  const double turn = orient2d(p[(lowest + n - 1) % n], p[lowest], p[(lowest + 1) % n]);
  if (turn != 0) return turn > 0 ? 1 : -1;
  long double area = 0;
  bool collinear = true;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = p[i];
    const Point& b = p[(i + 1) % n];
    area += static_cast<long double>(a.x) * b.y - static_cast<long double>(b.x) * a.y;
    if (collinear && orient2d(p[0], p[lowest == 0 ? 1 : lowest], a) != 0) collinear = false;
  }
  if (collinear) return 0;
  return area >= 0 ? 1 : -1;
}

void reverse_ring(CleanPolygon& out, std::size_t first) {
  std::reverse(out.points.begin() + first, out.points.end());
  std::reverse(out.original.begin() + first, out.original.end());
}

void drop_ring(CleanPolygon& out, std::size_t first) {
  out.points.resize(first);
  out.original.resize(first);
}

}  // namespace

Status clean_polygon(const PolygonView& in, CleanPolygon& out,
                     std::vector<Diagnostic>& diagnostics) {
  out.clear();
  const std::size_t rings = in.ring_offsets.empty() ? 0 : in.ring_offsets.size() - 1;
  if (rings == 0) {
    diagnostics.push_back({Issue::empty_input, 0, 0});
    return Status::invalid_input;
  }
  for (std::size_t r = 0; r <= rings; ++r) {
    const std::uint32_t offset = in.ring_offsets[r];
    const bool in_order = r == 0 ? offset == 0 : in.ring_offsets[r - 1] <= offset;
    if (!in_order || (r == rings && offset != in.points.size())) {
      diagnostics.push_back({Issue::invalid_offsets, r, 0});
      return Status::invalid_input;
    }
  }
  if (in.ring_offsets[1] == 0) {
    diagnostics.push_back({Issue::empty_input, 0, 0});
    return Status::invalid_input;
  }
  if (!check_coordinates(in, diagnostics)) return Status::invalid_input;

  for (std::size_t r = 0; r < rings; ++r) {
    const std::size_t first = out.points.size();
    append_deduplicated(in, in.ring_offsets[r], in.ring_offsets[r + 1], out);
    const std::size_t count = out.points.size() - first;
    const int orientation = count >= 3 ? ring_orientation(&out.points[first], count) : 0;
    if (count < 3 || orientation == 0) {
      const Issue issue =
          count < 3 ? (r == 0 ? Issue::outer_ring_too_small : Issue::hole_dropped_too_small)
                    : (r == 0 ? Issue::outer_ring_too_small : Issue::hole_dropped_zero_area);
      diagnostics.push_back({issue, r, 0});
      if (r == 0) return Status::invalid_input;
      drop_ring(out, first);
      continue;
    }
    if ((r == 0) != (orientation > 0)) reverse_ring(out, first);
    out.ring_starts.push_back(static_cast<std::uint32_t>(first));
    out.ring_source.push_back(static_cast<std::uint32_t>(r));
  }
  out.ring_starts.push_back(static_cast<std::uint32_t>(out.points.size()));
  return Status::ok;
}

}  // namespace pear::detail
