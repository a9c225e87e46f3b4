// GIS formats through GDAL/OGR: reading polygon layers (GeoPackage, Shapefile, FlatGeobuf, and
// whatever else OGR opens) and writing triangles as an OGR layer. Only the CLI uses GDAL; the
// library and libpear_io stay standard-library only. Built without GDAL (-Dgdal=disabled),
// available() is false and nothing here is ever reached.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "pear/io.hpp"

namespace pear::cli::gis {

/// Which layer and features of a dataset to read (--layer, --where).
struct LayerChoice {
  std::optional<std::string> layer;  ///< none: the first layer (a note names the others)
  std::optional<std::string> where;  ///< an OGR SQL attribute filter
};

/// What writing needs of the layer an input came from: its fields, spatial reference, and each
/// feature's FID and field values by feature_index. Opaque outside gis.cpp.
class Source;

struct Read {
  io::ReadResult read;                   ///< feature_index: the feature's place in the layer
  std::shared_ptr<const Source> source;  ///< none for a file pear reads itself
  std::string layer;                     ///< the layer's name (empty for pear's own formats)
  std::string note;                      ///< for stderr when not empty (other layers)
};

/// Built with GDAL.
bool available();

/// Whether GDAL is to read `name`: a file whose extension pear does not read itself, that GDAL
/// opens as a vector dataset (or whose extension a GDAL vector driver claims, so that GDAL's
/// error is the one reported).
bool reads(const std::string& name);

/// The polygons of one layer, with their properties (as JSON text, for GeoJSON output) and z;
/// other geometries skipped and listed. Throws io::ParseError naming the file (and layer) when
/// GDAL cannot open it, the layer does not exist, the filter is not valid, or no polygon is in
/// the layer.
Read read(const std::string& name, const LayerChoice& choice, const io::ReadOptions& options);

/// The GDAL vector driver that can create files with this extension (".gpkg" -> "GPKG"), if any.
std::optional<std::string> driver_for_extension(const std::string& extension);
/// Whether `name` is a GDAL vector driver that can create datasets.
bool is_writable_driver(const std::string& name);
/// The extension a driver's files have (".gpkg"), for one output per input in a directory.
std::string extension_of_driver(const std::string& name);

/// Writes one layer: one feature per input feature, a MultiPolygon of its polygons' triangles
/// (with z and m when the input has them), the source's fields and each feature's values,
/// pear's fields (pear_fid: the source feature's FID or feature_index, pear_tris, pear_stat),
/// and the source layer's spatial reference (else EPSG:srid when srid is not 0). The source is
/// the GDAL layer read, else the GeoJSON features' properties (each member a field, typed by
/// its values: integer, real, boolean, JSON for objects and arrays, text for a mix). A field
/// keeps its name unless one before it (the source's come first) has that name, ignoring
/// case: then it is written as name2 (or name3, ...) and a note (returned) says so. An
/// existing file is replaced. Throws std::runtime_error naming the path.
std::vector<std::string> write(const std::string& path, const std::string& driver,
                               const std::string& layer_name,
                               std::span<const io::TriangulatedPolygon> results,
                               const Source* source, std::uint32_t srid);

}  // namespace pear::cli::gis
