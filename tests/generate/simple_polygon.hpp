// An exact checker for simple polygons with holes, independent of the library's own code except
// for pear::orient2d.
#pragma once

#include <string>

#include "pear/geometry.hpp"

namespace pear::testing {

/// Empty when the polygon is a valid simple polygon with holes: every ring has at least 3
/// points, no repeated consecutive point (nor a repeated closing point), no two edges of any
/// rings cross, touch or overlap except consecutive edges at their shared vertex, every hole lies
/// inside the outer ring and outside every other hole. Otherwise what is wrong and where.
std::string simplicity_problem(const Polygon& polygon);

/// Exact orientation of a simple ring: +1 counterclockwise, -1 clockwise (orient2d at the
/// lowest-leftmost vertex, which is convex).
int ring_orientation(const Ring& ring);

/// Twice the signed area, summed in long double.
long double twice_signed_area(const Ring& ring);

}  // namespace pear::testing
