// CGAL's constrained Delaunay triangulation as a peer: the rings go in as constraints, then a
// flood fill over nesting levels keeps the faces inside (odd levels). CGAL 5.5 has no helper
// for the marking, so it is written here, and timed with the rest.
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "peers.hpp"

namespace bench {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
/// The input point number; CGAL's own crossing points (Steiner points) keep `none`.
struct PointId {
  static constexpr std::uint32_t none = UINT32_MAX;
  std::uint32_t index = none;
};
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<PointId, Kernel>;
using LevelFaceBase = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel, LevelFaceBase>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// Exact_predicates_tag: crossing constraints (a non-simple input) get a computed crossing
// point instead of an exception; on simple input it costs nothing.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

/// Faces get their nesting level: 0 outside, 1 inside the outer ring, 2 inside a hole, ...
/// Breadth-first over levels; a constrained edge leads one level deeper.
void mark_nesting_levels(Cdt& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::vector<Cdt::Face_handle> level_seeds = {cdt.infinite_face()};
  std::vector<Cdt::Face_handle> next_seeds;
  std::vector<Cdt::Face_handle> stack;
  for (int level = 0; !level_seeds.empty(); ++level) {
    next_seeds.clear();
    for (Cdt::Face_handle seed : level_seeds) {
      stack.push_back(seed);
      while (!stack.empty()) {
        const Cdt::Face_handle face = stack.back();
        stack.pop_back();
        if (face->info() != -1) continue;
        face->info() = level;
        for (int i = 0; i < 3; ++i) {
          const Cdt::Face_handle neighbour = face->neighbor(i);
          if (neighbour->info() != -1) continue;
          (cdt.is_constrained({face, i}) ? next_seeds : stack).push_back(neighbour);
        }
      }
    }
    std::swap(level_seeds, next_seeds);
  }
}

class CgalPolygon final : public PreparedPolygon {
 public:
  explicit CgalPolygon(const pear::Polygon& polygon) {
    std::uint32_t index = 0;
    for (const auto& ring : polygon) {
      ring_starts_.push_back(index);
      for (const auto& p : ring) points_.push_back({Kernel::Point_2(p.x, p.y), {index++}});
    }
    ring_starts_.push_back(index);
  }

  std::size_t triangulate() override {
    Cdt cdt;
    // Points first (CGAL sorts them along a Hilbert curve), then the ring edges as constraints.
    cdt.insert(points_.begin(), points_.end());
    std::vector<Cdt::Vertex_handle> handles(points_.size());
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
      handles[v->info().index] = v;
    for (std::size_t i = 0; i < handles.size(); ++i)  // repeated points share one vertex
      if (handles[i] == Cdt::Vertex_handle()) handles[i] = cdt.insert(points_[i].first);
    for (std::size_t r = 0; r + 1 < ring_starts_.size(); ++r) {
      const std::uint32_t begin = ring_starts_[r];
      const std::uint32_t end = ring_starts_[r + 1];
      for (std::uint32_t i = begin; i < end; ++i)
        cdt.insert_constraint(handles[i], handles[i + 1 < end ? i + 1 : begin]);
    }
    mark_nesting_levels(cdt);
    triangles_.clear();
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
      if (f->info() % 2 == 0) continue;
      const std::array<std::uint32_t, 3> corners = {
          f->vertex(0)->info().index, f->vertex(1)->info().index, f->vertex(2)->info().index};
      for (std::uint32_t corner : corners)
        if (corner == PointId::none)
          throw std::runtime_error("CGAL added a crossing point: the input is not simple");
      triangles_.push_back(corners);
    }
    return triangles_.size();
  }

  Triangles triangles() const override { return triangles_; }

 private:
  std::vector<std::pair<Kernel::Point_2, PointId>> points_;
  std::vector<std::uint32_t> ring_starts_;
  Triangles triangles_;
};

}  // namespace

std::unique_ptr<PreparedPolygon> prepare_cgal_cdt(const pear::Polygon& polygon) {
  return std::make_unique<CgalPolygon>(polygon);
}

}  // namespace bench
