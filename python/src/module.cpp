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

/// Past this many points a call takes an engine from pear's pool (the one the pool keeps for
/// large polygons) instead of the thread's Triangulator: no thread then holds a large
/// polygon's arrays for good, and pear.release_cached_engines() frees them from any thread.
constexpr std::size_t pooled_points = 65536;

/// A thread's Triangulator (pear's reuse object: its engine holds every buffer of a run) with
/// the ring offsets and the result it fills, kept between calls: a small polygon then costs no
/// allocation but its result's array. The coordinates are read where they are.
struct Scratch {
  Triangulator triangulator;
  std::vector<std::uint32_t> ring_offsets;
  std::vector<double> xy;  // x and y of (N, 3) coordinates
  Triangulation<> result;
};
Scratch& thread_scratch() {
  thread_local Scratch scratch;
  return scratch;
}

Triangulation<>& run(Scratch& s, const CoordinateView& view, const Options& options) {
  if (view.xy.size() < 2 * release_gil_points) {
    s.triangulator.triangulate_into(view, options, s.result);
  } else if (view.xy.size() <= 2 * pooled_points) {
    py::gil_scoped_release release;
    s.triangulator.triangulate_into(view, options, s.result);
  } else {
    py::gil_scoped_release release;
    Triangulator pooled;  // its engine goes back to the pool at the end of the call
    pooled.triangulate_into(view, options, s.result);
  }
  return s.result;
}

/// The result as pear.triangulate returns it, or the exception it raises; `points` (not null
/// for triangulate_points) goes first. Large triangle lists are moved into the array, small
/// ones copied (the buffer stays for the next call).
py::object finish(Triangulation<>& result, bool strict, const py::object& points,
                  const std::string& where = {}) {
  py::object triangles = triangles_array(std::move(result.triangles));
  if (result.status == Status::invalid_input || result.status == Status::index_overflow ||
      (result.status == Status::not_simple && strict))
    raise_for_status(result.status, result.diagnostics, triangles, where);
  if (points) {
    if (strict) return py::make_tuple(points, triangles);
    return py::make_tuple(points, triangles, status_object(result.status));
  }
  if (strict) return triangles;
  return py::make_tuple(triangles, status_object(result.status));
}

/// A shapely Polygon or MultiPolygon: its parts as one batch (pear's one run per part),
/// indices into the geometry's coordinates; the worst status of the parts (the first part
/// that has it names the place). with_points: those coordinates come back too.
py::object triangulate_geometry(py::handle geometry, const Options& options, bool strict,
                                bool with_points) {
  FlatPolygons flat = geometry_polygons(geometry, with_points);
  const std::size_t parts = flat.polygon_offsets.size() - 1;
  Scratch& s = thread_scratch();
  if (parts == 0) {  // an empty geometry: what empty coordinates give (empty_input)
    s.ring_offsets.assign(1, 0);
    return finish(run(s, CoordinateView{{}, s.ring_offsets}, options), strict, py::object());
  }
  if (parts == 1 && flat.coordinates.size() / 2 <= std::size_t{0xFFFFFFFF}) {
    // A Polygon: the one run on its coordinates, no batch to set up.
    s.ring_offsets.assign(flat.ring_offsets.begin(), flat.ring_offsets.end());
    const CoordinateView view{flat.coordinates, s.ring_offsets};
    Triangulation<>& one = run(s, view, options);
    const py::object points = with_points ? points_array(std::move(flat)) : py::object();
    return finish(one, strict, points);
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
  const py::object points = with_points ? points_array(std::move(flat)) : py::object();
  return finish(all, strict, points, where);
}

py::object triangulate(py::handle coords, py::handle ring_ends, const Options& options, bool strict,
                       bool with_points) {
  if (is_geometry(coords)) {
    if (!ring_ends.is_none())
      throw py::type_error("ring_ends goes with coordinates, not with a shapely geometry");
    return triangulate_geometry(coords, options, strict, with_points);
  }
  const Coordinates array = as_coordinates_with_z(coords);
  const auto n = static_cast<std::size_t>(array.shape(0));
  if (n > std::size_t{0xFFFFFFFF})
    throw py::value_error(std::to_string(n) + " points cannot be numbered by uint32 indices");
  Scratch& s = thread_scratch();
  ring_offsets_from(ring_ends, n, s.ring_offsets);
  return finish(run(s, CoordinateView{xy_of(array, s.xy), s.ring_offsets}, options), strict,
                with_points ? py::object(array) : py::object());
}

/// triangulate's arguments, as pear.triangulate's signature names them (and
/// pear.triangulate_points', the same).
struct TriangulateArguments {
  py::handle coords, ring_ends;  // null until given
  OptionArguments options;
  bool strict = true;
};

void keyword_argument(TriangulateArguments& a, const char* function, std::string_view name,
                      py::handle value) {
  // A keyword that names a positional argument given already: TypeError, as Python says it.
  const auto once = [&](py::handle& slot) {
    if (slot)
      throw py::type_error(std::string(function) + "() got multiple values for argument '" +
                           std::string(name) + "'");
    slot = value;
  };
  if (name == "strict")
    a.strict = bool_argument(value, "strict");
  else if (name == "ring_ends")
    once(a.ring_ends);
  else if (name == "coords")
    once(a.coords);
  else if (!option_argument(a.options, name, value))
    throw py::type_error(std::string(function) + "() got an unexpected keyword argument '" +
                         std::string(name) + "'");
}

/// pear.triangulate (and, WithPoints, pear.triangulate_points) as a vectorcall function: for
/// polygons of a few dozen points the generic binding's argument handling (a dict per call for
/// keywords) cost as much as the triangulation.
template <bool WithPoints>
PyObject* triangulate_vectorcall(PyObject*, PyObject* const* args, Py_ssize_t positional,
                                 PyObject* keyword_names) {
  // The name for messages: a string is made only for an error (a call makes none).
  constexpr const char* function = WithPoints ? "triangulate_points" : "triangulate";
  try {
    TriangulateArguments a;
    if (positional > 2)
      throw py::type_error(std::string(function) + "() takes at most 2 positional arguments");
    if (positional > 0) a.coords = args[0];
    if (positional > 1) a.ring_ends = args[1];
    const Py_ssize_t keywords = keyword_names ? PyTuple_GET_SIZE(keyword_names) : 0;
    for (Py_ssize_t k = 0; k < keywords; ++k)
      keyword_argument(a, function,
                       string_argument(PyTuple_GET_ITEM(keyword_names, k), "a keyword"),
                       args[positional + k]);
    if (!a.coords) throw py::type_error(std::string(function) + "() missing its argument 'coords'");
    const py::handle ring_ends = a.ring_ends ? a.ring_ends : py::handle(Py_None);
    return triangulate(a.coords, ring_ends, make_options(a.options), a.strict, WithPoints)
        .release()
        .ptr();
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

// The first line of each docstring is the signature inspect.signature and help() read.
PyMethodDef triangulate_definition = {
    "triangulate",
    reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(&triangulate_vectorcall<false>)),
    METH_FASTCALL | METH_KEYWORDS,
    "triangulate(coords, ring_ends=None, *, algorithm='automatic', heuristic='top', "
    "delaunay=False, threads=0, partitions=0, check_simplicity=True, strict=True)\n--\n\n"
    "Triangulates one polygon; returns an (M, 3) uint32 array of indices into coords.\n\n"
    "coords: an (N, 2) array-like of real numbers (a C-contiguous float64 array is not\n"
    "converted), (N, 3) with z (triangulated on x and y), or a shapely Polygon/MultiPolygon "
    "(indices then number its coordinates, rings\n"
    "closed, in shapely's order: pear.triangulate_points returns them with the triangles).\n"
    "ring_ends: None (one ring), integer ring offsets [0, ..., N], earcut's ring ends [..., N]\n"
    "or earcut's hole indices. Raises pear.InvalidInputError (a ValueError) naming ring and\n"
    "vertex for input that cannot be triangulated, pear.NotSimpleError carrying the\n"
    "best-effort triangles for a polygon that is not simple; strict=False returns (triangles,\n"
    "pear.Status) instead of raising NotSimpleError. Wrong types raise TypeError, wrong shapes\n"
    "and values out of range ValueError. See docs/python.md."};

PyMethodDef triangulate_points_definition = {
    "triangulate_points",
    reinterpret_cast<PyCFunction>(reinterpret_cast<void (*)()>(&triangulate_vectorcall<true>)),
    METH_FASTCALL | METH_KEYWORDS,
    "triangulate_points(coords, ring_ends=None, *, algorithm='automatic', heuristic='top', "
    "delaunay=False, threads=0, partitions=0, check_simplicity=True, strict=True)\n--\n\n"
    "pear.triangulate, returning (points, triangles): points the (N, 2) float64 coordinates\n"
    "the triangles index, (N, 3) with z where the input has z (for a shapely Polygon/MultiPolygon "
    "its coordinates in shapely's\n"
    "order, every ring closed; for an array, coords as read), triangles the (M, 3) uint32\n"
    "array. strict=False returns (points, triangles, pear.Status). Arguments and exceptions\n"
    "as for triangulate. pear.shapely_triangles(points, triangles) makes shapely Polygons of\n"
    "them. See docs/python.md."};

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
  const Coordinates points = as_coordinates_with_z(coords);
  std::vector<double> xy;  // x and y of (N, 3) coordinates
  // The offsets decide which addresses are read: they are copied while the GIL is held, so
  // that another thread writing the caller's arrays cannot change one between its check and
  // its use (issue 30). Coordinates are only values: read in place, the GIL released.
  const auto offsets = [](py::handle values, const char* name) {
    const auto array = as_offsets(values, name);
    return std::vector<std::int64_t>(array.data(), array.data() + array.shape(0));
  };
  const std::vector<std::int64_t> rings = offsets(ring_offsets, "ring_offsets");
  const std::vector<std::int64_t> polygons = offsets(polygon_offsets, "polygon_offsets");
  const PolygonBatch batch{xy_of(points, xy), rings, polygons};
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
}

py::object vectorcall_function(PyMethodDef& definition) {
  return py::reinterpret_steal<py::object>(
      PyCFunction_NewEx(&definition, nullptr, py::str("pear._pear").ptr()));
}

/// The module's functions. Each docstring starts with its signature in CPython's text
/// signature form ("name(args)\n--\n\n"), which inspect.signature and help() read: pybind11's
/// own would show every argument as a py::handle.
void bind_functions(py::module_& m) {
  py::options options;
  options.disable_function_signatures();
  m.add_object("triangulate", vectorcall_function(triangulate_definition));
  m.add_object("triangulate_points", vectorcall_function(triangulate_points_definition));
  m.def("triangulate_batch", &triangulate_batch, py::arg("coords"), py::arg("ring_offsets"),
        py::arg("polygon_offsets"),
        "triangulate_batch(coords, ring_offsets, polygon_offsets, **options)\n--\n\n"
        "Ragged arrays in, the batch's arrays out; use pear.triangulate_many.");
  m.def(
      "as_offsets", [](py::handle values, const char* name) { return as_offsets(values, name); },
      py::arg("values"), py::arg("name"),
      "as_offsets(values, name)\n--\n\n"
      "values as a 1-D int64 array by pear's rules (docs/python.md); errors name `name`.");
  m.def(
      "read_wkb", [](py::handle values) { return flat_arrays(read_wkb_sequence(values)); },
      py::arg("values"),
      "read_wkb(values)\n--\n\n"
      "WKB values (bytes or None) to (coords, ring_offsets, polygon_offsets, "
      "geometry_offsets); raises pear.WKBError naming the geometry and the byte.");
  m.def("read_geos", &read_geos, py::arg("values"),
        "read_geos(values)\n--\n\n"
        "shapely 1.8 geometries read by GEOS (their _geom, in the libgeos_c shapely loaded) "
        "to read_wkb's arrays, or None: then write WKB.");
  m.attr("has_geos_reader") = has_geos_reader();
  m.def(
      "release_cached_engines", [] { release_cached_engines(); },
      "release_cached_engines()\n--\n\n"
      "Frees the arrays pear keeps for the next calls: the engine of the last polygon of more "
      "than 65,536 points (about 300 bytes a point) and the small polygons' engines not in "
      "use. Each thread keeps its own small engine (up to 65,536 points' worth) until it ends.");
  m.def("triangles_wkb", &triangles_wkb, py::arg("coords"), py::arg("triangles"),
        "triangles_wkb(coords, triangles)\n--\n\nEach triangle as WKB Polygon bytes.");
  m.def(
      "describe_issue",
      [](int issue, std::size_t ring, std::size_t vertex) {
        return Diagnostic{static_cast<Issue>(issue), ring, vertex};
      },
      py::arg("issue"), py::arg("ring"), py::arg("vertex"),
      "describe_issue(issue, ring, vertex)\n--\n\n"
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
  bind_functions(m);
  bind_checks(m);
}
