// CGAL's constrained Delaunay triangulation as the fuzz targets' oracle: the triangles it puts
// inside the polygon, as point triples. The oracle is fallible (CGAL has failed on touching
// constraints): a failure or an added crossing point gives nothing, and the caller skips.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "pear/geometry.hpp"

namespace fuzz {

using PointTriangles = std::vector<std::array<pear::Point, 3>>;

/// Whether this build has the CGAL oracle (PEAR_FUZZ_WITH_CGAL).
bool have_cgal();

/// The CDT's triangles inside the polygon (odd nesting level: inside the outer ring, outside the
/// holes), counterclockwise; nullopt when CGAL threw or added a point of its own.
std::optional<PointTriangles> cgal_cdt_inside(const pear::Polygon& polygon);

}  // namespace fuzz
