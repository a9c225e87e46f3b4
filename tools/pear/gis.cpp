#include "gis.hpp"

#include <stdexcept>

#if PEAR_HAVE_GDAL
#include <cpl_conv.h>
#include <cpl_error.h>
#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <mutex>
#include <tuple>
#include <vector>

#include "gis_source.hpp"
#endif

namespace pear::cli::gis {

#if PEAR_HAVE_GDAL

namespace {

namespace fs = std::filesystem;

/// GDAL's drivers registered once, its messages kept for ours instead of printed.
void start_gdal() {
  static std::once_flag once;
  std::call_once(once, [] {
    GDALAllRegister();
    CPLSetErrorHandler(CPLQuietErrorHandler);
  });
}

std::string last_gdal_error() {
  const char* message = CPLGetLastErrorMsg();
  return message && *message ? message : "no reason given";
}

std::string lower(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

bool pear_reads_extension(const std::string& name) {
  const std::string n = lower(name);
  for (const char* ext : {".json", ".geojson", ".wkt", ".poly", ".wkb", ".hexwkb", ".hex", ".gz"})
    if (n.ends_with(ext)) return true;
  return false;
}

/// Calls visit(driver) for each GDAL vector driver.
template <class Visit>
void each_vector_driver(Visit visit) {
  start_gdal();
  GDALDriverManager* manager = GetGDALDriverManager();
  for (int i = 0; i < manager->GetDriverCount(); ++i) {
    GDALDriver* driver = manager->GetDriver(i);
    if (driver->GetMetadataItem(GDAL_DCAP_VECTOR) != nullptr) visit(driver);
  }
}

/// Whether a vector driver lists `extension` (".gpkg") among its file extensions.
bool claims_extension(GDALDriver* driver, const std::string& extension) {
  const char* list = driver->GetMetadataItem(GDAL_DMD_EXTENSIONS);
  if (list == nullptr || extension.size() < 2) return false;
  const std::string wanted = lower(extension.substr(1));
  std::string item;
  for (const char* c = list;; ++c) {
    if (*c == ' ' || *c == '\0') {
      if (lower(item) == wanted) return true;
      item.clear();
      if (*c == '\0') return false;
    } else {
      item += *c;
    }
  }
}

bool creates(GDALDriver* driver) {
  return driver->GetMetadataItem(GDAL_DCAP_CREATE) != nullptr;
}

}  // namespace

bool available() {
  return true;
}

bool reads(const std::string& name) {
  if (name == "-" || pear_reads_extension(name)) return false;
  std::error_code error;
  if (!fs::exists(name, error)) return false;  // pear's reader says it is missing
  const std::string extension = fs::path(name).extension().string();
  bool claimed = false;
  each_vector_driver([&](GDALDriver* d) { claimed = claimed || claims_extension(d, extension); });
  if (claimed) return true;
  return GDALIdentifyDriverEx(name.c_str(), GDAL_OF_VECTOR, nullptr, nullptr) != nullptr;
}

std::optional<std::string> driver_for_extension(const std::string& extension) {
  std::optional<std::string> found;
  each_vector_driver([&](GDALDriver* d) {
    if (!found && creates(d) && claims_extension(d, extension)) found = d->GetDescription();
  });
  return found;
}

bool is_writable_driver(const std::string& name) {
  start_gdal();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(name.c_str());
  return driver != nullptr && driver->GetMetadataItem(GDAL_DCAP_VECTOR) != nullptr &&
         creates(driver);
}

std::string extension_of_driver(const std::string& name) {
  start_gdal();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(name.c_str());
  const char* extension = driver ? driver->GetMetadataItem(GDAL_DMD_EXTENSION) : nullptr;
  return extension && *extension ? "." + std::string(extension) : "";
}

namespace {

// ---- reading

/// A string as a JSON string literal.
std::string json_string(const char* text) {
  std::string out = "\"";
  for (const char* c = text; *c; ++c) {
    const auto u = static_cast<unsigned char>(*c);
    if (u == '"' || u == '\\') {
      out += '\\';
      out += *c;
    } else if (u < 0x20) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", u);
      out += escape;
    } else {
      out += *c;
    }
  }
  return out + '"';
}

/// The feature's fields as a JSON object's text: numbers as numbers (a NaN or infinity as
/// null, which JSON has no number for), null as null, the rest (strings, dates, lists) as
/// OGR writes them as text.
std::string properties_json(OGRFeature& feature) {
  std::string out = "{";
  for (int i = 0; i < feature.GetFieldCount(); ++i) {
    if (!feature.IsFieldSet(i)) continue;
    OGRFieldDefn* field = feature.GetFieldDefnRef(i);
    if (out.size() > 1) out += ',';
    out += json_string(field->GetNameRef()) + ':';
    const OGRFieldType type = field->GetType();
    if (feature.IsFieldNull(i)) {
      out += "null";
    } else if (type == OFTInteger || type == OFTInteger64) {
      out += std::to_string(feature.GetFieldAsInteger64(i));
    } else if (type == OFTReal) {
      const double value = feature.GetFieldAsDouble(i);
      out += std::isfinite(value) ? io::format_double(value) : "null";
    } else {
      out += json_string(feature.GetFieldAsString(i));
    }
  }
  return out + '}';
}

/// Where a problem is: "FILE: layer 'L'".
std::string place(const std::string& name, OGRLayer* layer) {
  return name + ": layer '" + (layer ? layer->GetName() : "") + "'";
}

/// One geometry's polygons into `out`, parts of collections one by one; what is no polygon is
/// listed as skipped. Curved geometries are made linear first (GDAL's default steps).
void add_geometry(const OGRGeometry& geometry, std::size_t feature_index, const std::string& where,
                  const io::ReadOptions& options, io::ReadResult& out) {
  const OGRwkbGeometryType type = wkbFlatten(geometry.getGeometryType());
  if (type == wkbGeometryCollection || type == wkbMultiSurface) {
    for (const OGRGeometry* part : *geometry.toGeometryCollection())
      add_geometry(*part, feature_index, where, options, out);
    return;
  }
  if (geometry.hasCurveGeometry()) {
    const std::unique_ptr<OGRGeometry> linear(geometry.getLinearGeometry());
    if (linear) add_geometry(*linear, feature_index, where, options, out);
    return;
  }
  if (type != wkbPolygon && type != wkbMultiPolygon) {
    out.skipped.push_back({feature_index, OGRGeometryTypeToName(type), 0, 0, 0});
    return;
  }
  std::string wkb(static_cast<std::size_t>(geometry.WkbSize()), '\0');
  geometry.exportToWkb(wkbNDR, reinterpret_cast<unsigned char*>(wkb.data()), wkbVariantIso);
  io::ReadResult polygons = io::read_features(wkb, io::Format::wkb, where, options);
  for (io::Feature& feature : polygons.features) {
    feature.feature_index = feature_index;
    out.features.push_back(std::move(feature));
  }
}

OGRLayer* choose_layer(GDALDataset& dataset, const std::string& name, const LayerChoice& choice,
                       std::string& note) {
  if (dataset.GetLayerCount() == 0) throw io::ParseError(name, 0, 0, 0, "no layer in it");
  if (!choice.layer) {
    if (dataset.GetLayerCount() > 1)
      note = name + ": " + std::to_string(dataset.GetLayerCount()) + " layers; reading '" +
             dataset.GetLayer(0)->GetName() + "' (--layer NAME for another)";
    return dataset.GetLayer(0);
  }
  if (OGRLayer* layer = dataset.GetLayerByName(choice.layer->c_str())) return layer;
  std::string names;
  for (OGRLayer* layer : dataset.GetLayers())
    names += (names.empty() ? "" : ", ") + std::string(layer->GetName());
  throw io::ParseError(name, 0, 0, 0,
                       "no layer '" + *choice.layer + "' (its layers: " + names + ")");
}

/// The SRID for GeoJSON output: the layer's EPSG code, if it has one.
std::uint32_t epsg_of(OGRLayer& layer) {
  const OGRSpatialReference* srs = layer.GetSpatialRef();
  if (srs == nullptr) return 0;
  const char* authority = srs->GetAuthorityName(nullptr);
  const char* code = srs->GetAuthorityCode(nullptr);
  if (!authority || !code || std::string(authority) != "EPSG") return 0;
  return static_cast<std::uint32_t>(std::strtoul(code, nullptr, 10));
}

}  // namespace

Read read(const std::string& name, const LayerChoice& choice, const io::ReadOptions& options) {
  start_gdal();
  CPLErrorReset();
  auto source = std::make_shared<Source>();
  source->dataset.reset(
      GDALDataset::Open(name.c_str(), GDAL_OF_VECTOR | GDAL_OF_READONLY | GDAL_OF_VERBOSE_ERROR));
  if (!source->dataset)
    throw io::ParseError(name, 0, 0, 0, "GDAL cannot open it: " + last_gdal_error());
  Read result;
  OGRLayer* layer = choose_layer(*source->dataset, name, choice, result.note);
  source->layer = layer;
  CPLErrorReset();
  if (choice.where && layer->SetAttributeFilter(choice.where->c_str()) != OGRERR_NONE)
    throw io::ParseError(name, 0, 0, 0,
                         "layer '" + std::string(layer->GetName()) + "': --where '" +
                             *choice.where + "' is not a valid filter: " + last_gdal_error());
  layer->ResetReading();
  while (OGRFeatureUniquePtr feature{layer->GetNextFeature()}) {
    const std::size_t index = source->features.size();
    const std::size_t first = result.read.features.size();
    if (const OGRGeometry* geometry = feature->GetGeometryRef())
      add_geometry(*geometry, index,
                   place(name, layer) + ", feature " + std::to_string(feature->GetFID()), options,
                   result.read);
    feature->SetGeometryDirectly(nullptr);  // only the fields are kept for writing
    const std::string properties = properties_json(*feature);
    for (std::size_t f = first; f < result.read.features.size(); ++f)
      result.read.features[f].properties = properties;
    source->features.push_back(std::move(feature));
  }
  // Some drivers (GeoPackage's SQL) find a bad filter only when the features are read.
  if (CPLGetLastErrorType() >= CE_Failure)
    throw io::ParseError(name, 0, 0, 0,
                         "layer '" + std::string(layer->GetName()) +
                             "': " + (choice.where ? "--where '" + *choice.where + "': " : "") +
                             last_gdal_error());
  if (result.read.features.empty())
    throw io::ParseError(name, 0, 0, 0,
                         "layer '" + std::string(layer->GetName()) + "': no polygon in it (" +
                             std::to_string(source->features.size()) + " features, " +
                             std::to_string(result.read.skipped.size()) +
                             " geometries that are not polygons)");
  result.read.srid = epsg_of(*layer);
  result.layer = layer->GetName();
  result.source = std::move(source);
  return result;
}

namespace {

// ---- writing

/// pear's fields, after the source's: the source feature's FID (which not every format keeps
/// as the FID), the triangles, and the status (the first that is not ok among the parts).
constexpr const char* fid_field = "pear_fid";
constexpr const char* triangles_field = "pear_tris";
constexpr const char* status_field = "pear_stat";

[[noreturn]] void cannot_write(const std::string& path, const std::string& what) {
  throw std::runtime_error("cannot write " + path + ": " + what + ": " + last_gdal_error());
}

/// The output's fields: map[i] is the output index of source field i; then pear's.
struct OutputFields {
  std::vector<int> map;
  int fid = -1, triangles = -1, status = -1;
};

/// Adds `field` to the layer under its name or, when a field has that name already (ignoring
/// case, as GeoPackage and Shapefile do), under the first free one of name2, name3, ...,
/// which a note says. Returns the field's index.
int add_field(OGRLayer& layer, const OGRFieldDefn& definition, const std::string& path,
              const char* whose, std::vector<std::string>& notes) {
  OGRFieldDefn field(&definition);
  const std::string name = field.GetNameRef();
  std::string free = name;
  for (int n = 2; layer.GetLayerDefn()->GetFieldIndex(free.c_str()) >= 0; ++n)
    free = name + std::to_string(n);
  if (free != name) {
    field.SetName(free.c_str());
    notes.push_back(path + ": " + whose + " field '" + name + "' is written as '" + free +
                    "' (a field before it has that name)");
  }
  if (layer.CreateField(&field) != OGRERR_NONE) cannot_write(path, "field '" + free + "'");
  return layer.GetLayerDefn()->GetFieldCount() - 1;
}

/// The source's fields, then pear's: each keeps its name unless a field before it has it.
OutputFields create_fields(OGRLayer& out, const Source* source, const std::string& path,
                           std::vector<std::string>& notes) {
  OutputFields fields;
  if (source != nullptr) {
    OGRFeatureDefn* definition = source->fields();
    for (int i = 0; i < definition->GetFieldCount(); ++i)
      fields.map.push_back(
          add_field(out, *definition->GetFieldDefn(i), path, "the input's", notes));
  }
  fields.fid = add_field(out, OGRFieldDefn(fid_field, OFTInteger64), path, "pear's", notes);
  fields.triangles =
      add_field(out, OGRFieldDefn(triangles_field, OFTInteger64), path, "pear's", notes);
  fields.status = add_field(out, OGRFieldDefn(status_field, OFTString), path, "pear's", notes);
  return fields;
}

/// The triangles of one polygon, added to a MultiPolygon (with z and m when it has them).
void add_triangles(const io::TriangulatedPolygon& polygon, OGRMultiPolygon& out) {
  std::vector<Point> points;
  for (const Ring& ring : polygon.polygon) points.insert(points.end(), ring.begin(), ring.end());
  const bool z = !polygon.z.empty(), m = !polygon.m.empty();
  for (const auto& t : polygon.triangles) {
    auto ring = std::make_unique<OGRLinearRing>();
    ring->setNumPoints(4);
    for (int k = 0; k < 4; ++k) {
      const std::uint32_t v = t[k % 3];
      if (z && m)
        ring->setPoint(k, points[v].x, points[v].y, polygon.z[v], polygon.m[v]);
      else if (m)
        ring->setPointM(k, points[v].x, points[v].y, polygon.m[v]);
      else if (z)
        ring->setPoint(k, points[v].x, points[v].y, polygon.z[v]);
      else
        ring->setPoint(k, points[v].x, points[v].y);
    }
    auto triangle = std::make_unique<OGRPolygon>();
    triangle->addRingDirectly(ring.release());
    out.addGeometryDirectly(triangle.release());
  }
}

/// The source feature's values (and a GDAL layer's FID) for output feature `feature`.
void copy_values(const Source& source, std::size_t index, const OutputFields& fields,
                 OGRFeature& feature) {
  if (index >= source.features.size() || !source.features[index]) return;
  const OGRFeature& from = *source.features[index];
  for (int i = 0; i < static_cast<int>(fields.map.size()); ++i) {
    if (!from.IsFieldSet(i)) continue;
    if (from.IsFieldNull(i))
      feature.SetFieldNull(fields.map[i]);
    else
      feature.SetField(fields.map[i], from.GetRawFieldRef(i));
  }
  if (source.layer) feature.SetFID(from.GetFID());
}

/// One output feature for `parts`, the polygons of one input feature.
void write_feature(OGRLayer& layer, std::span<const io::TriangulatedPolygon> parts,
                   const Source* source, const OutputFields& fields, const std::string& path) {
  OGRFeature feature(layer.GetLayerDefn());
  const std::size_t index = parts.front().feature_index;
  if (source != nullptr) copy_values(*source, index, fields, feature);
  const bool from_layer = source != nullptr && source->layer != nullptr &&
                          index < source->features.size() && source->features[index];
  const GIntBig fid = from_layer ? source->features[index]->GetFID() : static_cast<GIntBig>(index);
  auto triangles = std::make_unique<OGRMultiPolygon>();
  std::size_t count = 0;
  const char* status = to_string(Status::ok);
  for (const io::TriangulatedPolygon& part : parts) {
    add_triangles(part, *triangles);
    count += part.triangles.size();
    if (part.status != Status::ok && status == std::string_view(to_string(Status::ok)))
      status = to_string(part.status);
  }
  // The layer's dimensions for every geometry (some drivers refuse a mix): 0 for a polygon
  // without the z or m that others have (write() notes it).
  triangles->set3D(OGR_GT_HasZ(layer.GetGeomType()));
  triangles->setMeasured(OGR_GT_HasM(layer.GetGeomType()));
  feature.SetField(fields.fid, fid);
  feature.SetField(fields.triangles, static_cast<GIntBig>(count));
  feature.SetField(fields.status, status);
  feature.SetGeometryDirectly(triangles.release());
  if (layer.CreateFeature(&feature) != OGRERR_NONE) cannot_write(path, "a feature");
}

/// The output's reference system: the source layer's, else EPSG:srid, else none.
std::unique_ptr<OGRSpatialReference, void (*)(OGRSpatialReference*)> reference(const Source* source,
                                                                               std::uint32_t srid) {
  auto release = [](OGRSpatialReference* srs) {
    if (srs) srs->Release();
  };
  std::unique_ptr<OGRSpatialReference, void (*)(OGRSpatialReference*)> out(nullptr, release);
  const OGRSpatialReference* from = source ? source->reference() : nullptr;
  if (from != nullptr) {
    out.reset(from->Clone());
  } else if (srid != 0) {
    out.reset(new OGRSpatialReference());
    out->SetAxisMappingStrategy(OAMS_TRADITIONAL_GIS_ORDER);
    if (out->importFromEPSG(static_cast<int>(srid)) != OGRERR_NONE) out.reset();
  }
  return out;
}

/// MultiPolygon with z and m where any polygon has them; a note for the polygons that lack
/// what others have (they get 0).
OGRwkbGeometryType geometry_type(std::span<const io::TriangulatedPolygon> results,
                                 const std::string& path, std::vector<std::string>& notes) {
  const auto without = [&](auto empty) {
    return static_cast<std::size_t>(std::count_if(results.begin(), results.end(), empty));
  };
  const std::size_t no_z = without([](const io::TriangulatedPolygon& r) { return r.z.empty(); });
  const std::size_t no_m = without([](const io::TriangulatedPolygon& r) { return r.m.empty(); });
  const bool z = no_z < results.size(), m = no_m < results.size();
  for (const auto& [has, lacking, what] : {std::tuple{z, no_z, "z"}, std::tuple{m, no_m, "m"}})
    if (has && lacking > 0)
      notes.push_back(path + ": " + std::to_string(lacking) + " of " +
                      std::to_string(results.size()) + " polygons have no " + what +
                      ", written with " + what + " 0");
  return z && m ? wkbMultiPolygonZM
         : m    ? wkbMultiPolygonM
         : z    ? wkbMultiPolygon25D
                : wkbMultiPolygon;
}

}  // namespace

std::vector<std::string> write(const std::string& path, const std::string& driver_name,
                               const std::string& layer_name,
                               std::span<const io::TriangulatedPolygon> results,
                               const Source* source, std::uint32_t srid) {
  start_gdal();
  CPLErrorReset();
  GDALDriver* driver = GetGDALDriverManager()->GetDriverByName(driver_name.c_str());
  if (driver == nullptr)
    throw std::runtime_error("cannot write " + path + ": no GDAL driver " + driver_name);
  // pear's own input: its GeoJSON properties become the fields.
  std::vector<std::string> notes;
  const std::shared_ptr<const Source> own =
      source ? nullptr : properties_source(results, path, notes);
  if (own) source = own.get();
  VSIStatBufL stat;
  if (VSIStatL(path.c_str(), &stat) == 0 && driver->Delete(path.c_str()) != CE_None)
    VSIUnlink(path.c_str());  // not a dataset of this driver: an ordinary file
  CPLErrorReset();
  GDALDatasetUniquePtr dataset(driver->Create(path.c_str(), 0, 0, 0, GDT_Unknown, nullptr));
  if (!dataset) cannot_write(path, "GDAL cannot create it");
  const auto srs = reference(source, srid);
  OGRLayer* layer = dataset->CreateLayer(layer_name.c_str(), srs.get(),
                                         geometry_type(results, path, notes), nullptr);
  if (layer == nullptr) cannot_write(path, "layer '" + layer_name + "'");
  const OutputFields fields = create_fields(*layer, source, path, notes);
  const bool transaction = dataset->StartTransaction() == OGRERR_NONE;  // GeoPackage: much faster
  for (std::size_t first = 0; first < results.size();) {
    std::size_t last = first + 1;
    while (last < results.size() && results[last].feature_index == results[first].feature_index)
      ++last;
    write_feature(*layer, results.subspan(first, last - first), source, fields, path);
    first = last;
  }
  if (transaction && dataset->CommitTransaction() != OGRERR_NONE) cannot_write(path, "commit");
  GDALClose(GDALDataset::ToHandle(dataset.release()));
  if (CPLGetLastErrorType() >= CE_Failure) cannot_write(path, "closing it");
  return notes;
}

#else  // built without GDAL: nothing here is reached

class Source {};

bool available() {
  return false;
}
bool reads(const std::string&) {
  return false;
}
Read read(const std::string& name, const LayerChoice&, const io::ReadOptions&) {
  throw io::ParseError(name, 0, 0, 0, "this pear was built without GDAL");
}
std::optional<std::string> driver_for_extension(const std::string&) {
  return std::nullopt;
}
bool is_writable_driver(const std::string&) {
  return false;
}
std::string extension_of_driver(const std::string&) {
  return "";
}
std::vector<std::string> write(const std::string& path, const std::string&, const std::string&,
                               std::span<const io::TriangulatedPolygon>, const Source*,
                               std::uint32_t) {
  throw std::runtime_error("cannot write " + path + ": this pear was built without GDAL");
}

#endif

}  // namespace pear::cli::gis
