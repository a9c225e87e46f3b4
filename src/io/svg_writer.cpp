// A picture of polygons and their triangles: the polygon filled (holes left open), triangles
// filled by the part that made them, thin edges where they are legible, the rings outlined.
// Coordinates are mapped to pixels here (y up), so geographic degrees and tiny inputs alike
// fill the viewport and the file holds short fixed-point numbers.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <ostream>
#include <string>

#include "pear/io.hpp"

namespace pear::io {
namespace {

// ColorBrewer "Set3" (12 light qualitative colours): neighbouring parts stay distinguishable.
constexpr const char* part_colours[] = {"#8dd3c7", "#ffffb3", "#bebada", "#fb8072",
                                        "#80b1d3", "#fdb462", "#b3de69", "#fccde5",
                                        "#d9d9d9", "#bc80bd", "#ccebc5", "#ffed6f"};
constexpr const char* single_colour = "#a6cee3";

struct View {
  double min_x = 0, max_y = 0, scale = 1, margin = 0, width = 0, height = 0;

  void fit(std::span<const TriangulatedPolygon> polygons, double size) {
    double min_y = std::numeric_limits<double>::infinity(), max_x = -min_y;
    min_x = min_y;
    max_y = -min_y;
    for (const auto& p : polygons)
      for (const Ring& ring : p.polygon)
        for (const Point& q : ring) {
          if (!std::isfinite(q.x) || !std::isfinite(q.y)) continue;
          min_x = std::min(min_x, q.x), max_x = std::max(max_x, q.x);
          min_y = std::min(min_y, q.y), max_y = std::max(max_y, q.y);
        }
    if (!(min_x <= max_x)) min_x = max_x = min_y = max_y = 0;
    const double span = std::max(max_x - min_x, max_y - min_y);
    margin = size * 0.02;
    scale = span > 0 && std::isfinite(span) ? (size - 2 * margin) / span : 1;
    width = (max_x - min_x) * scale + 2 * margin;
    height = (max_y - min_y) * scale + 2 * margin;
  }
  double x(const Point& p) const { return margin + (p.x - min_x) * scale; }
  double y(const Point& p) const { return margin + (max_y - p.y) * scale; }
};

void pixel(std::string& out, double v) {
  char buffer[48];
  const auto [end, ec] =
      std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed, 2);
  out.append(buffer, end);
}

void move_line(std::string& out, const View& view, const Point& p, char command) {
  out += command;
  pixel(out, view.x(p));
  out += ' ';
  pixel(out, view.y(p));
}

std::string rings_path(const View& view, std::span<const TriangulatedPolygon> polygons) {
  std::string d;
  for (const auto& p : polygons)
    for (const Ring& ring : p.polygon) {
      for (std::size_t i = 0; i < ring.size(); ++i) move_line(d, view, ring[i], i == 0 ? 'M' : 'L');
      if (!ring.empty()) d += 'Z';
    }
  return d;
}

// Average triangle side in pixels, to size the edges: thin where triangles are small.
double triangle_pixels(const View& view, std::span<const TriangulatedPolygon> polygons) {
  double area = 0;
  std::size_t count = 0;
  for (const auto& p : polygons) {
    std::vector<Point> points;
    for (const Ring& ring : p.polygon) points.insert(points.end(), ring.begin(), ring.end());
    for (const auto& t : p.triangles) {
      const Point &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
      area += std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / 2;
      ++count;
    }
  }
  return count == 0 ? 0 : std::sqrt(area / static_cast<double>(count)) * view.scale;
}

// One path per colour: triangles grouped by part.
std::map<std::uint32_t, std::string> triangle_paths(const View& view,
                                                    std::span<const TriangulatedPolygon> polygons) {
  std::map<std::uint32_t, std::string> paths;
  for (const auto& p : polygons) {
    std::vector<Point> points;
    for (const Ring& ring : p.polygon) points.insert(points.end(), ring.begin(), ring.end());
    for (std::size_t k = 0; k < p.triangles.size(); ++k) {
      std::string& d = paths[p.part.size() == p.triangles.size() ? p.part[k] : 0];
      const auto& t = p.triangles[k];
      move_line(d, view, points[t[0]], 'M');
      move_line(d, view, points[t[1]], 'L');
      move_line(d, view, points[t[2]], 'L');
      d += 'Z';
    }
  }
  return paths;
}

std::string escape_xml(std::string_view text) {
  std::string out;
  for (const char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else
      out += c;
  }
  return out;
}

void check(std::span<const TriangulatedPolygon> polygons) {
  for (const auto& p : polygons) {
    std::size_t n = 0;
    for (const Ring& ring : p.polygon) n += ring.size();
    for (const auto& t : p.triangles)
      for (const std::uint32_t v : t)
        if (v >= n) throw std::invalid_argument("write_svg: triangle index past the points");
  }
}

}  // namespace

void write_svg(std::ostream& out, std::span<const TriangulatedPolygon> polygons,
               const SvgOptions& options) {
  check(polygons);
  View view;
  view.fit(polygons, options.size);
  const double side = triangle_pixels(view, polygons);
  const double edge = std::clamp(side * 0.06, 0.15, 1.0);
  const double outline = std::clamp(options.size / 700, 0.8, 3.0);
  bool parts = false;
  for (const auto& p : polygons) parts = parts || !p.part.empty();

  // The title gets its own band under the picture, so it never covers the polygon.
  const double font = std::max(10.0, options.size / 60);
  const double band = options.title.empty() ? 0 : font * 1.6;
  std::string width, height;
  pixel(width, view.width);
  pixel(height, view.height + band);
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" viewBox=\"0 0 " << width << ' ' << height << "\">\n";
  if (!options.title.empty()) out << "<title>" << escape_xml(options.title) << "</title>\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"#fbfbf8\"/>\n";
  const std::string outline_path = rings_path(view, polygons);
  out << "<path fill=\"#e4e4de\" fill-rule=\"evenodd\" d=\"" << outline_path << "\"/>\n";
  // Edges only where a triangle is a few pixels across; below that they would blacken the fill.
  const bool edges = options.draw_edges && side >= 2.5;
  for (const auto& [part, d] : triangle_paths(view, polygons)) {
    const char* colour = parts ? part_colours[part % std::size(part_colours)] : single_colour;
    out << "<path fill=\"" << colour << '"';
    if (edges)
      out << " stroke=\"#2b4a6b\" stroke-opacity=\"0.55\" stroke-width=\"" << edge
          << "\" stroke-linejoin=\"round\"";
    else
      out << " stroke=\"" << colour << "\" stroke-width=\"0.3\"";  // hides hairline seams
    out << " d=\"" << d << "\"/>\n";
  }
  out << "<path fill=\"none\" stroke=\"#1b2838\" stroke-width=\"" << outline
      << "\" stroke-linejoin=\"round\" d=\"" << outline_path << "\"/>\n";
  if (!options.title.empty())
    out << "<text x=\"" << view.margin << "\" y=\"" << view.height + band * 0.6
        << "\" font-family=\"sans-serif\" font-size=\"" << font << "\" fill=\"#333\">"
        << escape_xml(options.title) << "</text>\n";
  out << "</svg>\n";
}

}  // namespace pear::io
