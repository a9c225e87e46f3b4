// A picture of polygons and their triangles: the polygon filled (holes left open), triangles
// filled by the part that made them, thin edges where they are legible, the rings outlined.
// Coordinates are mapped to pixels here (y up), so geographic degrees and tiny inputs alike
// fill the viewport. They are rounded to a grid of 1/10 pixel and written as differences on
// that grid, so the file holds short exact numbers whatever the input's scale.
//
// Large inputs: every path's data is cut into pieces of at most max_path_points points, each its
// own <path>. libxml2 (under rsvg-convert) refuses an attribute past 10 MB, and renderers
// draw many short paths faster than one long one. Triangles and outlines split anywhere; the
// even-odd fill, which needs a ring whole, is clipped into tiles instead (Sutherland-Hodgman
// against a cut at a whole pixel), each tile holding few enough points.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "pear/io.hpp"

namespace pear::io {
namespace {

// ColorBrewer "Set3" (12 light qualitative colours): neighbouring parts stay distinguishable.
constexpr const char* part_colours[] = {"#8dd3c7", "#ffffb3", "#bebada", "#fb8072",
                                        "#80b1d3", "#fdb462", "#b3de69", "#fccde5",
                                        "#d9d9d9", "#bc80bd", "#ccebc5", "#ffed6f"};
constexpr const char* single_colour = "#a6cee3";

// Coordinates are written on a grid of 1/10 pixel: invisible at the picture's size, and short.
constexpr std::int64_t steps_per_pixel = 10;
constexpr std::size_t max_path_points = svg_path_points_max;
constexpr double max_svg_size = 1e6;  // pixels: coordinates on the grid stay far below 2^53

struct GridPoint {
  std::int64_t x = 0, y = 0;
  bool operator==(const GridPoint&) const = default;
};
using GridRing = std::vector<GridPoint>;

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
  GridPoint grid(const Point& p) const {
    return {std::llround(x(p) * steps_per_pixel), std::llround(y(p) * steps_per_pixel)};
  }
};

void pixel(std::string& out, double v) {
  char buffer[48];
  const auto [end, ec] =
      std::to_chars(buffer, buffer + sizeof buffer, v, std::chars_format::fixed, 2);
  out.append(buffer, end);
}

/// Path data on the grid: each piece starts with an absolute move, then relative commands, so
/// numbers stay short and a piece can be drawn on its own.
class PathPieces {
 public:
  /// The next `points` points stay in one piece: a new one starts when this one would grow past
  /// max_path_points (a group larger than that gets a piece of its own).
  void reserve(std::size_t points) {
    if (points_ > 0 && points_ + points > max_path_points) finish();
  }
  void move(GridPoint p) {
    if (points_ == 0) {
      d_ += 'M';
      coordinates(p.x, p.y);
    } else {
      d_ += 'm';
      coordinates(p.x - at_.x, p.y - at_.y);
    }
    at_ = start_ = p;
    ++points_;
    line_open_ = false;
  }
  void line(GridPoint p) {
    if (!line_open_) d_ += 'l';
    line_open_ = true;
    coordinates(p.x - at_.x, p.y - at_.y);
    at_ = p;
    ++points_;
  }
  /// Closes the subpath; the pen goes back to its start, as SVG says.
  void close() {
    d_ += 'z';
    at_ = start_;
    line_open_ = false;
  }
  std::vector<std::string> take() {
    finish();
    return std::move(pieces_);
  }

 private:
  void coordinates(std::int64_t x, std::int64_t y) {
    number(x);
    number(y);
  }
  // Steps as a decimal without a leading zero or trailing zeros ("-.5", "12", "3.2"); a space
  // before it unless a command letter or its sign separates it.
  void number(std::int64_t steps) {
    const char last = d_.empty() ? 'M' : d_.back();
    if (steps >= 0 && last != 'M' && last != 'm' && last != 'l') d_ += ' ';
    if (steps < 0) d_ += '-';
    const std::uint64_t magnitude = steps < 0 ? 0 - static_cast<std::uint64_t>(steps) : steps;
    if (magnitude == 0) d_ += '0';
    if (magnitude >= steps_per_pixel) d_ += std::to_string(magnitude / steps_per_pixel);
    std::uint64_t fraction = magnitude % steps_per_pixel;
    if (fraction != 0) d_ += '.';
    for (std::uint64_t digit = steps_per_pixel / 10; fraction != 0; digit /= 10) {
      d_ += static_cast<char>('0' + fraction / digit);
      fraction %= digit;
    }
  }
  void finish() {
    if (points_ > 0) pieces_.push_back(std::move(d_));
    d_.clear();
    points_ = 0;
  }

  std::vector<std::string> pieces_;
  std::string d_;
  std::size_t points_ = 0;
  GridPoint at_, start_;
  bool line_open_ = false;
};

/// The rings on the grid, a point repeating its predecessor (or the first) dropped.
std::vector<GridRing> grid_rings(const View& view, std::span<const TriangulatedPolygon> polygons) {
  std::vector<GridRing> rings;
  for (const auto& p : polygons)
    for (const Ring& ring : p.polygon) {
      GridRing g;
      for (const Point& q : ring)
        if (const GridPoint at = view.grid(q); g.empty() || at != g.back()) g.push_back(at);
      while (g.size() > 1 && g.back() == g.front()) g.pop_back();
      if (!g.empty()) rings.push_back(std::move(g));
    }
  return rings;
}

/// Outlines: a ring longer than a piece is drawn as open runs that meet at shared points.
std::vector<std::string> outline_paths(const std::vector<GridRing>& rings) {
  PathPieces path;
  for (const GridRing& ring : rings) {
    if (ring.size() <= max_path_points) {
      path.reserve(ring.size());
      path.move(ring[0]);
      for (std::size_t i = 1; i < ring.size(); ++i) path.line(ring[i]);
      path.close();
      continue;
    }
    for (std::size_t first = 0; first < ring.size(); first += max_path_points - 1) {
      const std::size_t last = std::min(first + max_path_points - 1, ring.size());
      path.reserve(last - first + 1);
      path.move(ring[first]);
      for (std::size_t i = first + 1; i <= last; ++i) path.line(ring[i % ring.size()]);
    }
  }
  return path.take();
}

struct Tile {
  GridPoint low, high;  // corners, in grid steps
  std::vector<GridRing> rings;
  std::size_t points = 0;
};

// The point where segment a-b crosses the line coordinate[axis] == cut, rounded to the grid.
GridPoint crossing(GridPoint a, GridPoint b, int axis, std::int64_t cut) {
  const double va = axis == 0 ? a.x : a.y, vb = axis == 0 ? b.x : b.y;
  const double oa = axis == 0 ? a.y : a.x, ob = axis == 0 ? b.y : b.x;
  const auto other = std::llround(oa + (ob - oa) * ((static_cast<double>(cut) - va) / (vb - va)));
  return axis == 0 ? GridPoint{cut, other} : GridPoint{other, cut};
}

/// Sutherland-Hodgman against one half-plane: inside it, the clipped ring winds around every
/// point as the ring did, so the even-odd fill of a tile is the fill's part in that tile.
Tile clip(const Tile& tile, int axis, std::int64_t cut, bool keep_low) {
  Tile half{tile.low, tile.high, {}, 0};
  (axis == 0 ? (keep_low ? half.high.x : half.low.x) : (keep_low ? half.high.y : half.low.y)) = cut;
  const auto inside = [&](GridPoint p) {
    const std::int64_t v = axis == 0 ? p.x : p.y;
    return keep_low ? v <= cut : v >= cut;
  };
  for (const GridRing& ring : tile.rings) {
    GridRing out;
    const auto add = [&](GridPoint p) {
      if (out.empty() || out.back() != p) out.push_back(p);
    };
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const GridPoint a = ring[i == 0 ? ring.size() - 1 : i - 1], b = ring[i];
      if (inside(a) != inside(b)) add(crossing(a, b, axis, cut));
      if (inside(b)) add(b);
    }
    while (out.size() > 1 && out.back() == out.front()) out.pop_back();
    if (out.size() < 3) continue;
    half.points += out.size();
    half.rings.push_back(std::move(out));
  }
  return half;
}

/// A cut at a whole pixel strictly between low and high, near the middle; none when the span
/// holds no whole pixel inside.
std::optional<std::int64_t> whole_pixel_cut(std::int64_t low, std::int64_t high) {
  const std::int64_t middle = low + (high - low) / 2;
  std::int64_t cut = middle / steps_per_pixel * steps_per_pixel;
  if (cut > middle) cut -= steps_per_pixel;  // floor for negative middles too
  if (cut <= low) cut += steps_per_pixel;
  if (cut >= high) return std::nullopt;
  return cut;
}

/// The even-odd fill in tiles of at most max_path_points points, halving the longer side at a
/// whole pixel (so tile borders fall between pixels) until they fit or cannot be cut.
void fill_tiles(const Tile& tile, PathPieces& path) {
  if (tile.points > max_path_points) {
    const std::int64_t width = tile.high.x - tile.low.x, height = tile.high.y - tile.low.y;
    for (const int axis : {width >= height ? 0 : 1, width >= height ? 1 : 0}) {
      const auto cut = axis == 0 ? whole_pixel_cut(tile.low.x, tile.high.x)
                                 : whole_pixel_cut(tile.low.y, tile.high.y);
      if (!cut) continue;
      fill_tiles(clip(tile, axis, *cut, true), path);
      fill_tiles(clip(tile, axis, *cut, false), path);
      return;
    }
  }
  // One piece for the tile: its rings fill only together. Tiles may share a piece, as a tile's
  // rings stay inside its box and so change no parity outside it.
  path.reserve(tile.points);
  for (const GridRing& ring : tile.rings) {
    path.move(ring[0]);
    for (std::size_t i = 1; i < ring.size(); ++i) path.line(ring[i]);
    path.close();
  }
}

std::vector<std::string> fill_paths(const std::vector<GridRing>& rings) {
  Tile all;
  all.low = {std::numeric_limits<std::int64_t>::max(), std::numeric_limits<std::int64_t>::max()};
  all.high = {std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::min()};
  for (const GridRing& ring : rings) {
    if (ring.size() < 3) continue;
    for (const GridPoint& p : ring) {
      all.low = {std::min(all.low.x, p.x), std::min(all.low.y, p.y)};
      all.high = {std::max(all.high.x, p.x), std::max(all.high.y, p.y)};
    }
    all.points += ring.size();
    all.rings.push_back(ring);
  }
  PathPieces path;
  if (all.points > 0) fill_tiles(all, path);
  return path.take();
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

/// Triangles grouped by part, one colour each; a triangle that covers no area on the grid (its
/// corners rounded onto one line) is left out, as it would show nothing.
std::map<std::uint32_t, std::vector<std::string>> triangle_paths(
    const View& view, std::span<const TriangulatedPolygon> polygons) {
  std::map<std::uint32_t, PathPieces> paths;
  for (const auto& p : polygons) {
    std::vector<GridPoint> points;
    for (const Ring& ring : p.polygon)
      for (const Point& q : ring) points.push_back(view.grid(q));
    for (std::size_t k = 0; k < p.triangles.size(); ++k) {
      const GridPoint a = points[p.triangles[k][0]], b = points[p.triangles[k][1]],
                      c = points[p.triangles[k][2]];
      const double twice_area = static_cast<double>(b.x - a.x) * static_cast<double>(c.y - a.y) -
                                static_cast<double>(b.y - a.y) * static_cast<double>(c.x - a.x);
      if (twice_area == 0) continue;
      PathPieces& path = paths[p.part.size() == p.triangles.size() ? p.part[k] : 0];
      path.reserve(3);
      path.move(a);
      path.line(b);
      path.line(c);
      path.close();
    }
  }
  std::map<std::uint32_t, std::vector<std::string>> pieces;
  for (auto& [part, path] : paths) pieces[part] = path.take();
  return pieces;
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

// Points must be finite and the size sane, so that every pixel coordinate fits the grid.
void check(std::span<const TriangulatedPolygon> polygons, const SvgOptions& options) {
  if (!(options.size >= 1 && options.size <= max_svg_size))
    throw std::invalid_argument("write_svg: size must be 1 to " + format_double(max_svg_size) +
                                " pixels, not " + format_double(options.size));
  for (std::size_t i = 0; i < polygons.size(); ++i) {
    std::size_t n = 0;
    for (const Ring& ring : polygons[i].polygon) {
      for (const Point& q : ring)
        if (!std::isfinite(q.x) || !std::isfinite(q.y))
          throw std::invalid_argument("write_svg: polygon " + std::to_string(i) + " point " +
                                      std::to_string(n) + " is not finite");
        else
          ++n;
    }
    for (const auto& t : polygons[i].triangles)
      for (const std::uint32_t v : t)
        if (v >= n) throw std::invalid_argument("write_svg: triangle index past the points");
  }
}

void write_group(std::ostream& out, const std::string& attributes,
                 const std::vector<std::string>& pieces) {
  if (pieces.empty()) return;
  out << "<g " << attributes << ">\n";
  for (const std::string& d : pieces) out << "<path d=\"" << d << "\"/>\n";
  out << "</g>\n";
}

}  // namespace

void write_svg(std::ostream& out, std::span<const TriangulatedPolygon> polygons,
               const SvgOptions& options) {
  check(polygons, options);
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
  const std::vector<GridRing> rings = grid_rings(view, polygons);
  write_group(out, "fill=\"#e4e4de\" fill-rule=\"evenodd\"", fill_paths(rings));
  // Edges only where a triangle is a few pixels across; below that they would blacken the fill.
  const bool edges = options.draw_edges && side >= 2.5;
  for (const auto& [part, pieces] : triangle_paths(view, polygons)) {
    const std::string colour = parts ? part_colours[part % std::size(part_colours)] : single_colour;
    std::string style = "fill=\"" + colour + '"';
    if (edges) {
      std::string width_text;
      pixel(width_text, edge);
      style += " stroke=\"#2b4a6b\" stroke-opacity=\"0.55\" stroke-width=\"" + width_text +
               "\" stroke-linejoin=\"round\"";
    } else {
      style += " stroke=\"" + colour + "\" stroke-width=\"0.3\"";  // hides hairline seams
    }
    write_group(out, style, pieces);
  }
  std::string outline_text;
  pixel(outline_text, outline);
  // Round caps: where a long ring is cut into runs, the runs join as round joins would.
  write_group(out,
              "fill=\"none\" stroke=\"#1b2838\" stroke-width=\"" + outline_text +
                  "\" stroke-linejoin=\"round\" stroke-linecap=\"round\"",
              outline_paths(rings));
  if (!options.title.empty())
    out << "<text x=\"" << view.margin << "\" y=\"" << view.height + band * 0.6
        << "\" font-family=\"sans-serif\" font-size=\"" << font << "\" fill=\"#333\">"
        << escape_xml(options.title) << "</text>\n";
  out << "</svg>\n";
}

}  // namespace pear::io
