#include "cell_polygon.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace fuzz {
namespace {

constexpr std::array<int, 4> step_x = {1, 0, -1, 0};  // directions: right, up, left, down
constexpr std::array<int, 4> step_y = {0, 1, 0, -1};

struct Cells {
  int width = 0;
  int height = 0;
  std::vector<char> set;
  bool at(int x, int y) const {
    return x >= 0 && y >= 0 && x < width && y < height && set[y * width + x];
  }
};

/// The connected component of `cells` containing cell `start` (4- or 8-neighbours).
Cells component(const Cells& cells, int start, bool corner_connected) {
  Cells part{cells.width, cells.height, std::vector<char>(cells.set.size(), 0)};
  std::vector<int> stack = {start};
  part.set[start] = 1;
  while (!stack.empty()) {
    const int cell = stack.back();
    stack.pop_back();
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        if ((dx == 0 && dy == 0) || (dx != 0 && dy != 0 && !corner_connected)) continue;
        const int x = cell % cells.width + dx;
        const int y = cell / cells.width + dy;
        if (!cells.at(x, y) || part.at(x, y)) continue;
        part.set[y * cells.width + x] = 1;
        stack.push_back(y * cells.width + x);
      }
  }
  return part;
}

/// A boundary loop with the cells on its left, and at each vertex the angle inside the polygon
/// in quarter turns: 1 convex, 2 straight, 3 reflex.
struct Loop {
  std::vector<std::array<int, 2>> points;
  std::vector<int> quarter_turns;
  long long twice_area = 0;
};

class BoundaryTracer {
 public:
  BoundaryTracer(const Cells& part, bool corner_connected)
      : part_(part),
        stride_(part.width + 1),
        prefer_right_(corner_connected),
        out_((part.width + 1) * (part.height + 1), 0),
        used_(out_.size(), 0) {
    for (int y = 0; y < part.height; ++y)
      for (int x = 0; x < part.width; ++x) {
        if (!part.at(x, y)) continue;
        // Each side facing an empty cell, counterclockwise around the cell.
        if (!part.at(x, y - 1)) out_[vertex(x, y)] |= 1 << 0;
        if (!part.at(x + 1, y)) out_[vertex(x + 1, y)] |= 1 << 1;
        if (!part.at(x, y + 1)) out_[vertex(x + 1, y + 1)] |= 1 << 2;
        if (!part.at(x - 1, y)) out_[vertex(x, y + 1)] |= 1 << 3;
      }
  }

  std::vector<Loop> loops() {
    std::vector<Loop> all;
    for (int v = 0; v < static_cast<int>(out_.size()); ++v)
      for (int d = 0; d < 4; ++d)
        if ((out_[v] >> d & 1) && !(used_[v] >> d & 1)) all.push_back(trace(v, d));
    return all;
  }

 private:
  int vertex(int x, int y) const { return y * stride_ + x; }

  /// At a corner where two cells meet diagonally both turns are open: turning right joins the
  /// two cells (corner-connected), turning left keeps them apart.
  int next_direction(int v, int incoming) const {
    const int left = (incoming + 1) % 4, right = (incoming + 3) % 4;
    const int first = prefer_right_ ? right : left, second = prefer_right_ ? left : right;
    for (int d : {first, incoming, second})
      if (out_[v] >> d & 1) return d;
    return -1;
  }

  Loop trace(int start, int start_direction) {
    Loop loop;
    int v = start, d = start_direction;
    do {
      used_[v] |= 1 << d;
      const int x = v % stride_, y = v / stride_;
      const int nx = x + step_x[d], ny = y + step_y[d];
      loop.twice_area += static_cast<long long>(x) * ny - static_cast<long long>(nx) * y;
      v = vertex(nx, ny);
      const int next = next_direction(v, d);
      loop.points.push_back({nx, ny});
      // Where cells meet diagonally the loop passes twice, each time owning one cell's corner.
      const bool diagonal = out_[v] == 0b0101 || out_[v] == 0b1010;
      loop.quarter_turns.push_back(diagonal || next == (d + 1) % 4 ? 1 : next == d ? 2 : 3);
      d = next;
    } while (v != start || d != start_direction);
    return loop;
  }

  const Cells& part_;
  int stride_;
  bool prefer_right_;
  std::vector<unsigned char> out_;   ///< bit d: a boundary edge leaves in direction d
  std::vector<unsigned char> used_;  ///< bit d: that edge is traced
};

struct Placement {
  unsigned flags;
  int exponent;
  int offset;
  pear::Point operator()(const std::array<int, 2>& p) const { return (*this)(p[0], p[1]); }
  /// Exact for the quarters and eighths of the T-junction triangles too.
  pear::Point operator()(double x, double y) const {
    if (flags & cell_flags::place) {
      x = std::ldexp(x + offset, exponent);
      y = std::ldexp(y + offset, exponent);
    }
    if (flags & cell_flags::transpose) std::swap(x, y);
    return {x, y};
  }
};

/// The loop as a ring: straight vertices dropped if asked, placed, started at `rotation`.
pear::Ring make_ring(const Loop& loop, const Placement& place, std::size_t rotation,
                     std::size_t& quarter_turns) {
  pear::Ring ring;
  for (std::size_t i = 0; i < loop.points.size(); ++i) {
    if ((place.flags & cell_flags::drop_collinear) && loop.quarter_turns[i] == 2) continue;
    ring.push_back(place(loop.points[i]));
    quarter_turns += loop.quarter_turns[i];
  }
  std::rotate(ring.begin(), ring.begin() + rotation % ring.size(), ring.end());
  if (place.flags & cell_flags::reverse_rings) std::reverse(ring.begin(), ring.end());
  return ring;
}

/// Triangular holes on unit edges of the loops picked by the bytes left (cell_polygon.hpp):
/// each inside the set cell left of its edge, within a quarter of the edge's midpoint, so no
/// two meet (nor anything else) but at the apex, which lies inside the ring's edge.
std::size_t add_t_junctions(ByteReader& bytes, const std::vector<Loop>& loops,
                            const Placement& place, pear::Polygon& polygon) {
  std::size_t unit_edges = 0;
  for (const Loop& loop : loops) unit_edges += loop.points.size();
  std::vector<std::size_t> picked;
  while (!bytes.empty() && picked.size() < 8) {
    const std::size_t edge = bytes.u16() % unit_edges;
    if (std::find(picked.begin(), picked.end(), edge) != picked.end()) continue;
    picked.push_back(edge);
    std::size_t k = edge, l = 0;
    while (k >= loops[l].points.size()) k -= loops[l++].points.size();
    const auto& points = loops[l].points;
    const auto& from = points[(k + points.size() - 1) % points.size()];
    const auto& to = points[k];
    const double dx = to[0] - from[0], dy = to[1] - from[1];  // a unit step
    const double mx = from[0] + 0.5 * dx, my = from[1] + 0.5 * dy;
    const double lx = -dy, ly = dx;  // towards the cells, on the loop's left
    polygon.push_back({place(mx, my),
                       place(mx + 0.25 * lx + 0.125 * dx, my + 0.25 * ly + 0.125 * dy),
                       place(mx + 0.25 * lx - 0.125 * dx, my + 0.25 * ly - 0.125 * dy)});
  }
  return picked.size();
}

}  // namespace

std::optional<CellPolygon> decode_cell_polygon(ByteReader& bytes) {
  Cells cells;
  cells.width = 2 + bytes.byte() % 15;
  cells.height = 2 + bytes.byte() % 15;
  const unsigned flags = bytes.byte();
  const unsigned start = bytes.byte();
  const Placement place{flags, static_cast<std::int8_t>(bytes.byte()), bytes.u16()};
  std::vector<int> set_cells;
  cells.set.resize(cells.width * cells.height);
  for (std::size_t i = 0; i < cells.set.size(); i += 8) {
    const std::uint8_t bits = bytes.byte();
    for (std::size_t k = 0; k < 8 && i + k < cells.set.size(); ++k)
      if ((cells.set[i + k] = bits >> k & 1)) set_cells.push_back(static_cast<int>(i + k));
  }
  if (set_cells.empty()) return std::nullopt;
  const bool corner_connected = flags & cell_flags::corner_connected;
  const Cells part = component(cells, set_cells[start % set_cells.size()], corner_connected);
  std::vector<Loop> loops = BoundaryTracer(part, corner_connected).loops();
  // The one counterclockwise loop is the outer ring; the clockwise ones are holes.
  const auto outer =
      std::find_if(loops.begin(), loops.end(), [](const Loop& l) { return l.twice_area > 0; });
  require(
      outer != loops.end() && std::count_if(loops.begin(), loops.end(),
                                            [](const Loop& l) { return l.twice_area > 0; }) == 1,
      "cell polygon: not exactly one outer loop");
  std::iter_swap(loops.begin(), outer);
  if (loops.size() > 2)  // holes in another order
    std::rotate(loops.begin() + 1, loops.begin() + 1 + (flags >> 5) % (loops.size() - 1),
                loops.end());
  CellPolygon result;
  std::size_t quarter_turns = 0;
  for (std::size_t r = 0; r < loops.size(); ++r)
    result.polygon.push_back(make_ring(loops[r], place, start * (r + 1), quarter_turns));
  // Every triangle's angles sum to two quarter turns, and all its corners are ring corners.
  require(quarter_turns % 2 == 0, "cell polygon: odd angle sum");
  result.triangles = quarter_turns / 2;
  // A triangle standing on an edge: its exterior angles (5 half turns) at its three corners,
  // less the half turn its apex takes from the straight angle there: 4 more triangles.
  result.t_junctions = add_t_junctions(bytes, loops, place, result.polygon);
  result.triangles += 4 * result.t_junctions;
  return result;
}

}  // namespace fuzz
