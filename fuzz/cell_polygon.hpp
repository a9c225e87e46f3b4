// Polygons valid by construction, for the bridged, parallel and cdt targets: the boundary of
// one connected set of grid cells. Holes, holes and outer ring touching at corners, rings
// touching themselves, long collinear runs; every triangulation of it has a known count.
//
// Layout: width and height bytes (2 + b % 15 cells), a flags byte (below), a start byte (which
// set cell seeds the component), an exponent byte (int8) and a 16-bit offset for the exact
// placement, then the cells' bits row by row (missing bytes are empty cells). Bytes left after
// that make T-junctions: each 16 bits pick a unit edge of the boundary (modulo their number),
// and a triangular hole stands on its midpoint inside the cell beside it (apex at the midpoint,
// a quarter of a cell high, a quarter wide), so the apex lies exactly inside a ring's edge. At
// most 8; each adds 4 triangles to every triangulation.
#pragma once

#include <cstddef>
#include <optional>

#include "pear/geometry.hpp"
#include "support.hpp"

namespace fuzz {

namespace cell_flags {
inline constexpr unsigned corner_connected = 1;  ///< cells meeting at a corner are connected
inline constexpr unsigned drop_collinear = 2;    ///< leave out the vertices where rings go straight
inline constexpr unsigned reverse_rings = 4;     ///< clockwise outer ring, counterclockwise holes
inline constexpr unsigned transpose = 8;         ///< swap x and y
inline constexpr unsigned place = 16;            ///< (x + offset) * 2^exponent, exactly
}  // namespace cell_flags

struct CellPolygon {
  pear::Polygon polygon;        ///< outer ring first
  std::size_t triangles = 0;    ///< the triangle count of every triangulation of it
  std::size_t t_junctions = 0;  ///< triangular holes standing on an edge (the last holes)
};

/// Nothing when no cell is set.
std::optional<CellPolygon> decode_cell_polygon(ByteReader& bytes);

}  // namespace fuzz
