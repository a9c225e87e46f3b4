// The OpenGL Utility library's tessellator (SGI's sweep-line monotone decomposition, Debian
// libglu1-mesa) as a peer. Odd winding keeps the outer ring minus the holes; the edge-flag
// callback makes it emit plain triangles instead of fans and strips. It is timed from
// gluNewTess to gluDeleteTess, with the callbacks that collect the triangles.
#include <GL/glu.h>

#include <array>
#include <cstdint>
#include <deque>
#include <stdexcept>
#include <string>
#include <vector>

#include "pear/predicates.hpp"
#include "peers.hpp"

namespace bench {
namespace {

constexpr std::uint32_t steiner = UINT32_MAX;

#ifndef CALLBACK
#define CALLBACK
#endif
using Callback = void(CALLBACK*)();

class GluPolygon final : public PreparedPolygon {
 public:
  explicit GluPolygon(const pear::Polygon& polygon) : polygon_(polygon) {
    for (const auto& ring : polygon)
      for (const auto& p : ring) {
        coordinates_.push_back({p.x, p.y, 0.0});
        ids_.push_back(static_cast<std::uint32_t>(ids_.size()));
      }
  }

  std::size_t triangulate() override {
    corners_.clear();
    added_.clear();
    error_ = 0;
    GLUtesselator* tess = gluNewTess();
    if (tess == nullptr) throw std::runtime_error("GLU: gluNewTess failed");
    gluTessProperty(tess, GLU_TESS_WINDING_RULE, GLU_TESS_WINDING_ODD);
    gluTessNormal(tess, 0, 0, 1);
    gluTessCallback(tess, GLU_TESS_VERTEX_DATA, reinterpret_cast<Callback>(&on_vertex));
    gluTessCallback(tess, GLU_TESS_EDGE_FLAG_DATA, reinterpret_cast<Callback>(&on_edge_flag));
    gluTessCallback(tess, GLU_TESS_COMBINE_DATA, reinterpret_cast<Callback>(&on_combine));
    gluTessCallback(tess, GLU_TESS_ERROR_DATA, reinterpret_cast<Callback>(&on_error));
    gluTessBeginPolygon(tess, this);
    std::size_t index = 0;
    for (const auto& ring : polygon_) {
      gluTessBeginContour(tess);
      for (std::size_t k = 0; k < ring.size(); ++k, ++index)
        gluTessVertex(tess, coordinates_[index].data(), &ids_[index]);
      gluTessEndContour(tess);
    }
    gluTessEndPolygon(tess);
    gluDeleteTess(tess);
    if (error_ != 0)
      throw std::runtime_error(std::string("GLU: ") +
                               reinterpret_cast<const char*>(gluErrorString(error_)));
    return corners_.size() / 3;
  }

  Triangles triangles() const override {
    Triangles out;
    std::vector<pear::Point> points;
    for (const auto& ring : polygon_) points.insert(points.end(), ring.begin(), ring.end());
    for (std::size_t t = 0; t + 2 < corners_.size(); t += 3) {
      std::array<std::uint32_t, 3> tri = {corners_[t], corners_[t + 1], corners_[t + 2]};
      for (const std::uint32_t c : tri)
        if (c == steiner) throw std::runtime_error("GLU added a crossing point (a Steiner point)");
      if (pear::orient2d(points[tri[0]], points[tri[1]], points[tri[2]]) < 0)
        std::swap(tri[1], tri[2]);
      out.push_back(tri);
    }
    return out;
  }

 private:
  static void CALLBACK on_vertex(void* vertex, void* self) {
    static_cast<GluPolygon*>(self)->corners_.push_back(*static_cast<std::uint32_t*>(vertex));
  }
  static void CALLBACK on_edge_flag(GLboolean, void*) {}
  static void CALLBACK on_error(GLenum error, void* self) {
    static_cast<GluPolygon*>(self)->error_ = error;
  }
  /// Called where vertices coincide or edges cross: an input point at exactly the new place
  /// keeps its number (repeated vertices); anything else is a Steiner point.
  static void CALLBACK on_combine(GLdouble coords[3], void* data[4], GLfloat[4], void** out,
                                  void* self) {
    auto& polygon = *static_cast<GluPolygon*>(self);
    for (int k = 0; k < 4; ++k) {
      if (data[k] == nullptr || *static_cast<std::uint32_t*>(data[k]) == steiner) continue;
      const auto& c = polygon.coordinates_[*static_cast<std::uint32_t*>(data[k])];
      if (c[0] == coords[0] && c[1] == coords[1]) {
        *out = data[k];
        return;
      }
    }
    polygon.added_.push_back(steiner);
    *out = &polygon.added_.back();
  }

  const pear::Polygon& polygon_;
  std::vector<std::array<GLdouble, 3>> coordinates_;
  std::vector<std::uint32_t> ids_;
  std::deque<std::uint32_t> added_;
  std::vector<std::uint32_t> corners_;
  GLenum error_ = 0;
};

}  // namespace

std::unique_ptr<PreparedPolygon> prepare_glu(const pear::Polygon& polygon) {
  return std::make_unique<GluPolygon>(polygon);
}

}  // namespace bench
