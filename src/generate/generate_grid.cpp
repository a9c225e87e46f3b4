// pear: synthetic families built on a grid of unit cells: the Hilbert curve and a random maze
// (both as the outline of a thickened tree of cells), and a square with random holes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "generate_internal.hpp"

namespace pear::generate_detail {
namespace {

// Directions in counterclockwise order, so "next counterclockwise" is +1 (mod 4).
constexpr int dx[4] = {1, 0, -1, 0};  // east, north, west, south
constexpr int dy[4] = {0, 1, 0, -1};
constexpr int south = 3;
// Half the width of the thickened tree: corridors 0.5 wide, walls 0.5 thick.
constexpr double half_width = 0.25;

/// A tree over the cells of a width x height grid: bit d of mask[cell] says the tree joins the
/// cell to its neighbour in direction d.
struct CellTree {
  std::size_t width = 0;
  std::size_t height = 0;
  std::vector<std::uint8_t> mask;

  std::size_t index(std::size_t x, std::size_t y) const { return y * width + x; }
  void join(std::size_t cell, int direction) {
    mask[cell] |= static_cast<std::uint8_t>(1u << direction);
    const std::size_t other = neighbour(cell, direction);
    mask[other] |= static_cast<std::uint8_t>(1u << ((direction + 2) % 4));
  }
  std::size_t neighbour(std::size_t cell, int direction) const {
    return cell + static_cast<std::size_t>(dx[direction]) +
           static_cast<std::size_t>(dy[direction]) * width;  // wraps correctly when negative
  }
};

/// The counterclockwise outline of the tree thickened to corridors of width 0.5 around the cell
/// centres. An Euler tour: at each cell we sweep the four corners counterclockwise from the
/// parent's direction and descend into each child as we pass it. A corner between directions a
/// and b is a vertex when both are open (reflex) or both closed (convex); one open means the
/// outline runs straight through it.
Ring outline(const CellTree& tree, std::size_t root) {
  struct Frame {
    std::size_t cell;
    int parent;  // direction of the parent; the root's is a closed side (south of cell 0)
    int step;
  };
  Ring ring;
  std::vector<Frame> stack = {{root, south, 0}};
  while (!stack.empty()) {
    Frame& frame = stack.back();
    if (frame.step == 4) {
      stack.pop_back();
      continue;
    }
    const int a = (frame.parent + frame.step) % 4;
    const int b = (a + 1) % 4;
    ++frame.step;
    const unsigned mask = tree.mask[frame.cell];
    const bool open_a = (mask >> a) & 1u;
    const bool open_b = (mask >> b) & 1u;
    if (open_a == open_b) {
      const auto x = static_cast<double>(frame.cell % tree.width);
      const auto y = static_cast<double>(frame.cell / tree.width);
      ring.push_back({x + half_width * (dx[a] + dx[b]), y + half_width * (dy[a] + dy[b])});
    }
    if (open_b && b != frame.parent) {
      stack.push_back({tree.neighbour(frame.cell, b), (b + 2) % 4, 0});
    }
  }
  return ring;
}

/// Cell of step d along the Hilbert curve of side n (a power of two), by its quadrant digits.
void hilbert_cell(std::size_t n, std::size_t d, std::size_t& x, std::size_t& y) {
  x = y = 0;
  for (std::size_t s = 1; s < n; s *= 2, d /= 4) {
    const std::size_t rx = 1 & (d / 2);
    const std::size_t ry = 1 & (d ^ rx);
    if (ry == 0) {  // lower quadrants are the curve of side s reflected
      if (rx == 1) {
        x = s - 1 - x;
        y = s - 1 - y;
      }
      std::swap(x, y);
    }
    x += s * rx;
    y += s * ry;
  }
}

/// Outline vertices of the order-k Hilbert path: 4 + 2 * turns, where the path of order k has
/// turns(k) = 4 * turns(k - 1) + (4 if k is even, else 2) and turns(1) = 2.
std::size_t hilbert_vertices(std::size_t order) {
  std::size_t turns = 2;
  for (std::size_t k = 2; k <= order; ++k) turns = 4 * turns + (k % 2 == 0 ? 4 : 2);
  return 4 + 2 * turns;
}

/// A random spanning tree of the grid by Kruskal's algorithm over shuffled cell joints.
CellTree random_spanning_tree(std::size_t side, Rng& rng) {
  CellTree tree{side, side, std::vector<std::uint8_t>(side * side, 0)};
  std::vector<std::uint64_t> joints;  // cell * 2 + (0: east, 1: north)
  joints.reserve(2 * side * side);
  for (std::size_t y = 0; y < side; ++y) {
    for (std::size_t x = 0; x < side; ++x) {
      if (x + 1 < side) joints.push_back(2 * tree.index(x, y));
      if (y + 1 < side) joints.push_back(2 * tree.index(x, y) + 1);
    }
  }
  for (std::size_t i = joints.size(); i > 1; --i) std::swap(joints[i - 1], joints[rng.below(i)]);
  std::vector<std::size_t> parent(side * side);
  std::iota(parent.begin(), parent.end(), std::size_t{0});
  auto find = [&](std::size_t c) {
    while (parent[c] != c) c = parent[c] = parent[parent[c]];
    return c;
  };
  for (std::uint64_t joint : joints) {
    const std::size_t cell = joint / 2;
    const int direction = static_cast<int>(joint % 2);
    const std::size_t a = find(cell);
    const std::size_t b = find(tree.neighbour(cell, direction));
    if (a == b) continue;
    parent[a] = b;
    tree.join(cell, direction);
  }
  return tree;
}

}  // namespace

Polygon hilbert(std::size_t vertices) {
  std::size_t order = 1;
  for (std::size_t k = 2; k <= 11; ++k) {
    const auto distance = [&](std::size_t j) {
      const std::size_t count = hilbert_vertices(j);
      return count > vertices ? count - vertices : vertices - count;
    };
    if (distance(k) < distance(order)) order = k;
  }
  const std::size_t n = std::size_t{1} << order;
  CellTree tree{n, n, std::vector<std::uint8_t>(n * n, 0)};
  std::size_t px = 0;
  std::size_t py = 0;
  for (std::size_t d = 1; d < n * n; ++d) {
    std::size_t x;
    std::size_t y;
    hilbert_cell(n, d, x, y);
    const int direction = x > px ? 0 : y > py ? 1 : x < px ? 2 : 3;
    tree.join(tree.index(px, py), direction);
    px = x;
    py = y;
  }
  return {outline(tree, 0)};
}

Polygon random_maze(std::size_t vertices, std::uint64_t seed) {
  // The outline of a random spanning tree has about 2.2 vertices per cell. We start a little
  // small, then place the missing vertices at midpoints of distinct edges, and finally jitter
  // every vertex by at most 0.05 per coordinate: non-adjacent edges are at least 0.25 apart, so
  // the ring stays simple while no three vertices stay collinear by construction.
  if (vertices < 8) throw std::invalid_argument("random: needs at least 8 vertices");
  Rng rng(family_seed(seed, 2));
  auto side = static_cast<std::size_t>(std::sqrt(static_cast<double>(vertices) / 2.3));
  Ring ring;
  for (side = std::max<std::size_t>(side, 1);; --side) {
    ring = outline(random_spanning_tree(side, rng), 0);
    if (ring.size() <= vertices || side == 1) break;
  }
  const std::size_t extra = vertices - ring.size();
  if (extra > ring.size()) throw std::invalid_argument("random: size too small for a maze");
  std::vector<std::size_t> edges(ring.size());
  std::iota(edges.begin(), edges.end(), std::size_t{0});
  std::vector<bool> split(ring.size(), false);
  for (std::size_t i = 0; i < extra; ++i) {
    std::swap(edges[i], edges[i + rng.below(edges.size() - i)]);
    split[edges[i]] = true;
  }
  Ring result;
  result.reserve(vertices);
  for (std::size_t i = 0; i < ring.size(); ++i) {
    result.push_back(ring[i]);
    const Point& next = ring[(i + 1) % ring.size()];
    if (split[i]) result.push_back({(ring[i].x + next.x) / 2, (ring[i].y + next.y) / 2});
  }
  for (Point& p : result) {
    p.x += rng.uniform(-0.05, 0.05);
    p.y += rng.uniform(-0.05, 0.05);
  }
  return {result};
}

Polygon random_holes(std::size_t vertices, std::uint64_t seed) {
  // One hole in each of `count` random cells of a grid of unit cells, about 8 vertices each (at
  // most 100,000 holes): a star-shaped ring around a jittered centre with radius at most
  // 0.4 + 0.05 * sqrt(2) < 0.5, so holes touch neither each other nor the square.
  if (vertices < 7) throw std::invalid_argument("random-holes: needs at least 7 vertices");
  Rng rng(family_seed(seed, 3));
  const std::size_t hole_vertices = vertices - 4;
  const std::size_t count = std::clamp<std::size_t>(hole_vertices / 8, 1, 100'000);
  const auto side =
      static_cast<std::size_t>(std::ceil(std::sqrt(1.25 * static_cast<double>(count))));
  std::vector<std::size_t> cells(side * side);
  std::iota(cells.begin(), cells.end(), std::size_t{0});
  for (std::size_t i = 0; i < count; ++i)
    std::swap(cells[i], cells[i + rng.below(cells.size() - i)]);
  const auto extent = static_cast<double>(side);
  Polygon polygon = {{{0, 0}, {extent, 0}, {extent, extent}, {0, extent}}};
  polygon.reserve(count + 1);
  for (std::size_t h = 0; h < count; ++h) {
    const std::size_t k = hole_vertices / count + (h < hole_vertices % count ? 1 : 0);
    const Point center = {static_cast<double>(cells[h] % side) + 0.5 + rng.uniform(-0.05, 0.05),
                          static_cast<double>(cells[h] / side) + 0.5 + rng.uniform(-0.05, 0.05)};
    Ring hole(k);
    do {
      // One angle in the middle 40% of each of k equal sectors: every step is under half a turn.
      const double radius = rng.uniform(0.25, 0.4);
      const double phase = rng.uniform(0, 2 * std::numbers::pi);
      for (std::size_t i = 0; i < k; ++i) {
        const double angle = phase + (static_cast<double>(i) + rng.uniform(0.3, 0.7)) * 2 *
                                         std::numbers::pi / static_cast<double>(k);
        const double r = radius * rng.uniform(0.6, 1.0);
        hole[i] = {center.x + r * std::cos(angle), center.y + r * std::sin(angle)};
      }
    } while (!strictly_around(hole, center));
    std::reverse(hole.begin(), hole.end());  // holes clockwise
    polygon.push_back(std::move(hole));
  }
  return polygon;
}

}  // namespace pear::generate_detail
