// finish_strip_in_fans (src/core/strip_fans.cpp), an internal: on strips (a straight run and
// one or two nodes across from it) the fans are a valid triangulation (pear's validator: exact
// area, every edge), each run edge's triangle has the nearer of the two apexes, and the result
// is the same at every thread and partition count; every other cycle is left alone.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "core/strip_fans.hpp"
#include "pear/validate.hpp"
#include "run_contexts.hpp"

namespace pear::detail {
namespace {

/// A cycle of nodes at `points`, in order, each node its own vertex.
struct Cycle {
  Boundary b;
  std::vector<std::uint32_t> order;
  std::vector<std::uint8_t> pinch;
  explicit Cycle(const Ring& points) {
    for (const Point& p : points) order.push_back(b.add(p, b.size()));
    pinch.assign(points.size(), 0);
  }
};

/// The run (0, 0), (1, 0), ..., (n, 0), then the points after it.
Ring run_then(std::size_t n, std::initializer_list<Point> after) {
  Ring ring;
  for (std::size_t i = 0; i <= n; ++i) ring.push_back({static_cast<double>(i), 0});
  ring.insert(ring.end(), after);
  return ring;
}

/// Runs the finish at 1, 2 and 8 threads and 1, 2, 3 and 16 partitions: the same result every
/// time, which it returns (empty when it declined; then it appended nothing).
TriangleList finish(const Cycle& cycle, bool expect_done) {
  TriangleList first;
  bool have_first = false;
  for_each_context({1u, 2u, 8u}, {1u, 2u, 3u, 16u}, [&](const RunContext& ctx, RunProfile&) {
    TriangleList out{{7, 7, 7}};  // appended after what is there
    EXPECT_EQ(finish_strip_in_fans(cycle.b, cycle.order, cycle.pinch, ctx, out), expect_done);
    EXPECT_EQ(out.front(), (std::array<std::uint32_t, 3>{7, 7, 7}));
    out.erase(out.begin());
    if (!expect_done) {
      EXPECT_TRUE(out.empty());
    }
    if (!have_first) first = out, have_first = true;
    EXPECT_EQ(out, first) << "depends on the threads or partitions";
  });
  return first;
}

/// Valid (pear's validator), and each triangle on a run edge (i, i + 1) has its third corner
/// at `apex_of(i)`.
template <class ApexOf>
void expect_fans(const Ring& ring, const TriangleList& triangles, std::size_t run_edges,
                 ApexOf&& apex_of) {
  ASSERT_EQ(triangles.size(), ring.size() - 2);
  const ValidationReport report = validate(Polygon{ring}, triangles);
  EXPECT_TRUE(report.valid) << (report.messages.empty() ? "" : report.messages.front());
  std::size_t checked = 0;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k)
      if (t[(k + 1) % 3] == t[k] + 1 && t[k] < run_edges) {
        EXPECT_EQ(t[(k + 2) % 3], apex_of(t[k])) << "run edge " << t[k];
        ++checked;
      }
  EXPECT_EQ(checked, run_edges);
}

double squared(const Point& p, const Point& q) {
  return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y);
}

TEST(StripInFans, TwoApexesEachTakeTheNodesNearerThem) {
  // A rectangle 10,000 x 3 with the run along its foot: A = (10000, 3), B = (0, 3).
  const std::size_t n = 10'000;
  const Ring ring = run_then(n, {{10'000, 3}, {0, 3}});
  const std::uint32_t a = n + 1, b = n + 2;
  const TriangleList triangles = finish(Cycle(ring), true);
  expect_fans(ring, triangles, n, [&](std::uint32_t i) {
    return squared(ring[a], ring[i]) < squared(ring[b], ring[i]) ? a : b;
  });
}

TEST(StripInFans, TheCombsStripWithAToothLeftIsOneFan) {
  // What mark-and-cut leaves of a comb: B is a tooth's top that cannot see the run (the cycle
  // turns right at r_0), so A takes it all; the triangle A, B, r_0 closes it.
  const std::size_t n = 8'000;
  Ring ring;
  for (std::size_t i = 0; i <= n; ++i) ring.push_back({static_cast<double>(n - i), 1});
  ring.push_back({n + 1.0, 0});   // A
  ring.push_back({n + 1.0, 11});  // B
  const TriangleList triangles = finish(Cycle(ring), true);
  expect_fans(ring, triangles, n, [&](std::uint32_t) { return n + 1; });
}

TEST(StripInFans, ATriangleWithARunOnOneSideIsOneFan) {
  const std::size_t n = 5'000;
  const Ring ring = run_then(n, {{2'500, 40}});
  expect_fans(ring, finish(Cycle(ring), true), n, [&](std::uint32_t) { return n + 1; });
}

TEST(StripInFans, AReflexApexStillSeesItsPart) {
  // B low in the middle: the cycle turns right at B but left at r_0, so B's fan is inside.
  const std::size_t n = 6'000;
  const Ring ring = run_then(n, {{6'000, 10}, {3'000, 1}});
  const std::uint32_t a = n + 1, b = n + 2;
  expect_fans(ring, finish(Cycle(ring), true), n, [&](std::uint32_t i) {
    return squared(ring[a], ring[i]) < squared(ring[b], ring[i]) ? a : b;
  });
}

TEST(StripInFans, OtherCyclesAreLeftAlone) {
  {
    SCOPED_TRACE("too few nodes");
    finish(Cycle(run_then(min_strip_nodes - 4, {{100, 3}, {0, 3}})), false);
  }
  {
    SCOPED_TRACE("a notch in the run: more than four bends");
    Ring ring = run_then(10'000, {{10'000, 3}, {0, 3}});
    ring[5'000].y = 1;
    finish(Cycle(ring), false);
  }
  {
    SCOPED_TRACE("a node of the run at a position another node has");
    Cycle cycle(run_then(10'000, {{10'000, 3}, {0, 3}}));
    cycle.pinch[4'000] = 1;
    finish(cycle, false);
  }
  {
    SCOPED_TRACE("three nodes across: a square's sides");
    finish(Cycle(run_then(10'000, {{10'000, 3}, {5'000, 9}, {0, 3}})), false);
  }
  {
    SCOPED_TRACE("clockwise: both apexes on the wrong side");
    finish(Cycle(run_then(10'000, {{10'000, -3}, {0, -3}})), false);
  }
  {
    SCOPED_TRACE("crossing itself: the side from A to B crosses the run");
    finish(Cycle(run_then(10'000, {{10'000, 10}, {5'000, -1}})), false);
  }
}

}  // namespace
}  // namespace pear::detail
