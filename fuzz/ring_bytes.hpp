// Rings decoded from the fuzzer's bytes, for the degenerate inputs: coordinates snapped to a
// small integer grid (collinear runs, repeated points, touching vertices, zero-area spikes
// come often) or arbitrary doubles of any magnitude.
//
// Layout: a header byte (bits 0-1 the coordinate mode below, bit 5 T-junction moves; the other
// bits are the target's), a grid byte g (grid of 2 + g % 15 values per axis), an exponent byte
// e (int8), with bit 5 a count byte c and 1 + c % 4 moves of 3 bytes, then rings, each a count
// byte and that many points. At most 32 rings and max_vertices points in all.
//
// A move (the T-junction mutator) puts a vertex exactly onto another edge: vertex v (first
// byte, modulo the vertices) goes to a + k/8 (b - a) on edge a-b (second byte picks the edge's
// start vertex, third k = 1 + byte % 7). On the grids that point is exact, so the vertex lies
// inside the edge, and often at a lattice point another ring uses too.
#pragma once

#include <cstddef>
#include <cstdint>

#include "pear/geometry.hpp"
#include "support.hpp"

namespace fuzz {

enum class CoordinateMode : std::uint8_t {
  small_grid = 0,   ///< one byte a point: two nibbles, each modulo the grid size
  byte_grid = 1,    ///< two bytes a point: int8 x and y
  any_double = 2,   ///< sixteen bytes a point: the bits of two doubles (made finite)
  scaled_grid = 3,  ///< small_grid times 2^(2e): exact, from 2^-256 up to 2^254
};

inline constexpr std::size_t max_vertices = 256;
inline constexpr std::uint8_t t_junction_moves = 32;  ///< header bit

/// Decodes the rings after the header byte. Non-finite doubles are kept only when asked.
pear::Polygon decode_rings(ByteReader& bytes, std::uint8_t header, bool keep_non_finite = false);

}  // namespace fuzz
