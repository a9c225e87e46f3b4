#include "known_polygon.hpp"

#include "cell_polygon.hpp"
#include "polygon_oracle.hpp"
#include "ring_bytes.hpp"

namespace fuzz {

std::optional<KnownPolygon> decode_known_polygon(ByteReader& bytes, bool from_rings) {
  KnownPolygon known;
  if (from_rings) {
    known.polygon = decode_rings(bytes, bytes.byte());
    const PolygonFacts facts = examine(known.polygon);
    known.valid = facts.valid;
    known.triangles = facts.vertices + 2 * facts.holes - 2 - 2 * facts.repeated_points;
    known.twice_area = facts.twice_area;
    return known;
  }
  auto cells = decode_cell_polygon(bytes);
  if (!cells) return std::nullopt;
  known.polygon = std::move(cells->polygon);
  known.valid = true;
  known.triangles = cells->triangles;
  known.twice_area = twice_polygon_area(known.polygon);
  return known;
}

void check_known(const KnownPolygon& known, const pear::Triangulation<>& result,
                 bool check_delaunay) {
  check_any_result(known.polygon, result, check_delaunay);
  if (known.valid)
    check_exact_triangulation(known.polygon, result, known.triangles, known.twice_area);
}

}  // namespace fuzz
