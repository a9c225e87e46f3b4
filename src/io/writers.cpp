// Text writers. Every coordinate goes through format_double: std::to_chars' shortest form, which
// reads back to the same double, so outputs round-trip bit-identically.
#include <charconv>
#include <ostream>
#include <stdexcept>
#include <string>

#include "pear/io.hpp"
#include "rings.hpp"

namespace pear::io {

std::string format_double(double value) {
  char buffer[32];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, end);
}

namespace {

// Appends to a string and hands it to the stream in large pieces: much faster than many small
// stream insertions for million-point outputs.
class Sink {
 public:
  explicit Sink(std::ostream& out) : out_(out) { text_.reserve(1 << 17); }
  ~Sink() { flush(); }
  Sink& operator<<(std::string_view s) {
    text_ += s;
    if (text_.size() >= (1 << 16)) flush();
    return *this;
  }
  Sink& operator<<(char c) {
    text_ += c;
    return *this;
  }
  Sink& operator<<(double v) {
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    return *this << std::string_view(buffer, static_cast<std::size_t>(end - buffer));
  }
  Sink& operator<<(std::size_t v) {
    char buffer[24];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
    return *this << std::string_view(buffer, static_cast<std::size_t>(end - buffer));
  }
  void flush() {
    out_.write(text_.data(), static_cast<std::streamsize>(text_.size()));
    text_.clear();
  }

 private:
  std::ostream& out_;
  std::string text_;
};

// Point i of a polygon numbered ring after ring.
std::vector<Point> flat_points(const Polygon& polygon) {
  std::vector<Point> points;
  for (const Ring& ring : polygon) points.insert(points.end(), ring.begin(), ring.end());
  return points;
}

void check_triangles(const TriangulatedPolygon& p, std::size_t point_count) {
  if (!p.z.empty() && p.z.size() != point_count)
    throw std::invalid_argument("a polygon of " + std::to_string(point_count) + " points has " +
                                std::to_string(p.z.size()) + " z values");
  for (const auto& t : p.triangles)
    for (const std::uint32_t v : t)
      if (v >= point_count)
        throw std::invalid_argument("triangle index " + std::to_string(v) +
                                    " is past the polygon's " + std::to_string(point_count) +
                                    " points");
}

void json_position(Sink& out, const Point& p) {
  out << '[' << p.x << ',' << p.y << ']';
}

void json_ring(Sink& out, const Ring& ring) {
  out << '[';
  for (const Point& p : ring) {
    json_position(out, p);
    out << ',';
  }
  if (!ring.empty()) json_position(out, ring.front());  // GeoJSON rings are closed
  out << ']';
}

void json_polygon(Sink& out, const Polygon& polygon) {
  out << '[';
  for (std::size_t r = 0; r < polygon.size(); ++r) {
    if (r > 0) out << ',';
    json_ring(out, polygon[r]);
  }
  out << ']';
}

/// A triangle's closed ring, with z where the polygon has it.
void json_triangle(Sink& out, const std::vector<Point>& points, const std::vector<double>& z,
                   const std::array<std::uint32_t, 3>& t) {
  out << '[';
  for (int k = 0; k < 4; ++k) {
    const std::uint32_t v = t[k % 3];
    out << (k > 0 ? ",[" : "[") << points[v].x << ',' << points[v].y;
    if (!z.empty()) out << ',' << z[v];
    out << ']';
  }
  out << ']';
}

/// The members of a JSON object's text without its braces, less a top-level member named
/// "pear" (pear's own takes its place). The text is valid JSON (a reader's verbatim copy of a
/// properties object), so only strings and nesting need following.
std::string members_except_pear(std::string_view object) {
  const auto trim = [](std::string_view text) {
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return std::string_view{};
    return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
  };
  object = trim(object);
  if (object.empty()) return {};
  if (object.size() < 2 || object.front() != '{' || object.back() != '}')
    throw std::invalid_argument("properties must be a JSON object, not: " +
                                std::string(object.substr(0, 40)));
  std::string out;
  const auto keep = [&](std::string_view member) {
    member = trim(member);
    const std::string_view rest = member.starts_with("\"pear\"") ? trim(member.substr(6)) : "";
    if (member.empty() || rest.starts_with(':')) return;
    if (!out.empty()) out += ',';
    out += member;
  };
  int depth = 0;
  bool in_string = false;
  std::size_t start = 1;
  for (std::size_t i = 1; i + 1 < object.size(); ++i) {
    const char c = object[i];
    if (in_string) {
      i += c == '\\' ? 1 : 0;
      in_string = c != '"';
    } else if (c == '"') {
      in_string = true;
    } else if (c == '{' || c == '[') {
      ++depth;
    } else if (c == '}' || c == ']') {
      --depth;
    } else if (c == ',' && depth == 0) {
      keep(object.substr(start, i - start));
      start = i + 1;
    }
  }
  keep(object.substr(start, object.size() - 1 - start));
  return out;
}

/// The 2008 GeoJSON "crs" member that GDAL reads, for an SRID other than WGS 84's.
void json_crs(Sink& out, std::uint32_t srid) {
  if (srid == 0 || srid == 4326) return;  // none, or RFC 7946's default
  out << "\"crs\":{\"type\":\"name\",\"properties\":{\"name\":\"urn:ogc:def:crs:EPSG::"
      << std::size_t{srid} << "\"}},";
}

}  // namespace

void write_obj(std::ostream& stream, std::span<const TriangulatedPolygon> polygons) {
  Sink out(stream);
  std::size_t offset = 1;  // OBJ numbers vertices from 1 across the whole file
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const std::vector<Point> points = flat_points(polygons[i].polygon);
    check_triangles(polygons[i], points.size());
    out << "o polygon_" << i << '\n';
    const std::vector<double>& z = polygons[i].z;
    for (std::size_t v = 0; v < points.size(); ++v)
      out << "v " << points[v].x << ' ' << points[v].y << ' ' << (z.empty() ? 0.0 : z[v]) << '\n';
    for (const auto& t : polygons[i].triangles)
      out << "f " << offset + t[0] << ' ' << offset + t[1] << ' ' << offset + t[2] << '\n';
    offset += points.size();
  }
}

void write_geojson(std::ostream& stream, std::span<const TriangulatedPolygon> polygons,
                   std::uint32_t srid) {
  Sink out(stream);
  out << "{\"type\":\"FeatureCollection\",";
  json_crs(out, srid);
  out << "\"features\":[";
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    const TriangulatedPolygon& polygon = polygons[i];
    const std::vector<Point> points = flat_points(polygon.polygon);
    check_triangles(polygon, points.size());
    const std::string members = members_except_pear(polygon.properties);
    out << (i > 0 ? ",\n" : "\n") << "{\"type\":\"Feature\",\"properties\":{" << members
        << (members.empty() ? "" : ",") << "\"pear\":{\"index\":" << i
        << ",\"feature\":" << polygon.feature_index << ",\"triangles\":" << polygon.triangles.size()
        << ",\"status\":\"" << std::string_view(to_string(polygon.status))
        << "\"}},\"geometry\":{\"type\":\"MultiPolygon\",\"coordinates\":[";
    for (std::size_t k = 0; k < polygon.triangles.size(); ++k) {
      out << (k > 0 ? ",[" : "[");
      json_triangle(out, points, polygon.z, polygon.triangles[k]);
      out << ']';
    }
    out << "]}}";
  }
  out << "\n]}\n";
}

void write_node_ele(std::ostream& node_stream, std::ostream& ele_stream,
                    std::span<const TriangulatedPolygon> polygons) {
  std::size_t point_total = 0;
  std::size_t triangle_total = 0;
  for (const auto& p : polygons) {
    for (const Ring& ring : p.polygon) point_total += ring.size();
    triangle_total += p.triangles.size();
  }
  Sink node(node_stream);
  Sink ele(ele_stream);
  node << point_total << " 2 0 0\n";
  ele << triangle_total << " 3 0\n";
  std::size_t offset = 0;
  std::size_t triangle_number = 0;
  for (const auto& polygon : polygons) {
    const std::vector<Point> points = flat_points(polygon.polygon);
    check_triangles(polygon, points.size());
    for (std::size_t i = 0; i < points.size(); ++i)
      node << offset + i << ' ' << points[i].x << ' ' << points[i].y << '\n';
    for (const auto& t : polygon.triangles)
      ele << triangle_number++ << ' ' << offset + t[0] << ' ' << offset + t[1] << ' '
          << offset + t[2] << '\n';
    offset += points.size();
  }
}

void write_geojson_polygons(std::ostream& stream, std::span<const Polygon> polygons) {
  Sink out(stream);
  if (polygons.size() == 1) {
    out << "{\"type\":\"Polygon\",\"coordinates\":";
    json_polygon(out, polygons[0]);
  } else {
    out << "{\"type\":\"MultiPolygon\",\"coordinates\":[";
    for (std::size_t i = 0; i < polygons.size(); ++i) {
      if (i > 0) out << ",\n";
      json_polygon(out, polygons[i]);
    }
    out << ']';
  }
  out << "}\n";
}

void write_wkt(std::ostream& stream, std::span<const Polygon> polygons) {
  Sink out(stream);
  // read_wkt needs at least one geometry; an empty one reads back as no polygons.
  if (polygons.empty()) out << "POLYGON EMPTY\n";
  for (const Polygon& polygon : polygons) {
    if (polygon.empty()) {
      out << "POLYGON EMPTY\n";
      continue;
    }
    out << "POLYGON (";
    for (std::size_t r = 0; r < polygon.size(); ++r) {
      out << (r > 0 ? ", (" : "(");
      const Ring& ring = polygon[r];
      if (ring.empty()) throw std::invalid_argument("write_wkt: an empty ring");
      for (std::size_t i = 0; i <= ring.size(); ++i) {  // closed, as WKT requires
        const Point& p = ring[i % ring.size()];
        out << (i > 0 ? ", " : "") << p.x << ' ' << p.y;
      }
      out << ')';
    }
    out << ")\n";
  }
}

void write_poly(std::ostream& stream, std::span<const Polygon> polygons) {
  std::vector<Ring> rings;
  std::vector<std::size_t> holes;  // indices into rings
  for (const Polygon& polygon : polygons) {
    for (std::size_t r = 0; r < polygon.size(); ++r) {
      if (polygon[r].size() < 3)
        throw std::invalid_argument("write_poly: a ring has fewer than 3 points");
      if (r > 0) holes.push_back(rings.size());
      rings.push_back(polygon[r]);
    }
  }
  std::vector<detail::Box> boxes;
  for (const Ring& ring : rings) boxes.push_back(detail::bounding_box(ring));
  std::vector<Point> hole_points;
  for (const std::size_t h : holes) {
    Point point;
    if (!detail::interior_point(rings[h], rings, boxes, point))
      throw std::invalid_argument("write_poly: ring " + std::to_string(h) +
                                  " has no interior point for its hole marker (zero area?)");
    hole_points.push_back(point);
  }
  std::size_t total = 0;
  for (const Ring& ring : rings) total += ring.size();
  Sink out(stream);
  out << total << " 2 0 0\n";
  std::size_t v = 0;
  for (const Ring& ring : rings)
    for (const Point& p : ring) out << v++ << ' ' << p.x << ' ' << p.y << '\n';
  out << total << " 0\n";
  std::size_t first = 0;
  for (const Ring& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i)
      out << first + i << ' ' << first + i << ' ' << first + (i + 1) % ring.size() << '\n';
    first += ring.size();
  }
  out << hole_points.size() << '\n';
  for (std::size_t h = 0; h < hole_points.size(); ++h)
    out << h << ' ' << hole_points[h].x << ' ' << hole_points[h].y << '\n';
}

}  // namespace pear::io
