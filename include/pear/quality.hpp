// pear: angle quality of a triangulation (the paper's Table 1 numbers) and a min-angle histogram.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "pear/detail/flat_polygon.hpp"
#include "pear/export.hpp"
#include "pear/geometry.hpp"

namespace pear {

struct QualityStatistics {
  std::size_t triangles = 0;
  double dev60_avg_deg = 0;      ///< average |angle - 60°| over all angles of all triangles
  double min_angle_avg_deg = 0;  ///< average over triangles of the smallest angle
  double min_angle_deg = 0;      ///< smallest angle anywhere
  std::array<std::size_t, 12> min_angle_histogram{};  ///< bins of 5°: [0,5), [5,10), ... [55,60]
};

/// Angle statistics of `triangles`, index triples into `points`.
PEAR_API QualityStatistics quality(std::span<const Point> points,
                                   std::span<const std::array<std::uint32_t, 3>> triangles);

/// Same for a polygon given as rings (triangles number its points ring after ring, as
/// pear::triangulate's do) and any index type.
template <ring_range Rings, class Index>
QualityStatistics quality(const Rings& rings, const std::vector<std::array<Index, 3>>& triangles) {
  detail::FlatPolygon flat;
  detail::flatten(rings, flat);
  std::vector<std::array<std::uint32_t, 3>> wide(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k) wide[t][k] = static_cast<std::uint32_t>(triangles[t][k]);
  return quality(std::span<const Point>(flat.points), wide);
}

}  // namespace pear
