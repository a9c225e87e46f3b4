// What a GDAL output takes from its input (gis.cpp): a GDAL layer read, or the fields made from
// GeoJSON properties (gis_properties.cpp). Only in a build with GDAL.
#pragma once

#include <gdal_priv.h>
#include <ogrsf_frmts.h>

#include <memory>
#include <span>
#include <string>
#include <vector>

#include "gis.hpp"
#include "pear/io.hpp"

namespace pear::cli::gis {

/// Releases a feature definition made here (OGR counts its references).
struct ReleaseDefinition {
  void operator()(OGRFeatureDefn* definition) const { definition->Release(); }
};

/// Fields, reference system and each feature's values. For a GDAL input: its layer (the
/// dataset kept open; the features share the layer's definition). For pear's own GeoJSON:
/// fields made from the features' properties.
class Source {
 public:
  GDALDatasetUniquePtr dataset;
  OGRLayer* layer = nullptr;
  std::unique_ptr<OGRFeatureDefn, ReleaseDefinition> own_fields;
  std::vector<OGRFeatureUniquePtr> features;  ///< by feature_index (null: none), no geometry

  OGRFeatureDefn* fields() const { return layer ? layer->GetLayerDefn() : own_fields.get(); }
  const OGRSpatialReference* reference() const { return layer ? layer->GetSpatialRef() : nullptr; }
};

/// pear's own input (GeoJSON) as a Source: the members of the features' properties become
/// fields, in the order first met, each typed by all its values (gis.hpp's write says how);
/// features by feature_index. Null when no feature has properties. A note names an integer at
/// int64's limit (GDAL's JSON reader clamps larger ones to it). Throws std::runtime_error
/// naming `path` (the output) and the feature when GDAL's JSON parser refuses properties.
std::shared_ptr<const Source> properties_source(std::span<const io::TriangulatedPolygon> results,
                                                const std::string& path,
                                                std::vector<std::string>& notes);

}  // namespace pear::cli::gis
