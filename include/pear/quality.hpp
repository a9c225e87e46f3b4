// pear: angle quality of a triangulation (the paper's Table 1 numbers) and a min-angle histogram.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "pear/geometry.hpp"

namespace pear {

struct QualityStatistics {
  std::size_t triangles = 0;
  double dev60_avg_deg = 0;      ///< average |angle - 60°| over all angles of all triangles
  double min_angle_avg_deg = 0;  ///< average over triangles of the smallest angle
  double min_angle_deg = 0;      ///< smallest angle anywhere
  std::array<std::size_t, 12> min_angle_histogram{};  ///< bins of 5°: [0,5), [5,10), ... [55,60]
};

QualityStatistics quality(std::span<const Point> points,
                          std::span<const std::array<std::uint32_t, 3>> triangles);

}  // namespace pear
