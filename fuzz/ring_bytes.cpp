#include "ring_bytes.hpp"

#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

namespace fuzz {
namespace {

/// An infinity or NaN becomes a finite double by clearing the exponent's top bit.
double make_finite(double value) {
  if (std::isfinite(value)) return value;
  std::uint64_t bits;
  std::memcpy(&bits, &value, sizeof bits);
  bits &= ~(std::uint64_t{1} << 62);
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

struct PointDecoder {
  CoordinateMode mode;
  int grid;
  int exponent;
  bool keep_non_finite;

  pear::Point next(ByteReader& bytes) const {
    switch (mode) {
      case CoordinateMode::small_grid:
      case CoordinateMode::scaled_grid: {
        const std::uint8_t b = bytes.byte();
        const double x = (b & 15) % grid;
        const double y = (b >> 4) % grid;
        if (mode == CoordinateMode::small_grid) return {x, y};
        return {std::ldexp(x, exponent), std::ldexp(y, exponent)};
      }
      case CoordinateMode::byte_grid: {
        const double x = static_cast<std::int8_t>(bytes.byte());
        return {x, static_cast<double>(static_cast<std::int8_t>(bytes.byte()))};
      }
      case CoordinateMode::any_double:
        break;
    }
    const double x = bytes.f64();
    const double y = bytes.f64();
    if (keep_non_finite) return {x, y};
    return {make_finite(x), make_finite(y)};
  }
};

/// The T-junction mutator (ring_bytes.hpp): vertex v moved onto edge e at k/8 of its length.
struct Move {
  std::uint8_t vertex, edge, eighths;
};

void move_onto_edge(pear::Polygon& rings, const Move& move, std::size_t total) {
  std::vector<std::pair<std::size_t, std::size_t>> at;  // (ring, index) of each vertex
  for (std::size_t r = 0; r < rings.size(); ++r)
    for (std::size_t i = 0; i < rings[r].size(); ++i) at.emplace_back(r, i);
  if (total < 2 || at.size() != total) return;
  const auto [vr, vi] = at[move.vertex % total];
  const auto [er, ei] = at[move.edge % total];
  const pear::Ring& ring = rings[er];
  const pear::Point a = ring[ei], b = ring[(ei + 1) % ring.size()];
  const double t = (1 + move.eighths % 7) / 8.0;
  rings[vr][vi] = {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

}  // namespace

pear::Polygon decode_rings(ByteReader& bytes, std::uint8_t header, bool keep_non_finite) {
  const PointDecoder decoder{static_cast<CoordinateMode>(header & 3), 2 + bytes.byte() % 15,
                             2 * static_cast<std::int8_t>(bytes.byte()), keep_non_finite};
  std::vector<Move> moves;
  if (header & t_junction_moves) {
    moves.resize(1 + bytes.byte() % 4);
    for (Move& m : moves) m = {bytes.byte(), bytes.byte(), bytes.byte()};
  }
  pear::Polygon rings;
  std::size_t total = 0;
  while (!bytes.empty() && rings.size() < 32 && total < max_vertices) {
    const std::size_t count = bytes.byte();
    pear::Ring& ring = rings.emplace_back();
    for (std::size_t i = 0; i < count && total < max_vertices; ++i, ++total)
      ring.push_back(decoder.next(bytes));
  }
  for (const Move& m : moves) move_onto_edge(rings, m, total);
  return rings;
}

}  // namespace fuzz
