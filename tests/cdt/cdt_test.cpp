// Constrained Delaunay by flips on small polygons chosen for one difficulty each, and on the
// synthetic families: validator's Delaunay check, flip statistics, determinism across thread
// counts, and (with the CGAL oracle) equality with CGAL.
#include <gtest/gtest.h>

#include <cmath>

#include "pear/config.hpp"
#include "pear/generate.hpp"
#include "sizes.hpp"
#include "support.hpp"

namespace pear::testing {
namespace {

void expect_cdt_everywhere(const Polygon& polygon, const std::string& what) {
  CdtCheck expect_cdt(polygon);
  for (Algorithm algorithm : all_algorithms)
    for (unsigned threads : {1u, 2u})
      for (unsigned partitions : {1u, 3u}) {
        SCOPED_TRACE(what + " " + algorithm_name(algorithm) + " threads " +
                     std::to_string(threads) + " partitions " + std::to_string(partitions));
        const auto result = constrained_delaunay(polygon, algorithm, threads, partitions);
        ASSERT_EQ(result.status, Status::ok);
        expect_cdt(result.triangles);
      }
}

TEST(Cdt, ConvexPolygonInGeneralPosition) {
  Ring ring;
  for (int i = 0; i < 60; ++i) {
    const double angle = 2 * M_PI * i / 60;
    ring.push_back({std::cos(angle) * (3 + 0.01 * (i % 7)), std::sin(angle) * 2});
  }
  expect_cdt_everywhere({ring}, "ellipse");
}

TEST(Cdt, CocircularPointsAreNeverFlipped) {
  // 12 points exactly on the circle of radius 5: every triangulation is a CDT.
  const Ring ring = {{5, 0},  {4, 3},   {3, 4},   {0, 5},  {-3, 4}, {-4, 3},
                     {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}};
  const Polygon circle = {ring};
  const auto result = constrained_delaunay(circle, Algorithm::sequential, 1, 1);
  ASSERT_EQ(result.status, Status::ok);
  EXPECT_EQ(result.delaunay.flips, 0u);
  EXPECT_EQ(result.delaunay.edges, ring.size() - 3);
  CdtCheck expect_cdt(circle);
  expect_cdt(result.triangles);
}

TEST(Cdt, ZeroAreaTriangleFromCollinearRunIsFlippedAway) {
  // A long bottom edge cut into collinear pieces: ear clipping may leave flat triangles there.
  Ring ring;
  for (int x = 0; x <= 20; ++x) ring.push_back({static_cast<double>(x), 0});
  ring.push_back({20, 1});
  ring.push_back({10, 0.5});
  ring.push_back({0, 1});
  expect_cdt_everywhere({ring}, "collinear run");
}

TEST(Cdt, BridgeToAHoleIsNotAConstraint) {
  const Polygon polygon = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}}, {{4, 4}, {4, 6}, {6, 6}, {6, 4}}};
  expect_cdt_everywhere(polygon, "square hole");
}

TEST(Cdt, HoleTouchingTheOuterRingAtAVertex) {
  const Polygon polygon = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}, {0, 5}},
                           {{0, 5}, {4, 6}, {4, 4}},
                           {{7, 2}, {7, 3}, {8, 3}}};
  expect_cdt_everywhere(polygon, "touching hole");
}

TEST(Cdt, StatisticsAddUp) {
  const Polygon polygon = generate_polygon("star", 5000, 3);
  const auto result = constrained_delaunay(polygon, Algorithm::sequential, 2, 4);
  ASSERT_EQ(result.status, Status::ok);
  EXPECT_EQ(result.delaunay.edges, 5000u - 3);
  EXPECT_GT(result.delaunay.flips_in_partitions, 0u);
  EXPECT_EQ(result.delaunay.flips,
            result.delaunay.flips_in_partitions + result.delaunay.flips_on_borders);
  const auto one = constrained_delaunay(polygon, Algorithm::sequential, 1, 1);
  EXPECT_EQ(one.delaunay.flips_in_partitions + one.delaunay.flips_on_borders, 0u);
  EXPECT_GT(one.delaunay.flips, 0u);
}

// Random holes give many border flips: the fix-up runs rounds of parallel flips there.
TEST(Cdt, BorderRoundsRunInParallelAndGiveTheSameCdt) {
  const Polygon polygon = generate_polygon("random-holes", 20000, 5);
  Triangles first;
  for (unsigned threads : {1u, 2u, 4u}) {
    RunProfile profile;
    const auto result = constrained_delaunay(polygon, Algorithm::sequential, threads, 4, &profile);
    ASSERT_EQ(result.status, Status::ok);
    EXPECT_GT(tasks_of(profile, "cdt border round: flip"), 0u)
        << "no round was large enough to run in parallel";
    EXPECT_GT(result.delaunay.flips_on_borders, 1000u);
    if (threads == 1) {
      first = result.triangles;
      CdtCheck expect_cdt(polygon);
      expect_cdt(result.triangles);
    }
    EXPECT_EQ(result.triangles, first) << threads << " threads";
  }
}

/// How many phases the profile recorded under `name` (a border round records one each).
std::size_t phases_named(const RunProfile& profile, std::string_view name) {
  std::size_t count = 0;
  for (const auto& phase : profile.phases) count += phase.name == name;
  return count;
}

// A thin ellipse with a cluster of small holes at its centre (160 holes: runs too many to be
// "a few long ones") after partition-and-cut at 2 partitions: the flips from its chains'
// triangles cascade across the border, two waiting on each other at a time. The border rounds
// hand such a cascade to Lawson's loop instead of running a round per two flips (at 100,000
// points 3.7 million rounds, 26 s); and since points in convex position take each set's own
// CDT far from the whole one (4.5 million flips across the border, against about 100,000 from
// the clip on one partition), past 4 flips an edge the border flips stop and the clip's
// triangles are flipped on one partition.
Polygon thin_ellipse_with_holes() {
  Ring ring;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    const double angle = 2 * M_PI * i / n;
    ring.push_back({1000 * std::cos(angle), 200 * std::sin(angle)});
  }
  Polygon polygon{ring};
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 10; ++j) {
      const double x = 0.3 * i, y = 0.3 * j;
      polygon.push_back({{x, y}, {x, y + 0.1}, {x + 0.1, y + 0.1}, {x + 0.1, y}});
    }
  return polygon;
}

TEST(Cdt, CascadesAcrossBordersGoToLawsonAndPastABudgetToOnePartition) {
  const Polygon polygon = thin_ellipse_with_holes();
  RunProfile profile;
  const auto result = constrained_delaunay(polygon, Algorithm::partition_and_cut, 2, 2, &profile);
  ASSERT_EQ(result.status, Status::ok);
  expect_delaunay(polygon, result.triangles);
  EXPECT_LE(phases_named(profile, "cdt border round: test"), 64u);
  EXPECT_EQ(phases_named(profile, "cdt border rounds: Lawson"), 1u);
  // Given up: the statistics are the one partition's.
  EXPECT_EQ(phases_named(profile, "cdt flip"), 1u);
  EXPECT_EQ(result.delaunay.flips_in_partitions + result.delaunay.flips_on_borders, 0u);
  EXPECT_LT(result.delaunay.flips, 20 * result.delaunay.edges);
}

// The CDT's arrays stay with the engine between runs (the mesh, its build's keys, the sets, the
// flags, the clip's copy, the border rounds' marks): one Triangulator takes polygons larger and
// smaller than the last, on one partition and in sets (with border rounds, and with the border
// flips given up and the clip's copy restored), and each comes out as a Triangulator that
// never ran before makes it.
TEST(Cdt, ArraysKeptBetweenRunsGiveEachPolygonItsOwnCdt) {
  const struct {
    Polygon polygon;
    Algorithm algorithm;
    unsigned partitions;
  } runs[] = {
      {generate_polygon("random-holes", 20000, 5), Algorithm::sequential, 4},
      {generate_polygon("star", 600, 2), Algorithm::sequential, 1},
      {thin_ellipse_with_holes(), Algorithm::partition_and_cut, 2},
      {generate_polygon("random-holes", 8000, 7), Algorithm::partition_and_cut, 3},
      {generate_polygon("random-holes", 20000, 5), Algorithm::sequential, 4},
      {generate_polygon("random-holes", 20000, 5), Algorithm::sequential, 1},
      {generate_polygon("spiral", 30000, 3), Algorithm::automatic, 16},
  };
  Triangulator kept;
  for (const auto& run : runs) {
    SCOPED_TRACE(std::to_string(run.polygon.front().size()) + " outer vertices, partitions " +
                 std::to_string(run.partitions));
    Options options{.algorithm = run.algorithm, .delaunay = true};
    options.threads = 2;
    options.partitions = run.partitions;
    options.executor = executor_for(2);
    const auto again = kept.triangulate(run.polygon, options);
    Triangulator fresh;
    const auto first = fresh.triangulate(run.polygon, options);
    ASSERT_EQ(first.status, Status::ok);
    EXPECT_EQ(again.triangles, first.triangles);
    EXPECT_EQ(again.delaunay.flips, first.delaunay.flips);
    EXPECT_EQ(again.delaunay.flips_on_borders, first.delaunay.flips_on_borders);
    expect_delaunay(run.polygon, again.triangles);
  }
}

// Many sets give more border half-edges than one task pairs: they are paired in ranges of
// their order, and the two half-edges of an edge must land in one range.
TEST(Cdt, BordersPairedInRangesGiveTheCdt) {
  const Polygon polygon = generate_polygon("random-holes", 60000, 11);
  CdtCheck expect_cdt(polygon);
  Triangles first;
  for (unsigned threads : {1u, 2u}) {
    RunProfile profile;
    const auto result = constrained_delaunay(polygon, Algorithm::sequential, threads, 64, &profile);
    ASSERT_EQ(result.status, Status::ok);
    EXPECT_GE(tasks_of(profile, "cdt relink borders: pair"), PEAR_HAS_THREADS ? 3u : 1u)
        << "the borders fit one range: nothing tested";
    if (threads == 1) {
      first = result.triangles;
      expect_cdt(result.triangles);
    }
    EXPECT_EQ(result.triangles, first) << threads << " threads";
  }
}

/// The CDT after `algorithm`'s clip at `partitions`: its flip sets runs of the clip order
/// (`runs`) or pieces of the walk, the CDT, and the same triangles at 1, 2 and 4 threads.
void expect_sets(const char* kind, Algorithm algorithm, unsigned partitions, bool runs) {
  SCOPED_TRACE(std::string(kind) + ", " + std::to_string(partitions) + " partitions");
  const Polygon polygon = generate_polygon(kind, 30000, 3);
  CdtCheck expect_cdt(polygon);
  Triangles first;
  for (unsigned threads : {1u, 2u, 4u}) {
    RunProfile profile;
    const auto result = constrained_delaunay(polygon, algorithm, threads, partitions, &profile);
    ASSERT_EQ(result.status, Status::ok);
    EXPECT_EQ(tasks_of(profile, "cdt partition: clip order") != 0, runs);
    EXPECT_EQ(tasks_of(profile, "cdt partition"), runs ? 0u : 1u);
    if (algorithm == Algorithm::divide_and_conquer) {
      EXPECT_EQ(tasks_of(profile, "clip parts"), partitions) << "split, as the test means";
    }
    if (threads == 1) {
      first = result.triangles;
      expect_cdt(result.triangles);
    }
    EXPECT_EQ(result.triangles, first) << threads << " threads";
  }
}

// Partition-and-cut emits its triangles chain after chain: the flips' sets are runs of that
// order (no breadth-first walk) when nearly all came from chains, as on a star; a spiral's
// chains leave half its triangles to the sequential finish, whose order is by ear quality, and
// keeps the walk. Either way the CDT, and the same triangles on any thread count.
TEST(Cdt, SetsAreRunsOfTheClipOrderOnlyWhereChainsEmittedNearlyAll) {
  expect_sets("star", Algorithm::partition_and_cut, 8, true);
  expect_sets("spiral", Algorithm::partition_and_cut, 8, false);
  expect_sets("star", Algorithm::partition_and_cut, 2, true);
  expect_sets("spiral", Algorithm::partition_and_cut, 2, false);
}

// Divide-and-conquer emits its triangles part after part, each a slab of the plane: runs of
// that order are the flips' sets (no walk), but along corridors, which wind through every slab
// (a spiral: the walk). The CDT either way, the same on any thread count.
TEST(Cdt, DivideAndConquerSlabsAreSetsButAlongCorridors) {
  expect_sets("koch", Algorithm::divide_and_conquer, 4, true);
  expect_sets("random-holes", Algorithm::divide_and_conquer, 2, true);
  expect_sets("spiral", Algorithm::divide_and_conquer, 4, false);
  expect_sets("spiral", Algorithm::divide_and_conquer, 2, false);
}

/// With `delaunay` the clip only picks where the flips start: from `fast` where the outline is
/// runs of 3 to 64 edges monotone in x (random polygons with holes: 4, like coastlines), from the
/// heuristic asked for where they are shorter (random polygons: 2.2) or below 20,000 nodes.
/// Either way the CDT that CGAL gives.
TEST(Cdt, FlipsStartFromFastWhereRunsAreCoastLike) {
  struct Case {
    const char* kind;
    std::size_t vertices;
    bool from_fast;
  };
  for (const Case c : {Case{"random-holes", 30000, true}, Case{"random", 30000, false},
                       Case{"random-holes", 5000, false}}) {
    SCOPED_TRACE(std::string(c.kind) + " " + std::to_string(c.vertices));
    const Polygon polygon = generate_polygon(c.kind, c.vertices, 9);
    Options options{.algorithm = Algorithm::sequential, .delaunay = true, .threads = 1};
    const auto from_top = triangulate(polygon, options);
    options.heuristic = EarHeuristic::fast;
    const auto from_fast = triangulate(polygon, options);
    ASSERT_EQ(from_top.status, Status::ok);
    ASSERT_EQ(from_fast.status, Status::ok);
    // The same start gives the same flips in the same order: the same list.
    EXPECT_EQ(from_top.triangles == from_fast.triangles, c.from_fast);
    EXPECT_EQ(from_top.delaunay.flips == from_fast.delaunay.flips, c.from_fast);
    CdtCheck expect_cdt(polygon);
    expect_cdt(from_top.triangles);
  }
}

// Points in convex position have long Delaunay edges that cross any triangle sets, and each
// set's own CDT is far from the whole one: flipping in sets first took a 20,000-point ellipse up
// to 11 million flips across the sets' borders, against 28,238 on one partition. Where the
// outline has a few long runs the flips stay on one partition, whichever clip came first.
TEST(Cdt, OutlinesOfAFewLongRunsFlipOnOnePartition) {
  Ring ring;
  for (int i = 0; i < 20'000; ++i) {
    const double angle = 2 * M_PI * i / 20'000;
    ring.push_back({1000 * std::cos(angle), 400 * std::sin(angle)});
  }
  const Polygon ellipse{ring};
  const auto one = constrained_delaunay(ellipse, Algorithm::sequential, 1, 1);
  ASSERT_EQ(one.status, Status::ok);
  CdtCheck expect_cdt(ellipse);
  for (Algorithm algorithm : all_algorithms)
    for (unsigned partitions : {3u, 16u}) {
      SCOPED_TRACE(std::string(algorithm_name(algorithm)) + " partitions " +
                   std::to_string(partitions));
      const auto result = constrained_delaunay(ellipse, algorithm, 2, partitions);
      ASSERT_EQ(result.status, Status::ok);
      EXPECT_EQ(result.delaunay.flips_in_partitions + result.delaunay.flips_on_borders, 0u);
      EXPECT_LE(result.delaunay.flips, 3 * one.delaunay.flips);
      expect_cdt(result.triangles);
    }
}

TEST(Cdt, WithoutDelaunayNoStatistics) {
  const auto result = triangulate(generate_polygon("star", 500, 3));
  EXPECT_EQ(result.delaunay.flips, 0u);
  EXPECT_EQ(result.delaunay.edges, 0u);
}

class Families : public ::testing::TestWithParam<std::string> {};

TEST_P(Families, CdtForEveryAlgorithm) {
  const Polygon polygon = generate_polygon(GetParam(), 3000, 11);
  expect_cdt_everywhere(polygon, GetParam());
}

TEST_P(Families, SameTrianglesOnOneTwoAndFourThreads) {
  const Polygon polygon = generate_polygon(GetParam(), family_size(20000), 5);
  for (Algorithm algorithm : all_algorithms)
    for (unsigned partitions : {2u, 4u, 7u}) {
      SCOPED_TRACE(std::string(algorithm_name(algorithm)) + " partitions " +
                   std::to_string(partitions));
      const auto one = constrained_delaunay(polygon, algorithm, 1, partitions);
      ASSERT_EQ(one.status, Status::ok);
      for (unsigned threads : {2u, 4u}) {
        const auto many = constrained_delaunay(polygon, algorithm, threads, partitions);
        EXPECT_EQ(many.triangles, one.triangles) << threads << " threads";
        EXPECT_EQ(many.delaunay.flips, one.delaunay.flips);
      }
    }
}

std::vector<std::string> kinds() {
  std::vector<std::string> out;
  for (std::string_view kind : generator_kinds()) out.emplace_back(kind);
  return out;
}

INSTANTIATE_TEST_SUITE_P(Synthetic, Families, ::testing::ValuesIn(kinds()), [](const auto& info) {
  std::string name = info.param;
  std::replace(name.begin(), name.end(), '-', '_');
  return name;
});

// Found by fuzz/cdt (corpus/fuzz/cdt/crash-hole-in-reflex-corner): the hole touches the outer
// ring at its reflex corner, so triangles on one side of edge (4,4)-(8,8) use the outer ring's
// copy of (4,4) and on the other the hole's; the flip across that edge was missed.
TEST(Cdt, FlipAcrossAnEdgeFromAPointTheHoleTouches) {
  const Polygon polygon = {{{0, 0}, {4, 0}, {4, 4}, {8, 4}, {8, 8}, {0, 8}},
                           {{4, 4}, {4, 6}, {2, 6}, {2, 4}}};
  expect_cdt_everywhere(polygon, "hole in the reflex corner");
}

}  // namespace
}  // namespace pear::testing
