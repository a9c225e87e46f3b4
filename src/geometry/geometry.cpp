#include <string>

#include "pear/geometry.hpp"

namespace pear {

const char* to_string(Status status) {
  switch (status) {
    case Status::ok:
      return "ok";
    case Status::not_simple:
      return "not_simple";
    case Status::invalid_input:
      return "invalid_input";
    case Status::index_overflow:
      return "index_overflow";
  }
  return "unknown";
}

const char* to_string(Issue issue) {
  switch (issue) {
    case Issue::empty_input:
      return "empty_input";
    case Issue::non_finite_coordinate:
      return "non_finite_coordinate";
    case Issue::coordinate_out_of_range:
      return "coordinate_out_of_range";
    case Issue::outer_ring_too_small:
      return "outer_ring_too_small";
    case Issue::hole_dropped_too_small:
      return "hole_dropped_too_small";
    case Issue::hole_dropped_zero_area:
      return "hole_dropped_zero_area";
    case Issue::index_overflow:
      return "index_overflow";
    case Issue::not_simple:
      return "not_simple";
    case Issue::invalid_offsets:
      return "invalid_offsets";
    case Issue::invalid_options:
      return "invalid_options";
    case Issue::spike_dissolved:
      return "spike_dissolved";
    case Issue::t_junction_split:
      return "t_junction_split";
    case Issue::hole_outside_outer_ring:
      return "hole_outside_outer_ring";
    case Issue::hole_inside_hole:
      return "hole_inside_hole";
  }
  return "unknown";
}

namespace {
const char* explain(Issue issue) {
  switch (issue) {
    case Issue::empty_input:
      return "the polygon has no rings";
    case Issue::non_finite_coordinate:
      return "coordinate is NaN or infinite";
    case Issue::coordinate_out_of_range:
      return "coordinate magnitude is outside [2^-200, 2^200] (and not zero)";
    case Issue::outer_ring_too_small:
      return "outer ring has fewer than 3 distinct points or zero area";
    case Issue::hole_dropped_too_small:
      return "hole has fewer than 3 distinct points; ignored";
    case Issue::hole_dropped_zero_area:
      return "hole has zero area; ignored";
    case Issue::index_overflow:
      return "vertex count does not fit the index type";
    case Issue::not_simple:
      return "rings cross or overlap near here; the triangulation is a best effort";
    case Issue::invalid_offsets:
      return "offsets must start at 0, never decrease, and end at the number of points";
    case Issue::invalid_options:
      return "Options::threads is above pear::max_threads (4096)";
    case Issue::spike_dissolved:
      return "the ring folds back here (a zero-width spike); its tip is dropped";
    case Issue::t_junction_split:
      return "vertex lies inside an edge; the edge is split there and the vertex used on both "
             "sides";
    case Issue::hole_outside_outer_ring:
      return "hole lies outside the outer ring; the triangulation is a best effort";
    case Issue::hole_inside_hole:
      return "hole lies inside another hole; the triangulation is a best effort";
  }
  return "unknown issue";
}
}  // namespace

std::string describe(const Diagnostic& d) {
  return "ring " + std::to_string(d.ring) + ", vertex " + std::to_string(d.vertex) + ": " +
         explain(d.issue);
}

}  // namespace pear
