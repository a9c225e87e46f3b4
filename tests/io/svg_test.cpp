// The SVG picture: fitted to the viewport whatever the input's scale, y up, one subpath per
// triangle, a colour per part; large inputs cut into short paths that still draw the polygon.
// The paths are read back by a small interpreter of SVG's path grammar (M m L l Z z, implicit
// repeats), so the tests check where the points land, not how they are spelled.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <regex>
#include <set>
#include <sstream>

#include "pear/io.hpp"

namespace {

namespace io = pear::io;
using pear::Point;
using pear::Ring;

std::string svg(const std::vector<io::TriangulatedPolygon>& polygons, io::SvgOptions options = {}) {
  std::ostringstream out;
  io::write_svg(out, polygons, options);
  return out.str();
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

using Subpath = std::vector<Point>;

// The subpaths of one `d` attribute in absolute pixels, per the SVG path grammar.
std::vector<Subpath> read_path(const std::string& d) {
  std::vector<Subpath> subpaths;
  const std::regex token("[MmLlZz]|[-+]?(?:[0-9]+\\.?[0-9]*|\\.[0-9]+)(?:[eE][-+]?[0-9]+)?");
  char command = 0;
  Point at{0, 0}, start{0, 0};
  std::vector<double> numbers;
  for (std::sregex_iterator it(d.begin(), d.end(), token), end; it != end; ++it) {
    const std::string t = it->str();
    if (std::isalpha(static_cast<unsigned char>(t[0]))) {
      command = t[0];
      if (command == 'Z' || command == 'z') at = start;
      continue;
    }
    numbers.push_back(std::stod(t));
    if (numbers.size() < 2) continue;
    const bool relative = command == 'm' || command == 'l';
    const Point p =
        relative ? Point{at.x + numbers[0], at.y + numbers[1]} : Point{numbers[0], numbers[1]};
    numbers.clear();
    if (command == 'M' || command == 'm') {
      subpaths.push_back({p});
      start = p;
      command = command == 'M' ? 'L' : 'l';  // pairs after a move are lines
    } else {
      EXPECT_TRUE(command == 'L' || command == 'l') << "unexpected command in " << d;
      subpaths.back().push_back(p);
    }
    at = p;
  }
  EXPECT_TRUE(numbers.empty()) << "odd number count in " << d;
  return subpaths;
}

// Every path's subpaths, for the paths whose enclosing <g> carries `style` (all when empty).
// Plain searches, not std::regex: its recursion overflows the stack on long texts.
std::vector<std::vector<Subpath>> paths(const std::string& svg_text,
                                        const std::string& style = "") {
  std::vector<std::vector<Subpath>> out;
  for (std::size_t g = svg_text.find("<g "); g != std::string::npos;
       g = svg_text.find("<g ", g + 1)) {
    const std::size_t body = svg_text.find('>', g), end = svg_text.find("</g>", g);
    if (svg_text.substr(g, body - g).find(style) == std::string::npos) continue;
    const std::string tag = "<path d=\"";
    for (std::size_t p = svg_text.find(tag, body); p < end; p = svg_text.find(tag, p + 1)) {
      const std::size_t from = p + tag.size();
      out.push_back(read_path(svg_text.substr(from, svg_text.find('"', from) - from)));
    }
  }
  return out;
}

std::size_t subpath_count(const std::string& svg_text, const std::string& style = "") {
  std::size_t n = 0;
  for (const auto& subpaths : paths(svg_text, style)) n += subpaths.size();
  return n;
}

// A 4 x 1 rectangle listed from its top-left corner, split into two triangles.
io::TriangulatedPolygon rectangle(double scale = 1, Point shift = {0, 0}) {
  auto at = [&](double x, double y) { return Point{shift.x + x * scale, shift.y + y * scale}; };
  return {.polygon = {{at(0, 1), at(0, 0), at(4, 0), at(4, 1)}},
          .triangles = {{0, 1, 2}, {0, 2, 3}}};
}

TEST(Svg, FitsTheViewportKeepingTheAspect) {
  const std::string text = svg({rectangle()});
  // 2% margins: the 4-unit side spans 1000 - 2 * 20 pixels, so one unit is 240 pixels.
  EXPECT_NE(text.find("width=\"1000.00\" height=\"280.00\""), std::string::npos)
      << text.substr(0, 200);
  EXPECT_NE(text.find("viewBox=\"0 0 1000.00 280.00\""), std::string::npos);
}

TEST(Svg, YAxisPointsUp) {
  const std::string text = svg({rectangle()});
  // The first ring point is the top-left corner (0, 1): it lands at the top margin.
  const auto outline = paths(text, "fill=\"none\"");
  ASSERT_EQ(outline.size(), 1u) << text;
  ASSERT_EQ(outline[0].size(), 1u) << text;
  const Subpath expected = {{20, 20}, {20, 260}, {980, 260}, {980, 20}};
  ASSERT_EQ(outline[0][0].size(), expected.size()) << text;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(outline[0][0][i].x, expected[i].x, 1e-9) << i;
    EXPECT_NEAR(outline[0][0][i].y, expected[i].y, 1e-9) << i;
  }
}

TEST(Svg, OnePathCommandPerTriangleAndRing) {
  const std::string text = svg({rectangle(), rectangle(1, {10, 0})});
  // Per polygon: one ring drawn twice (fill and outline) and two triangles.
  EXPECT_EQ(subpath_count(text), 2u * (2 + 2));
  EXPECT_EQ(subpath_count(text, "fill-rule=\"evenodd\""), 2u);
  EXPECT_EQ(count(text, "<svg"), 1u);
  EXPECT_EQ(count(text, "</svg>"), 1u);
}

TEST(Svg, ColoursTrianglesByPart) {
  auto parted = rectangle();
  EXPECT_EQ(count(svg({parted}), "#8dd3c7"), 0u);
  parted.part = {0, 1};
  const std::string text = svg({parted});
  EXPECT_EQ(count(text, "fill=\"#8dd3c7\""), 1u);
  EXPECT_EQ(count(text, "fill=\"#ffffb3\""), 1u);
}

TEST(Svg, TinyAndHugeInputsGiveTheSamePicture) {
  // Scaling by a power of two is exact, so the pixel coordinates must match to the last digit.
  const std::string unit = svg({rectangle()});
  EXPECT_EQ(svg({rectangle(std::ldexp(1.0, -60), {std::ldexp(3.0, -60), 0})}),
            svg({rectangle(1, {3, 0})}));
  EXPECT_EQ(svg({rectangle(std::ldexp(1.0, 80))}), unit);
}

TEST(Svg, GeographicDegreesFillTheViewport) {
  const std::string text = svg({rectangle(1e-4, {151.2, -33.9})});
  EXPECT_NE(text.find("width=\"1000.00\" height=\"280.00\""), std::string::npos)
      << text.substr(0, 200);
  for (const auto& subpaths : paths(text))
    for (const Subpath& subpath : subpaths)
      for (const Point& p : subpath) {
        EXPECT_GE(p.x, 0.0);
        EXPECT_LE(p.x, 1000.0);
        EXPECT_GE(p.y, 0.0);
        EXPECT_LE(p.y, 280.0);
      }
}

// A polygon of `n` points on a circle, counterclockwise, or clockwise for a hole.
Ring circle(Point centre, double radius, std::size_t n, bool hole = false) {
  Ring ring;
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(n);
    ring.push_back({centre.x + radius * std::cos(angle),
                    centre.y + (hole ? -1 : 1) * radius * std::sin(angle)});
  }
  return ring;
}

// Whether a point is inside the paths' even-odd fill, each path filled on its own.
bool filled(const std::vector<std::vector<Subpath>>& fill, Point q) {
  for (const auto& subpaths : fill) {
    bool odd = false;
    for (const Subpath& s : subpaths)
      for (std::size_t i = 0, j = s.size() - 1; i < s.size(); j = i++)
        if ((s[i].y > q.y) != (s[j].y > q.y) &&
            q.x < s[j].x + (s[i].x - s[j].x) * (q.y - s[j].y) / (s[i].y - s[j].y))
          odd = !odd;
    if (odd) return true;
  }
  return false;
}

void expect_short_paths(const std::string& text) {
  for (const auto& subpaths : paths(text)) {
    std::size_t points = 0;
    for (const Subpath& s : subpaths) points += s.size();
    EXPECT_LE(points, io::svg_path_points_max);
  }
}

// 60,000 points around a disc with three holes of 8,000: far more than one path may hold.
TEST(Svg, LargePolygonIsFilledInShortPathsWithItsHolesOpen) {
  const Point hole_centres[] = {{-0.5, 0}, {0.5, 0}, {0, 0.5}};
  io::TriangulatedPolygon disc{{circle({0, 0}, 1, 60000)}, {}, {}};
  for (const Point c : hole_centres) disc.polygon.push_back(circle(c, 0.2, 8000, true));
  const std::string text = svg({disc});
  expect_short_paths(text);
  const auto fill = paths(text, "fill-rule=\"evenodd\"");
  EXPECT_GT(fill.size(), 20u);
  // The disc spans 20..980 pixels: centre 500, radius 480; y points down in the picture. The
  // samples are pixel centres, so none lies on a tile's border (a whole pixel).
  std::size_t inside = 0;
  for (int i = 0; i < 61; ++i)
    for (int j = 0; j < 61; ++j) {
      const Point at{16.5 + 16 * i, 16.5 + 16 * j}, p{(at.x - 500) / 480, (500 - at.y) / 480};
      const double from_rim = std::abs(std::hypot(p.x, p.y) - 1);
      double from_holes = 1e9;
      bool in_hole = false;
      for (const Point c : hole_centres) {
        const double r = std::hypot(p.x - c.x, p.y - c.y);
        from_holes = std::min(from_holes, std::abs(r - 0.2));
        in_hole = in_hole || r < 0.2;
      }
      if (std::min(from_rim, from_holes) * 480 < 1) continue;  // a pixel from a ring: either
      const bool expected = std::hypot(p.x, p.y) < 1 && !in_hole;
      inside += expected;
      EXPECT_EQ(filled(fill, at), expected) << at.x << ", " << at.y;
    }
  EXPECT_GT(inside, 1000u);
}

TEST(Svg, LargeRingsAreOutlinedInShortPathsThroughEveryPoint) {
  io::TriangulatedPolygon disc{
      {circle({0, 0}, 1, 30000), circle({0, 0}, 0.5, 15000, true)}, {}, {}};
  const std::string text = svg({disc});
  expect_short_paths(text);
  std::set<std::pair<long, long>> drawn;  // on a grid of 1/10 pixel, as io.hpp documents
  for (const auto& subpaths : paths(text, "fill=\"none\""))
    for (const Subpath& s : subpaths)
      for (const Point& p : s) drawn.insert({std::lround(p.x * 10), std::lround(p.y * 10)});
  for (const Ring& ring : disc.polygon)
    for (const Point& p : ring) {
      const long x = std::lround((500 + 480 * p.x) * 10), y = std::lround((500 - 480 * p.y) * 10);
      bool near = false;
      for (long dx = -1; dx <= 1; ++dx)
        for (long dy = -1; dy <= 1; ++dy) near = near || drawn.count({x + dx, y + dy}) > 0;
      ASSERT_TRUE(near) << p.x << ", " << p.y;
    }
}

TEST(Svg, ManyTrianglesAreDrawnInShortPathsCoveringThePolygon) {
  constexpr std::size_t n = 40000;
  io::TriangulatedPolygon fan{{circle({0, 0}, 1, n)}, {}, {}};
  for (std::uint32_t i = 1; i + 1 < n; ++i) fan.triangles.push_back({0, i, i + 1});
  const std::string text = svg({fan});
  expect_short_paths(text);
  double area = 0;
  std::size_t triangles = 0;
  for (const auto& subpaths : paths(text, "fill=\"#a6cee3\""))
    for (const Subpath& t : subpaths) {
      ASSERT_EQ(t.size(), 3u);
      area += (t[1].x - t[0].x) * (t[2].y - t[0].y) - (t[1].y - t[0].y) * (t[2].x - t[0].x);
      ++triangles;
    }
  EXPECT_GT(triangles, io::svg_path_points_max);
  // The disc's area in square pixels (y down: clockwise), the corners rounded by at most 0.05
  // pixel. Signed areas: rounding may turn a sliver a tenth of a pixel wide over.
  EXPECT_NEAR(-area / 2, std::numbers::pi * 480 * 480, 0.002 * std::numbers::pi * 480 * 480);
}

TEST(Svg, NonFiniteCoordinatesAndBadSizesAreRefused) {
  auto bad = rectangle();
  bad.polygon[0][2].x = std::nan("");
  EXPECT_THROW(svg({bad}), std::invalid_argument);
  EXPECT_THROW(svg({rectangle()}, {.size = 0}), std::invalid_argument);
  EXPECT_THROW(svg({rectangle()}, {.size = 1e300}), std::invalid_argument);
}

TEST(Svg, TitleIsEscaped) {
  const std::string text = svg({rectangle()}, {.title = "a<b & c"});
  EXPECT_NE(text.find("<title>a&lt;b &amp; c</title>"), std::string::npos);
}

}  // namespace
