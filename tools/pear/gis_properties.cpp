// GeoJSON properties as the fields of a GDAL output: each member a field, typed by all its
// values as GDAL's GeoJSON driver types them, parsed with GDAL's JSON reader (cpl_json.h).
#include <cpl_error.h>
#include <cpl_json.h>

#include <algorithm>
#include <map>
#include <stdexcept>
#include <utility>

#include "gis_source.hpp"

namespace pear::cli::gis {
namespace {

/// What a GeoJSON property's values need of a field, JSON's kinds merged into the narrowest
/// OGR type that holds every value met (as GDAL's GeoJSON driver does): numbers widen from
/// integer to real, objects and arrays are JSON text, and a mix of kinds is text.
enum class Kind { none, boolean, integer, integer64, real, json, text };

Kind kind_of(const CPLJSONObject& value) {
  switch (value.GetType()) {
    case CPLJSONObject::Type::Boolean:
      return Kind::boolean;
    case CPLJSONObject::Type::Integer:
      return Kind::integer;
    case CPLJSONObject::Type::Long:
      return Kind::integer64;
    case CPLJSONObject::Type::Double:
      return Kind::real;
    case CPLJSONObject::Type::Object:
    case CPLJSONObject::Type::Array:
      return Kind::json;
    case CPLJSONObject::Type::String:
      return Kind::text;
    default:
      return Kind::none;  // null
  }
}

Kind merge(Kind a, Kind b) {
  if (a == Kind::none || a == b) return b;
  if (b == Kind::none) return a;
  const auto number = [](Kind k) { return k >= Kind::integer && k <= Kind::real; };
  return number(a) && number(b) ? std::max(a, b) : Kind::text;
}

std::unique_ptr<OGRFieldDefn> field_definition(const std::string& name, Kind kind) {
  const OGRFieldType type = kind == Kind::boolean || kind == Kind::integer ? OFTInteger
                            : kind == Kind::integer64                      ? OFTInteger64
                            : kind == Kind::real                           ? OFTReal
                                                                           : OFTString;
  auto field = std::make_unique<OGRFieldDefn>(name.c_str(), type);
  if (kind == Kind::boolean) field->SetSubType(OFSTBoolean);
  if (kind == Kind::json) field->SetSubType(OFSTJSON);
  return field;
}

/// One property's value into a field of its merged kind: a string as it is, any other value
/// in a text field as its JSON.
void set_property(OGRFeature& feature, int field, Kind kind, const CPLJSONObject& value) {
  if (kind_of(value) == Kind::none) return feature.SetFieldNull(field);
  if (kind == Kind::boolean) return feature.SetField(field, value.ToBool() ? 1 : 0);
  if (kind == Kind::integer) return feature.SetField(field, value.ToInteger());
  if (kind == Kind::integer64) return feature.SetField(field, static_cast<GIntBig>(value.ToLong()));
  if (kind == Kind::real) return feature.SetField(field, value.ToDouble());
  const bool text = value.GetType() == CPLJSONObject::Type::String;
  feature.SetField(
      field, (text ? value.ToString() : value.Format(CPLJSONObject::PrettyFormat::Plain)).c_str());
}

/// Each feature's properties (a JSON object's text), parsed once per feature (its parts are
/// adjacent in the results and share them).
std::vector<std::pair<std::size_t, std::unique_ptr<CPLJSONDocument>>> parse_properties(
    std::span<const io::TriangulatedPolygon> results, const std::string& path) {
  std::vector<std::pair<std::size_t, std::unique_ptr<CPLJSONDocument>>> parsed;
  for (const io::TriangulatedPolygon& r : results) {
    if (r.properties.empty() || (!parsed.empty() && parsed.back().first == r.feature_index))
      continue;
    auto document = std::make_unique<CPLJSONDocument>();
    CPLErrorReset();
    if (!document->LoadMemory(r.properties))
      throw std::runtime_error("cannot write " + path + ": feature " +
                               std::to_string(r.feature_index) +
                               "'s properties: " + CPLGetLastErrorMsg());
    parsed.emplace_back(r.feature_index, std::move(document));
  }
  return parsed;
}

}  // namespace

std::shared_ptr<const Source> properties_source(std::span<const io::TriangulatedPolygon> results,
                                                const std::string& path) {
  const auto parsed = parse_properties(results, path);
  if (parsed.empty()) return nullptr;
  std::map<std::string, int> field_of_name;
  std::vector<Kind> kinds;
  auto source = std::make_shared<Source>();
  source->own_fields.reset(new OGRFeatureDefn("properties"));
  source->own_fields->Reference();
  std::vector<std::string> names;
  for (const auto& [index, document] : parsed)
    for (const CPLJSONObject& member : document->GetRoot().GetChildren()) {
      const auto [at, added] = field_of_name.try_emplace(member.GetName(), kinds.size());
      if (added) kinds.push_back(Kind::none), names.push_back(member.GetName());
      kinds[at->second] = merge(kinds[at->second], kind_of(member));
    }
  for (std::size_t f = 0; f < kinds.size(); ++f) {
    source->own_fields->AddFieldDefn(field_definition(names[f], kinds[f]).get());
  }
  for (const auto& [index, document] : parsed) {
    OGRFeatureUniquePtr feature(OGRFeature::CreateFeature(source->own_fields.get()));
    for (const CPLJSONObject& member : document->GetRoot().GetChildren()) {
      const int field = field_of_name.at(member.GetName());
      set_property(*feature, field, kinds[field], member);
    }
    if (source->features.size() <= index) source->features.resize(index + 1);
    source->features[index] = std::move(feature);
  }
  return source;
}

}  // namespace pear::cli::gis
