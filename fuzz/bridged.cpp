// Fuzz target "bridged": polygons with many holes that are valid by construction
// (cell_polygon.hpp: holes, corners touching, rings touching themselves, collinear runs), so
// every result must be Status::ok, valid, with the construction's triangle count and exact area.
// The simplicity check may be off: a valid polygon must triangulate the same way without it,
// unless a hole stands on an edge (a T-junction, which only the check finds and splits).
#include <cstddef>
#include <cstdint>

#include "cell_polygon.hpp"
#include "support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteReader bytes(data, size);
  const std::uint8_t header = bytes.byte();
  const auto cells = fuzz::decode_cell_polygon(bytes);
  if (!cells) return 0;
  pear::Options options;
  options.heuristic = header & 1 ? pear::EarHeuristic::fast : pear::EarHeuristic::top;
  // Without the check, a vertex inside an edge is not split (README): only without T-junctions.
  options.check_simplicity = !(header & 2) || cells->t_junctions > 0;
  const pear::Triangulation<> result = pear::triangulate(cells->polygon, options);
  fuzz::check_any_result(cells->polygon, result);
  fuzz::check_exact_triangulation(cells->polygon, result, cells->triangles,
                                  fuzz::twice_polygon_area(cells->polygon));
  return 0;
}
