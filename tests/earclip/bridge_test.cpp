// Hole bridging in parts (src/earclip/bridge.cpp): every hole's ray and visible vertex found as
// parallel tasks, then spliced in order. On polygons built to hit its hard cases (rays that hit
// other holes, bridges that cross a later hole's ray, holes that share a target vertex, touch
// the shell or lie on its edges, leftmost vertices on one line, chains, a hole outside the
// shell) the bridged boundary must be the serial joining's, node for node, at 1, 2, 3 and 8
// threads and 2, 3, 16 and 4,096 parts; one cycle through every node; no two edges crossing.
// And the untangling of the points it passes twice (src/earclip/touching.cpp) the same with its
// hashing in parts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include "boundary_support.hpp"
#include "clean/clean.hpp"
#include "core/link_runs.hpp"
#include "earclip/bridge.hpp"
#include "earclip/touching.hpp"
#include "geometry/segments.hpp"
#include "pear/generate.hpp"
#include "pear/pear.hpp"
#include "run_contexts.hpp"

namespace pear::detail {
namespace {

using testing::cleaned;

struct Bridged {
  Boundary boundary;
  std::vector<std::uint32_t> unjoined;
  std::size_t redone = 0;
};

/// How the bridger is told the rings are apart: not at all, or apart with few holes joined
/// without a grid (the engine's way), or apart with the grid whatever the holes (its splice in
/// parts on rings apart, bridge_splice.cpp, on the hard cases below of a few dozen holes).
enum class Apart { no, yes, grid };

Bridged bridge(const CleanPolygon& clean, const RunContext& ctx, bool in_parts,
               Apart apart = Apart::no) {
  Bridged out{testing::rings_as_cycles(clean), {}, 0};
  Boundary& b = out.boundary;
  HoleBridger bridger;
  if (apart == Apart::grid) bridger.scan_up_to(0);
  out.unjoined = bridger.join(clean, b, ctx, in_parts, apart != Apart::no);
  out.redone = bridger.redone();
  return out;
}

/// Proper crossings between edges of the boundary (exact signs; shared ends and touching
/// are allowed, as on any weakly simple boundary).
std::size_t crossing_edges(const Boundary& b) {
  std::size_t crossings = 0;
  for (std::uint32_t u = 0; u < b.size(); ++u) {
    const Point &a = b.pos[u], &c = b.pos[b.next[u]];
    for (std::uint32_t v = u + 1; v < b.size(); ++v) {
      const Point &p = b.pos[v], &q = b.pos[b.next[v]];
      const double s1 = orient2d(a, c, p), s2 = orient2d(a, c, q);
      const double s3 = orient2d(p, q, a), s4 = orient2d(p, q, c);
      if (((s1 > 0 && s2 < 0) || (s1 < 0 && s2 > 0)) && ((s3 > 0 && s4 < 0) || (s3 < 0 && s4 > 0)))
        ++crossings;
    }
  }
  return crossings;
}

/// Whether no two vertices of the polygon share a position (what `apart` asks of the caller).
bool apart(const CleanPolygon& clean) {
  std::vector<Point> points(clean.points.begin(), clean.points.end());
  std::sort(points.begin(), points.end(), lexicographic_less);
  return std::adjacent_find(points.begin(), points.end()) == points.end();
}

void expect_same_boundary(const Bridged& joined, const Bridged& serial) {
  EXPECT_EQ(joined.unjoined, serial.unjoined);
  EXPECT_EQ(joined.boundary.next, serial.boundary.next);
  EXPECT_EQ(joined.boundary.prev, serial.boundary.prev);
  EXPECT_EQ(joined.boundary.vertex, serial.boundary.vertex);
  EXPECT_TRUE(joined.boundary.pos == serial.boundary.pos);
}

/// The serial joining is valid (one cycle, no crossing edges) and the joining in parts is the
/// same at every thread and part count; so is the joining without a grid, where the rings are
/// apart and the holes few enough. Returns the most holes any run in parts had to redo.
std::size_t expect_same_in_parts(const Polygon& polygon, bool check_crossings = true) {
  const CleanPolygon clean = cleaned(polygon);
  const Bridged serial = bridge(clean, RunContext{}, false);
  if (serial.unjoined.empty()) {
    EXPECT_EQ(testing::cycle_length(serial.boundary, 0), serial.boundary.size());
    if (check_crossings) {
      EXPECT_EQ(crossing_edges(serial.boundary), 0u);
    }
  }
  const bool scanned = apart(clean) && clean.ring_count() - 1 <= HoleBridger::scanned_holes;
  if (scanned) {
    SCOPED_TRACE("without a grid");
    expect_same_boundary(bridge(clean, RunContext{}, false, Apart::yes), serial);
  }
  std::size_t redone = 0;
  for_each_context(
      {1u, 2u, 3u, 8u}, {2u, 3u, 16u, 4096u},
      [&](const RunContext& ctx, const RunProfile& profile) {
        const std::uint32_t partitions = ctx.partitions;
        const Bridged parts = bridge(clean, ctx, true);
        expect_same_boundary(parts, serial);
        if (apart(clean)) {
          SCOPED_TRACE("rings apart, in parts");
          expect_same_boundary(bridge(clean, ctx, true, Apart::yes), serial);
          SCOPED_TRACE("rings apart, the grid, in parts");
          const Bridged waited = bridge(clean, ctx, true, Apart::grid);
          expect_same_boundary(waited, serial);
          EXPECT_EQ(waited.redone, parts.redone);
        }
        redone = std::max(redone, parts.redone);
        // The points where the boundary passes more than once, untangled with the hashing in
        // parts: the same links, the same verdict, the same shared positions.
        Boundary one = serial.boundary, many = serial.boundary;
        TouchingPoints serial_points, points_in_parts;
        EXPECT_EQ(points_in_parts.untangle(many, ctx, partitions + 1), serial_points.untangle(one));
        EXPECT_EQ(many.next, one.next);
        EXPECT_EQ(many.prev, one.prev);
        EXPECT_EQ(points_in_parts.shared_positions(), serial_points.shared_positions());
        // The search really ran as tasks, as many as the parts ask (or the holes allow).
        const auto find =
            std::find_if(profile.phases.begin(), profile.phases.end(),
                         [](const auto& p) { return p.name == "bridge: find attachments"; });
        // (Without threads the joining in parts is the serial one.)
        if (PEAR_HAS_THREADS && clean.ring_count() - 1 > HoleBridger::few_holes) {
          EXPECT_NE(find, profile.phases.end());
          if (find == profile.phases.end()) return;
          EXPECT_EQ(find->task_seconds.size(),
                    RunContext{.partitions = partitions}.tasks_for(clean.ring_count() - 1, 4));
          EXPECT_GT(find->task_seconds.size(), 1u);
        }
      });
  return redone;
}

Ring square(double x, double y, double side) {
  return {{x, y}, {x + side, y}, {x + side, y + side}, {x, y + side}};
}

Ring outer(double size) {
  return square(0, 0, size);
}

TEST(BridgeInParts, RaysThatHitOtherHoles) {
  // Rows of holes, each row shifted: a hole's ray hits the hole to its left, or one a row
  // above or below, or the shell.
  Polygon polygon{outer(1000)};
  for (int row = 0; row < 12; ++row)
    for (int col = 0; col < 12; ++col)
      polygon.push_back(square(40 + 75.0 * col + 13 * (row % 3), 40 + 75.0 * row, 30));
  expect_same_in_parts(polygon);
}

TEST(BridgeInParts, BridgesCrossingLaterRaysAreRedone) {
  // Holes in a column to the right of a spike of the shell: each one's bridge runs down-left
  // to the spike's upper base (0, 520), across the rays of the holes above it, and they share
  // that target. The holes after the first see an earlier bridge nearer than the edge they
  // hit: the splice finds them again, as the serial joining sees them.
  Polygon polygon{{{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}, {0, 520}, {400, 500}, {0, 480}}};
  for (const bool above : {true, false})  // and below the spike, towards (0, 480)
    for (int k = 0; k < 8; ++k) {
      const double y = above ? 501 + 2.3 * k : 497 - 2.3 * k;
      polygon.push_back({{500, y}, {500, y + 1}, {520, y + 1.5}, {520, y - 0.5}});
    }
  EXPECT_EQ(expect_same_in_parts(polygon) > 0, PEAR_HAS_THREADS != 0);
  // Every one of them is bridged to a base of the spike: a copy of it per bridge.
  const Bridged serial = bridge(cleaned(polygon), RunContext{}, false);
  const auto at = [&](Point p) {
    return std::count(serial.boundary.pos.begin(), serial.boundary.pos.end(), p);
  };
  EXPECT_EQ(at({0, 520}), 1 + 8);
  EXPECT_EQ(at({0, 480}), 1 + 8);
}

TEST(BridgeInParts, RaysThroughTheSpikesTip) {
  // Leftmost vertices at the tip's height: the rays hit the tip itself, or the hole before.
  Polygon polygon{{{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}, {0, 520}, {400, 500}, {0, 480}}};
  for (int k = 0; k < 10; ++k)
    polygon.push_back({{450.0 + 40 * k, 500},
                       {460.0 + 40 * k, 510},
                       {470.0 + 40 * k, 500},
                       {460.0 + 40 * k, 490}});
  expect_same_in_parts(polygon);
}

TEST(BridgeInParts, LeftmostVerticesOnOneLine) {
  // Leftmost vertices on one vertical line (ties broken by y) and on one horizontal line, with
  // holes whose left side is vertical (two leftmost candidates).
  Polygon polygon{outer(1000)};
  for (int k = 0; k < 10; ++k) polygon.push_back(square(300, 50 + 90.0 * k, 40));
  for (int k = 0; k < 6; ++k)
    polygon.push_back({{500.0 + 70 * k, 480},
                       {530.0 + 70 * k, 500},
                       {560.0 + 70 * k, 480},
                       {530.0 + 70 * k, 460}});
  expect_same_in_parts(polygon);
}

TEST(BridgeInParts, HolesTouchingTheShellAndEachOther) {
  // Holes sharing a vertex with the shell (touching splices), a hole whose leftmost vertex
  // lies inside a shell edge (the boundary runs through it: edge ids move, so the holes
  // after it are found again), and a checkerboard of holes touching at corners.
  Polygon polygon{{{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}, {0, 700}, {0, 300}}};
  polygon.push_back({{0, 300}, {40, 280}, {40, 320}});
  polygon.push_back({{0, 500}, {40, 480}, {40, 520}});  // inside the edge (0, 700)-(0, 300)
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 10; ++j)
      if ((i + j) % 2 == 0) polygon.push_back(square(200 + 20.0 * i, 200 + 20.0 * j, 20));
  expect_same_in_parts(polygon);
}

TEST(BridgeInParts, HoleVertexInsideAnEdgeWithNoRepeatedPosition) {
  // No two vertices share a position (apart, as a check that only looks for repeated positions
  // says), but one hole's leftmost vertex lies inside the shell's left edge: the splice in parts
  // on rings apart meets a ray through a vertex, makes what waits and hands the rest to the
  // grid's splice (splice_apart returning false), with the same boundary.
  Polygon polygon{{{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}}};
  for (int k = 0; k < 4; ++k) polygon.push_back(square(100 + 150.0 * k, 100, 40));
  polygon.push_back({{0, 500}, {40, 480}, {40, 520}});  // inside the edge (0, 1000)-(0, 0)
  for (int k = 0; k < 4; ++k) polygon.push_back(square(100 + 150.0 * k, 800, 40));
  ASSERT_TRUE(apart(cleaned(polygon)));
  expect_same_in_parts(polygon);
}

TEST(BridgeInParts, TwoHolesTouchingTheShellAtOneVertex) {
  // Both holes touch the shell at (0, 500); the first one's splice turns the shell node's
  // sector there, so the second must splice at the first hole's node, not at the shell node
  // the parallel search found (fails with the search's node kept after the first splice).
  Polygon polygon{{{0, 0}, {1000, 0}, {1000, 1000}, {0, 1000}, {0, 500}}};
  polygon.push_back({{0, 500}, {200, 700}, {200, 600}});  // leaves up-right
  polygon.push_back({{0, 500}, {200, 450}, {200, 400}});  // leaves below the first
  for (int k = 0; k < 6; ++k) polygon.push_back(square(500 + 60.0 * k, 100, 20));
  expect_same_in_parts(polygon);
}

TEST(BridgeInParts, ChainsOfHoles) {
  // Thin holes in a staircase: every ray hits the hole before it, and bridges pile up.
  Polygon polygon{outer(2000)};
  for (int k = 0; k < 60; ++k)
    polygon.push_back({{100.0 + 30 * k, 100.0 + 29 * k},
                       {110.0 + 30 * k, 140.0 + 29 * k},
                       {120.0 + 30 * k, 100.0 + 29 * k}});
  expect_same_in_parts(polygon);
}

TEST(BridgeInParts, HolesWithNothingToTheirLeftAreLeftOutAndTheRestJoined) {
  // Not a polygon (the engine's check says so first): one hole outside the shell, one
  // crossing its left side, both with nothing to the left of their leftmost vertex. The holes
  // to the right of the crossing one must not see it: the serial joining never merged it.
  Polygon polygon{outer(1000)};
  polygon.push_back(square(-500, 700, 100));
  polygon.push_back({{-100, 400}, {300, 450}, {300, 350}});
  for (int k = 0; k < 8; ++k) polygon.push_back(square(400 + 60.0 * k, 380, 40));
  // Seen from (400, 380) across where the crossing hole was: one in front of its right side,
  // which the search would take, and one behind it at a smaller angle, which the serial
  // joining takes.
  polygon.push_back({{330, 370}, {340, 372}, {340, 368}});
  polygon.push_back({{100, 372}, {110, 373}, {110, 371}});
  const CleanPolygon clean = cleaned(polygon);
  EXPECT_EQ(bridge(clean, RunContext{}, false).unjoined.size(), 2u);
  expect_same_in_parts(polygon, false);
}

TEST(BridgeInParts, GeneratedFamilies) {
  for (const char* kind : {"holes", "random-holes"})
    for (std::uint64_t seed : {1u, 2u, 3u}) {
      SCOPED_TRACE(std::string(kind) + " seed " + std::to_string(seed));
      expect_same_in_parts(generate_polygon(kind, 1500, seed));
    }
}

/// Up to 64 holes on rings that share no position are joined without a grid (the rays in one
/// pass over the edges, the visible vertices in one over the nodes): the serial grid's
/// boundary, and in parts the passes are tasks.
TEST(BridgeWithoutAGrid, RandomHolesUpTo64) {
  for (std::uint64_t seed : {1u, 2u, 3u, 4u, 5u})
    for (std::size_t vertices : {40u, 400u, 500u}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", " + std::to_string(vertices));
      const Polygon polygon = generate_polygon("random-holes", vertices, seed);
      const CleanPolygon clean = cleaned(polygon);
      ASSERT_TRUE(apart(clean));
      ASSERT_LE(clean.ring_count() - 1, HoleBridger::scanned_holes);
      expect_same_in_parts(polygon);
    }
}

/// A 20,000-gon with holes along its diameters: in parts the passes run as tasks.
TEST(BridgeWithoutAGrid, LargeOutlineFewHoles) {
  Polygon polygon{{}};
  for (int i = 0; i < 20000; ++i) {
    const double angle = 2 * 3.141592653589793 * i / 20000;
    polygon[0].push_back({1000 * std::cos(angle), 1000 * std::sin(angle)});
  }
  for (int k = -5; k < 5; ++k) {
    polygon.push_back(square(100.0 * k + 20, 30.0 * k, 40));
    polygon.push_back(square(-15, 100.0 * k + 45, 10));
  }
  expect_same_in_parts(polygon, false);  // convex outline, holes apart: no crossing to look for
  const CleanPolygon clean = cleaned(polygon);
  for_each_context({2u}, {4u}, [&](const RunContext& ctx, const RunProfile& profile) {
    bridge(clean, ctx, true, Apart::yes);
    for (const char* phase : {"bridge: rays", "bridge: sights"}) {
      const auto at = std::find_if(profile.phases.begin(), profile.phases.end(),
                                   [&](const auto& p) { return p.name == phase; });
      EXPECT_EQ(at != profile.phases.end(), PEAR_HAS_THREADS != 0) << phase;
      if (PEAR_HAS_THREADS && at != profile.phases.end()) {
        EXPECT_GT(at->task_seconds.size(), 1u);
      }
    }
  });
}

/// Past 512 holes they are sorted in tasks (and ranked in tasks): the same joining as the
/// serial one at every thread and part count, the merge rounds run.
TEST(BridgeInParts, ManyHolesSortedInParts) {
  const Polygon polygon = generate_polygon("random-holes", 12000, 4);
  ASSERT_GT(polygon.size(), 1024u);
  expect_same_in_parts(polygon, false);
  for_each_context({2u}, {16u}, [&](const RunContext& ctx, const RunProfile& profile) {
    bridge(cleaned(polygon), ctx, true);
    const auto merges =
        std::count_if(profile.phases.begin(), profile.phases.end(),
                      [](const auto& p) { return p.name == "bridge: merge holes"; });
    EXPECT_EQ(merges > 0, PEAR_HAS_THREADS != 0);
  });
}

/// One entry per cycle of at least three nodes, node by node: the cycle through `first`
/// entered there, then the others entered at their lowest node; the cycles through `skip`
/// left out.
std::vector<std::uint32_t> cycles_walked(const Boundary& b, std::uint32_t first,
                                         const std::vector<std::uint32_t>& skip) {
  std::vector<std::uint8_t> seen(b.size(), 0);
  const auto walk = [&](std::uint32_t start) {
    std::size_t length = 0;
    for (std::uint32_t v = start; !seen[v]; v = b.next[v]) seen[v] = 1, ++length;
    return length;
  };
  for (std::uint32_t hole : skip) walk(hole);
  std::vector<std::uint32_t> entries;
  if (!seen[first] && walk(first) >= 3) entries.push_back(first);
  for (std::uint32_t u = 0; u < b.size(); ++u)
    if (!seen[u] && walk(u) >= 3) entries.push_back(u);
  return entries;
}

/// Rings of `sizes` nodes, each linked into its own cycle in node order, then `splits`
/// diagonals within the first ring (each cuts a cycle in two, copies at the end).
Boundary rings(const std::vector<std::uint32_t>& sizes, std::uint32_t splits) {
  Boundary b;
  for (std::uint32_t size : sizes) {
    const std::uint32_t first = b.size();
    for (std::uint32_t i = 0; i < size; ++i) b.add({double(first + i), double(i % 7)}, b.size());
    for (std::uint32_t i = 0; i < size; ++i) b.link(first + i, first + (i + 1) % size);
  }
  for (std::uint32_t k = 0; k < splits; ++k) b.add_diagonal(1000 * k + 10, 1000 * k + 500);
  return b;
}

TEST(Cycles, TheSameEntriesInPartsAsNodeByNode) {
  // Many rings (two of two nodes, left out), a ring cut into pieces, an unjoined hole skipped.
  std::vector<std::uint32_t> sizes{60'000, 2, 25'000, 3, 2, 40'000};
  for (int k = 0; k < 50; ++k) sizes.push_back(100 + 37 * k);
  const Boundary b = rings(sizes, 30);
  const std::vector<std::uint32_t> skip{60'002 + 7};  // in the ring of 25,000
  for (std::uint32_t first : {0u, 777u, 60'000u, b.size() - 1}) {
    SCOPED_TRACE("first " + std::to_string(first));
    const std::vector<std::uint32_t> expected = cycles_walked(b, first, skip);
    ASSERT_GT(expected.size(), 50u);
    TouchingPoints serial;
    EXPECT_EQ(serial.cycles(b, first, skip), expected);
    for_each_context({1u, 2u}, {2u, 3u, 16u}, [&](const RunContext& ctx, const RunProfile&) {
      TouchingPoints points;
      EXPECT_EQ(points.cycles(b, first, skip, ctx, link_tasks(b.size(), ctx.partitions)), expected);
    });
  }
}

/// The cycle through `entry`, node by node (past the boundary's size where it does not close).
std::vector<std::uint32_t> walk_node_by_node(const Boundary& b, std::uint32_t entry) {
  std::vector<std::uint32_t> nodes;
  std::uint32_t v = entry;
  do nodes.push_back(v), v = b.next[v];
  while (v != entry && nodes.size() <= b.size());
  return nodes;
}

/// cycle_runs (core/link_runs.hpp) against a walk node by node: rings joined by bridges (their
/// copies numbered past the rings), nodes unlinked (their stale links point on), entries at a
/// run's start, inside a run (the cycle then closes with a run that stops short of it) and at
/// a copy; a cycle that does not close gives no runs.
TEST(Cycles, RunsFromTheJumpsLayOutTheWalk) {
  Boundary b = rings({30'000, 5'000, 700, 9}, 0);
  b.add_diagonal(12'000, 30'000 + 2'500);         // joins the second ring
  b.add_diagonal(29'000, 35'000 + 350);           // the third
  b.add_diagonal(35'000 + 700 + 4, 30'000 + 10);  // the fourth, from the third
  for (std::uint32_t v : {100u, 101u, 20'000u, 35'000u + 699u}) b.unlink(v);
  const auto walked = [&](std::uint32_t entry) { return walk_node_by_node(b, entry); };
  for_each_context({1u, 2u}, {1u, 4u}, [&](const RunContext& ctx, const RunProfile&) {
    std::vector<std::uint32_t> jumps;
    ASSERT_TRUE(find_link_jumps(b, ctx, "jumps", 4, jumps, [](std::size_t, std::size_t) {}));
    JumpLinks links;
    link_jumps(b, jumps, ctx, "jump links", 3, links);
    for (std::uint32_t entry : {0u, 5'000u, 12'001u, 30'000u + 2'600u, b.size() - 1}) {
      const std::vector<std::uint32_t> expected = walked(entry);
      ASSERT_EQ(expected.size(), 30'000u + 5'000u + 700u + 9u - 4u + 6u) << "one cycle";
      CycleLayout layout;
      layout.assign(cycle_runs(b, entry, jumps, links));
      ASSERT_EQ(layout.size, expected.size()) << "entry " << entry;
      std::vector<std::uint32_t> order(layout.size);
      layout.for_positions(0, order.size(), [&](std::size_t i, std::uint32_t v) { order[i] = v; });
      EXPECT_EQ(order, expected) << "entry " << entry;
    }
  });
  // A link cut: the cycle through node 0 no longer closes.
  b.next[29'500] = 29'500;
  std::vector<std::uint32_t> jumps;
  const RunContext serial;
  ASSERT_TRUE(find_link_jumps(b, serial, "jumps", 1, jumps, [](std::size_t, std::size_t) {}));
  JumpLinks links;
  link_jumps(b, jumps, serial, "jump links", 1, links);
  EXPECT_TRUE(cycle_runs(b, 0, jumps, links).empty());
}

/// walk_cycle_by_rulers (core/link_runs.hpp) against a walk node by node: links scrambled (runs
/// of one node), a second cycle beside it (a ring left out, its rulers never reached), nodes
/// unlinked (their stale links point on), entries on and off a ruler; a cycle that does not
/// close gives none.
TEST(Cycles, RulersLayOutTheWalk) {
  Boundary b = rings({50'000, 20'000}, 0);
  std::vector<std::uint32_t> order(50'000);
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.end(), std::mt19937(5));
  for (std::size_t i = 0; i < order.size(); ++i) b.link(order[i], order[(i + 1) % order.size()]);
  for (std::uint32_t v : {order[10], order[11], order[700]}) b.unlink(v);
  const auto walked = [&](std::uint32_t entry) { return walk_node_by_node(b, entry); };
  for_each_context({1u, 2u}, {4u, 16u}, [&](const RunContext& ctx, const RunProfile&) {
    for (std::uint32_t entry : {order[0], order[1], 64u * 100, 50'000u + 7, 50'000u + 64}) {
      const std::vector<std::uint32_t> expected = walked(entry);
      ASSERT_EQ(expected.size(), entry < 50'000 ? 50'000u - 3 : 20'000u) << "entry " << entry;
      std::vector<std::uint32_t> cycle{1, 2, 3};
      ASSERT_TRUE(walk_cycle_by_rulers(b, entry, ctx, cycle)) << "entry " << entry;
      EXPECT_EQ(cycle, expected) << "entry " << entry;
    }
  });
  // A link cut: the cycle through order[0] no longer closes; the other still does.
  b.next[order[20'000]] = order[20'000];
  const RunContext serial;
  std::vector<std::uint32_t> cycle{1, 2, 3};
  EXPECT_FALSE(walk_cycle_by_rulers(b, order[0], serial, cycle));
  EXPECT_EQ(cycle, (std::vector<std::uint32_t>{1, 2, 3})) << "untouched";
  EXPECT_TRUE(walk_cycle_by_rulers(b, 50'000u + 7, serial, cycle));
  EXPECT_EQ(cycle, walked(50'000u + 7));
}

TEST(Cycles, ScrambledLinksAreWalkedNodeByNode) {
  Boundary b = rings({70'000}, 0);
  std::vector<std::uint32_t> order(b.size());
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.end(), std::mt19937(3));
  // Two cycles: the first half of the shuffled order, and the second.
  const std::size_t half = order.size() / 2;
  for (std::size_t i = 0; i < half; ++i) b.link(order[i], order[(i + 1) % half]);
  for (std::size_t i = half; i < order.size(); ++i)
    b.link(order[i], order[i + 1 == order.size() ? half : i + 1]);
  const std::vector<std::uint32_t> expected = cycles_walked(b, order[half + 5], {});
  ASSERT_EQ(expected.size(), 2u);
  for_each_context({2u}, {16u}, [&](const RunContext& ctx, const RunProfile& profile) {
    TouchingPoints points;
    EXPECT_EQ(points.cycles(b, order[half + 5], {}, ctx, link_tasks(b.size(), ctx.partitions)),
              expected);
    // The jumps were too many: one pass found that, the walk went node by node.
    EXPECT_EQ(std::count_if(profile.phases.begin(), profile.phases.end(),
                            [](const auto& p) { return p.name == "bridge: link jumps"; }),
              PEAR_HAS_THREADS ? 1 : 0);
  });
}

}  // namespace
}  // namespace pear::detail
