// Options at their limits (issue 19's audit): the partitions are clamped before any stage sizes
// its work by them, and the output depends on the partitions, never on the threads, for every
// algorithm including automatic.
#include <gtest/gtest.h>

#include <algorithm>
#include <climits>
#include <cmath>
#include <string>

#include "pear/generate.hpp"
#include "pear/pear.hpp"
#include "pear/validate.hpp"

namespace pear {
namespace {

constexpr Algorithm algorithms[] = {Algorithm::automatic, Algorithm::sequential,
                                    Algorithm::partition_and_cut, Algorithm::mark_and_cut,
                                    Algorithm::divide_and_conquer};

// --partitions 65536 on a square took 8 s and 6.3 GB (a chain clipper with a 4,096-bucket queue
// per partition); 10^6 through the API escaped as std::bad_alloc and UINT_MAX spawned 4.3e9
// tasks. Each now costs what the polygon needs (the test's time limit would catch a relapse).
TEST(Options, HugePartitionCountsAreClampedEarly) {
  const Polygon square = {{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const Polygon koch = generate_polygon("koch", 3000, 1);
  for (unsigned partitions : {65536u, 1'000'000u, UINT_MAX}) {
    for (Algorithm algorithm : algorithms) {
      for (bool delaunay : {false, true}) {
        SCOPED_TRACE(std::to_string(partitions) + " partitions, algorithm " +
                     std::to_string(static_cast<int>(algorithm)));
        const Options options = {
            .algorithm = algorithm, .delaunay = delaunay, .threads = 2, .partitions = partitions};
        const auto small = triangulate(square, options);
        ASSERT_EQ(small.status, Status::ok);
        EXPECT_EQ(small.triangles.size(), 2u);
        const auto larger = triangulate(koch, options);
        ASSERT_EQ(larger.status, Status::ok);
        EXPECT_TRUE(validate(koch, larger.triangles).valid);
        // Above max_partitions every count is max_partitions.
        const auto clamped = triangulate(koch, Options{.algorithm = algorithm,
                                                       .delaunay = delaunay,
                                                       .threads = 2,
                                                       .partitions = max_partitions});
        EXPECT_EQ(larger.triangles, clamped.triangles);
      }
    }
  }
}

// automatic chose partition-and-cut only when the executor had more than one thread, so
// --partitions 4 gave different files at --threads 1 and 2 (Newfoundland, Africa). The choice
// depends on the size and the partitions only.
TEST(Options, AutomaticDependsOnPartitionsNotThreads) {
  for (std::string_view kind : {"koch", "random-holes", "spiral"}) {
    const Polygon polygon = generate_polygon(kind, 40000, 3);
    for (Algorithm algorithm : algorithms) {
      for (bool delaunay : {false, true}) {
        SCOPED_TRACE(std::string(kind) + ", algorithm " +
                     std::to_string(static_cast<int>(algorithm)) + (delaunay ? ", CDT" : ""));
        const auto one = triangulate(
            polygon, {.algorithm = algorithm, .delaunay = delaunay, .threads = 1, .partitions = 4});
        const auto two = triangulate(
            polygon, {.algorithm = algorithm, .delaunay = delaunay, .threads = 2, .partitions = 4});
        ASSERT_EQ(one.status, Status::ok);
        EXPECT_EQ(one.triangles, two.triangles);
      }
    }
  }
  // And automatic on such a polygon is, at any thread count: divide-and-conquer with 2
  // partitions, partition-and-cut with 4, the sequential engine with 1 (docs/parallel.md).
  const Polygon koch = generate_polygon("koch", 40000, 3);
  const auto same = [&](unsigned partitions, Algorithm algorithm) {
    const auto chosen = triangulate(koch, {.threads = 1, .partitions = partitions});
    const auto named =
        triangulate(koch, {.algorithm = algorithm, .threads = 2, .partitions = partitions});
    return chosen.triangles == named.triangles;
  };
  EXPECT_TRUE(same(1, Algorithm::sequential));
  EXPECT_TRUE(same(2, Algorithm::divide_and_conquer));
  EXPECT_FALSE(same(2, Algorithm::partition_and_cut));
  EXPECT_TRUE(same(4, Algorithm::partition_and_cut));
  EXPECT_FALSE(same(4, Algorithm::divide_and_conquer));
}

// Past two partitions automatic takes divide-and-conquer along corridors (more than 16 runs of
// edges monotone in x, over 64 edges a run: a spiral's walls) and where holes are many (a hole
// every 16 nodes or more often: grids of holes, random polygons with holes), mark-and-cut on a
// few long runs (a comb: 2 runs), and partition-and-cut elsewhere (the star: runs of 1.5
// edges).
TEST(Options, AutomaticTakesDivideAndConquerAlongCorridors) {
  struct Case {
    const char* kind;
    Algorithm expected, other;
  };
  for (const Case c :
       {Case{"spiral", Algorithm::divide_and_conquer, Algorithm::partition_and_cut},
        Case{"comb", Algorithm::mark_and_cut, Algorithm::partition_and_cut},
        Case{"star", Algorithm::partition_and_cut, Algorithm::divide_and_conquer},
        Case{"holes", Algorithm::divide_and_conquer, Algorithm::partition_and_cut},
        Case{"random-holes", Algorithm::divide_and_conquer, Algorithm::partition_and_cut}}) {
    SCOPED_TRACE(c.kind);
    const Polygon polygon = generate_polygon(c.kind, 60000, 3);
    for (unsigned partitions : {4u, 8u}) {
      const auto chosen = triangulate(polygon, {.threads = 1, .partitions = partitions});
      const auto expected =
          triangulate(polygon, {.algorithm = c.expected, .threads = 2, .partitions = partitions});
      const auto other =
          triangulate(polygon, {.algorithm = c.other, .threads = 2, .partitions = partitions});
      ASSERT_EQ(chosen.status, Status::ok);
      EXPECT_EQ(chosen.triangles, expected.triangles) << partitions << " partitions";
      EXPECT_NE(chosen.triangles, other.triangles) << partitions << " partitions";
    }
  }
}

// On large coast-like outlines (runs of 3 to 64 edges: random polygons with holes have 4)
// automatic cuts divide-and-conquer into more parts than partitions, up to four partitions:
// twice as many from 100,000 nodes, four times from 300,000, and from 300,000 also on one
// partition (8 parts). Below 100,000 nodes the partitions. Past four partitions such outlines
// get partition-and-cut, but these, with a hole every 8 vertices, divide-and-conquer in the same
// parts.
TEST(Options, AutomaticCutsLargeCoastLikeOutlinesIntoMoreParts) {
  const auto same = [](const Polygon& polygon, unsigned partitions, Algorithm algorithm,
                       unsigned parts) {
    const auto chosen = triangulate(polygon, {.threads = 1, .partitions = partitions});
    const auto named =
        triangulate(polygon, {.algorithm = algorithm, .threads = 2, .partitions = parts});
    EXPECT_EQ(chosen.status, Status::ok);
    EXPECT_EQ(named.status, Status::ok);
    return chosen.triangles == named.triangles;
  };
  const Polygon large = generate_polygon("random-holes", 120000, 3);
  EXPECT_TRUE(same(large, 1, Algorithm::sequential, 1));
  EXPECT_TRUE(same(large, 2, Algorithm::divide_and_conquer, 4));
  EXPECT_FALSE(same(large, 2, Algorithm::divide_and_conquer, 2));
  EXPECT_TRUE(same(large, 3, Algorithm::divide_and_conquer, 6));
  EXPECT_TRUE(same(large, 8, Algorithm::divide_and_conquer, 16));
  const Polygon huge = generate_polygon("random-holes", 310000, 3);
  EXPECT_TRUE(same(huge, 1, Algorithm::divide_and_conquer, 8));
  EXPECT_TRUE(same(huge, 4, Algorithm::divide_and_conquer, 16));
  const Polygon smaller = generate_polygon("random-holes", 60000, 3);
  EXPECT_TRUE(same(smaller, 2, Algorithm::divide_and_conquer, 2));
  EXPECT_TRUE(same(smaller, 4, Algorithm::divide_and_conquer, 4));
  // A coast-like outline without holes (a circle rippled every 12 vertices: runs of about 6
  // edges monotone in x) past four partitions: partition-and-cut.
  Ring rippled;
  for (int i = 0; i < 120000; ++i) {
    const double r = 1000 + 0.2 * std::sin(2 * M_PI * (i % 12) / 12.0);
    const double angle = 2 * M_PI * i / 120000;
    rippled.push_back({r * std::cos(angle), r * std::sin(angle)});
  }
  EXPECT_TRUE(same(Polygon{rippled}, 8, Algorithm::partition_and_cut, 8));
  EXPECT_TRUE(same(Polygon{rippled}, 4, Algorithm::divide_and_conquer, 8));
}

// Few long runs monotone in x (a comb: 2; an outline convex or nearly so): mark-and-cut at any
// partition count, 2 included, where divide-and-conquer's repair of the comb's base strip and
// partition-and-cut's chains along its teeth cost more than they save.
TEST(Options, AutomaticTakesMarkAndCutWhereRunsAreFewAndLong) {
  Ring ellipse;
  for (int i = 0; i < 40000; ++i) {
    const double angle = 2 * M_PI * i / 40000;
    ellipse.push_back({1000 * std::cos(angle), 200 * std::sin(angle)});
  }
  for (const Polygon& polygon : {generate_polygon("comb", 60000, 3), Polygon{ellipse}}) {
    for (unsigned partitions : {2u, 4u}) {
      const auto chosen = triangulate(polygon, {.threads = 1, .partitions = partitions});
      const auto mark_and_cut = triangulate(
          polygon, {.algorithm = Algorithm::mark_and_cut, .threads = 2, .partitions = partitions});
      const auto divide_and_conquer = triangulate(
          polygon,
          {.algorithm = Algorithm::divide_and_conquer, .threads = 2, .partitions = partitions});
      ASSERT_EQ(chosen.status, Status::ok);
      EXPECT_EQ(chosen.triangles, mark_and_cut.triangles) << partitions << " partitions";
      EXPECT_NE(chosen.triangles, divide_and_conquer.triangles) << partitions << " partitions";
      // With the CDT its flips run on one thread (no sets), and give the CDT.
      RunProfile profile;
      const auto cdt = triangulate(
          polygon, {.delaunay = true, .threads = 2, .partitions = partitions, .profile = &profile});
      ASSERT_EQ(cdt.status, Status::ok);
      EXPECT_TRUE(validate(polygon, cdt.triangles, {.check_delaunay = true}).valid);
      EXPECT_EQ(cdt.delaunay.flips_in_partitions, 0u);
      const auto flip_phase = [&](const char* name) {
        return std::any_of(profile.phases.begin(), profile.phases.end(),
                           [&](const RunProfile::Phase& p) { return p.name == name; });
      };
      EXPECT_TRUE(flip_phase("cdt flip"));
      EXPECT_FALSE(flip_phase("cdt flip sets"));
    }
  }
}

// A polygon the check finds not simple: automatic goes straight to the sequential engine's
// best effort at every partition count, instead of clipping parts in parallel and falling back
// (the Natural Earth land mass land_0004 ran slower at 2 threads than at 1).
TEST(Options, AutomaticTakesNotSimplePolygonsSequentially) {
  Polygon polygon = generate_polygon("koch", 40000, 3);
  double x0 = polygon[0][0].x, x1 = x0, y0 = polygon[0][0].y;
  for (const Point& p : polygon[0])
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y);
  // A hole reaching out below the shell: its edges cross the outer ring.
  const double mid = (x0 + x1) / 2, width = (x1 - x0) / 50;
  polygon.push_back({{mid, y0 - width}, {mid - width, y0 + width}, {mid + width, y0 + width}});
  const auto sequential = triangulate(polygon, {.algorithm = Algorithm::sequential, .threads = 1});
  ASSERT_EQ(sequential.status, Status::not_simple);
  for (unsigned partitions : {2u, 4u}) {
    SCOPED_TRACE(std::to_string(partitions) + " partitions");
    RunProfile profile;
    const auto chosen =
        triangulate(polygon, {.threads = 2, .partitions = partitions, .profile = &profile});
    EXPECT_EQ(chosen.status, Status::not_simple);
    EXPECT_EQ(chosen.triangles, sequential.triangles);
    for (const auto& phase : profile.phases) EXPECT_NE(phase.name, "fall back to sequential");
  }
}

// Each phase's elapsed time holds its tasks: on one thread their sum, on several at least the
// longest (a phase left at 0 or timed around part of its tasks fails).
TEST(Options, ProfileRecordsEachPhaseElapsedTime) {
  const Polygon polygon = generate_polygon("star", 40'000);
  for (const unsigned threads : {1u, 2u}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    RunProfile profile;
    const auto result = triangulate(polygon, {.algorithm = Algorithm::partition_and_cut,
                                              .delaunay = true,
                                              .threads = threads,
                                              .partitions = 4,
                                              .profile = &profile});
    ASSERT_EQ(result.status, Status::ok);
    ASSERT_GT(profile.phases.size(), 5u);
    for (const auto& phase : profile.phases) {
      SCOPED_TRACE(phase.name);
      double sum = 0, longest = 0;
      for (const double t : phase.task_seconds) sum += t, longest = std::max(longest, t);
      EXPECT_GT(phase.wall_seconds, 0.0);
      EXPECT_GE(phase.wall_seconds, (threads == 1 ? sum : longest) * (1 - 1e-9));
    }
  }
}

}  // namespace
}  // namespace pear
