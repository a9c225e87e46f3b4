// The fuzz targets' own exact judgement of an input polygon, independent of pear's cleaning and
// simplicity check: is every coordinate one pear must accept, and is the polygon certainly
// valid (then pear must triangulate it exactly)?
#pragma once

#include <gmpxx.h>

#include <cstddef>

#include "pear/geometry.hpp"

namespace fuzz {

struct PolygonFacts {
  /// Every coordinate finite and zero or of magnitude in [2^-200, 2^200] (README's contract).
  bool coordinates_in_range = true;
  /// Certainly a valid polygon: every ring has >= 3 points after dropping repeated consecutive
  /// ones and visits no point twice; no two edges cross, overlap or touch except at shared
  /// endpoints; every hole lies inside the outer ring and outside every other hole. Rings may
  /// touch each other at vertices. False also when undecided (e.g. self-touching rings).
  bool valid = false;
  std::size_t vertices = 0;         ///< n: after dropping repeated consecutive points
  std::size_t holes = 0;            ///< h
  std::size_t repeated_points = 0;  ///< m: vertices minus distinct points
  mpq_class twice_area = 0;         ///< outer minus holes, exact; set when valid
};

PolygonFacts examine(const pear::Polygon& polygon);

/// The rings without repeated consecutive points (nor a closing point), as pear cleans them.
pear::Polygon drop_repeated_points(const pear::Polygon& polygon);

}  // namespace fuzz
