// pear.validate, pear.quality and the exact predicates orient2d and incircle.
#include <pybind11/stl.h>

#include <limits>
#include <string>

#include "arrays.hpp"
#include "pear/predicates.hpp"
#include "pear/quality.hpp"
#include "pear/validate.hpp"

namespace pear::python {
namespace {

/// A polygon's points and ring offsets from coordinates and ring ends, or from a shapely
/// Polygon (its coordinates, rings closed).
struct PolygonInput {
  std::vector<Point> points;
  std::vector<std::uint32_t> ring_offsets;
};

PolygonInput polygon_input(py::handle polygon, py::handle ring_ends) {
  PolygonInput in;
  if (is_geometry(polygon)) {
    if (!ring_ends.is_none())
      throw py::type_error("ring_ends goes with coordinates, not with a shapely geometry");
    const FlatPolygons flat = geometry_polygons(polygon);
    if (flat.polygon_offsets.size() == 1) {  // an empty geometry: as empty coordinates
      in.ring_offsets.assign(1, 0);
      return in;
    }
    if (flat.polygon_offsets.size() != 2)
      throw py::value_error("validate takes one Polygon; this geometry has " +
                            std::to_string(flat.polygon_offsets.size() - 1) + " polygons");
    for (std::size_t i = 0; i < flat.coordinates.size(); i += 2)
      in.points.push_back({flat.coordinates[i], flat.coordinates[i + 1]});
    for (std::int64_t offset : flat.ring_offsets)
      in.ring_offsets.push_back(static_cast<std::uint32_t>(offset));
    return in;
  }
  const Coordinates array = as_coordinates(polygon, "polygon");
  const auto n = static_cast<std::size_t>(array.shape(0));
  for (std::size_t i = 0; i < n; ++i) in.points.push_back({array.at(i, 0), array.at(i, 1)});
  ring_offsets_from(ring_ends, n, in.ring_offsets);
  return in;
}

/// All points of coords: an (N, 2) array-like or any shapely geometry's coordinates.
std::vector<Point> points_of(py::handle coords) {
  std::vector<Point> points;
  if (is_geometry(coords)) {
    const FlatPolygons flat = geometry_polygons(coords);
    for (std::size_t i = 0; i < flat.coordinates.size(); i += 2)
      points.push_back({flat.coordinates[i], flat.coordinates[i + 1]});
    return points;
  }
  const Coordinates array = as_coordinates(coords);
  for (py::ssize_t i = 0; i < array.shape(0); ++i)
    points.push_back({array.at(i, 0), array.at(i, 1)});
  return points;
}

ValidationReport validate_triangles(py::handle polygon, py::handle triangles, py::handle ring_ends,
                                    py::handle check_delaunay, py::handle allow_zero_area,
                                    py::handle check_count, py::handle max_messages) {
  ValidateOptions options;
  options.check_delaunay = bool_argument(check_delaunay, "check_delaunay");
  options.allow_zero_area = bool_argument(allow_zero_area, "allow_zero_area");
  options.check_count = bool_argument(check_count, "check_count");
  options.max_messages = static_cast<std::size_t>(
      count_argument(max_messages, "max_messages", std::numeric_limits<long>::max()));
  const PolygonInput in = polygon_input(polygon, ring_ends);
  const std::vector<Triangle> indices = triangles_from(triangles, in.points.size());
  py::gil_scoped_release release;
  return validate(PolygonView{in.points, in.ring_offsets}, indices, options);
}

QualityStatistics triangle_quality(py::handle coords, py::handle triangles) {
  const std::vector<Point> points = points_of(coords);
  const std::vector<Triangle> indices = triangles_from(triangles, points.size());
  py::gil_scoped_release release;
  return quality(points, indices);
}

/// A predicate on single points (a float back) or on (N, 2) arrays of them, a single point
/// standing for all N (an array back).
template <std::size_t Arity, class Predicate>
py::object predicate(const std::array<py::handle, Arity>& args, Predicate f) {
  std::array<Coordinates, Arity> arrays;
  std::array<bool, Arity> single{};
  py::ssize_t n = -1;
  static constexpr const char* names[] = {"a", "b", "c", "d"};
  for (std::size_t k = 0; k < Arity; ++k) {
    auto array = as_real_array(args[k], names[k]);
    single[k] = array.ndim() == 1;
    if (single[k] && array.shape(0) != 2)
      throw py::value_error(std::string(names[k]) + " must have 2 coordinates, not " +
                            std::to_string(array.shape(0)));
    if (!single[k]) {
      array = as_coordinates(array, names[k]);
      if (n >= 0 && array.shape(0) != n)
        throw py::value_error("point arrays must have the same length");
      n = array.shape(0);
    }
    arrays[k] = std::move(array);
  }
  const auto point = [&](std::size_t k, py::ssize_t i) {
    const double* xy = arrays[k].data() + (single[k] ? 0 : 2 * i);
    return Point{xy[0], xy[1]};
  };
  std::array<Point, Arity> p;
  if (n < 0) {
    for (std::size_t k = 0; k < Arity; ++k) p[k] = point(k, 0);
    return py::float_(f(p));
  }
  py::array_t<double> out(n);
  double* result = out.mutable_data();
  for (py::ssize_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < Arity; ++k) p[k] = point(k, i);
    result[i] = f(p);
  }
  return out;
}

}  // namespace

void bind_checks(py::module_& m) {
  py::class_<ValidationReport>(m, "ValidationReport",
                               "What pear.validate found; valid is True for a valid triangulation.")
      .def_readonly("valid", &ValidationReport::valid)
      .def_readonly("triangles", &ValidationReport::triangles)
      .def_readonly("expected_triangles", &ValidationReport::expected_triangles)
      .def_readonly("zero_area_triangles", &ValidationReport::zero_area_triangles)
      .def_readonly("bad_orientation", &ValidationReport::bad_orientation)
      .def_readonly("bad_edges", &ValidationReport::bad_edges)
      .def_readonly("non_delaunay_edges", &ValidationReport::non_delaunay_edges)
      .def_readonly("polygon_area", &ValidationReport::polygon_area)
      .def_readonly("triangle_area", &ValidationReport::triangle_area)
      .def_readonly("area_rel_error", &ValidationReport::area_rel_error)
      .def_readonly("messages", &ValidationReport::messages)
      .def("__bool__", [](const ValidationReport& r) { return r.valid; })
      .def("__repr__", [](const ValidationReport& r) {
        return "ValidationReport(valid=" + std::string(r.valid ? "True" : "False") +
               ", triangles=" + std::to_string(r.triangles) +
               ", expected_triangles=" + std::to_string(r.expected_triangles) +
               ", messages=" + std::to_string(r.messages.size()) + ")";
      });
  py::class_<QualityStatistics>(m, "QualityStatistics",
                                "Angle statistics of a triangulation (the paper's Table 1).")
      .def_readonly("triangles", &QualityStatistics::triangles)
      .def_readonly("dev60_avg_deg", &QualityStatistics::dev60_avg_deg)
      .def_readonly("min_angle_avg_deg", &QualityStatistics::min_angle_avg_deg)
      .def_readonly("min_angle_deg", &QualityStatistics::min_angle_deg)
      .def_readonly("min_angle_histogram", &QualityStatistics::min_angle_histogram)
      .def("__repr__", [](const QualityStatistics& q) {
        return "QualityStatistics(triangles=" + std::to_string(q.triangles) +
               ", min_angle_avg_deg=" + std::to_string(q.min_angle_avg_deg) +
               ", dev60_avg_deg=" + std::to_string(q.dev60_avg_deg) + ")";
      });
  // Text signatures in the docstrings (inspect.signature, help()), as in module.cpp.
  py::options options;
  options.disable_function_signatures();
  m.def("validate", &validate_triangles, py::arg("polygon"), py::arg("triangles"),
        py::arg("ring_ends") = py::none(), py::kw_only(), py::arg("check_delaunay") = false,
        py::arg("allow_zero_area") = false, py::arg("check_count") = true,
        py::arg("max_messages") = 20,
        "validate(polygon, triangles, ring_ends=None, *, check_delaunay=False, "
        "allow_zero_area=False, check_count=True, max_messages=20)\n--\n\n"
        "Checks exactly that triangles triangulate the polygon (coords and ring_ends, or a "
        "shapely Polygon); returns a ValidationReport.");
  m.def("quality", &triangle_quality, py::arg("coords"), py::arg("triangles"),
        "quality(coords, triangles)\n--\n\n"
        "Angle statistics of triangles (indices into coords or a shapely geometry's "
        "coordinates).");
  m.def(
      "orient2d",
      [](py::handle a, py::handle b, py::handle c) {
        return predicate<3>({a, b, c}, [](const auto& p) { return orient2d(p[0], p[1], p[2]); });
      },
      py::arg("a"), py::arg("b"), py::arg("c"),
      "orient2d(a, b, c)\n--\n\n"
      "Twice the signed area of (a, b, c), its sign exact: > 0 counterclockwise, < 0 "
      "clockwise, 0 collinear. Points, or (N, 2) arrays of them (an array back).");
  m.def(
      "incircle",
      [](py::handle a, py::handle b, py::handle c, py::handle d) {
        return predicate<4>({a, b, c, d},
                            [](const auto& p) { return incircle(p[0], p[1], p[2], p[3]); });
      },
      py::arg("a"), py::arg("b"), py::arg("c"), py::arg("d"),
      "incircle(a, b, c, d)\n--\n\n"
      "For counterclockwise a, b, c: > 0 if d is inside their circumcircle, < 0 outside, 0 on "
      "it, the sign exact. Points, or (N, 2) arrays of them (an array back).");
}

}  // namespace pear::python
