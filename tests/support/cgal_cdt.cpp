#include "cgal_cdt.hpp"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace pear::testing {

/// The input point number; CGAL's own crossing points (Steiner points) keep `none`. Outside the
/// anonymous namespace: CgalCdt::Input, which has external linkage, holds them.
struct CgalPointId {
  static constexpr std::uint32_t none = UINT32_MAX;
  std::uint32_t index = none;
};

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using PointId = CgalPointId;
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

}  // namespace

struct CgalCdt::Input {
  std::vector<std::pair<Kernel::Point_2, PointId>> points;
  std::vector<std::uint32_t> ring_starts;
  std::size_t distinct_points = 0;  ///< repeated points are one vertex in CGAL
};

CgalCdt::CgalCdt(const Polygon& polygon) : input_(std::make_unique<Input>()) {
  std::uint32_t index = 0;
  std::vector<Point> sorted;
  for (const Ring& ring : polygon) {
    input_->ring_starts.push_back(index);
    for (const Point& p : ring) {
      input_->points.push_back({Kernel::Point_2(p.x, p.y), {index++}});
      sorted.push_back(p);
    }
  }
  input_->ring_starts.push_back(index);
  const auto less = [](const Point& a, const Point& b) {
    return std::pair{a.x, a.y} < std::pair{b.x, b.y};
  };
  std::sort(sorted.begin(), sorted.end(), less);
  input_->distinct_points = std::unique(sorted.begin(), sorted.end()) - sorted.begin();
}

CgalCdt::~CgalCdt() = default;
CgalCdt::CgalCdt(CgalCdt&&) noexcept = default;
CgalCdt& CgalCdt::operator=(CgalCdt&&) noexcept = default;

std::size_t CgalCdt::triangulate() {
  const auto& points = input_->points;
  const auto& ring_starts = input_->ring_starts;
  Cdt cdt;
  // Points first (CGAL sorts them along a Hilbert curve), then the ring edges as constraints.
  cdt.insert(points.begin(), points.end());
  std::vector<Cdt::Vertex_handle> handles(points.size());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    handles[v->info().index] = v;
  for (std::size_t i = 0; i < handles.size(); ++i)  // repeated points share one vertex
    if (handles[i] == Cdt::Vertex_handle()) handles[i] = cdt.insert(points[i].first);
  for (std::size_t r = 0; r + 1 < ring_starts.size(); ++r) {
    const std::uint32_t begin = ring_starts[r];
    const std::uint32_t end = ring_starts[r + 1];
    for (std::uint32_t i = begin; i < end; ++i) {
      const Cdt::Vertex_handle next = handles[i + 1 < end ? i + 1 : begin];
      if (handles[i] != next) cdt.insert_constraint(handles[i], next);  // CGAL fails on length 0
    }
  }
  if (cdt.number_of_vertices() != input_->distinct_points)
    throw std::runtime_error("CGAL added a crossing point: the input is not simple");
  mark_nesting_levels(cdt);
  triangles_.clear();
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->info() % 2 == 1)
      triangles_.push_back(
          {f->vertex(0)->info().index, f->vertex(1)->info().index, f->vertex(2)->info().index});
  return triangles_.size();
}

const CgalCdt::Triangles& CgalCdt::triangles() const {
  return triangles_;
}

std::optional<PointTriangles> cgal_cdt_inside(const Polygon& polygon) {
  std::vector<Point> points;
  for (const Ring& ring : polygon) points.insert(points.end(), ring.begin(), ring.end());
  PointTriangles inside;
  try {
    CgalCdt cdt(polygon);
    cdt.triangulate();
    for (const auto& [a, b, c] : cdt.triangles())
      inside.push_back({points[a], points[b], points[c]});
  } catch (...) {  // CGAL's failures are exceptions; the oracle declines, pear is not blamed
    return std::nullopt;
  }
  return inside;
}

}  // namespace pear::testing
