// Fuzz target "degenerate": rings decoded from the bytes (ring_bytes.hpp), on a small grid
// (collinear runs, repeated points, touching vertices, zero-area spikes; with header bit 5,
// vertices moved exactly onto other edges: T-junctions) or as doubles of any magnitude. Every
// result passes check_any_result; coordinates pear must refuse give invalid_input; a polygon the
// exact oracle (polygon_oracle.hpp) finds valid must come back ok with n + 2h - 2 - 2m triangles
// covering exactly its area, the area CGAL's CDT covers too.
#include <cstddef>
#include <cstdint>

#include "polygon_oracle.hpp"
#include "ring_bytes.hpp"
#include "support.hpp"
#ifdef PEAR_WITH_CGAL_ORACLE
#include "cgal_cdt.hpp"
#endif

namespace {

// Header bits above the coordinate mode.
constexpr unsigned keep_non_finite = 4;
constexpr unsigned fast_heuristic = 8;
constexpr unsigned reuse_triangulator = 16;

void check_valid_polygon(const pear::Polygon& polygon, const fuzz::PolygonFacts& facts,
                         const pear::Triangulation<>& result) {
  const std::size_t expected = facts.vertices + 2 * facts.holes - 2 - 2 * facts.repeated_points;
  fuzz::check_exact_triangulation(polygon, result, expected, facts.twice_area);
#ifdef PEAR_WITH_CGAL_ORACLE
  // As pear's contract repairs it: a spike as a constraint would be an edge in CGAL's CDT.
  const auto cgal = pear::testing::cgal_cdt_inside(fuzz::repair(polygon));
  if (!cgal) return;
  mpq_class cgal_area = 0;
  for (const auto& [a, b, c] : *cgal) cgal_area += fuzz::twice_area(a, b, c);
  fuzz::require(cgal_area == facts.twice_area, "CGAL's CDT covers another area than pear",
                fuzz::describe(polygon));
#endif
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteReader bytes(data, size);
  const std::uint8_t header = bytes.byte();
  const pear::Polygon polygon = fuzz::decode_rings(bytes, header, header & keep_non_finite);
  pear::Options options;
  options.heuristic = header & fast_heuristic ? pear::EarHeuristic::fast : pear::EarHeuristic::top;
  const pear::Triangulation<> result = pear::triangulate(polygon, options);
  fuzz::check_any_result(polygon, result);
  if (header &
      reuse_triangulator) {  // buffers kept from earlier inputs must not leak into this one
    static pear::Triangulator reused;
    const pear::Triangulation<> again = reused.triangulate(polygon, options);
    fuzz::require(again.status == result.status && again.triangles == result.triangles,
                  "a reused Triangulator answers differently", fuzz::describe(polygon));
  }
  const fuzz::PolygonFacts facts = fuzz::examine(polygon);
  if (polygon.empty() || !facts.coordinates_in_range)
    fuzz::require(result.status == pear::Status::invalid_input,
                  "refused coordinates or no rings, yet not invalid_input",
                  fuzz::describe(polygon));
  if (facts.valid) check_valid_polygon(polygon, facts, result);
  return 0;
}
