// CGAL's constrained Delaunay triangulation of a polygon, the one oracle of the CDT tests, the
// fuzz targets and bench's cgal_cdt peer: the rings go in as constraints, and a flood fill over
// nesting levels keeps the faces inside (odd levels). CGAL 5.5 has no helper for the marking.
// Built only when CGAL, GMP and MPFR are found; its users then see PEAR_WITH_CGAL_ORACLE.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "pear/geometry.hpp"

namespace pear::testing {

class CgalCdt {
 public:
  using Triangles = std::vector<std::array<std::uint32_t, 3>>;

  /// Converts the points (not part of a timed triangulate()).
  explicit CgalCdt(const Polygon& polygon);
  ~CgalCdt();
  CgalCdt(CgalCdt&&) noexcept;
  CgalCdt& operator=(CgalCdt&&) noexcept;

  /// Triangulates again, keeping the triangles inside, and returns their count. Throws
  /// std::runtime_error when CGAL adds a point where constraints cross (the input is not
  /// simple), and passes CGAL's own exceptions on.
  std::size_t triangulate();
  /// The last result: counterclockwise index triples into the polygon's points numbered ring
  /// after ring; a point repeated under several indices appears under one of them.
  const Triangles& triangles() const;

 private:
  struct Input;
  std::unique_ptr<Input> input_;
  Triangles triangles_;
};

using PointTriangles = std::vector<std::array<Point, 3>>;

/// The CDT's triangles inside the polygon as corner points, for inputs of any kind (repeated
/// points, rings of one or two points): nullopt when CGAL threw or added a point of its own (the
/// oracle is fallible: CGAL has failed on touching constraints; the caller then skips).
std::optional<PointTriangles> cgal_cdt_inside(const Polygon& polygon);

}  // namespace pear::testing
