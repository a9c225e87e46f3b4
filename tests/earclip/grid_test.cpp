// The uniform grid's triangle query (GridFrame::any_row_span_of_triangle) must visit the cell of
// every point inside or on a triangle: the ear test relies on it to find every reflex vertex
// that could block an ear. The row spans carry only a rounding slack, no extra columns, so
// these tests aim at rounding: points exactly on row and column boundaries, triangles whose
// edges pass through them, slivers, and coordinates far from the origin. Inside is decided by
// the exact orient2d.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

#include "core/boundary.hpp"
#include "core/reflex_grid.hpp"
#include "geometry/uniform_grid.hpp"
#include "pear/predicates.hpp"

namespace pear::detail {
namespace {

bool inside_or_on(const Point& a, const Point& b, const Point& c, const Point& p) {
  return orient2d(a, b, p) >= 0 && orient2d(b, c, p) >= 0 && orient2d(c, a, p) >= 0;
}

/// Every point of `points` inside or on (a, b, c) lies in a cell the query visits.
void expect_all_found(const GridFrame& frame, const std::vector<Point>& points, Point a, Point b,
                      Point c) {
  if (orient2d(a, b, c) < 0) std::swap(b, c);
  std::set<std::size_t> visited;
  frame.any_row_span_of_triangle(a, b, c, [&](std::size_t first, std::size_t last) {
    for (std::size_t cell = first; cell <= last; ++cell) visited.insert(cell);
    return false;
  });
  for (const Point& p : points) {
    if (!inside_or_on(a, b, c, p)) continue;
    const std::size_t cell = frame.cell(frame.column(p.x), frame.row(p.y));
    ASSERT_TRUE(visited.count(cell))
        << "point (" << p.x << ", " << p.y << ") in triangle (" << a.x << ", " << a.y << ") ("
        << b.x << ", " << b.y << ") (" << c.x << ", " << c.y << ") not in a visited cell";
  }
}

struct Case {
  double scale, offset;
};

class GridQuery : public ::testing::TestWithParam<Case> {};

// Points on a lattice whose lines are the grid's row and column boundaries (and thirds of
// them), triangles with corners on the same lattice: edges run exactly through points, along
// boundaries and across them at every slope, thin ones included.
TEST_P(GridQuery, FindsEveryPointOfTrianglesOnTheBoundaryLattice) {
  const auto [scale, offset] = GetParam();
  const int lattice = 48;  // 16 cells a side, 3 lattice steps a cell
  std::vector<Point> points;
  for (int i = 0; i <= lattice; ++i)
    for (int j = 0; j <= lattice; ++j)
      points.push_back({offset + scale * i / 3.0, offset + scale * j / 3.0});
  GridFrame frame;
  frame.fit({offset, offset}, {offset + scale * 16, offset + scale * 16}, 256);
  ASSERT_EQ(frame.nx, 16);
  std::mt19937 random(7);
  std::uniform_int_distribution<int> coordinate(0, lattice);
  for (int k = 0; k < 3000; ++k) {
    const auto corner = [&] {
      return points[coordinate(random) * (lattice + 1) + coordinate(random)];
    };
    const Point a = corner(), b = corner(), c = corner();
    if (orient2d(a, b, c) == 0) continue;
    expect_all_found(frame, points, a, b, c);
  }
}

// Slivers between random points: the thin triangles of a random star, whose row spans are one
// cell wide.
TEST_P(GridQuery, FindsEveryPointOfRandomSlivers) {
  const auto [scale, offset] = GetParam();
  std::mt19937 random(11);
  std::uniform_real_distribution<double> unit(0, 1);
  std::vector<Point> points;
  for (int i = 0; i < 4000; ++i)
    points.push_back({offset + scale * 16 * unit(random), offset + scale * 16 * unit(random)});
  GridFrame frame;
  frame.fit({offset, offset}, {offset + scale * 16, offset + scale * 16}, points.size() / 2);
  std::uniform_int_distribution<std::size_t> pick(0, points.size() - 1);
  for (int k = 0; k < 3000; ++k) {
    const Point a = points[pick(random)], c = points[pick(random)];
    // b close to the segment a-c: a sliver whose long edges pass near many points.
    const double t = unit(random), lean = (unit(random) - 0.5) * 1e-3;
    const Point b{a.x + t * (c.x - a.x) - lean * (c.y - a.y),
                  a.y + t * (c.y - a.y) + lean * (c.x - a.x)};
    if (orient2d(a, b, c) == 0) continue;
    // Points exactly on the long edges too: the edge's own end points and midpoints of the lattice.
    std::vector<Point> with_edges = points;
    with_edges.push_back(a);
    with_edges.push_back(b);
    with_edges.push_back(c);
    expect_all_found(frame, with_edges, a, b, c);
  }
}

/// ReflexGrid as the clippers use it: nodes leave one by one (in random order, some added late
/// as a split's copies do), and after every change a query over a triangle finds exactly the
/// nodes still in the grid inside it, down to none left and back to one added after that (the
/// query skips an empty grid: its count must follow every add and remove); the query within
/// the triangle's box (the ear tests') the same nodes in the same order, less those outside the
/// box; and a query over a box (the chains' gathering of other chains' nodes) the nodes still
/// in the grid within it. Every fourth round crowds 150 nodes into one cell: its columns are
/// scanned 64 at a time.
TEST(ReflexGridQuery, FindsTheNodesStillInTheGridAsTheyLeave) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> coordinate(0.0, 100.0);
  for (int round = 0; round < 20; ++round) {
    Boundary b;
    const std::uint32_t n = 50 + static_cast<std::uint32_t>(rng() % 200);
    const std::uint32_t crowded = round % 4 == 3 ? 150 : 0;
    for (std::uint32_t v = 0; v <= n + 20; ++v) {
      const double scale = v < crowded ? 1e-3 : 1;
      b.add({scale * coordinate(rng), scale * coordinate(rng)}, v);
    }
    std::vector<std::uint32_t> built(n);
    for (std::uint32_t v = 0; v < n; ++v) built[v] = v;
    ReflexGrid grid;
    grid.build(b, built);
    std::vector<std::uint32_t> in_grid = built;
    std::uint32_t next_extra = n;
    const auto expect_found = [&](const char* when) {
      for (int q = 0; q < 8; ++q) {
        Point a{coordinate(rng), coordinate(rng)}, c{coordinate(rng), coordinate(rng)};
        Point t{coordinate(rng), coordinate(rng)};
        if (orient2d(a, t, c) < 0) std::swap(t, c);
        if (q == 0 && crowded > 0) a = {-1, -1}, t = {50, -1}, c = {-1, 50};  // over the crowd
        std::set<std::uint32_t> expected, found;
        for (std::uint32_t v : in_grid)
          if (inside_or_on(a, t, c, b.pos[v])) expected.insert(v);
        const Box box{std::min({a.x, t.x, c.x}), std::min({a.y, t.y, c.y}),
                      std::max({a.x, t.x, c.x}), std::max({a.y, t.y, c.y})};
        const auto in_box = [&](const Point& p) {
          return p.x >= box.x0 && p.x <= box.x1 && p.y >= box.y0 && p.y <= box.y1;
        };
        std::vector<std::uint32_t> near_in_box, boxed;
        grid.any_near_triangle(a, t, c, [&](const ReflexGrid::Entry& e) {
          if (inside_or_on(a, t, c, e.pos)) found.insert(e.node);
          if (in_box(e.pos)) near_in_box.push_back(e.node);
          return false;
        });
        ASSERT_EQ(found, expected)
            << when << ", round " << round << ", " << in_grid.size() << " nodes in the grid";
        // Both ways (a SIMD scan of the cells, a test a node), whichever the grid would take.
        for (const bool scanned : {false, true}) {
          boxed.clear();
          const auto collect = [&](const ReflexGrid::Entry& e) {
            EXPECT_EQ(e.pos, b.pos[e.node]);
            boxed.push_back(e.node);
            return false;
          };
          if (scanned)
            grid.any_in_box_near_triangle<true>(a, t, c, box, collect);
          else
            grid.any_in_box_near_triangle<false>(a, t, c, box, collect);
          ASSERT_EQ(boxed, near_in_box) << when << ", round " << round << ", scanned " << scanned;
        }
        // It stops where the visit says so.
        if (boxed.size() > 1) {
          std::size_t visits = 0;
          EXPECT_TRUE(grid.any_in_box_near_triangle(
              a, t, c, box, [&](const ReflexGrid::Entry&) { return ++visits == 2; }));
          EXPECT_EQ(visits, 2u);
        }
      }
      // Boxes (some past the grid's edges, some a single point at a node): exactly the nodes
      // still in the grid within them.
      for (int q = 0; q < 8; ++q) {
        Point lo{coordinate(rng) - 20, coordinate(rng) - 20}, hi{coordinate(rng), coordinate(rng)};
        if (q == 0 && !in_grid.empty()) lo = hi = b.pos[in_grid[rng() % in_grid.size()]];
        std::set<std::uint32_t> expected, found;
        for (std::uint32_t v : in_grid) {
          const Point& p = b.pos[v];
          if (p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y) expected.insert(v);
        }
        grid.for_each_in_box(lo, hi, [&](const ReflexGrid::Entry& e) {
          EXPECT_TRUE(found.insert(e.node).second) << "visited twice";
        });
        ASSERT_EQ(found, expected) << when << ", box " << q;
      }
      // The whole square: every node still in the grid, and no other.
      std::set<std::uint32_t> all;
      for (const Point& a : {Point{-1, -1}, Point{101, 101}}) {
        grid.any_near_triangle(a, {101, -1}, {-1, 101}, [&](const ReflexGrid::Entry& e) {
          all.insert(e.node);
          return false;
        });
      }
      ASSERT_EQ(all, std::set<std::uint32_t>(in_grid.begin(), in_grid.end())) << when;
    };
    expect_found("built");
    while (!in_grid.empty()) {
      const std::size_t k = rng() % in_grid.size();
      grid.remove(in_grid[k], b.pos[in_grid[k]]);
      in_grid.erase(in_grid.begin() + static_cast<std::ptrdiff_t>(k));
      if (rng() % 8 == 0 && next_extra < n + 20) {
        grid.add(next_extra, b.pos[next_extra]);
        in_grid.push_back(next_extra++);
      }
      expect_found("after a removal");
    }
    grid.add(next_extra, b.pos[next_extra]);
    in_grid.push_back(next_extra);
    expect_found("one added to an empty grid");
  }
}

INSTANTIATE_TEST_SUITE_P(Magnitudes, GridQuery,
                         ::testing::Values(Case{1, 0}, Case{1e-7, 0}, Case{0.1, 1e8},
                                           Case{1e3, -1e9}, Case{3, 0.5}, Case{1e-3, 1e3}));

}  // namespace
}  // namespace pear::detail
