// Fuzz target "cdt": Options::delaunay on polygons known valid (cells, or rings the exact
// oracle accepts), through any algorithm, 1 to 3 threads. The result must be an exact
// triangulation, pass pear::validate's Delaunay check, and (in builds with the CGAL oracle) have
// the same edges as CGAL's CDT up to cocircular ties: every edge that is strictly Delaunay (its two
// triangles not cocircular) or a ring edge lies in every CDT, so each side's such edges must be
// edges of the other.
//
// Until the flipping lands, Options::delaunay is a no-op: the Delaunay checks run only when the
// result reports interior edges (DelaunayStatistics::edges > 0), so the replay passes honestly
// and the target starts checking the day the CDT is there (docs/fuzzing.md).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "known_polygon.hpp"
#include "pear/predicates.hpp"
#include "polygon_oracle.hpp"
#ifdef PEAR_WITH_CGAL_ORACLE
#include "cgal_cdt.hpp"
#endif

namespace {

#ifdef PEAR_WITH_CGAL_ORACLE
using Segment = std::pair<std::array<double, 2>, std::array<double, 2>>;

Segment segment(const pear::Point& a, const pear::Point& b) {
  return std::minmax(std::array{a.x, a.y}, std::array{b.x, b.y});
}

struct Edges {
  std::vector<Segment> all;     ///< every edge, sorted, repeated once per triangle side
  std::vector<Segment> strict;  ///< ring edges and edges whose triangles are not cocircular
  bool contains(const Segment& s) const { return std::binary_search(all.begin(), all.end(), s); }
};

/// The edges of counterclockwise triangles given by their corners.
Edges edges_of(const pear::testing::PointTriangles& triangles) {
  struct Side {
    Segment segment;
    pear::Point a, b, opposite;
  };
  std::vector<Side> sides;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k)
      sides.push_back({segment(t[k], t[(k + 1) % 3]), t[k], t[(k + 1) % 3], t[(k + 2) % 3]});
  std::sort(sides.begin(), sides.end(),
            [](const Side& s, const Side& t) { return s.segment < t.segment; });
  Edges edges;
  for (std::size_t i = 0; i < sides.size(); ++i) {
    edges.all.push_back(sides[i].segment);
    const bool shared = i + 1 < sides.size() && sides[i + 1].segment == sides[i].segment;
    const bool after_shared = i > 0 && sides[i - 1].segment == sides[i].segment;
    if (after_shared) continue;
    if (!shared ||
        pear::incircle(sides[i].a, sides[i].b, sides[i].opposite, sides[i + 1].opposite) != 0)
      edges.strict.push_back(sides[i].segment);
  }
  return edges;
}

void compare_with_cgal(const pear::Polygon& polygon, const fuzz::Triangles& triangles) {
  // CGAL gets the polygon as pear's contract repairs it (spikes dissolved, T-junctions split):
  // a spike as a constraint would be an edge of its CDT.
  const auto cgal = pear::testing::cgal_cdt_inside(fuzz::repair(polygon));
  if (!cgal) return;
  const std::vector<pear::Point> points = fuzz::flat_points(polygon);
  pear::testing::PointTriangles ours;
  for (const auto& [a, b, c] : triangles) ours.push_back({points[a], points[b], points[c]});
  fuzz::require(ours.size() == cgal->size(), "CGAL's CDT has another triangle count",
                fuzz::describe(polygon));
  const Edges pear_edges = edges_of(ours);
  const Edges cgal_edges = edges_of(*cgal);
  for (const Segment& s : pear_edges.strict)
    fuzz::require(cgal_edges.contains(s), "a strictly Delaunay edge of pear's is not in CGAL's CDT",
                  fuzz::describe(polygon));
  for (const Segment& s : cgal_edges.strict)
    fuzz::require(pear_edges.contains(s), "a strictly Delaunay edge of CGAL's is not in pear's CDT",
                  fuzz::describe(polygon));
}
#endif

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteReader bytes(data, size);
  const std::uint8_t header = bytes.byte();
  pear::Options options;
  options.delaunay = true;
  options.algorithm = static_cast<pear::Algorithm>(1 + (header >> 1) % 4);
  options.threads = 1 + (header >> 3) % 3;
  options.executor = fuzz::shared_executor(options.threads);
  options.partitions = 1 + bytes.byte() % 8;
  const auto known = fuzz::decode_known_polygon(bytes, header & 1);
  if (!known) return 0;
  const pear::Triangulation<> result = pear::triangulate(known->polygon, options);
  const bool flipped = result.delaunay.edges > 0;  // the CDT ran and had edges to consider
  fuzz::check_known(*known, result, flipped);
#ifdef PEAR_WITH_CGAL_ORACLE
  if (flipped && known->valid) compare_with_cgal(known->polygon, result.triangles);
#endif
  return 0;
}
