// pear: deterministic synthetic polygon families for tests, benchmarks and `pear generate`.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "pear/export.hpp"
#include "pear/geometry.hpp"

namespace pear {

/// The generator names accepted by generate_polygon: "star", "comb", "spiral", "koch", "hilbert",
/// "random", "holes" (a square with a grid of square holes), "random-holes".
PEAR_API std::span<const std::string_view> generator_kinds();

/// A valid polygon (outer ring CCW, holes CW, closing point not repeated) of the given family with
/// about `vertices` vertices (exactly, where the family allows), deterministic in `seed`.
/// Throws std::invalid_argument for an unknown kind or a size the family cannot make.
PEAR_API Polygon generate_polygon(std::string_view kind, std::size_t vertices,
                                  std::uint64_t seed = 1);

}  // namespace pear
