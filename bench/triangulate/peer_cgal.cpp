// CGAL's constrained Delaunay triangulation as a peer: the one CGAL oracle of the tests and fuzz
// targets (tests/support/cgal_cdt.hpp), the nesting-level flood fill timed with the rest.
#include "cgal_cdt.hpp"
#include "peers.hpp"

namespace bench {
namespace {

class CgalPolygon final : public PreparedPolygon {
 public:
  explicit CgalPolygon(const pear::Polygon& polygon) : cdt_(polygon) {}
  std::size_t triangulate() override { return cdt_.triangulate(); }
  Triangles triangles() const override { return cdt_.triangles(); }

 private:
  pear::testing::CgalCdt cdt_;
};

}  // namespace

std::unique_ptr<PreparedPolygon> prepare_cgal_cdt(const pear::Polygon& polygon) {
  return std::make_unique<CgalPolygon>(polygon);
}

}  // namespace bench
