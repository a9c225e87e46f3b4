// pear internals that the public templates need: a ring range copied into flat arrays.
#pragma once

#include <concepts>
#include <cstdint>
#include <limits>
#include <ranges>
#include <span>
#include <type_traits>
#include <vector>

#include "pear/geometry.hpp"

namespace pear::detail {

/// The polygon as the engine reads it: all points in input order, ring after ring (or, for
/// rings already held as arrays of Points, only where each ring is: `rings`).
struct FlatPolygon {
  std::vector<Point> points;
  std::vector<std::uint32_t> ring_starts;  ///< ring r is [ring_starts[r], ring_starts[r+1])
  std::vector<std::span<const Point>> rings;
  void clear() {
    points.clear();
    ring_starts.clear();
    rings.clear();
  }
};

/// A polygon as its rings' arrays (ring_spans), for the engine: ring r is rings[r], its points
/// numbered from ring_offsets[r]; ring_offsets ends with the count.
struct RingSpans {
  std::span<const std::span<const Point>> rings;
  std::span<const std::uint32_t> ring_offsets;
};

/// Rings whose points lie in arrays of pear::Point (pear::Polygon, a vector of spans): read
/// where they are, ring by ring, never copied into one array first.
template <class Rings>
concept point_array_rings =
    std::ranges::contiguous_range<std::ranges::range_reference_t<const Rings>> &&
    std::same_as<std::ranges::range_value_t<std::ranges::range_reference_t<const Rings>>, Point>;

/// The polygon's rings as spans, and where each starts in the numbering of all the points
/// (one more offset: the count). Returns false when the count exceeds 2^32 - 2.
template <point_array_rings Rings>
bool ring_spans(const Rings& rings, FlatPolygon& flat) {
  flat.clear();
  std::size_t total = 0;
  for (const auto& ring : rings) {
    flat.ring_starts.push_back(static_cast<std::uint32_t>(total));
    flat.rings.emplace_back(std::ranges::data(ring), std::ranges::size(ring));
    total += std::ranges::size(ring);
    if (total >= std::numeric_limits<std::uint32_t>::max()) return false;
  }
  flat.ring_starts.push_back(static_cast<std::uint32_t>(total));
  return true;
}

/// The number of points in a ring range (each ring's size where it has one).
template <ring_range Rings>
std::size_t vertex_count(const Rings& rings) {
  std::size_t count = 0;
  for (const auto& ring : rings) {
    if constexpr (std::ranges::sized_range<decltype(ring)>) {
      count += static_cast<std::size_t>(std::ranges::size(ring));
    } else {
      for ([[maybe_unused]] const auto& point : ring) ++count;
    }
  }
  return count;
}

/// Copies any ring range into a FlatPolygon. Returns false when the count exceeds 2^32 - 2.
template <ring_range Rings>
bool flatten(const Rings& rings, FlatPolygon& flat) {
  flat.clear();
  // Sized rings are counted first, so a first call on a large polygon grows its arrays once.
  if constexpr (std::ranges::sized_range<std::ranges::range_reference_t<const Rings>>) {
    const std::size_t count = vertex_count(rings);
    if (count < std::numeric_limits<std::uint32_t>::max()) flat.points.reserve(count);
  }
  std::size_t total = 0;
  for (const auto& ring : rings) {
    flat.ring_starts.push_back(static_cast<std::uint32_t>(total));
    for (const auto& p : ring) {
      using P = std::remove_cvref_t<decltype(p)>;
      if (++total >= std::numeric_limits<std::uint32_t>::max()) return false;
      flat.points.push_back(Point{point_traits<P>::x(p), point_traits<P>::y(p)});
    }
  }
  flat.ring_starts.push_back(static_cast<std::uint32_t>(total));
  return true;
}

}  // namespace pear::detail
