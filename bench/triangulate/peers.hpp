// The triangulators measured by bench_triangulate: pear and the peers found at build time.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "pear/geometry.hpp"

namespace bench {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

/// One polygon in a triangulator's own input form, ready to be triangulated again and again.
class PreparedPolygon {
 public:
  virtual ~PreparedPolygon() = default;
  /// The timed part: triangulates, keeps the result (dropping the previous one), and returns
  /// the triangle count. Throws std::runtime_error when the triangulator fails.
  virtual std::size_t triangulate() = 0;
  /// The last result as counterclockwise index triples into the polygon's points numbered ring
  /// after ring (not timed).
  virtual Triangles triangles() const = 0;
};

struct Triangulator {
  std::string name;
  /// Converts the polygon to the triangulator's input form (not timed). The polygon outlives it.
  std::unique_ptr<PreparedPolygon> (*prepare)(const pear::Polygon& polygon);
};

/// pear's sequential engine with the "fast" and the "top" ear heuristics, then the peers
/// compiled in and available at run time.
std::vector<Triangulator> triangulators();

std::unique_ptr<PreparedPolygon> prepare_pear_fast(const pear::Polygon& polygon);
std::unique_ptr<PreparedPolygon> prepare_pear_top(const pear::Polygon& polygon);
#ifdef PEAR_BENCH_WITH_CGAL
std::unique_ptr<PreparedPolygon> prepare_cgal_cdt(const pear::Polygon& polygon);
#endif
#ifdef PEAR_BENCH_WITH_GEOS
/// Empty when the GEOS library lacks the C++ entry points (see peer_geos.cpp).
bool geos_available(std::string& why_not);
std::unique_ptr<PreparedPolygon> prepare_geos_ear(const pear::Polygon& polygon);
std::unique_ptr<PreparedPolygon> prepare_geos_cdt(const pear::Polygon& polygon);
#endif

/// Maps triangles given by coordinates back to the polygon's point numbering (ring after ring),
/// ordering each counterclockwise. Throws when a corner is not an input point.
class PointIndex {
 public:
  explicit PointIndex(const pear::Polygon& polygon);
  std::uint32_t at(const pear::Point& p) const;
  std::array<std::uint32_t, 3> triangle(const pear::Point& a, const pear::Point& b,
                                        const pear::Point& c) const;

 private:
  std::vector<std::pair<pear::Point, std::uint32_t>> sorted_;
};

}  // namespace bench
