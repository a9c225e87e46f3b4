// pear: an independent checker for triangulations of polygons (with holes).
//
// Checks, together proving a valid triangulation (a degree-one covering of the polygon):
//   indices in range, no repeated triangle, every triangle strictly counterclockwise by exact
//   orient2d, every boundary edge of the cleaned input (repeated points dropped, zero-width
//   spikes dissolved) used by exactly one triangle on its inner side, or, where vertices lie
//   inside it (T-junctions), its parts between them each so used (a triangle's edge is never
//   split), every other edge by zero or two triangles with opposite orientation, the triangle
//   count n + 2h - 2 - 2m (n counting each point inside a boundary edge once more; m: those
//   and the kept vertices minus distinct kept points, i.e. touching rings; enforced wherever no
//   ring passes a point twice, since self-touching rings can differ and the other checks
//   suffice), and the total triangle area equal to the polygon's area.
// Optionally: every non-boundary edge locally Delaunay by exact incircle (for a CDT).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "pear/geometry.hpp"
#include "pear/pear.hpp"

namespace pear {

struct ValidateOptions {
  bool check_delaunay = false;    ///< also require every interior edge to be locally Delaunay
  bool allow_zero_area = false;   ///< accept zero-area triangles (degenerate input)
  bool check_count = true;        ///< require n + 2h - 2 - 2m triangles (no Steiner points)
  std::size_t max_messages = 20;  ///< stop recording messages after this many
};

struct ValidationReport {
  bool valid = true;
  std::size_t triangles = 0;
  std::size_t expected_triangles =
      0;  ///< n + 2h - 2 - 2m for the cleaned input (m: repeated points)
  std::size_t zero_area_triangles = 0;  ///< collinear triangles (reported separately)
  std::size_t bad_orientation = 0;      ///< clockwise triangles
  std::size_t bad_edges = 0;            ///< edges used the wrong number of times or directions
  std::size_t non_delaunay_edges = 0;   ///< only counted with check_delaunay
  double polygon_area = 0;              ///< outer minus holes, robustly summed
  double triangle_area = 0;             ///< sum of triangle areas, robustly summed
  double area_rel_error =
      0;  ///< |triangle_area - polygon_area| / polygon_area, exact: 0 when valid
  std::vector<std::string> messages;  ///< what failed and where, at most max_messages
};

/// Validates triangles (indices into polygon.points) against the polygon.
PEAR_API ValidationReport validate(const PolygonView& polygon,
                                   std::span<const std::array<std::uint32_t, 3>> triangles,
                                   const ValidateOptions& options = {});

/// Same for any ring range and index type.
template <ring_range Rings, class Index>
ValidationReport validate(const Rings& rings, std::span<const std::array<Index, 3>> triangles,
                          const ValidateOptions& options = {}) {
  detail::FlatPolygon flat;
  detail::flatten(rings, flat);
  std::vector<std::array<std::uint32_t, 3>> wide(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (std::size_t k = 0; k < 3; ++k) wide[t][k] = static_cast<std::uint32_t>(triangles[t][k]);
  return validate(PolygonView{flat.points, flat.ring_starts}, wide, options);
}

/// Same for a vector of triangles, as a Triangulation holds them.
template <ring_range Rings, class Index>
ValidationReport validate(const Rings& rings, const std::vector<std::array<Index, 3>>& triangles,
                          const ValidateOptions& options = {}) {
  return validate(rings, std::span<const std::array<Index, 3>>(triangles), options);
}

}  // namespace pear
