// The triangulators measured by bench_triangulate: pear and the peers found at build time.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
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
  /// Extra numbers about the last run, reported as benchmark counters (pear: CDT flips).
  virtual std::map<std::string, double> statistics() const { return {}; }
};

struct Triangulator {
  /// pear_top, pear_fast, pear_cdt (sequential, top heuristic, then flips), pear_ALG_tN[_cdt]
  /// (ALG = pc, mc, dc, auto; N threads and partitions), cgal_cdt, geos_ear, geos_cdt, glu.
  std::string name;
  /// Converts the polygon to the triangulator's input form (not timed). The polygon outlives it.
  std::function<std::unique_ptr<PreparedPolygon>(const pear::Polygon&)> prepare;
  unsigned threads = 1;  ///< threads the triangulator runs on (the peers: 1)
};

/// pear's sequential engine, CDT and parallel variants at 1, 2, 4, 8 and 16 threads, then the peers
/// compiled in and available at run time.
std::vector<Triangulator> triangulators();

std::vector<Triangulator> pear_triangulators();
#ifdef PEAR_WITH_CGAL_ORACLE
std::unique_ptr<PreparedPolygon> prepare_cgal_cdt(const pear::Polygon& polygon);
#endif
#ifdef PEAR_BENCH_WITH_GEOS
/// Empty when the GEOS library lacks the C++ entry points (see peer_geos.cpp).
bool geos_available(std::string& why_not);
std::unique_ptr<PreparedPolygon> prepare_geos_ear(const pear::Polygon& polygon);
std::unique_ptr<PreparedPolygon> prepare_geos_cdt(const pear::Polygon& polygon);
#endif
#ifdef PEAR_BENCH_WITH_GLU
std::unique_ptr<PreparedPolygon> prepare_glu(const pear::Polygon& polygon);
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
