// GeoJSON (RFC 7946) polygons by a strict recursive-descent scan: no document tree is built;
// coordinates go straight into rings. Members may come in any order: a "coordinates" (or
// "geometry", ...) value seen before "type" is skipped and read again once the type is known.
#include <cmath>
#include <string>
#include <vector>

#include "pear/io.hpp"
#include "readers.hpp"
#include "scanner.hpp"

namespace pear::io {
namespace {

using detail::Mode;
using detail::NumberSyntax;
using detail::Scanner;

constexpr int max_depth = 512;  // deeper nesting is refused rather than overflowing the stack
constexpr std::size_t none = static_cast<std::size_t>(-1);

// Which GeoJSON types an object may have where it appears.
enum class Place { top, geometry, feature };

class GeoJsonReader {
 public:
  GeoJsonReader(std::string_view text, std::string_view name, const ReadOptions& options, Mode mode)
      : s_(text, name), options_(options), mode_(mode) {}

  ReadResult read() {
    s_.skip_space();
    if (s_.peek() == '{') {
      object(Place::top, 0);
    } else if (s_.peek() == '[') {
      bare_array();
    } else {
      s_.fail_expected(s_.pos, "a GeoJSON object '{' or an array of rings '['");
    }
    s_.skip_space();
    if (!s_.at_end()) s_.fail_expected(s_.pos, "end of file after the GeoJSON value");
    return std::move(result_);
  }

 private:
  // Members of one object that matter; offsets of values not yet read.
  struct Members {
    std::string type;
    std::size_t object_start = 0;
    std::size_t type_at = none;
    std::size_t coordinates = none, geometry = none, geometries = none, features = none;
    bool coordinates_read = false, geometry_read = false, geometries_read = false,
         features_read = false;
    bool skipped = false;           // a geometry that is no polygon, in features mode
    std::size_t first_feature = 0;  // result_.features' size when the object started
    std::string_view properties;    // a Feature's properties object, as text
  };

  void object(Place place, int depth) {
    if (depth > max_depth) s_.fail(s_.pos, "expected at most 512 nested GeoJSON objects");
    Members m;
    m.object_start = s_.pos;
    m.first_feature = result_.features.size();
    s_.expect('{', "'{'");
    s_.skip_space();
    if (s_.peek() == '}') s_.fail_expected(s_.pos, "a \"type\" member");
    for (;;) {
      s_.skip_space();
      member(m, place, depth);
      s_.skip_space();
      if (s_.peek() == '}') break;
      s_.expect(',', "',' or '}' in an object");
    }
    ++s_.pos;
    const std::size_t end = s_.pos;
    if (m.type_at == none) s_.fail(m.object_start, "expected a \"type\" member in this object");
    finish(m, depth);
    if (m.type == "Feature" && !m.properties.empty())
      for (std::size_t f = m.first_feature; f < result_.features.size(); ++f)
        result_.features[f].properties = m.properties;
    s_.pos = end;
  }

  void member(Members& m, Place place, int depth) {
    const std::size_t key_at = s_.pos;
    const std::string key = string_value("a member name in double quotes");
    s_.skip_space();
    s_.expect(':', "':' after a member name");
    s_.skip_space();
    const std::size_t value_at = s_.pos;
    auto remember = [&](std::size_t& slot) {
      if (slot != none)
        s_.fail(key_at, "expected each member once but found \"" + key + "\" again");
      slot = value_at;
    };
    if (key == "type") {
      if (m.type_at != none) s_.fail(key_at, "expected each member once but found \"type\" again");
      m.type_at = value_at;
      m.type = string_value("a GeoJSON type name in double quotes");
      check_type(m, place);
    } else if (key == "coordinates") {
      remember(m.coordinates);
      m.coordinates_read = try_read(m, m.coordinates, depth);
    } else if (key == "geometry") {
      remember(m.geometry);
      m.geometry_read = try_read(m, m.geometry, depth);
    } else if (key == "geometries") {
      remember(m.geometries);
      m.geometries_read = try_read(m, m.geometries, depth);
    } else if (key == "features") {
      remember(m.features);
      m.features_read = try_read(m, m.features, depth);
    } else if (mode_ == Mode::features && key == "properties") {
      skip_value(depth + 1);
      m.properties = properties_text(value_at);
    } else if (mode_ == Mode::features && key == "crs" && depth == 0) {
      skip_value(depth + 1);
      crs(value_at);
    } else {
      skip_value(depth + 1);
    }
  }

  // The properties value that ends at pos: an object's text, or empty for null.
  std::string_view properties_text(std::size_t at) {
    const std::string_view text = s_.text().substr(at, s_.pos - at);
    if (text == "null") return {};
    if (text.front() != '{') s_.fail_expected(at, "an object or null as a Feature's properties");
    return text;
  }

  // The 2008 GeoJSON "crs" member, as GDAL writes it for a layer not in WGS 84:
  // {"type":"name","properties":{"name":"urn:ogc:def:crs:EPSG::32633"}} (or "EPSG:32633");
  // OGC's CRS84 is WGS 84 in longitude, latitude order, EPSG 4326 as GIS software orders it.
  void crs(std::size_t at) {
    const std::string_view text = s_.text().substr(at, s_.pos - at);
    std::uint32_t srid = 0;
    if (text.find("CRS84") != std::string_view::npos) {
      srid = 4326;
    } else if (const std::size_t epsg = text.rfind("EPSG:"); epsg != std::string_view::npos) {
      std::size_t p = epsg + 5;
      while (p < text.size() && text[p] == ':') ++p;
      for (; p < text.size() && text[p] >= '0' && text[p] <= '9' && srid < 100000000; ++p)
        srid = srid * 10 + static_cast<std::uint32_t>(text[p] - '0');
    }
    if (srid == 0) s_.fail_expected(at, "a \"crs\" naming EPSG:N or CRS84");
    result_.srid = srid;
  }

  void check_type(Members& m, Place place) {
    const std::string& t = m.type;
    if (mode_ == Mode::features && place != Place::feature &&
        (t == "Point" || t == "MultiPoint" || t == "LineString" || t == "MultiLineString")) {
      m.skipped = true;
      const detail::Location where = s_.location(m.object_start);
      result_.skipped.push_back({feature_index_, t, where.line, where.column, m.object_start});
      return;
    }
    const bool geometry = t == "Polygon" || t == "MultiPolygon" || t == "GeometryCollection";
    const bool ok = place == Place::top ? geometry || t == "Feature" || t == "FeatureCollection"
                    : place == Place::feature ? t == "Feature"
                                              : geometry;
    if (ok) return;
    const char* expected =
        place == Place::top       ? "Polygon, MultiPolygon, Feature, FeatureCollection "
                                    "or GeometryCollection"
        : place == Place::feature ? "Feature"
                                  : "Polygon, MultiPolygon or GeometryCollection";
    s_.fail(m.type_at, std::string("expected type ") + expected + " but found \"" + t + "\"");
  }

  // Reads the value at `at` now if the type is known and says it belongs to this member;
  // otherwise skips it to be read in finish().
  bool try_read(const Members& m, std::size_t at, int depth) {
    if (m.type_at != none && wanted(m, at)) {
      read_member_value(m, at, depth);
      return true;
    }
    skip_value(depth + 1);
    return false;
  }

  bool wanted(const Members& m, std::size_t at) const {
    const std::string& t = m.type;
    if (m.skipped) return false;
    if (at == m.coordinates) return t == "Polygon" || t == "MultiPolygon";
    if (at == m.geometry) return t == "Feature";
    if (at == m.geometries) return t == "GeometryCollection";
    return at == m.features && t == "FeatureCollection";
  }

  void read_member_value(const Members& m, std::size_t at, int depth) {
    s_.pos = at;
    const std::string& t = m.type;
    if (t == "Polygon") {
      polygon_coordinates();
    } else if (t == "MultiPolygon") {
      array_of([&] { polygon_coordinates(); }, "an array of polygons '['");
    } else if (t == "Feature") {
      if (s_.text().substr(s_.pos, 4) == "null") {
        s_.pos += 4;  // a Feature without a location: no polygon
      } else {
        object(Place::geometry, depth + 1);
      }
    } else if (t == "GeometryCollection") {
      numbered(
          depth == 0, [&] { object(Place::geometry, depth + 1); }, "an array of geometries '['");
    } else {
      numbered(
          true, [&] { object(Place::feature, depth + 1); }, "an array of features '['");
    }
  }

  // An array of a file's features (or top-level geometries), each numbered for feature_index_
  // when `count` says so.
  template <class Element>
  void numbered(bool count, Element element, const char* what) {
    std::size_t index = 0;
    array_of(
        [&] {
          if (count) feature_index_ = index++;
          element();
        },
        what);
  }

  void finish(const Members& m, int depth) {
    struct Need {
      const char* type;
      std::size_t at;
      bool read;
      const char* member;
    };
    const Need needs[] = {{"Polygon", m.coordinates, m.coordinates_read, "coordinates"},
                          {"MultiPolygon", m.coordinates, m.coordinates_read, "coordinates"},
                          {"Feature", m.geometry, m.geometry_read, "geometry"},
                          {"GeometryCollection", m.geometries, m.geometries_read, "geometries"},
                          {"FeatureCollection", m.features, m.features_read, "features"}};
    for (const Need& need : needs) {
      if (m.type != need.type || m.skipped) continue;
      if (need.at == none)
        s_.fail(m.object_start,
                std::string("expected a \"") + need.member + "\" member in this " + need.type);
      if (!need.read) read_member_value(m, need.at, depth);
    }
  }

  template <class Element>
  void array_of(Element element, const char* what) {
    s_.expect('[', what);
    s_.skip_space();
    if (s_.peek() == ']') {
      ++s_.pos;
      return;
    }
    for (;;) {
      s_.skip_space();
      element();
      s_.skip_space();
      if (s_.peek() == ']') break;
      s_.expect(',', "',' or ']' in an array");
    }
    ++s_.pos;
  }

  void polygon_coordinates() {
    Feature feature;
    feature.feature_index = feature_index_;
    Polygon& polygon = feature.polygon;
    int numbers = 0;  // per position in this polygon: 2, or 3 with z (features mode)
    array_of(
        [&] {
          const std::size_t ring_at = s_.pos;
          Ring& ring = polygon.emplace_back();
          array_of(
              [&] {
                const std::size_t at = s_.pos;
                double z = 0;
                int n = 0;
                ring.push_back(position(z, n));
                if (mode_ == Mode::polygons) return;
                if (numbers == 0) numbers = n;
                if (n != numbers)
                  s_.fail(at, "expected " + std::to_string(numbers) +
                                  " numbers in every position of this polygon, as in its "
                                  "first, but found " +
                                  std::to_string(n) + " (its z would be partial)");
                if (n == 3) feature.z.push_back(z);
              },
              "a ring: an array of positions '['");
          const std::size_t kept = ring.size();
          detail::finish_ring(ring, s_, ring_at, options_);
          if (numbers == 3 && ring.size() < kept) feature.z.pop_back();  // the closing point
        },
        "a polygon: an array of rings '['");
    if (!polygon.empty()) result_.features.push_back(std::move(feature));
  }

  // x and y; the third number (altitude) in z; how many numbers (2, or 3 for 3 or more).
  Point position(double& z, int& numbers) {
    s_.expect('[', "a position '[x, y]'");
    s_.skip_space();
    Point p;
    p.x = s_.number(NumberSyntax::json);
    s_.skip_space();
    s_.expect(',', "',' and the y coordinate");
    s_.skip_space();
    p.y = s_.number(NumberSyntax::json);
    s_.skip_space();
    numbers = 2;
    while (s_.peek() == ',') {  // an altitude; anything after it is ignored
      ++s_.pos;
      s_.skip_space();
      const double value = s_.number(NumberSyntax::json);
      if (numbers == 2) z = value, numbers = 3;
      s_.skip_space();
    }
    s_.expect(']', "',' or ']' after a coordinate");
    return p;
  }

  // `[[[x,y],...],...]` (one polygon) or `[[[[x,y],...],...],...]` (several), as earcut's fixtures.
  void bare_array() {
    int depth = 0;
    std::size_t p = s_.pos;
    const std::string_view text = s_.text();
    while (p < text.size()) {
      const char c = text[p];
      if (c == '[') {
        ++depth;
      } else if (c != ' ' && c != '\n' && c != '\r' && c != '\t') {
        break;
      }
      ++p;
    }
    if (p < text.size() && text[p] == ']' && depth == 1) {  // `[]`: no polygons
      s_.pos = p + 1;
      return;
    }
    if (depth == 3) {
      polygon_coordinates();
    } else if (depth == 4) {
      array_of([&] { polygon_coordinates(); }, "an array of polygons '['");
    } else {
      s_.fail_expected(p, "an array of rings [[[x,y],...],...] or of polygons at nesting depth " +
                              std::to_string(depth + 1));
    }
  }

  std::string string_value(const char* what) {
    if (s_.peek() != '"') s_.fail_expected(s_.pos, what);
    const std::size_t start = s_.pos;
    std::string out;
    ++s_.pos;
    const std::string_view text = s_.text();
    for (;;) {
      if (s_.at_end()) s_.fail_expected(start, "a string closed by '\"'");
      const char c = text[s_.pos];
      if (c == '"') break;
      if (static_cast<unsigned char>(c) < 0x20)
        s_.fail_expected(s_.pos, "'\"' or a string character");
      if (c == '\\') {
        escape(out);
        continue;
      }
      out.push_back(c);
      ++s_.pos;
    }
    ++s_.pos;
    return out;
  }

  void escape(std::string& out) {
    const std::string_view text = s_.text();
    const std::size_t at = s_.pos++;
    const char e = s_.peek();
    const std::string_view simple = "\"\\/bfnrt";
    const std::string_view meaning = "\"\\/\b\f\n\r\t";
    if (const auto k = simple.find(e); e != '\0' && k != std::string_view::npos) {
      out.push_back(meaning[k]);
      ++s_.pos;
      return;
    }
    if (e != 'u') s_.fail_expected(at, "an escape such as \\n or \\u00e9");
    ++s_.pos;
    for (int i = 0; i < 4; ++i, ++s_.pos) {
      if (s_.at_end() || !std::isxdigit(static_cast<unsigned char>(text[s_.pos])))
        s_.fail_expected(s_.pos, "four hex digits after \\u");
    }
    out.push_back('?');  // names we compare against are ASCII; the code point itself is not needed
  }

  void skip_value(int depth) {
    if (depth > max_depth) s_.fail(s_.pos, "expected at most 512 nested JSON values");
    const char c = s_.peek();
    if (c == '{') {
      ++s_.pos;
      s_.skip_space();
      if (s_.peek() == '}') {
        ++s_.pos;
        return;
      }
      for (;;) {
        s_.skip_space();
        string_value("a member name in double quotes");
        s_.skip_space();
        s_.expect(':', "':' after a member name");
        s_.skip_space();
        skip_value(depth + 1);
        s_.skip_space();
        if (s_.peek() == '}') break;
        s_.expect(',', "',' or '}' in an object");
      }
      ++s_.pos;
    } else if (c == '[') {
      array_of([&] { skip_value(depth + 1); }, "'['");
    } else if (c == '"') {
      string_value("a string");
    } else if (c == 't' || c == 'f' || c == 'n') {
      for (const std::string_view word : {"true", "false", "null"}) {
        if (s_.text().substr(s_.pos, word.size()) == word) {
          s_.pos += word.size();
          return;
        }
      }
      s_.fail_expected(s_.pos, "a JSON value");
    } else {
      if (c != '-' && !(c >= '0' && c <= '9')) s_.fail_expected(s_.pos, "a JSON value");
      s_.number(NumberSyntax::json);
    }
  }

  Scanner s_;
  const ReadOptions& options_;
  Mode mode_;
  ReadResult result_;
  std::size_t feature_index_ = 0;
};

}  // namespace

ReadResult detail::read_geojson(std::string_view text, std::string_view name,
                                const ReadOptions& options, Mode mode) {
  return GeoJsonReader(text, name, options, mode).read();
}

std::vector<Polygon> read_geojson(std::string_view text, std::string_view name,
                                  const ReadOptions& options) {
  return detail::polygons_of(detail::read_geojson(text, name, options, Mode::polygons));
}

}  // namespace pear::io
