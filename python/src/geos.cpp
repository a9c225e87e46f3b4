// shapely 1.8 geometries read through their GEOS handles, no WKB in between: triangulate_many
// over a GeoSeries without a Python step per geometry. The GEOS functions are looked up with
// dlsym in the very library shapely loaded (its ctypes handle), so they are always the
// library that made the geometries, whatever libgeos_c the module was built beside; the
// module does not link libgeos_c and imports where GEOS is missing. geos_c.h (libgeos-dev at
// build time) only gives the functions' types: without it read_geos is not compiled and
// pear._many writes WKB instead.
#include "arrays.hpp"

#if PEAR_PYTHON_GEOS && __has_include(<dlfcn.h>)
#define GEOS_USE_ONLY_R_API
#include <dlfcn.h>
#include <geos_c.h>

#include <algorithm>
#include <optional>
#include <span>
#include <utility>
#include <vector>

namespace pear::python {
namespace {

/// The reentrant C API functions the reader calls (GEOS >= 3.10 has them all).
struct GeosApi {
  decltype(&GEOS_init_r) init;
  decltype(&GEOS_finish_r) finish;
  decltype(&GEOSGeomTypeId_r) type_id;
  decltype(&GEOSisEmpty_r) is_empty;
  decltype(&GEOSGetExteriorRing_r) exterior;
  decltype(&GEOSGetNumInteriorRings_r) interior_count;
  decltype(&GEOSGetInteriorRingN_r) interior;
  decltype(&GEOSGetNumGeometries_r) part_count;
  decltype(&GEOSGetGeometryN_r) part;
  decltype(&GEOSGetNumCoordinates_r) point_count;
  decltype(&GEOSGeom_getCoordSeq_r) coordinates;
  decltype(&GEOSCoordSeq_getSize_r) size;
  decltype(&GEOSCoordSeq_copyToBuffer_r) copy;
};

template <class Function>
bool look_up(void* library, const char* name, Function& function) {
  function = reinterpret_cast<Function>(dlsym(library, name));
  return function != nullptr;
}

/// The functions in the library of dlopen handle `library`; nothing when one is missing (a
/// GEOS before 3.10).
std::optional<GeosApi> resolve(void* library) {
  GeosApi api;
  const bool found = look_up(library, "GEOS_init_r", api.init) &&
                     look_up(library, "GEOS_finish_r", api.finish) &&
                     look_up(library, "GEOSGeomTypeId_r", api.type_id) &&
                     look_up(library, "GEOSisEmpty_r", api.is_empty) &&
                     look_up(library, "GEOSGetExteriorRing_r", api.exterior) &&
                     look_up(library, "GEOSGetNumInteriorRings_r", api.interior_count) &&
                     look_up(library, "GEOSGetInteriorRingN_r", api.interior) &&
                     look_up(library, "GEOSGetNumGeometries_r", api.part_count) &&
                     look_up(library, "GEOSGetGeometryN_r", api.part) &&
                     look_up(library, "GEOSGetNumCoordinates_r", api.point_count) &&
                     look_up(library, "GEOSGeom_getCoordSeq_r", api.coordinates) &&
                     look_up(library, "GEOSCoordSeq_getSize_r", api.size) &&
                     look_up(library, "GEOSCoordSeq_copyToBuffer_r", api.copy);
  if (!found) return std::nullopt;
  return api;
}

/// Reads geometries into flat polygons as pear::io::read_wkb would from their WKB (rings as
/// GEOS holds them, closing point included; an empty Polygon or part has no polygon). Each
/// call answers false for what the WKB path must handle (another geometry type, a GEOS error).
class Reader {
 public:
  Reader(const GeosApi& api, FlatPolygons& out) : api_(api), context_(api.init()), out_(out) {}
  ~Reader() {
    if (context_) api_.finish(context_);
  }
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  /// Room for the points of these geometries: growing the array as it fills cost more (in
  /// page faults and copies) than asking each geometry for its count first.
  void reserve(std::span<const GEOSGeometry* const> geometries) {
    if (!context_) return;
    std::size_t points = 0;
    for (const GEOSGeometry* g : geometries)
      if (g) points += static_cast<std::size_t>(std::max(api_.point_count(context_, g), 0));
    out_.coordinates.reserve(2 * points);
  }

  /// One geometry (null: a missing one), as the next entry of geometry_offsets.
  bool geometry(const GEOSGeometry* g) {
    if (!context_) return false;
    if (g && !parts(g)) return false;
    out_.geometry_offsets.push_back(static_cast<std::int64_t>(out_.polygon_offsets.size() - 1));
    return true;
  }

 private:
  bool parts(const GEOSGeometry* g) {
    const int type = api_.type_id(context_, g);
    if (type == GEOS_POLYGON) return polygon(g);
    if (type == GEOS_GEOMETRYCOLLECTION)  // only empty (shapely 1.8's Polygon()), as in WKB
      return api_.part_count(context_, g) == 0;
    if (type != GEOS_MULTIPOLYGON) return false;
    const int count = api_.part_count(context_, g);
    if (count < 0) return false;
    for (int p = 0; p < count; ++p) {
      const GEOSGeometry* part = api_.part(context_, g, p);
      if (!part || api_.type_id(context_, part) != GEOS_POLYGON || !polygon(part)) return false;
    }
    return true;
  }

  bool polygon(const GEOSGeometry* g) {
    const char empty = api_.is_empty(context_, g);
    if (empty == 1) return true;  // WKB writes no ring for it: no polygon
    const int holes = api_.interior_count(context_, g);
    if (empty != 0 || holes < 0 || !ring(api_.exterior(context_, g))) return false;
    for (int h = 0; h < holes; ++h)
      if (!ring(api_.interior(context_, g, h))) return false;
    out_.polygon_offsets.push_back(static_cast<std::int64_t>(out_.ring_offsets.size() - 1));
    return true;
  }

  bool ring(const GEOSGeometry* ring) {
    const GEOSCoordSequence* sequence = ring ? api_.coordinates(context_, ring) : nullptr;
    unsigned size = 0;
    if (!sequence || api_.size(context_, sequence, &size) == 0) return false;
    std::vector<double>& xy = out_.coordinates;
    const std::size_t start = xy.size();
    xy.resize(start + 2 * std::size_t{size});
    if (size > 0 && api_.copy(context_, sequence, xy.data() + start, 0, 0) == 0) return false;
    out_.ring_offsets.push_back(static_cast<std::int64_t>(xy.size() / 2));
    return true;
  }

  const GeosApi& api_;
  GEOSContextHandle_t context_;
  FlatPolygons& out_;
};

/// Which types of geometry read their handle as BaseGeometry's `_geom` property does, from
/// the instance's `__geom__`, without the property's Python call (a fifth of the read's time):
/// a BaseGeometry whose type does not override `_geom` (shapely's proxies do). A few types are
/// met in a sequence (Polygon, MultiPolygon): a short list remembers them.
class HandleTypes {
 public:
  explicit HandleTypes(py::handle geometry_type)
      : geometry_type_(geometry_type),
        property_(geometry_type.attr("__dict__")["_geom"]),
        direct_name_("__geom__") {}

  /// The element's GEOS handle, or nothing when it is not a geometry with one.
  std::optional<const GEOSGeometry*> handle(py::handle item) {
    const std::optional<bool> direct = reads_direct(Py_TYPE(item.ptr()));
    if (!direct) return std::nullopt;
    const py::object handle =
        *direct ? py::object(item.attr(direct_name_)) : py::object(item.attr("_geom"));
    void* address = PyLong_Check(handle.ptr()) ? PyLong_AsVoidPtr(handle.ptr()) : nullptr;
    if (!address) {
      PyErr_Clear();
      return std::nullopt;
    }
    return static_cast<const GEOSGeometry*>(address);
  }

 private:
  /// Whether `type` reads `__geom__` directly (false: through `_geom`); nothing when it is not
  /// a geometry type.
  std::optional<bool> reads_direct(PyTypeObject* type) {
    for (const auto& [known, direct] : known_)
      if (known == type) return direct;
    const auto object = py::reinterpret_borrow<py::object>(reinterpret_cast<PyObject*>(type));
    const int is_geometry = PyObject_IsSubclass(object.ptr(), geometry_type_.ptr());
    if (is_geometry < 0) throw py::error_already_set();
    if (is_geometry == 0) return std::nullopt;
    const bool direct = object.attr("_geom").ptr() == property_.ptr();
    if (known_.size() < 8) known_.emplace_back(type, direct);
    return direct;
  }

  py::handle geometry_type_;
  py::object property_;
  py::str direct_name_;
  std::vector<std::pair<PyTypeObject*, bool>> known_;  // the sequence's items keep them alive
};

/// The GEOS handle of each element (null for None), or nothing when one is not a geometry of
/// `geometry_type` with a handle. `held` keeps the elements alive.
std::optional<std::vector<const GEOSGeometry*>> handles(py::handle sequence,
                                                        py::handle geometry_type,
                                                        std::vector<py::object>& held) {
  HandleTypes types(geometry_type);
  std::vector<const GEOSGeometry*> out;
  for (py::handle item : py::iter(sequence)) {
    if (item.is_none()) {
      out.push_back(nullptr);
      continue;
    }
    const std::optional<const GEOSGeometry*> handle = types.handle(item);
    if (!handle) return std::nullopt;
    held.push_back(py::reinterpret_borrow<py::object>(item));
    out.push_back(*handle);
  }
  return out;
}

/// shapely 1.8's libgeos_c (the dlopen handle its ctypes loader holds) and its geometry base
/// class, looked up here rather than taken from the caller: an address passed in could point
/// anywhere. Nothing for shapely 2 (no shapely.geos.lgeos) or without shapely.
struct Shapely {
  void* library = nullptr;
  py::object geometry_type;
};

std::optional<Shapely> find_shapely() {
  try {
    const py::object lgeos = py::module_::import("shapely.geos").attr("lgeos");
    const py::object handle = lgeos.attr("_lgeos").attr("_handle");
    void* library = PyLong_Check(handle.ptr()) ? PyLong_AsVoidPtr(handle.ptr()) : nullptr;
    if (!library) {
      PyErr_Clear();
      return std::nullopt;
    }
    return Shapely{library, py::module_::import("shapely.geometry.base").attr("BaseGeometry")};
  } catch (const py::error_already_set&) {
    return std::nullopt;
  }
}

}  // namespace

py::object read_geos(py::handle sequence) {
  const std::optional<Shapely> shapely = find_shapely();
  if (!shapely) return py::none();
  // Resolved once for the library first found; another library (not expected: shapely loads
  // one) is resolved at each call.
  static void* const first_library = shapely->library;
  static const std::optional<GeosApi> first_api = resolve(first_library);
  const std::optional<GeosApi> api =
      shapely->library == first_library ? first_api : resolve(shapely->library);
  if (!api) return py::none();
  std::vector<py::object> held;
  const auto geometries = handles(sequence, shapely->geometry_type, held);
  if (!geometries) return py::none();
  FlatPolygons flat;
  flat.coordinates = spare_coordinates();
  bool read = true;
  {
    py::gil_scoped_release release;
    Reader reader(*api, flat);
    reader.reserve(*geometries);
    for (const GEOSGeometry* g : *geometries)
      if (!(read = reader.geometry(g))) break;
  }
  if (!read) return py::none();
  return flat_arrays(std::move(flat));
}

bool has_geos_reader() {
  return true;
}

}  // namespace pear::python

#else  // no geos_c.h at build time: pear._many writes WKB

namespace pear::python {
py::object read_geos(py::handle) {
  return py::none();
}
bool has_geos_reader() {
  return false;
}
}  // namespace pear::python

#endif
