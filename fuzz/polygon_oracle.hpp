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
  /// Certainly a valid polygon once repaired (repair() below): every ring has >= 3 points and
  /// visits no point twice; no two edges cross, overlap or touch except at shared endpoints;
  /// every hole lies inside the outer ring and outside every other hole. Rings may touch each
  /// other at vertices, or at a vertex inside another ring's edge (split by the repair). False
  /// also when undecided (e.g. self-touching rings).
  bool valid = false;
  std::size_t vertices = 0;         ///< n: of the repaired rings (split points included)
  std::size_t holes = 0;            ///< h
  std::size_t repeated_points = 0;  ///< m: vertices minus distinct points
  mpq_class twice_area = 0;         ///< outer minus holes, exact; set when valid
};

PolygonFacts examine(const pear::Polygon& polygon);

/// The rings without repeated consecutive points (nor a closing point), as pear cleans them.
pear::Polygon drop_repeated_points(const pear::Polygon& polygon);

/// The rings as pear's contract repairs them (README), written here apart from pear: repeated
/// points dropped, zero-width spikes dissolved (a vertex where the ring turns straight back
/// leaves, until none does), then every edge split at each point of any ring lying strictly
/// inside it. Quadratic: for the fuzzers' small polygons.
pear::Polygon repair(const pear::Polygon& polygon);

}  // namespace fuzz
