// pear: points, rings and polygons, and how any user point type is read.
#pragma once

#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <ranges>
#include <string>
#include <utility>
#include <vector>

#include "pear/export.hpp"

namespace pear {

/// A point in the plane. An aggregate, so `Point{1.0, 2.0}` works.
struct Point {
  double x;
  double y;
  friend bool operator==(const Point&, const Point&) = default;
};

/// A ring: a closed chain of points. The closing point may or may not be repeated.
using Ring = std::vector<Point>;
/// A polygon: the outer ring first, then the holes. Either orientation is accepted.
using Polygon = std::vector<Ring>;

/// Customization point: how pear reads the coordinates of a user's point type.
/// Specialize `point_traits<P>` with `static double x(const P&)` and `static double y(const P&)`
/// for a type that has neither `.x/.y` members nor is a `std::array`/`std::pair` of two numbers.
template <class P>
struct point_traits;

template <class P>
concept has_xy_members = requires(const P& p) {
  { p.x } -> std::convertible_to<double>;
  { p.y } -> std::convertible_to<double>;
};

template <has_xy_members P>
struct point_traits<P> {
  static double x(const P& p) { return static_cast<double>(p.x); }
  static double y(const P& p) { return static_cast<double>(p.y); }
};

template <class T>
struct point_traits<std::array<T, 2>> {
  static double x(const std::array<T, 2>& p) { return static_cast<double>(p[0]); }
  static double y(const std::array<T, 2>& p) { return static_cast<double>(p[1]); }
};

template <class T>
struct point_traits<std::pair<T, T>> {
  static double x(const std::pair<T, T>& p) { return static_cast<double>(p.first); }
  static double y(const std::pair<T, T>& p) { return static_cast<double>(p.second); }
};

/// A type pear can read as a point.
template <class P>
concept point_like = requires(const P& p) {
  { point_traits<P>::x(p) } -> std::convertible_to<double>;
  { point_traits<P>::y(p) } -> std::convertible_to<double>;
};

/// A range of rings, each a range of point_like values: `std::vector<std::vector<Vec2>>`,
/// `std::span<const std::vector<std::array<float,2>>>`, and so on.
template <class R>
concept ring_range = std::ranges::forward_range<R> &&
    std::ranges::forward_range<std::ranges::range_reference_t<R>> && point_like<
        std::remove_cvref_t<std::ranges::range_reference_t<std::ranges::range_reference_t<R>>>>;

/// Coordinates must lie in this magnitude range (or be zero): there the exact predicates can
/// neither overflow nor underflow. 2^200 and 2^-200.
inline constexpr double max_coordinate = 0x1p200;
inline constexpr double min_nonzero_coordinate = 0x1p-200;

/// Overall outcome of a triangulation.
enum class Status : std::uint8_t {
  ok,              ///< valid triangulation of the (cleaned) input
  not_simple,      ///< input is not a simple polygon; a best-effort triangulation is returned
  invalid_input,   ///< nothing triangulated: empty input, NaN/inf, out-of-range coordinates, ...
  index_overflow,  ///< the vertex count does not fit the requested index type
};

/// What a diagnostic is about.
enum class Issue : std::uint8_t {
  empty_input,              ///< no rings at all (error)
  non_finite_coordinate,    ///< NaN or infinity (error)
  coordinate_out_of_range,  ///< |c| > 2^200 or 0 < |c| < 2^-200 (error)
  outer_ring_too_small,     ///< outer ring has fewer than 3 distinct points or zero area (error)
  hole_dropped_too_small,   ///< a hole with fewer than 3 distinct points was ignored (warning)
  hole_dropped_zero_area,   ///< a hole with zero area was ignored (warning)
  index_overflow,           ///< more vertices than the index type can number (error)
  not_simple,               ///< rings cross or overlap; result is best effort (warning)
  invalid_offsets,          ///< ring (or polygon) offsets out of order or past the points (error)
  invalid_options,          ///< Options out of range: threads above max_threads (error)
  spike_dissolved,   ///< a zero-width spike's tip (the ring folds back on itself) was dropped,
                     ///< the boundary and area unchanged; the tip is not used (warning)
  t_junction_split,  ///< the vertex lies inside an edge (of its own or another ring): the edge
                     ///< is split there and the vertex used on both sides (warning)
  hole_outside_outer_ring,  ///< the hole is not inside the outer ring (not_simple)
  hole_inside_hole,         ///< the hole lies inside another hole (not_simple)
};

/// One finding about the input, naming the ring (0 = outer) and the vertex index within that ring
/// (the caller's numbering, before any cleaning).
struct Diagnostic {
  Issue issue;
  std::size_t ring = 0;
  std::size_t vertex = 0;

  /// Whether it says the input is not a valid polygon here (Status::not_simple's reasons).
  bool is_not_simple() const {
    return issue == Issue::not_simple || issue == Issue::hole_outside_outer_ring ||
           issue == Issue::hole_inside_hole;
  }

  bool is_error() const {
    return issue == Issue::empty_input || issue == Issue::non_finite_coordinate ||
           issue == Issue::coordinate_out_of_range || issue == Issue::outer_ring_too_small ||
           issue == Issue::index_overflow || issue == Issue::invalid_offsets ||
           issue == Issue::invalid_options;
  }
};

/// Short machine-readable name of a status ("ok", "not_simple", ...).
PEAR_API const char* to_string(Status status);
/// Short machine-readable name of an issue.
PEAR_API const char* to_string(Issue issue);
/// A sentence for people: "ring 2, vertex 17: coordinate is NaN or infinite".
PEAR_API std::string describe(const Diagnostic& diagnostic);

}  // namespace pear
