// Triangle's .poly format (J. R. Shewchuk's documented file format): a vertex list, a segment
// list, hole points and optional regional attributes. Segments are walked into closed rings and
// the rings nested even-odd into polygons with holes.
#include <array>
#include <string>
#include <vector>

#include "pear/io.hpp"
#include "rings.hpp"
#include "scanner.hpp"

namespace pear::io {
namespace {

using detail::NumberSyntax;
using detail::Scanner;

constexpr std::size_t no_vertex = static_cast<std::size_t>(-1);

class PolyReader {
 public:
  PolyReader(std::string_view text, std::string_view name, const ReadOptions& options)
      : s_(text, name), options_(options) {}

  std::vector<Polygon> read() {
    s_.skip_space_and_comments();
    vertices();
    segments();
    holes();
    regions();
    if (!s_.at_end()) s_.fail_expected(s_.pos, "end of file after the hole list");
    walk_rings();
    return nest_rings();
  }

 private:
  void next() { s_.end_token(); }
  std::size_t count(const char* what) {
    const std::size_t value = s_.count(what);
    next();
    return value;
  }
  double number() {
    const double value = s_.number(NumberSyntax::loose);
    next();
    return value;
  }
  // Vertices are numbered consecutively from 0 or 1, as the first one says (Triangle's rule);
  // segment, hole and region numbers are read but, as in Triangle, not checked.
  void vertex_number(std::size_t i) {
    const std::size_t at = s_.pos;
    const long long value = s_.integer("vertex number");
    if (i == 0 && (value == 0 || value == 1)) base_ = static_cast<std::size_t>(value);
    if (value != static_cast<long long>(base_ + i))
      s_.fail(at, "expected vertex number " + std::to_string(base_ + i) + " (consecutive from " +
                      std::to_string(base_) + ") but found " + s_.describe_found(at));
    next();
  }

  void vertices() {
    const std::size_t count_at = s_.pos;
    const std::size_t n = count("vertex count");
    if (n == 0)
      s_.fail(count_at,
              "expected a vertex count above 0 (vertices in a separate .node file are "
              "not supported) but found 0");
    const std::size_t dim_at = s_.pos;
    if (count("dimension") != 2) s_.fail_expected(dim_at, "dimension 2");
    const std::size_t attributes = count("attribute count");
    const std::size_t markers = bounded(1, "boundary marker count (0 or 1)");
    points_.reserve(std::min<std::size_t>(n, s_.text().size() / 4));
    for (std::size_t i = 0; i < n; ++i) {
      vertex_at_.push_back(s_.pos);
      vertex_number(i);
      const double x = number();
      const double y = number();
      points_.push_back(Point{x, y});
      for (std::size_t a = 0; a < attributes; ++a) number();
      for (std::size_t m = 0; m < markers; ++m) skip_integer("boundary marker");
    }
  }

  std::size_t bounded(std::size_t max, const char* what) {
    const std::size_t at = s_.pos;
    const std::size_t value = count(what);
    if (value > max) s_.fail_expected(at, what);
    return value;
  }
  void skip_integer(const char* what) {
    s_.integer(what);
    next();
  }

  void segments() {
    const std::size_t m = count("segment count");
    const std::size_t markers = bounded(1, "boundary marker count (0 or 1)");
    neighbours_.assign(points_.size(), {no_vertex, no_vertex});
    for (std::size_t j = 0; j < m; ++j) {
      const std::size_t at = s_.pos;
      skip_integer("segment number");
      const std::size_t a = endpoint();
      const std::size_t b = endpoint();
      if (a == b)
        s_.fail(at, "expected a segment between two vertices but found a loop at vertex " +
                        std::to_string(a + base_));
      link(a, b, at);
      link(b, a, at);
      for (std::size_t k = 0; k < markers; ++k) skip_integer("boundary marker");
    }
  }

  std::size_t endpoint() {
    const std::size_t at = s_.pos;
    const long long v = s_.integer("vertex number");
    if (v < static_cast<long long>(base_) || v >= static_cast<long long>(base_ + points_.size()))
      s_.fail(at, "expected a vertex number from " + std::to_string(base_) + " to " +
                      std::to_string(base_ + points_.size() - 1) + " but found " +
                      std::to_string(v));
    next();
    return static_cast<std::size_t>(v) - base_;
  }

  void link(std::size_t from, std::size_t to, std::size_t at) {
    auto& slots = neighbours_[from];
    if (slots[1] != no_vertex)
      s_.fail(at, "expected each vertex on exactly two segments (closed rings) but vertex " +
                      std::to_string(from + base_) + " is on a third one here");
    slots[slots[0] == no_vertex ? 0 : 1] = to;
  }

  void holes() {
    if (s_.at_end()) s_.fail_expected(s_.pos, "the hole count");
    const std::size_t h = count("hole count");
    for (std::size_t i = 0; i < h; ++i) {
      hole_at_.push_back(s_.pos);
      skip_integer("hole number");
      const double x = number();
      const double y = number();
      hole_points_.push_back(Point{x, y});
    }
  }

  // Optional: "<count>" then "<number> <x> <y> <attribute> <maximum area>" per region.
  void regions() {
    if (s_.at_end()) return;
    const std::size_t r = count("regional attribute count");
    for (std::size_t i = 0; i < r; ++i) {
      skip_integer("region number");
      for (int k = 0; k < 4; ++k) number();
    }
  }

  void walk_rings() {
    // Every vertex on exactly two segments first: then the segments form closed rings, and no
    // walk below can reach a vertex with a missing neighbour.
    for (std::size_t v = 0; v < points_.size(); ++v) {
      const auto& slots = neighbours_[v];
      if (slots[0] == no_vertex || slots[1] == no_vertex)
        s_.fail(vertex_at_[v], "expected vertex " + std::to_string(v + base_) +
                                   " on two segments (closed rings) but it is on " +
                                   (slots[0] == no_vertex ? "none" : "only one"));
    }
    std::vector<bool> visited(points_.size(), false);
    for (std::size_t start = 0; start < points_.size(); ++start) {
      if (visited[start]) continue;
      Ring& ring = rings_.emplace_back();
      std::size_t previous = no_vertex;
      std::size_t current = start;
      do {
        visited[current] = true;
        ring.push_back(points_[current]);
        const auto& next = neighbours_[current];
        const std::size_t step = next[0] == previous ? next[1] : next[0];
        previous = current;
        current = step;
      } while (current != start);
      detail::finish_ring(ring, s_, vertex_at_[start], options_);
    }
  }

  std::vector<Polygon> nest_rings() {
    const std::size_t r = rings_.size();
    std::vector<detail::Box> boxes(r);
    for (std::size_t i = 0; i < r; ++i) boxes[i] = detail::bounding_box(rings_[i]);
    const detail::BoxGrid grid(boxes);
    std::vector<std::vector<std::size_t>> containers(r);
    std::vector<std::size_t> depth(r, 0);
    for (std::size_t i = 0; i < r; ++i) {
      // The middle of an edge: rings that touch share vertices, rarely edge midpoints.
      const Ring& ring = rings_[i];
      const Point p = ring.size() < 2 ? ring.front()
                                      : Point{ring[0].x + (ring[1].x - ring[0].x) / 2,
                                              ring[0].y + (ring[1].y - ring[0].y) / 2};
      grid.candidates(p, [&](std::size_t k) {
        if (k != i && boxes[k].contains(p) && detail::inside(rings_[k], p))
          containers[i].push_back(k);
      });
      depth[i] = containers[i].size();
    }
    check_hole_points(grid);
    std::vector<Polygon> polygons;
    std::vector<std::size_t> polygon_of(r, no_vertex);
    for (std::size_t i = 0; i < r; ++i) {
      if (depth[i] % 2 != 0) continue;
      polygon_of[i] = polygons.size();
      polygons.push_back({rings_[i]});
    }
    for (std::size_t i = 0; i < r; ++i) {
      if (depth[i] % 2 == 0) continue;
      // The innermost container is the deepest one that starts a polygon. Overlapping rings
      // can make the depths disagree; a ring left without one starts its own polygon.
      std::size_t parent = no_vertex;
      for (const std::size_t k : containers[i])
        if (depth[k] % 2 == 0 && (parent == no_vertex || depth[k] > depth[parent])) parent = k;
      if (parent == no_vertex) {
        polygons.push_back({rings_[i]});
      } else {
        polygons[polygon_of[parent]].push_back(rings_[i]);
      }
    }
    return polygons;
  }

  void check_hole_points(const detail::BoxGrid& grid) {
    for (std::size_t h = 0; h < hole_points_.size(); ++h) {
      if (detail::containing_count(rings_, grid, hole_points_[h]) % 2 == 1)
        s_.fail(hole_at_[h], "expected hole point " + std::to_string(h + base_) +
                                 " inside a hole or outside every ring, but it lies in the "
                                 "polygon's filled area (rings nest even-odd)");
    }
  }

  Scanner s_;
  const ReadOptions& options_;
  std::size_t base_ = 0;
  std::vector<Point> points_;
  std::vector<std::size_t> vertex_at_;
  std::vector<std::array<std::size_t, 2>> neighbours_;
  std::vector<Point> hole_points_;
  std::vector<std::size_t> hole_at_;
  std::vector<Ring> rings_;
};

}  // namespace

std::vector<Polygon> read_poly(std::string_view text, std::string_view name,
                               const ReadOptions& options) {
  return PolyReader(text, name, options).read();
}

}  // namespace pear::io
