#include "cgal_cdt.hpp"

#ifdef PEAR_FUZZ_WITH_CGAL
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>

#include <algorithm>
#include <deque>
#include <utility>
#endif

namespace fuzz {

#ifndef PEAR_FUZZ_WITH_CGAL

bool have_cgal() {
  return false;
}
std::optional<PointTriangles> cgal_cdt_inside(const pear::Polygon&) {
  return std::nullopt;
}

#else

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using LevelFace = CGAL::Triangulation_face_base_with_info_2<int, Kernel>;
using Face = CGAL::Constrained_triangulation_face_base_2<Kernel, LevelFace>;
using Tds = CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_2<Kernel>, Face>;
// Exact_predicates_tag: crossing constraints get an intersection point instead of an exception.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

/// Each face's level is the fewest constraints crossed to reach it from the infinite face
/// (0-1 breadth-first search): 1 inside the outer ring, 2 inside a hole.
void assign_levels(Cdt& cdt) {
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
  std::deque<std::pair<Cdt::Face_handle, int> > queue = {{cdt.infinite_face(), 0}};
  while (!queue.empty()) {
    const auto [face, level] = queue.front();
    queue.pop_front();
    if (face->info() != -1) continue;
    face->info() = level;
    for (int i = 0; i < 3; ++i) {
      const Cdt::Face_handle next = face->neighbor(i);
      if (next->info() != -1) continue;
      if (cdt.is_constrained({face, i}))
        queue.emplace_back(next, level + 1);
      else
        queue.emplace_front(next, level);
    }
  }
}

std::optional<PointTriangles> triangulate_inside(const pear::Polygon& polygon) {
  Cdt cdt;
  std::vector<Kernel::Point_2> distinct;
  for (const pear::Ring& ring : polygon) {
    std::vector<Cdt::Vertex_handle> corners;
    for (const pear::Point& p : ring) {
      corners.push_back(cdt.insert(Kernel::Point_2(p.x, p.y)));
      distinct.push_back(corners.back()->point());
    }
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const Cdt::Vertex_handle next = corners[(i + 1) % corners.size()];
      if (corners[i] != next) cdt.insert_constraint(corners[i], next);
    }
  }
  std::sort(distinct.begin(), distinct.end());
  const auto points = std::unique(distinct.begin(), distinct.end()) - distinct.begin();
  if (cdt.number_of_vertices() != static_cast<std::size_t>(points)) return std::nullopt;
  assign_levels(cdt);
  PointTriangles inside;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info() % 2 == 0) continue;
    auto& triangle = inside.emplace_back();
    for (int k = 0; k < 3; ++k)
      triangle[k] = {f->vertex(k)->point().x(), f->vertex(k)->point().y()};
  }
  return inside;
}

}  // namespace

bool have_cgal() {
  return true;
}

std::optional<PointTriangles> cgal_cdt_inside(const pear::Polygon& polygon) {
  try {
    return triangulate_inside(polygon);
  } catch (...) {  // CGAL's failures are exceptions; the oracle declines, pear is not blamed
    return std::nullopt;
  }
}

#endif

}  // namespace fuzz
