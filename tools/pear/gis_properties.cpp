// GeoJSON properties as the fields of a GDAL output: each member a field, typed by all its
// values as GDAL's GeoJSON driver types them, parsed with GDAL's JSON reader (cpl_json.h).
#include <cpl_error.h>
#include <cpl_json.h>

#include <algorithm>
#include <limits>
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

/// The field's type for values of `kind` (a field of only nulls is text, as in GDAL).
void set_field_kind(OGRFieldDefn& field, Kind kind) {
  field.SetType(kind == Kind::boolean || kind == Kind::integer ? OFTInteger
                : kind == Kind::integer64                      ? OFTInteger64
                : kind == Kind::real                           ? OFTReal
                                                               : OFTString);
  field.SetSubType(kind == Kind::boolean ? OFSTBoolean : kind == Kind::json ? OFSTJSON : OFSTNone);
}

/// Whether an integer is at int64's limit, where GDAL's JSON reader (json-c) clamps larger ones.
bool at_integer_limit(const CPLJSONObject& value) {
  if (value.GetType() != CPLJSONObject::Type::Long) return false;
  const GInt64 number = value.ToLong();
  return number == std::numeric_limits<GInt64>::max() ||
         number == std::numeric_limits<GInt64>::min();
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
                                                const std::string& path,
                                                std::vector<std::string>& notes) {
  const auto parsed = parse_properties(results, path);
  if (parsed.empty()) return nullptr;
  std::map<std::string, int> field_of_name;
  std::vector<Kind> kinds;
  auto source = std::make_shared<Source>();
  source->own_fields.reset(new OGRFeatureDefn("properties"));
  source->own_fields->Reference();
  for (const auto& [index, document] : parsed)
    for (const CPLJSONObject& member : document->GetRoot().GetChildren()) {
      const auto [at, added] = field_of_name.try_emplace(member.GetName(), kinds.size());
      if (added) {
        OGRFieldDefn field(member.GetName().c_str(), OFTString);  // typed once all are met
        source->own_fields->AddFieldDefn(&field);
        kinds.push_back(Kind::none);
      }
      kinds[at->second] = merge(kinds[at->second], kind_of(member));
    }
  for (std::size_t f = 0; f < kinds.size(); ++f)
    set_field_kind(*source->own_fields->GetFieldDefn(static_cast<int>(f)), kinds[f]);
  std::vector<bool> clamped(kinds.size());
  for (const auto& [index, document] : parsed) {
    OGRFeatureUniquePtr feature(OGRFeature::CreateFeature(source->own_fields.get()));
    for (const CPLJSONObject& member : document->GetRoot().GetChildren()) {
      const int field = field_of_name.at(member.GetName());
      set_property(*feature, field, kinds[field], member);
      if (!clamped[field] && at_integer_limit(member)) {
        clamped[field] = true;
        notes.push_back(path + ": feature " + std::to_string(index) + "'s property '" +
                        member.GetName() +
                        "' is an integer at or past 64 bits' limit, written as " +
                        std::to_string(member.ToLong()) + " (GDAL's JSON reader clamps it)");
      }
    }
    if (source->features.size() <= index) source->features.resize(index + 1);
    source->features[index] = std::move(feature);
  }
  return source;
}

}  // namespace pear::cli::gis
