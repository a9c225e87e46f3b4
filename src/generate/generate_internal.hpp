// pear: shared pieces of the synthetic polygon generators.
#pragma once

#include <cstddef>
#include <cstdint>
#include <random>

#include "pear/geometry.hpp"

namespace pear::generate_detail {

/// A portable random source: mt19937_64's sequence is fixed by the standard, and we turn its
/// words into numbers ourselves because std's distributions differ between standard libraries.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  /// Uniform in [0, 1) with 53 random bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1p-53; }
  double uniform(double low, double high) { return low + (high - low) * uniform(); }
  /// Uniform in [0, bound); bound > 0. The modulo bias is below 2^-40 for our bounds.
  std::size_t below(std::size_t bound) { return static_cast<std::size_t>(engine_() % bound); }

 private:
  std::mt19937_64 engine_;
};

/// Mixes the family's name into the seed so families with the same seed are unrelated.
std::uint64_t family_seed(std::uint64_t seed, std::uint64_t family);

/// True when the ring goes strictly counterclockwise around `center`, each step less than a half
/// turn, by exact orient2d: then it is a simple star-shaped polygon around `center`.
bool strictly_around(const Ring& ring, const Point& center);

Polygon star(std::size_t vertices, std::uint64_t seed);
Polygon comb(std::size_t vertices);
Polygon spiral(std::size_t vertices);
Polygon koch(std::size_t vertices);
Polygon holes(std::size_t vertices);
Polygon hilbert(std::size_t vertices);
Polygon random_maze(std::size_t vertices, std::uint64_t seed);
Polygon random_holes(std::size_t vertices, std::uint64_t seed);

}  // namespace pear::generate_detail
