// The SVG picture: fitted to the viewport whatever the input's scale, y up, one path command per
// triangle, a colour per part.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <sstream>

#include "pear/io.hpp"

namespace {

namespace io = pear::io;
using pear::Point;

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

// A 4 x 1 rectangle listed from its top-left corner, split into two triangles.
io::TriangulatedPolygon rectangle(double scale = 1, Point shift = {0, 0}) {
  auto at = [&](double x, double y) { return Point{shift.x + x * scale, shift.y + y * scale}; };
  return {{{at(0, 1), at(0, 0), at(4, 0), at(4, 1)}}, {{0, 1, 2}, {0, 2, 3}}, {}};
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
  EXPECT_NE(text.find("d=\"M20.00 20.00L20.00 260.00L980.00 260.00L980.00 20.00Z\""),
            std::string::npos)
      << text;
}

TEST(Svg, OnePathCommandPerTriangleAndRing) {
  const std::string text = svg({rectangle(), rectangle(1, {10, 0})});
  // Per polygon: one ring drawn twice (fill and outline) and two triangles.
  EXPECT_EQ(count(text, "M"), 2u * (2 + 2));
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
  const std::regex number("[0-9]+\\.[0-9]+");
  for (std::sregex_iterator it(text.begin(), text.end(), number), end; it != end; ++it) {
    const double v = std::stod(it->str());
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, 1000.0);
  }
}

TEST(Svg, TitleIsEscaped) {
  const std::string text = svg({rectangle()}, {.title = "a<b & c"});
  EXPECT_NE(text.find("<title>a&lt;b &amp; c</title>"), std::string::npos);
}

}  // namespace
