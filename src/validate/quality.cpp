// pear: angle quality of a triangulation (include/pear/quality.hpp): the two numbers of the
// paper's Table 1 (average deviation of all angles from 60 degrees; average smallest angle per
// triangle) and a histogram of the smallest angles.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "pear/quality.hpp"

namespace pear {
namespace {

// The angle at `apex` between the sides to p and q, in degrees. atan2 of |cross| and dot stays
// accurate for slivers, where acos of a normalized dot product loses all its digits.
double angle_deg(const Point& apex, const Point& p, const Point& q) {
  const double ux = p.x - apex.x, uy = p.y - apex.y;
  const double vx = q.x - apex.x, vy = q.y - apex.y;
  const double cross = ux * vy - uy * vx;
  const double dot = ux * vx + uy * vy;
  return std::atan2(std::fabs(cross), dot) * (180.0 / std::numbers::pi);
}

}  // namespace

QualityStatistics quality(std::span<const Point> points,
                          std::span<const std::array<std::uint32_t, 3>> triangles) {
  QualityStatistics statistics;
  long double deviation_sum = 0;  // long double: millions of terms lose no visible digit
  long double min_angle_sum = 0;
  double global_min = 180;
  for (const auto& triangle : triangles) {
    // Triangles naming a point that does not exist are not measured (validate() reports them).
    if (std::any_of(triangle.begin(), triangle.end(),
                    [&](std::uint32_t v) { return v >= points.size(); }))
      continue;
    const Point& a = points[triangle[0]];
    const Point& b = points[triangle[1]];
    const Point& c = points[triangle[2]];
    const double angles[3] = {angle_deg(a, b, c), angle_deg(b, c, a), angle_deg(c, a, b)};
    double smallest = 180;
    for (double angle : angles) {
      deviation_sum += std::fabs(angle - 60);
      smallest = std::min(smallest, angle);
    }
    min_angle_sum += smallest;
    global_min = std::min(global_min, smallest);
    const auto bin = static_cast<std::size_t>(std::clamp(smallest / 5, 0.0, 11.0));
    ++statistics.min_angle_histogram[bin];
    ++statistics.triangles;
  }
  if (statistics.triangles == 0) return statistics;
  const auto count = static_cast<double>(statistics.triangles);
  statistics.dev60_avg_deg = static_cast<double>(deviation_sum / (3 * count));
  statistics.min_angle_avg_deg = static_cast<double>(min_angle_sum / count);
  statistics.min_angle_deg = global_min;
  return statistics;
}

}  // namespace pear
