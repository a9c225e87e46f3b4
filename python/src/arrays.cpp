// numpy arrays in and out, Options by name, pear's exceptions raised from C++, and triangles as
// WKB (the reading is pear::io::read_wkb).
#include "arrays.hpp"

#include <bit>
#include <cstring>
#include <limits>
#include <string>

namespace pear::python {

namespace {
std::string type_name(py::handle value) {
  return py::str(py::type::handle_of(value).attr("__name__"));
}
}  // namespace

Options make_options(const OptionArguments& arguments) {
  const auto [algorithm, heuristic, delaunay, check_simplicity, threads, partitions] = arguments;
  Options options;
  if (algorithm == "automatic" || algorithm == "auto")
    options.algorithm = Algorithm::automatic;
  else if (algorithm == "sequential")
    options.algorithm = Algorithm::sequential;
  else if (algorithm == "partition_and_cut")
    options.algorithm = Algorithm::partition_and_cut;
  else if (algorithm == "mark_and_cut")
    options.algorithm = Algorithm::mark_and_cut;
  else if (algorithm == "divide_and_conquer")
    options.algorithm = Algorithm::divide_and_conquer;
  else
    throw py::value_error("algorithm '" + std::string(algorithm) +
                          "' is not one of automatic, sequential, partition_and_cut, "
                          "mark_and_cut, divide_and_conquer");
  if (heuristic == "top")
    options.heuristic = EarHeuristic::top;
  else if (heuristic == "fast")
    options.heuristic = EarHeuristic::fast;
  else
    throw py::value_error("heuristic '" + std::string(heuristic) + "' is not one of top, fast");
  options.delaunay = delaunay;
  options.threads = static_cast<unsigned>(threads);
  options.partitions = static_cast<unsigned>(partitions);
  options.check_simplicity = check_simplicity;
  return options;
}

bool option_argument(OptionArguments& a, std::string_view name, py::handle value) {
  constexpr long limit = max_threads;
  if (name == "algorithm")
    a.algorithm = string_argument(value, "algorithm");
  else if (name == "heuristic")
    a.heuristic = string_argument(value, "heuristic");
  else if (name == "delaunay")
    a.delaunay = bool_argument(value, "delaunay");
  else if (name == "check_simplicity")
    a.check_simplicity = bool_argument(value, "check_simplicity");
  else if (name == "threads")
    a.threads = count_argument(value, "threads", limit, " (all)", "pear's limit of ");
  else if (name == "partitions")
    a.partitions =
        count_argument(value, "partitions", limit, " (the thread count)", "pear's limit of ");
  else
    return false;
  return true;
}

std::string_view string_argument(py::handle value, const char* name) {
  Py_ssize_t size = 0;
  const char* text =
      PyUnicode_Check(value.ptr()) ? PyUnicode_AsUTF8AndSize(value.ptr(), &size) : nullptr;
  if (!text) {
    if (PyErr_Occurred()) throw py::error_already_set();  // a str that is not UTF-8
    throw py::type_error(std::string(name) + " must be a str, not " + type_name(value));
  }
  return {text, static_cast<std::size_t>(size)};
}

bool bool_argument(py::handle value, const char* name) {
  if (value.ptr() == Py_True) return true;
  if (value.ptr() == Py_False) return false;
  if (py::isinstance(value, py::module_::import("numpy").attr("bool_")))
    return PyObject_IsTrue(value.ptr()) == 1;
  throw py::type_error(std::string(name) + " must be a bool, not " + type_name(value));
}

long count_argument(py::handle value, const char* name, long most, const char* zero,
                    const char* limit) {
  if (PyBool_Check(value.ptr()) || !PyIndex_Check(value.ptr()))
    throw py::type_error(std::string(name) + " must be an int, not " + type_name(value));
  const auto number = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
  if (!number) throw py::error_already_set();
  int overflow = 0;
  const long count = PyLong_AsLongAndOverflow(number.ptr(), &overflow);
  if (count == -1 && PyErr_Occurred()) throw py::error_already_set();
  if (overflow != 0 || count < 0 || count > most)
    throw py::value_error(std::string(name) + " " + std::string(py::str(number)) +
                          " is not between 0" + zero + " and " + limit + std::to_string(most));
  return count;
}

namespace {

/// What numpy makes of `value` with no dtype asked, not 0-d. `expected` says what the argument
/// must be, for the TypeError of a scalar or None.
py::array any_array(py::handle value, const char* name, const char* expected) {
  py::array array;
  if (py::isinstance<py::array>(value)) {
    array = py::reinterpret_borrow<py::array>(value);
  } else {
    auto& api = py::detail::npy_api::get();
    PyObject* made = api.PyArray_FromAny_(value.ptr(), nullptr, 0, 0,
                                          py::detail::npy_api::NPY_ARRAY_ENSUREARRAY_, nullptr);
    if (!made) {
      // A ragged list is a shape, anything else numpy refuses a type.
      const bool shape = PyErr_ExceptionMatches(PyExc_ValueError);
      const py::error_already_set error;
      if (shape)
        throw py::value_error(std::string(name) +
                              " is not an array: " + std::string(py::str(error.value())));
      throw py::type_error(std::string(name) + " must be " + expected + ", not " +
                           type_name(value));
    }
    array = py::reinterpret_steal<py::array>(made);
  }
  if (array.ndim() == 0)
    throw py::type_error(std::string(name) + " must be " + expected + ", not " + type_name(value));
  return array;
}

std::string dtype_name(const py::array& array) {
  return py::str(array.dtype());
}

/// "name[i]" or "name[i, j]" for entry `flat` of a C-ordered array.
std::string entry_name(const char* name, const py::array& array, py::ssize_t flat) {
  std::string index;
  for (py::ssize_t d = array.ndim() - 1; d >= 0; --d) {
    index = std::to_string(flat % array.shape(d)) + (index.empty() ? "" : ", ") + index;
    flat /= array.shape(d);
  }
  return std::string(name) + "[" + index + "]";
}

/// An object array's elements as int64: each a Python or numpy int (not a bool) that fits.
Integers integers_from_objects(const py::array& objects, const char* name) {
  Integers out(std::vector<py::ssize_t>(objects.shape(), objects.shape() + objects.ndim()));
  const py::object integer = py::module_::import("numpy").attr("integer");
  const py::list items = objects.attr("ravel")().attr("tolist")();
  std::int64_t* values = out.mutable_data();
  for (py::ssize_t i = 0; i < static_cast<py::ssize_t>(items.size()); ++i) {
    const py::handle item = items[i];
    if (PyBool_Check(item.ptr()) || !(PyLong_Check(item.ptr()) || py::isinstance(item, integer)))
      throw py::type_error(std::string(name) + " must be integers, not " + type_name(item));
    int overflow = 0;
    const auto number = py::reinterpret_steal<py::object>(PyNumber_Index(item.ptr()));
    if (!number) throw py::error_already_set();
    const long long value = PyLong_AsLongLongAndOverflow(number.ptr(), &overflow);
    if (overflow != 0)
      throw py::value_error(entry_name(name, objects, i) + " = " + std::string(py::str(item)) +
                            " does not fit in int64");
    values[i] = value;
  }
  return out;
}

}  // namespace

Coordinates as_real_array(py::handle value, const char* name) {
  // The common case first: an array as it is needed is borrowed, not converted.
  if (py::isinstance<Coordinates>(value) && py::reinterpret_borrow<py::array>(value).ndim() > 0)
    return py::reinterpret_borrow<Coordinates>(value);
  const py::array array = any_array(value, name, "an array-like of numbers");
  const char kind = array.dtype().kind();
  if (kind != 'i' && kind != 'u' && kind != 'f')
    throw py::type_error(std::string(name) + " must be real numbers (an integer or floating " +
                         "dtype), not " + dtype_name(array));
  return Coordinates::ensure(array);
}

namespace {
Coordinates coordinates_of_width(py::handle coords, const char* name, py::ssize_t widest) {
  Coordinates array = as_real_array(coords, name);
  if (array.ndim() != 2 || array.shape(1) < 2 || array.shape(1) > widest) {
    std::string shape;
    for (py::ssize_t d = 0; d < array.ndim(); ++d)
      shape += (d ? ", " : "") + std::to_string(array.shape(d));
    throw py::value_error(std::string(name) + " must have shape (N, 2)" +
                          (widest == 3 ? " or (N, 3)" : "") + ", not (" + shape + ")");
  }
  return array;
}
}  // namespace

Coordinates as_coordinates(py::handle coords, const char* name) {
  return coordinates_of_width(coords, name, 2);
}

Coordinates as_coordinates_with_z(py::handle coords, const char* name) {
  return coordinates_of_width(coords, name, 3);
}

std::span<const double> xy_of(const Coordinates& array, std::vector<double>& xy) {
  const auto n = static_cast<std::size_t>(array.shape(0));
  const auto width = static_cast<std::size_t>(array.shape(1));
  if (width == 2) return {array.data(), 2 * n};
  xy.resize(2 * n);
  for (std::size_t i = 0; i < n; ++i) {
    xy[2 * i] = array.data()[width * i];
    xy[2 * i + 1] = array.data()[width * i + 1];
  }
  return xy;
}

Integers as_integers(py::handle value, const char* name) {
  if (py::isinstance<Integers>(value) && py::reinterpret_borrow<py::array>(value).ndim() > 0)
    return py::reinterpret_borrow<Integers>(value);
  const py::array array = any_array(value, name, "an array-like of integers");
  const char kind = array.dtype().kind();
  if (array.size() == 0)  // [] is float64 to numpy, and nothing to convert
    return Integers(std::vector<py::ssize_t>(array.shape(), array.shape() + array.ndim()));
  if (kind == 'O') return integers_from_objects(array, name);
  if (kind != 'i' && kind != 'u')
    throw py::type_error(std::string(name) + " must be integers, not " + dtype_name(array));
  if (kind == 'u' && array.itemsize() == 8) {
    using Unsigned = py::array_t<std::uint64_t, py::array::c_style | py::array::forcecast>;
    const Unsigned values = Unsigned::ensure(array);
    for (py::ssize_t i = 0; i < values.size(); ++i)
      if (values.data()[i] > std::uint64_t{std::numeric_limits<std::int64_t>::max()})
        throw py::value_error(entry_name(name, array, i) + " = " +
                              std::to_string(values.data()[i]) + " does not fit in int64");
  }
  return Integers::ensure(array);
}

Integers as_offsets(py::handle values, const char* name) {
  Integers array = as_integers(values, name);
  if (array.ndim() != 1)
    throw py::value_error(std::string(name) + " must be one-dimensional, not " +
                          std::to_string(array.ndim()) + "-dimensional");
  return array;
}

namespace {
/// Appends ring_ends' entries to offsets (which holds the leading 0), checking each.
template <class Values>
void append_ring_ends(const Values& values, py::ssize_t count, std::size_t n,
                      std::vector<std::uint32_t>& offsets) {
  for (py::ssize_t i = 0; i < count; ++i) {
    const auto value = static_cast<std::int64_t>(values(i));
    if (value < offsets.back() || value > static_cast<std::int64_t>(n))
      throw py::value_error("ring_ends[" + std::to_string(i) + "] = " + std::to_string(value) +
                            (value < offsets.back()
                                 ? " is below the entry before it"
                                 : " is past the " + std::to_string(n) + " points"));
    if (i == 0 && value == 0) continue;  // ring offsets: the leading 0 is already there
    offsets.push_back(static_cast<std::uint32_t>(value));
  }
}

/// Reads a 1-D integer array of element type T in place; false when ring_ends is not one.
template <class T>
bool append_if_array_of(py::handle ring_ends, std::size_t n, std::vector<std::uint32_t>& offsets) {
  if (!py::isinstance<py::array_t<T, 0>>(ring_ends)) return false;
  const auto array = py::reinterpret_borrow<py::array_t<T, 0>>(ring_ends);
  if (array.ndim() != 1) return false;
  const auto values = array.template unchecked<1>();
  append_ring_ends([&](py::ssize_t i) { return values(i); }, array.shape(0), n, offsets);
  return true;
}
}  // namespace

void ring_offsets_from(py::handle ring_ends, std::size_t n, std::vector<std::uint32_t>& offsets) {
  offsets.clear();
  offsets.push_back(0);
  // Arrays of the usual index types are read as they are (mapbox_earcut's are uint32).
  if (!ring_ends.is_none() && !append_if_array_of<std::uint32_t>(ring_ends, n, offsets) &&
      !append_if_array_of<std::int64_t>(ring_ends, n, offsets) &&
      !append_if_array_of<std::int32_t>(ring_ends, n, offsets)) {
    const auto ends = as_offsets(ring_ends, "ring_ends");
    const std::int64_t* values = ends.data();
    append_ring_ends([&](py::ssize_t i) { return values[i]; }, ends.shape(0), n, offsets);
  }
  if (offsets.back() != n) offsets.push_back(static_cast<std::uint32_t>(n));
}

template <class T>
py::array vector_array(std::vector<T>&& values) {
  auto* owned = new std::vector<T>(std::move(values));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array_t<T>(static_cast<py::ssize_t>(owned->size()), owned->data(), owner);
}
template py::array vector_array(std::vector<std::int64_t>&&);
template py::array vector_array(std::vector<std::uint8_t>&&);
template py::array vector_array(std::vector<double>&&);

namespace {

/// A new (rows, 3) uint32 array from numpy's constructor itself: array_t's constructor allocates
/// two vectors, for the shape and the strides, which a per-polygon call notices.
py::array new_triangle_rows(py::ssize_t rows) {
  auto& api = py::detail::npy_api::get();
  const Py_intptr_t shape[2] = {rows, 3};
  PyObject* array =
      api.PyArray_NewFromDescr_(api.PyArray_Type_, py::dtype::of<std::uint32_t>().release().ptr(),
                                2, shape, nullptr, nullptr, 0, nullptr);
  if (!array) throw py::error_already_set();
  return py::reinterpret_steal<py::array>(array);
}

}  // namespace

py::array triangles_array(std::vector<Triangle>&& triangles) {
  const auto count = static_cast<py::ssize_t>(triangles.size());
  // Below this a copy costs less than a second Python object to own the vector.
  if (triangles.size() < 4096) {
    py::array array = new_triangle_rows(count);
    if (count > 0) std::memcpy(array.mutable_data(), triangles.data(), triangles.size() * 12);
    return array;
  }
  auto* owned = new std::vector<Triangle>(std::move(triangles));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<Triangle>*>(p); });
  return py::array_t<std::uint32_t>({count, py::ssize_t{3}},
                                    reinterpret_cast<const std::uint32_t*>(owned->data()), owner);
}

std::vector<Triangle> triangles_from(py::handle triangles, std::size_t points) {
  const Integers array = as_integers(triangles, "triangles");
  if (array.ndim() != 2 || array.shape(1) != 3)
    throw py::value_error("triangles must have shape (M, 3)");
  std::vector<Triangle> out(static_cast<std::size_t>(array.shape(0)));
  const std::int64_t* values = array.data();
  for (std::size_t i = 0; i < 3 * out.size(); ++i) {
    if (values[i] < 0 || static_cast<std::uint64_t>(values[i]) >= points)
      throw py::value_error("triangles[" + std::to_string(i / 3) + "] has index " +
                            std::to_string(values[i]) + ", not one of the " +
                            std::to_string(points) + " points");
    out[i / 3][i % 3] = static_cast<std::uint32_t>(values[i]);
  }
  return out;
}

namespace {
py::object errors_module() {
  return py::module_::import("pear._types");
}

py::list diagnostics_list(std::span<const Diagnostic> diagnostics) {
  py::list list;
  for (const Diagnostic& d : diagnostics) list.append(py::cast(d));
  return list;
}
}  // namespace

void raise_for_status(Status status, std::span<const Diagnostic> diagnostics, py::object triangles,
                      const std::string& where) {
  const Diagnostic* first = diagnostics.empty() ? nullptr : &diagnostics.front();
  for (const Diagnostic& d : diagnostics)
    if (d.is_error() || (status == Status::not_simple && d.is_not_simple())) {
      first = &d;
      break;
    }
  const std::string message = where + (first ? describe(*first) : std::string(to_string(status)));
  py::object error;
  if (status == Status::not_simple)
    error =
        errors_module().attr("NotSimpleError")(message, triangles, diagnostics_list(diagnostics));
  else
    error = errors_module().attr("InvalidInputError")(
        message, first ? to_string(first->issue) : to_string(status),
        first ? py::int_(first->ring) : py::int_(0), first ? py::int_(first->vertex) : py::int_(0),
        diagnostics_list(diagnostics));
  PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(error.ptr())), error.ptr());
  throw py::error_already_set();
}

bool is_geometry(py::handle value) {
  // On the type: shapely's wkb is a property, and asking the object would write the WKB.
  return !py::isinstance<py::array>(value) && py::hasattr(py::type::handle_of(value), "wkb");
}

FlatPolygons geometry_polygons(py::handle geometry, bool keep_z) {
  const py::bytes wkb = geometry.attr("wkb");
  const std::string_view bytes = wkb;
  FlatPolygons flat;
  flat.keep_z = keep_z && py::hasattr(geometry, "has_z") && geometry.attr("has_z").cast<bool>();
  try {
    io::read_wkb(std::as_bytes(std::span(bytes.data(), bytes.size())), flat);
  } catch (const io::ParseError& e) {
    throw py::value_error(std::string(py::str(geometry.attr("geom_type"))) +
                          " is not a Polygon or MultiPolygon: " + e.detail());
  }
  return flat;
}

FlatPolygons read_wkb_sequence(py::handle sequence) {
  // bytes are immutable: read in place, kept alive by `held` (the sequence may be a generator).
  // A bytearray may be resized or written by another thread once the GIL is released, so its
  // contents are copied now, while the GIL is held (issue 30: reading it in place read freed
  // memory); the copy is a memcpy of bytes the parser reads anyway.
  struct Value {
    const std::byte* in_place;  // null: copied, at `offset` in `copies`
    std::size_t offset, size;
  };
  std::vector<Value> places;
  std::vector<py::object> held;
  std::vector<std::byte> copies;
  for (py::handle item : py::iter(sequence)) {
    PyObject* object = item.ptr();
    if (item.is_none()) {
      places.push_back({nullptr, copies.size(), 0});
    } else if (PyBytes_Check(object)) {
      held.push_back(py::reinterpret_borrow<py::object>(item));
      places.push_back({reinterpret_cast<const std::byte*>(PyBytes_AS_STRING(object)), 0,
                        static_cast<std::size_t>(PyBytes_GET_SIZE(object))});
    } else if (PyByteArray_Check(object)) {
      const auto* bytes = reinterpret_cast<const std::byte*>(PyByteArray_AS_STRING(object));
      const auto size = static_cast<std::size_t>(PyByteArray_GET_SIZE(object));
      places.push_back({nullptr, copies.size(), size});
      copies.insert(copies.end(), bytes, bytes + size);
    } else {
      throw py::type_error("geometry " + std::to_string(places.size()) +
                           " is not WKB (bytes, bytearray or None) but " +
                           std::string(py::str(py::type::handle_of(item).attr("__name__"))));
    }
  }
  std::vector<std::span<const std::byte>> values;
  values.reserve(places.size());
  for (const Value& v : places)
    values.emplace_back(v.in_place ? v.in_place : copies.data() + v.offset, v.size);
  FlatPolygons flat;
  flat.coordinates = spare_coordinates();
  std::string error;
  std::size_t index = 0, offset = 0;
  {
    py::gil_scoped_release release;
    std::size_t bytes = 0;
    for (const auto& value : values) bytes += value.size();
    flat.coordinates.reserve(bytes / 8);  // at most one double per 8 bytes
    try {
      for (; index < values.size(); ++index) io::read_wkb(values[index], flat);
    } catch (const io::ParseError& e) {
      error = "geometry " + std::to_string(index) + ", " + e.detail(), offset = e.offset();
    }
  }
  if (!error.empty()) {
    const py::object e = py::module_::import("pear._types").attr("WKBError")(error, index, offset);
    PyErr_SetObject(reinterpret_cast<PyObject*>(Py_TYPE(e.ptr())), e.ptr());
    throw py::error_already_set();
  }
  return flat;
}

py::array points_array(std::vector<double>&& xy) {
  const auto points = static_cast<py::ssize_t>(xy.size() / 2);
  auto* owned = new std::vector<double>(std::move(xy));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>({points, py::ssize_t{2}}, owned->data(), owner);
}

py::array points_array(FlatPolygons&& flat) {
  if (flat.z.empty()) return points_array(std::move(flat.coordinates));
  const std::size_t n = flat.z.size();
  std::vector<double> xyz(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    xyz[3 * i] = flat.coordinates[2 * i];
    xyz[3 * i + 1] = flat.coordinates[2 * i + 1];
    xyz[3 * i + 2] = flat.z[i];
  }
  auto* owned = new std::vector<double>(std::move(xyz));
  py::capsule owner(owned, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array_t<double>({static_cast<py::ssize_t>(n), py::ssize_t{3}}, owned->data(), owner);
}

namespace {
/// The buffer spare_coordinates hands out: the largest kept, between 64 kB and 64 MB (smaller
/// ones come from malloc's own free lists; larger ones are not worth holding idle). Only
/// touched with the GIL held: a capsule's destructor runs with it, readers take it before
/// releasing it. Never destroyed: arrays may be freed as the interpreter exits.
std::vector<double>& kept_coordinates() {
  static auto* kept = new std::vector<double>();
  return *kept;
}

void keep_coordinates(std::vector<double>&& xy) {
  constexpr std::size_t least = (64 << 10) / sizeof(double), most = (64 << 20) / sizeof(double);
  const std::size_t capacity = xy.capacity();
  if (capacity >= least && capacity <= most && capacity > kept_coordinates().capacity())
    kept_coordinates() = std::move(xy);
}

/// A batch read's (N, 2) coordinates, its buffer kept for the next read when freed.
py::array coordinates_array(std::vector<double>&& xy) {
  const auto points = static_cast<py::ssize_t>(xy.size() / 2);
  auto* owned = new std::vector<double>(std::move(xy));
  py::capsule owner(owned, [](void* p) {
    auto* buffer = static_cast<std::vector<double>*>(p);
    keep_coordinates(std::move(*buffer));
    delete buffer;
  });
  return py::array_t<double>({points, py::ssize_t{2}}, owned->data(), owner);
}
}  // namespace

std::vector<double> spare_coordinates() {
  std::vector<double> spare = std::move(kept_coordinates());
  kept_coordinates() = std::vector<double>();
  spare.clear();
  return spare;
}

py::tuple flat_arrays(FlatPolygons&& flat) {
  return py::make_tuple(coordinates_array(std::move(flat.coordinates)),
                        vector_array(std::move(flat.ring_offsets)),
                        vector_array(std::move(flat.polygon_offsets)),
                        vector_array(std::move(flat.geometry_offsets)));
}

py::object status_object(Status status) {
  // pear.Status's members, looked up once (kept for the life of the process).
  static PyObject* members[4] = {};
  const auto code = static_cast<std::size_t>(status);
  if (!members[code])
    members[code] = py::module_::import("pear._types").attr("Status")(code).release().ptr();
  return py::reinterpret_borrow<py::object>(members[code]);
}

namespace {
void put_uint32(char*& at, std::uint32_t value) {
  if constexpr (std::endian::native == std::endian::big) value = __builtin_bswap32(value);
  std::memcpy(at, &value, 4);
  at += 4;
}
void put_double(char*& at, double value) {
  auto bits = std::bit_cast<std::uint64_t>(value);
  if constexpr (std::endian::native == std::endian::big) bits = __builtin_bswap64(bits);
  std::memcpy(at, &bits, 8);
  at += 8;
}
}  // namespace

std::string triangles_to_wkb(std::span<const double> coordinates,
                             std::span<const std::array<std::uint32_t, 3>> triangles) {
  constexpr std::uint32_t wkb_polygon = 3;
  std::string out(triangles.size() * triangle_wkb_size, '\0');
  char* at = out.data();
  for (const auto& t : triangles) {
    *at++ = 1;  // little endian
    put_uint32(at, wkb_polygon);
    put_uint32(at, 1);  // one ring
    put_uint32(at, 4);  // closed: the first corner again
    for (int k = 0; k < 4; ++k) {
      const std::size_t i = t[k % 3];
      put_double(at, coordinates[2 * i]);
      put_double(at, coordinates[2 * i + 1]);
    }
  }
  return out;
}

}  // namespace pear::python
