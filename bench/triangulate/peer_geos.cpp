// GEOS's two polygon triangulators as peers: PolygonTriangulator (ear clipping, holes joined to
// the shell) and ConstrainedDelaunayTriangulator (the same, then Delaunay edge flips).
//
// Debian 12 ships GEOS's C++ library but only the C API's headers. The C API's GEOSGeometry* is
// the C++ geos::geom::Geometry*, so we build and read geometries through the C API and call the
// two static C++ entry points, found by their mangled names at run time:
//   static std::unique_ptr<geom::Geometry> triangulate(const geom::Geometry*);
// A unique_ptr with an empty deleter has the same layout and is returned the same way, so ours
// frees through GEOSGeom_destroy_r (the Geometry destructor is virtual).
#include <dlfcn.h>
#include <geos_c.h>

#include <cstdarg>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "peers.hpp"

namespace geos::geom {
class Geometry;
}

namespace bench {
namespace {

GEOSContextHandle_t context() {
  static GEOSContextHandle_t handle = [] {
    GEOSContextHandle_t h = GEOS_init_r();
    GEOSContext_setErrorMessageHandler_r(
        h, [](const char* message, void*) { std::fprintf(stderr, "GEOS: %s\n", message); },
        nullptr);
    return h;
  }();
  return handle;
}

struct GeosDelete {
  void operator()(geos::geom::Geometry* g) const {
    GEOSGeom_destroy_r(context(), reinterpret_cast<GEOSGeometry*>(g));
  }
};
using GeosGeometry = std::unique_ptr<geos::geom::Geometry, GeosDelete>;
using TriangulateFunction = GeosGeometry (*)(const geos::geom::Geometry*);

TriangulateFunction find_entry(const char* mangled) {
  return reinterpret_cast<TriangulateFunction>(dlsym(RTLD_DEFAULT, mangled));
}

const TriangulateFunction ear_clipping = find_entry(
    "_ZN4geos11triangulate7polygon19PolygonTriangulator11triangulateEPKNS_4geom8GeometryE");
const TriangulateFunction constrained_delaunay = find_entry(
    "_ZN4geos11triangulate7polygon31ConstrainedDelaunayTriangulator11triangulateEPKNS_4geom8"
    "GeometryE");

GEOSGeometry* make_ring(const pear::Ring& ring) {
  std::vector<double> xy;
  xy.reserve(2 * ring.size() + 2);
  for (const auto& p : ring) xy.insert(xy.end(), {p.x, p.y});
  xy.insert(xy.end(), {ring.front().x, ring.front().y});  // GEOS rings are closed
  GEOSCoordSequence* sequence = GEOSCoordSeq_copyFromBuffer_r(
      context(), xy.data(), static_cast<unsigned>(ring.size() + 1), 0, 0);
  return GEOSGeom_createLinearRing_r(context(), sequence);
}

class GeosPolygon final : public PreparedPolygon {
 public:
  GeosPolygon(const pear::Polygon& polygon, TriangulateFunction function)
      : polygon_(polygon), function_(function) {
    std::vector<GEOSGeometry*> holes;
    for (std::size_t r = 1; r < polygon.size(); ++r) holes.push_back(make_ring(polygon[r]));
    input_.reset(reinterpret_cast<geos::geom::Geometry*>(GEOSGeom_createPolygon_r(
        context(), make_ring(polygon[0]), holes.data(), static_cast<unsigned>(holes.size()))));
  }

  std::size_t triangulate() override {
    result_.reset();
    result_ = function_(input_.get());
    if (!result_) throw std::runtime_error("GEOS gave no result");
    return static_cast<std::size_t>(GEOSGetNumGeometries_r(context(), geometry(result_)));
  }

  Triangles triangles() const override {
    const PointIndex index(polygon_);
    Triangles triangles;
    const int count = GEOSGetNumGeometries_r(context(), geometry(result_));
    for (int t = 0; t < count; ++t) {
      const GEOSGeometry* triangle = GEOSGetGeometryN_r(context(), geometry(result_), t);
      const GEOSCoordSequence* corners =
          GEOSGeom_getCoordSeq_r(context(), GEOSGetExteriorRing_r(context(), triangle));
      pear::Point p[3];
      for (unsigned k = 0; k < 3; ++k)
        GEOSCoordSeq_getXY_r(context(), corners, k, &p[k].x, &p[k].y);
      triangles.push_back(index.triangle(p[0], p[1], p[2]));
    }
    return triangles;
  }

 private:
  static GEOSGeometry* geometry(const GeosGeometry& g) {
    return reinterpret_cast<GEOSGeometry*>(g.get());
  }

  const pear::Polygon& polygon_;
  TriangulateFunction function_;
  GeosGeometry input_;
  GeosGeometry result_;
};

}  // namespace

bool geos_available(std::string& why_not) {
  if (ear_clipping != nullptr && constrained_delaunay != nullptr) return true;
  why_not = "this GEOS library lacks the C++ polygon triangulators (GEOS >= 3.10)";
  return false;
}

std::unique_ptr<PreparedPolygon> prepare_geos_ear(const pear::Polygon& polygon) {
  return std::make_unique<GeosPolygon>(polygon, ear_clipping);
}
std::unique_ptr<PreparedPolygon> prepare_geos_cdt(const pear::Polygon& polygon) {
  return std::make_unique<GeosPolygon>(polygon, constrained_delaunay);
}

}  // namespace bench
