// pear._pear: the Python module's C++ side. pear/__init__.py re-exports it; docs/python.md is
// the reference. One polygon: pear.triangulate; many: triangulate_batch (ragged arrays) after
// read_wkb (WKB values), the GIL released and the polygons spread over pear's scheduler.
#include <pybind11/stl.h>

#include <algorithm>
#include <string>

#include "arrays.hpp"
#include "pear/batch.hpp"
#include "pear/pear.hpp"

namespace pear::python {
namespace {

/// Polygons with at least this many points are triangulated with the GIL released: below it,
/// releasing and taking the lock back costs more than another thread could gain.
constexpr std::size_t release_gil_points = 256;

/// A thread's Triangulator (pear's reuse object: its engine holds every buffer of a run) with
/// the ring offsets and the result it fills, kept between calls: a small polygon then costs no
/// allocation but its result's array. The coordinates are read where they are.
struct Scratch {
  Triangulator triangulator;
  std::vector<std::uint32_t> ring_offsets;
  Triangulation<> result;
};
Scratch& thread_scratch() {
  thread_local Scratch scratch;
  return scratch;
}

Triangulation<>& run(Scratch& s, const CoordinateView& view, const Options& options) {
  if (view.xy.size() < 2 * release_gil_points) {
    s.triangulator.triangulate_into(view, options, s.result);
  } else {
    py::gil_scoped_release release;
    s.triangulator.triangulate_into(view, options, s.result);
  }
  return s.result;
}

/// The result as pear.triangulate returns it, or the exception it raises. Large triangle
/// lists are moved into the array, small ones copied (the buffer stays for the next call).
py::object finish(Triangulation<>& result, bool strict, const std::string& where = {}) {
  py::object triangles = triangles_array(std::move(result.triangles));
  if (result.status == Status::invalid_input || result.status == Status::index_overflow ||
      (result.status == Status::not_simple && strict))
    raise_for_status(result.status, result.diagnostics, triangles, where);
  if (strict) return triangles;
  return py::make_tuple(triangles, status_object(result.status));
}

/// A shapely Polygon or MultiPolygon: its parts as one batch (pear's one run per part),
/// indices into the geometry's coordinates; the worst status of the parts (the first part
/// that has it names the place).
py::object triangulate_geometry(py::handle geometry, const Options& options, bool strict) {
  const FlatPolygons flat = geometry_polygons(geometry);
  const std::size_t parts = flat.polygon_offsets.size() - 1;
  Scratch& s = thread_scratch();
  if (parts == 0) {  // an empty geometry: what empty coordinates give (empty_input)
    s.ring_offsets.assign(1, 0);
    return finish(run(s, CoordinateView{{}, s.ring_offsets}, options), strict);
  }
  const PolygonBatch batch{flat.coordinates, flat.ring_offsets, flat.polygon_offsets};
  BatchTriangulation<> result;
  if (flat.coordinates.size() < 2 * release_gil_points) {
    result = triangulate_batch(batch, options);
  } else {
    py::gil_scoped_release release;
    result = triangulate_batch(batch, options);
  }
  const auto worst = static_cast<std::size_t>(
      std::max_element(result.status.begin(), result.status.end()) - result.status.begin());
  Triangulation<> all;
  all.triangles = std::move(result.triangles);
  all.status = result.status[worst];
  std::string where;
  if (all.status != Status::ok) {
    all.diagnostics.assign(result.diagnostics.begin() + result.diagnostic_offsets[worst],
                           result.diagnostics.begin() + result.diagnostic_offsets[worst + 1]);
    if (parts > 1) where = "polygon " + std::to_string(worst) + " of the MultiPolygon, ";
  }
  return finish(all, strict, where);
}

py::object triangulate(py::handle coords, py::handle ring_ends, const Options& options,
                       bool strict) {
  if (is_geometry(coords)) {
    if (!ring_ends.is_none())
      throw py::type_error("ring_ends goes with coordinates, not with a shapely geometry");
    return triangulate_geometry(coords, options, strict);
  }
  const Coordinates array = as_coordinates(coords);
  const auto n = static_cast<std::size_t>(array.shape(0));
  if (n > std::size_t{0xFFFFFFFF})
    throw py::value_error(std::to_string(n) + " points cannot be numbered by uint32 indices");
  Scratch& s = thread_scratch();
  ring_offsets_from(ring_ends, n, s.ring_offsets);
  return finish(run(s, CoordinateView{std::span(array.data(), 2 * n), s.ring_offsets}, options),
                strict);
}

/// triangulate's arguments, as pear.triangulate's signature names them.
struct TriangulateArguments {
  py::handle coords, ring_ends;  // null until given
  OptionArguments options;
  bool strict = true;
};

void keyword_argument(TriangulateArguments& a, std::string_view name, py::handle value) {
  // A keyword that names a positional argument given already: TypeError, as Python says it.
  const auto once = [&](py::handle& slot) {
    if (slot)
      throw py::type_error("triangulate() got multiple values for argument '" + std::string(name) +
                           "'");
    slot = value;
  };
  if (name == "strict")
    a.strict = bool_argument(value, "strict");
  else if (name == "ring_ends")
    once(a.ring_ends);
  else if (name == "coords")
    once(a.coords);
  else if (!option_argument(a.options, name, value))
    throw py::type_error("triangulate() got an unexpected keyword argument '" + std::string(name) +
                         "'");
}

/// pear.triangulate as a vectorcall function: for polygons of a few dozen points the generic
/// binding's argument handling (a dict per call for keywords) cost as much as the triangulation.
PyObject* triangulate_vectorcall(PyObject*, PyObject* const* args, Py_ssize_t positional,
                                 PyObject* keyword_names) {
  try {
    TriangulateArguments a;
    if (positional > 2) throw py::type_error("triangulate() takes at most 2 positional arguments");
    if (positional > 0) a.coords = args[0];
    if (positional > 1) a.ring_ends = args[1];
    const Py_ssize_t keywords = keyword_names ? PyTuple_GET_SIZE(keyword_names) : 0;
    for (Py_ssize_t k = 0; k < keywords; ++k)
      keyword_argument(a, string_argument(PyTuple_GET_ITEM(keyword_names, k), "a keyword"),
                       args[positional + k]);
    if (!a.coords) throw py::type_error("triangulate() missing its argument 'coords'");
    const py::handle ring_ends = a.ring_ends ? a.ring_ends : py::handle(Py_None);
    return triangulate(a.coords, ring_ends, make_options(a.options), a.strict).release().ptr();
  } catch (py::error_already_set& e) {
    e.restore();
  } catch (const py::builtin_exception& e) {
    e.set_error();
  } catch (const std::bad_alloc&) {
    PyErr_NoMemory();
  } catch (const std::exception& e) {
    PyErr_SetString(PyExc_RuntimeError, e.what());
  }
  return nullptr;
}

PyMethodDef triangulate_definition = {
    "triangulate",
    reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(&triangulate_vectorcall)),
    METH_FASTCALL | METH_KEYWORDS,
    "triangulate(coords, ring_ends=None, *, algorithm='automatic', heuristic='top', "
    "delaunay=False, threads=0, partitions=0, check_simplicity=True, strict=True)\n--\n\n"
    "Triangulates one polygon; returns an (M, 3) uint32 array of indices into coords.\n\n"
    "coords: an (N, 2) array-like of real numbers (a C-contiguous float64 array is not\n"
    "converted), or a shapely Polygon/MultiPolygon (indices then number its coordinates, rings\n"
    "closed, in shapely's order). ring_ends: None (one ring), integer ring offsets [0, ..., N],\n"
    "earcut's ring ends [..., N] or earcut's hole indices. Raises pear.InvalidInputError (a\n"
    "ValueError) naming ring and vertex for input that cannot be triangulated,\n"
    "pear.NotSimpleError carrying the best-effort triangles for a polygon that is not simple;\n"
    "strict=False returns (triangles, pear.Status) instead of raising NotSimpleError. Wrong\n"
    "types raise TypeError, wrong shapes and values out of range ValueError. See\n"
    "docs/python.md."};

/// triangulate_batch's result as numpy arrays, by name (pear._many.BatchResult wraps it).
struct BatchArrays {
  py::object triangles, triangle_offsets, status, diagnostic_offsets, diagnostic_issue,
      diagnostic_ring, diagnostic_vertex;
  std::size_t delaunay_flips = 0;
};

/// Many polygons in the layout of shapely 2's to_ragged_array; returns the batch's arrays.
BatchArrays triangulate_batch(py::handle coords, py::handle ring_offsets,
                              py::handle polygon_offsets, const py::kwargs& keywords) {
  OptionArguments arguments;
  for (const auto& [name, value] : keywords)
    if (!option_argument(arguments, string_argument(name, "a keyword"), value))
      throw py::type_error("triangulate_batch() got an unexpected keyword argument '" +
                           std::string(py::str(name)) + "'");
  const Options options = make_options(arguments);
  const Coordinates points = as_coordinates(coords);
  // The offsets decide which addresses are read: they are copied while the GIL is held, so
  // that another thread writing the caller's arrays cannot change one between its check and
  // its use (issue 30). Coordinates are only values: read in place, the GIL released.
  const auto offsets = [](py::handle values, const char* name) {
    const auto array = as_offsets(values, name);
    return std::vector<std::int64_t>(array.data(), array.data() + array.shape(0));
  };
  const std::vector<std::int64_t> rings = offsets(ring_offsets, "ring_offsets");
  const std::vector<std::int64_t> polygons = offsets(polygon_offsets, "polygon_offsets");
  const PolygonBatch batch{std::span(points.data(), static_cast<std::size_t>(2 * points.shape(0))),
                           rings, polygons};
  BatchTriangulation<> result;
  std::vector<std::uint8_t> status, issues;
  std::vector<std::int64_t> diagnostic_rings, diagnostic_vertices;
  {
    py::gil_scoped_release release;
    result = triangulate_batch<std::uint32_t>(batch, options);
    status.resize(result.status.size());
    std::transform(result.status.begin(), result.status.end(), status.begin(),
                   [](Status s) { return static_cast<std::uint8_t>(s); });
    for (const Diagnostic& d : result.diagnostics) {
      issues.push_back(static_cast<std::uint8_t>(d.issue));
      diagnostic_rings.push_back(static_cast<std::int64_t>(d.ring));
      diagnostic_vertices.push_back(static_cast<std::int64_t>(d.vertex));
    }
  }
  return {triangles_array(std::move(result.triangles)),
          vector_array(std::move(result.triangle_offsets)),
          vector_array(std::move(status)),
          vector_array(std::move(result.diagnostic_offsets)),
          vector_array(std::move(issues)),
          vector_array(std::move(diagnostic_rings)),
          vector_array(std::move(diagnostic_vertices)),
          result.delaunay_flips};
}

void bind_batch_arrays(py::module_& m) {
  py::class_<BatchArrays>(m, "BatchArrays",
                          "triangulate_batch's arrays by name; pear.BatchResult holds them.")
      .def_readonly("triangles", &BatchArrays::triangles)
      .def_readonly("triangle_offsets", &BatchArrays::triangle_offsets)
      .def_readonly("status", &BatchArrays::status)
      .def_readonly("diagnostic_offsets", &BatchArrays::diagnostic_offsets)
      .def_readonly("diagnostic_issue", &BatchArrays::diagnostic_issue)
      .def_readonly("diagnostic_ring", &BatchArrays::diagnostic_ring)
      .def_readonly("diagnostic_vertex", &BatchArrays::diagnostic_vertex)
      .def_readonly("delaunay_flips", &BatchArrays::delaunay_flips);
}

/// Triangles as a list of WKB Polygons (for GeoSeries.from_wkb).
py::list triangles_wkb(py::handle coords, py::handle triangles) {
  const Coordinates points = as_coordinates(coords);
  const auto n = static_cast<std::size_t>(points.shape(0));
  const std::vector<Triangle> indices = triangles_from(triangles, n);
  std::string bytes;
  {
    py::gil_scoped_release release;
    bytes = triangles_to_wkb(std::span(points.data(), 2 * n), indices);
  }
  py::list out(indices.size());
  for (std::size_t t = 0; t < indices.size(); ++t)
    out[t] = py::bytes(bytes.data() + t * triangle_wkb_size, triangle_wkb_size);
  return out;
}

void bind_diagnostic(py::module_& m) {
  py::class_<Diagnostic>(m, "Diagnostic",
                         "One finding about the input: the issue, the ring (0 = outer) and the "
                         "vertex within that ring, in the caller's numbering.")
      .def_property_readonly("issue", [](const Diagnostic& d) { return to_string(d.issue); })
      .def_readonly("ring", &Diagnostic::ring)
      .def_readonly("vertex", &Diagnostic::vertex)
      .def_property_readonly("is_error", &Diagnostic::is_error)
      .def_property_readonly("is_not_simple", &Diagnostic::is_not_simple)
      .def("__str__", [](const Diagnostic& d) { return describe(d); })
      .def("__repr__",
           [](const Diagnostic& d) {
             return "Diagnostic(issue='" + std::string(to_string(d.issue)) +
                    "', ring=" + std::to_string(d.ring) + ", vertex=" + std::to_string(d.vertex) +
                    ")";
           })
      .def("__eq__",
           [](const Diagnostic& a, const Diagnostic& b) {
             return a.issue == b.issue && a.ring == b.ring && a.vertex == b.vertex;
           })
      .def(py::pickle(
          [](const Diagnostic& d) {
            return py::make_tuple(static_cast<int>(d.issue), d.ring, d.vertex);
          },
          [](const py::tuple& t) {
            return Diagnostic{static_cast<Issue>(t[0].cast<int>()), t[1].cast<std::size_t>(),
                              t[2].cast<std::size_t>()};
          }));
  m.def(
      "describe_issue",
      [](int issue, std::size_t ring, std::size_t vertex) {
        return Diagnostic{static_cast<Issue>(issue), ring, vertex};
      },
      "A Diagnostic from an issue code and its place (triangulate_many's arrays).");
}

}  // namespace
}  // namespace pear::python

PYBIND11_MODULE(_pear, m) {
  namespace py = pybind11;
  using namespace pear::python;
  m.doc() = "pear's C++ core; use the package pear (docs/python.md).";
  bind_diagnostic(m);
  bind_batch_arrays(m);
  m.add_object("triangulate", py::reinterpret_steal<py::object>(PyCFunction_NewEx(
                                  &triangulate_definition, nullptr, py::str("pear._pear").ptr())));
  m.def("triangulate_batch", &triangulate_batch, py::arg("coords"), py::arg("ring_offsets"),
        py::arg("polygon_offsets"),
        "Ragged arrays in, the batch's arrays out (options by keyword); use "
        "pear.triangulate_many.");
  m.def(
      "as_offsets", [](py::handle values, const char* name) { return as_offsets(values, name); },
      py::arg("values"), py::arg("name"),
      "values as a 1-D int64 array by pear's rules (docs/python.md); errors name `name`.");
  m.def(
      "read_wkb", [](py::handle values) { return flat_arrays(read_wkb_sequence(values)); },
      py::arg("values"),
      "WKB values (bytes or None) to (coords, ring_offsets, polygon_offsets, "
      "geometry_offsets); raises pear.WKBError naming the geometry and the byte.");
  m.def("triangles_wkb", &triangles_wkb, py::arg("coords"), py::arg("triangles"),
        "Each triangle as WKB Polygon bytes.");
  bind_checks(m);
}
