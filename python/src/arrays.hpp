// What the module's functions share: numpy arrays in and out, Options from keyword arguments,
// shapely geometries through their WKB, and pear's exceptions (pear/_types.py) raised from C++.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "pear/io.hpp"
#include "pear/pear.hpp"

namespace pear::python {

namespace py = pybind11;

using Coordinates = py::array_t<double, py::array::c_style | py::array::forcecast>;
using Triangle = std::array<std::uint32_t, 3>;
/// Polygons read from WKB, every ring with its closing point (pear::io::read_wkb's flat form).
using FlatPolygons = io::PolygonArrays;

/// The keyword arguments every triangulating function takes, as given.
struct OptionArguments {
  std::string_view algorithm = "automatic", heuristic = "top";
  bool delaunay = false, check_simplicity = true;
  long threads = 0, partitions = 0;
};
/// Options from them. Unknown names raise ValueError listing the known ones.
Options make_options(const OptionArguments& arguments);
/// Reads the keyword argument `name` into `arguments` by the rules below (a str, a bool, a
/// count in range); false when `name` is not one of the options.
bool option_argument(OptionArguments& arguments, std::string_view name, py::handle value);

// How arguments are read (docs/python.md, "How arguments are read"): an array-like is what
// numpy makes of it with no dtype asked; a scalar or None is not one (TypeError), nor is an
// array whose dtype is not the kind asked for (TypeError); a shape or value out of range is a
// ValueError. Every message names the argument.

using Integers = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>;

/// `value` as a C-contiguous float64 array of any shape (not 0-d): the caller's own array when
/// it is one already (no copy), else numpy's conversion of an integer or floating array.
/// Complex, bool, str, bytes, datetime and object arrays raise TypeError, not a cast.
Coordinates as_real_array(py::handle value, const char* name);
/// as_real_array, then shape (N, 2) or ValueError.
Coordinates as_coordinates(py::handle coords, const char* name = "coords");
/// as_real_array, then shape (N, 2) or (N, 3) (x, y, z: triangulated on x and y) or ValueError.
Coordinates as_coordinates_with_z(py::handle coords, const char* name = "coords");
/// x and y of an (N, 2) or (N, 3) array, interleaved: the array's own memory for (N, 2), else
/// a copy in `xy` (which keeps it).
std::span<const double> xy_of(const Coordinates& array, std::vector<double>& xy);

/// `value` as a C-contiguous int64 array of any shape (not 0-d): an integer dtype only (floats,
/// even 4.0, and bool raise TypeError, as numpy's indexing does); values int64 cannot hold
/// raise ValueError naming the entry. An empty array-like is empty whatever its dtype.
Integers as_integers(py::handle value, const char* name);
/// as_integers, one-dimensional (else ValueError): offsets and ring ends.
Integers as_offsets(py::handle values, const char* name);

/// The ring offsets (0, ..., n) of a polygon of n points from `ring_ends`: None (one ring), ring
/// offsets, earcut's ring ends (mapbox_earcut: each ring's end, the last n) or earcut.js' hole
/// indices (each hole's start): a missing leading 0 and trailing n are added. Raises ValueError
/// naming the entry that is out of order or range.
void ring_offsets_from(py::handle ring_ends, std::size_t n, std::vector<std::uint32_t>& offsets);

/// A str option (TypeError for anything else).
std::string_view string_argument(py::handle value, const char* name);
/// A flag: True, False or numpy.bool_ (TypeError for anything else: "no" is not False).
bool bool_argument(py::handle value, const char* name);
/// A count: an int (or anything with __index__ but bool) in [0, most], else TypeError or
/// ValueError "NAME VALUE is not between 0ZERO and LIMITMOST" (what 0 and `most` mean).
long count_argument(py::handle value, const char* name, long most, const char* zero = "",
                    const char* limit = "");

/// Triangles as an (M, 3) uint32 array: a copy for few triangles, else the vector itself, moved
/// into the array's owner.
py::array triangles_array(std::vector<Triangle>&& triangles);
/// A vector moved into a 1-D numpy array of the same element type (no copy).
template <class T>
py::array vector_array(std::vector<T>&& values);
/// Interleaved coordinates x0, y0, x1, y1, ... moved into an (N, 2) float64 array (no copy).
py::array points_array(std::vector<double>&& xy);
/// The points of flat polygons: (N, 2), or (N, 3) with their z when flat.z has them.
py::array points_array(FlatPolygons&& flat);
/// (M, 3) uint32 triangles from any array-like, checked against `points` (indices in range).
std::vector<Triangle> triangles_from(py::handle triangles, std::size_t points);

/// The exception pear raises for a status other than ok (pear.InvalidInputError for
/// invalid_input and index_overflow, pear.NotSimpleError for not_simple), its message `where`
/// followed by the first error's (or the crossing's) description. `triangles` goes with
/// NotSimpleError.
[[noreturn]] void raise_for_status(Status status, std::span<const Diagnostic> diagnostics,
                                   py::object triangles, const std::string& where = {});

/// Whether `value` is a shapely geometry (its type has a `wkb` attribute; not an array).
bool is_geometry(py::handle value);
/// A shapely Polygon or MultiPolygon's polygons, read from its WKB: points in shapely's order
/// (every ring closed), so indices into them are indices into its coordinates. keep_z: their z
/// too, when the geometry has z (shapely's has_z).
FlatPolygons geometry_polygons(py::handle geometry, bool keep_z = false);
/// Reads sequence[i] as WKB (bytes, bytearray or None) for every i, the GIL released while
/// parsing; a ParseError becomes pear.WKBError naming i and the byte.
FlatPolygons read_wkb_sequence(py::handle sequence);
/// Flat polygons as numpy arrays: coordinates (N, 2), ring, polygon and geometry offsets. When
/// the coordinates array is freed, its buffer is kept for the next batch read.
py::tuple flat_arrays(FlatPolygons&& flat);
/// An empty buffer for a batch read's coordinates: the one kept from the last coordinates
/// array freed (flat_arrays), else a new one. Called with the GIL held. A read into fresh
/// memory faulted its pages in (glibc gives large freed blocks back to the system), which
/// cost as much as reading shapely's geometries through GEOS.
std::vector<double> spare_coordinates();

/// Bytes of one triangle as a WKB Polygon.
inline constexpr std::size_t triangle_wkb_size = 1 + 4 + 4 + 4 + 4 * 16;
/// Every triangle (indices into the points of `coordinates`) as a little-endian WKB Polygon of
/// one closed ring, back to back: triangle t is bytes [t * triangle_wkb_size, (t+1) * ...).
/// The indices must be in range (the caller checks). No Python: callable without the GIL.
std::string triangles_to_wkb(std::span<const double> coordinates,
                             std::span<const std::array<std::uint32_t, 3>> triangles);

/// shapely 1.8 geometries (or None) read through their GEOS handles (geos.cpp) into what
/// flat_arrays(read_wkb_sequence(their WKB)) would give; None where the caller must write WKB
/// instead: an element that is not a `geometry_type` with a handle, a geometry that is not a
/// Polygon, MultiPolygon or empty collection, a GEOS before 3.10, a module built without
/// geos_c.h. `library`: the dlopen handle of shapely's libgeos_c (its ctypes CDLL's _handle).
py::object read_geos(py::handle sequence);
/// Whether the module was built with geos.cpp's reader.
bool has_geos_reader();

/// Registers validate, quality, orient2d, incircle and their result types (checks.cpp).
void bind_checks(py::module_& module);

/// pear.Status(status): the Python enum member.
py::object status_object(Status status);

}  // namespace pear::python
