// A polygon whose correct triangulation is known in count and area, for the targets that run it
// through several configurations (parallel, cdt): either cells (valid by construction) or rings
// from the bytes that the exact oracle judges.
#pragma once

#include <gmpxx.h>

#include <cstddef>
#include <optional>

#include "pear/geometry.hpp"
#include "support.hpp"

namespace fuzz {

struct KnownPolygon {
  pear::Polygon polygon;
  bool valid = false;         ///< certainly valid: then the two numbers below hold
  std::size_t triangles = 0;  ///< the triangle count of every triangulation
  mpq_class twice_area = 0;
};

/// Cells (cell_polygon.hpp) or, when from_rings, rings (ring_bytes.hpp, its header byte first).
/// Nothing when no cell is set.
std::optional<KnownPolygon> decode_known_polygon(ByteReader& bytes, bool from_rings);

/// Checks a result against what is known: check_any_result, and check_exact_triangulation when
/// the polygon is valid.
void check_known(const KnownPolygon& known, const pear::Triangulation<>& result,
                 bool check_delaunay = false);

}  // namespace fuzz
