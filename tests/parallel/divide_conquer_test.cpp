// Divide and conquer (paper §2.1) through the public API: split lines through holes, collinear
// runs, vertical edges and bridges, touching holes, tiny polygons, the whole shared corpus and
// the synthetic families. Every result must pass the independent validator with the exact
// triangle count, be bit-identical at 1, 2 and 8 threads, and (for the constructed cases, where
// nothing is degenerate) come from the parallel path, not the sequential fallback.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "gtest_corpus.hpp"
#include "pear/config.hpp"
#include "pear/generate.hpp"
#include "pear/pear.hpp"
#include "pear/validate.hpp"
#include "sizes.hpp"

namespace pear {
namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

struct Run {
  Triangles triangles;
  Status status = Status::ok;
  bool fell_back = false;  ///< the profile shows the sequential fallback
  bool split = false;      ///< the profile shows parts being clipped
};

Run divide_and_conquer(const Polygon& polygon, unsigned partitions, unsigned threads) {
  RunProfile profile;
  const auto result = triangulate(polygon, Options{.algorithm = Algorithm::divide_and_conquer,
                                                   .threads = threads,
                                                   .partitions = partitions,
                                                   .profile = &profile});
  Run run{result.triangles, result.status};
  for (const auto& phase : profile.phases) {
    run.fell_back |= phase.name == "fall back to sequential";
    run.split |= phase.name == "clip parts";
  }
  return run;
}

/// Valid with the exact count and area at every partition count, the same at 1, 2 and 8
/// threads. Returns how many partition counts fell back to the sequential engine. For input
/// that only the engine's weaker notion accepts (a self-touching ring), the count is not checked.
int expect_valid(const Polygon& polygon,
                 std::initializer_list<unsigned> partitions = {1, 2, 3, 4, 8},
                 bool check_count = true) {
  int fallbacks = 0;
  for (unsigned k : partitions) {
    SCOPED_TRACE("partitions " + std::to_string(k));
    const Run one = divide_and_conquer(polygon, k, 1);
    EXPECT_EQ(one.status, Status::ok);
    const ValidationReport report = validate(polygon, std::span(one.triangles));
    EXPECT_TRUE(report.valid) << (report.messages.empty() ? "" : report.messages.front());
    if (check_count) {
      EXPECT_EQ(report.triangles, report.expected_triangles);
    }
    EXPECT_LE(report.area_rel_error, 1e-9);
    for (unsigned threads : {2u, 8u})
      EXPECT_EQ(divide_and_conquer(polygon, k, threads).triangles, one.triangles)
          << "threads " << threads;
    fallbacks += one.fell_back;
  }
  return fallbacks;
}

/// Valid, and split into parts with no fallback at each partition count given.
void expect_split_cleanly(const Polygon& polygon, std::initializer_list<unsigned> partitions) {
  EXPECT_EQ(expect_valid(polygon, partitions), 0);
  for (unsigned k : partitions) EXPECT_TRUE(divide_and_conquer(polygon, k, 2).split) << k;
}

Ring rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Ring reversed(Ring ring) {
  std::reverse(ring.begin(), ring.end());
  return ring;
}

TEST(DivideAndConquer, SplitLinesThroughHoles) {
  // Holes spread over the whole width: every line crosses holes and the bridges to them.
  Polygon polygon = {rectangle(0, 0, 100, 20)};
  for (int i = 0; i < 9; ++i)
    polygon.push_back(reversed(rectangle(5 + 10 * i, 5, 12 + 10 * i, 15)));
  expect_split_cleanly(polygon, {2, 3, 4, 8});
}

TEST(DivideAndConquer, SteinerPointsOnBridges) {
  // Small holes stacked at one x far right of the outer ring's leftmost point: their bridges
  // run across the lines, so Steiner points fall on both sides of a bridge.
  Polygon polygon = {{{0, 0}, {50, -40}, {100, 0}, {50, 40}}};
  for (int i = -3; i <= 3; ++i)
    polygon.push_back(reversed({{70, 4.0 * i}, {72, 4.0 * i + 1}, {71, 4.0 * i + 2}}));
  expect_split_cleanly(polygon, {2, 3, 4, 8});
}

TEST(DivideAndConquer, SplitLinesThroughCollinearRuns) {
  // A long strip with a vertex at every integer x on both sides: lines cut edges of runs.
  Ring strip;
  for (int x = 0; x <= 40; ++x) strip.push_back({double(x), 0});
  for (int x = 40; x >= 0; --x) strip.push_back({double(x), 3});
  expect_split_cleanly({strip}, {2, 3, 4, 8});
}

TEST(DivideAndConquer, SplitLinesBesideVerticalEdges) {
  // A staircase: every x carries a vertical edge, the lines fall between them.
  Ring stairs = {{0, 0}, {20, 0}};
  for (int i = 20; i > 0; --i) {
    stairs.push_back({double(i), double(21 - i)});
    stairs.push_back({double(i - 1), double(21 - i)});
  }
  expect_split_cleanly({stairs}, {2, 3, 4, 8});
}

TEST(DivideAndConquer, CombTeethCrossingEveryLine) {
  // Horizontal teeth: each line crosses every tooth, many interior segments per line.
  Ring comb = {{0, 0}, {30, 0}};
  for (int t = 0; t < 12; ++t) {
    comb.push_back({30, 2.0 * t + 1});
    comb.push_back({1, 2.0 * t + 1});
    comb.push_back({1, 2.0 * t + 2});
  }
  comb.push_back({30, 25});
  comb.push_back({0, 25});
  expect_split_cleanly({comb}, {2, 3, 4, 8});
}

TEST(DivideAndConquer, TouchingHoles) {
  // Holes touching each other and the outer ring at vertices.
  const Polygon polygon = {rectangle(0, 0, 12, 6),
                           {{2, 3}, {4, 1}, {6, 3}, {4, 5}},
                           {{6, 3}, {8, 1}, {10, 3}, {8, 5}},
                           {{10, 3}, {12, 0}, {11, 3}, {12, 6}}};
  EXPECT_EQ(expect_valid(polygon), 0);
}

TEST(DivideAndConquer, PinchNodesUsedInterchangeably) {
  // Regression: pairs of holes touching at a vertex, bridged across the split line. A part's
  // clipper may use either node of a touching vertex, and the repair, matching triangle edges
  // by node, found a flat hole and dropped a triangle; corners are now matched by point.
  const Polygon polygon = {rectangle(0, 0, 20, 8),
                           {{5, 6}, {5, 3}, {3, 3}},
                           {{5, 3}, {7, 3}, {5, 1}},
                           {{15, 6}, {15, 5}, {13, 5}},
                           {{15, 5}, {17, 5}, {15, 4}}};
  expect_split_cleanly(polygon, {2, 3, 4, 8});
}

TEST(DivideAndConquer, PieceClippedByTheFallbackOnACrossingHole) {
  // Regression (CI's fuzz run, parallel target): the last hole crosses itself (its first edge
  // cuts its third at y = 3), and a piece through it needs the clipper's fallback, which adds
  // node copies after the piece's corners. The fan reduction and the boundary-edge test took
  // the grown node count for the corner count and read past the corners (heap-buffer-overflow
  // under ASan, garbage without). Now: not_simple at that hole, the same at every thread count.
  const Polygon polygon = {{{22, 14}, {17, 12}, {5, 12}, {0, 12}, {0, 0}, {22, 0}},
                           {{9, 4}, {10, 4}, {10, 3}, {9, 3}},
                           {{6, 9}, {7, 9}, {7, 8}, {6, 8}},
                           {{7, 10}, {17, 10}, {17, 5}, {8, 5}},
                           {{13, 4}, {14, 2.0078125}, {14, 3}, {13, 3}}};
  for (unsigned k : {2u, 3u, 4u, 8u}) {
    SCOPED_TRACE("partitions " + std::to_string(k));
    const auto result = triangulate(
        polygon,
        Options{.algorithm = Algorithm::divide_and_conquer, .threads = 2, .partitions = k});
    EXPECT_EQ(result.status, Status::not_simple);
    EXPECT_TRUE(std::any_of(result.diagnostics.begin(), result.diagnostics.end(),
                            [](const Diagnostic& d) { return d.is_not_simple() && d.ring == 4; }));
    const pear::Run one = divide_and_conquer(polygon, k, 1);
    for (unsigned threads : {2u, 8u})
      EXPECT_EQ(divide_and_conquer(polygon, k, threads).triangles, one.triangles) << threads;
  }
}

/// The repair's search for the holes and its check in several tasks each (thousands of
/// triangles at Steiner points): valid, no fallback, the same triangles at 1, 2 and 8 threads
/// (expect_valid), and the tasks really split the passes (a build without threads has no such
/// passes: one phase each).
/// The tasks of each phase of a run at 16 partitions on 2 threads (the polygon split cleanly).
std::map<std::string, std::size_t> tasks_per_phase(const Polygon& polygon) {
  expect_split_cleanly(polygon, {16});
  RunProfile profile;
  triangulate(polygon, Options{.algorithm = Algorithm::divide_and_conquer,
                               .threads = 2,
                               .partitions = 16,
                               .profile = &profile});
  std::map<std::string, std::size_t> tasks;
  for (const auto& phase : profile.phases) tasks[phase.name] += phase.task_seconds.size();
  return tasks;
}

TEST(DivideAndConquer, RepairInTasks) {
  std::map<std::string, std::size_t> tasks = tasks_per_phase(generate_polygon("random", 20000, 3));
  if (PEAR_HAS_THREADS) {
    EXPECT_GT(tasks["find Steiner holes: glue"], 1u);
    EXPECT_GT(tasks["check Steiner holes: sums"], 1u);
  } else {
    EXPECT_EQ(tasks["find Steiner holes"] + tasks["check Steiner holes"], 2u);
  }
}

// Past two passes' worth of nodes (link_tasks) the cycle is copied from its runs in tasks, and
// the split lines' sample and the repair's sorts are tasks too: the same triangles at every
// thread count, no step left on one thread where tasks were due.
TEST(DivideAndConquer, SerialStepsInTasks) {
  std::map<std::string, std::size_t> tasks = tasks_per_phase(generate_polygon("random", 70000, 5));
  if (PEAR_HAS_THREADS) {
    EXPECT_GT(tasks["cycle: copy"], 1u);
    EXPECT_EQ(tasks.count("cycle: walk"), 0u);
    EXPECT_GT(tasks["split lines: sample"], 1u);
    EXPECT_GT(tasks["split lines: merge"], 1u);
    EXPECT_GT(tasks["find Steiner holes: merge corners"], 1u);
    EXPECT_GT(tasks["find Steiner holes: merge edges"], 1u);
  } else {
    EXPECT_EQ(tasks["cycle: walk"], 1u);
    EXPECT_EQ(tasks.count("split lines: merge"), 0u);
  }
}

TEST(DivideAndConquer, MorePartitionsThanVertices) {
  expect_valid({{{0, 0}, {1, 0}, {0, 1}}}, {1, 2, 8, 64});
  expect_valid({rectangle(0, 0, 1, 1)}, {2, 16});
  expect_valid({{{0, 0}, {2, 0}, {2, 1}, {1, 2}, {0, 1}}}, {3, 7, 100});
}

TEST(DivideAndConquer, NearlyEqualXGivesFewerParts) {
  // x values one ulp apart: no line fits between them, the split uses fewer lines.
  const double x = 1.0, next = std::nextafter(1.0, 2.0);
  expect_valid({{{x, 0}, {next, 0}, {next, 1}, {x, 1}}}, {2, 4});
}

TEST(DivideAndConquer, InvalidInputIsReported) {
  const Polygon bowtie = {{{0, 0}, {2, 2}, {2, 0}, {0, 2}}};
  for (unsigned k : {2u, 4u})
    EXPECT_EQ(divide_and_conquer(bowtie, k, 2).status, Status::not_simple);
}

// The synthetic families at sizes where every line crosses many edges.
class DivideAndConquerFamilies : public ::testing::TestWithParam<std::string> {};

TEST_P(DivideAndConquerFamilies, ValidAndDeterministic) {
  for (std::size_t n : {std::size_t{1000}, testing::family_size(20000)}) {
    SCOPED_TRACE(n);
    EXPECT_EQ(expect_valid(generate_polygon(GetParam(), n, 3)), 0);
  }
}

INSTANTIATE_TEST_SUITE_P(Generated, DivideAndConquerFamilies,
                         ::testing::Values("star", "comb", "spiral", "koch", "hilbert", "random",
                                           "holes", "random-holes"),
                         [](const auto& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// Every polygon of the shared corpus (skipped when it is absent).
class DivideAndConquerCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(DivideAndConquerCorpus, ValidAndDeterministic) {
  const corpus::Folder folder = corpus::read_folder(corpus::shared_root(), GetParam());
  PEAR_SKIP_IF_MISSING(folder);
  int polygons = 0, fallbacks = 0, split_runs = 0;
  // Every 7th county, as parallel-variants-corpus takes them: all 2,614 at 15 runs each were
  // half a minute of CI, for 20-vertex outlines that divide-and-conquer hardly splits.
  const std::size_t stride = GetParam() == "counties" ? 7 : 1;
  for (std::size_t i = 0; i < folder.files.size(); i += stride) {
    const corpus::File& file = folder.files[i];
    PEAR_SKIP_IF_MISSING(file);
    SCOPED_TRACE(file.file);
    for (const Polygon& polygon : testing::read_polygons(file)) {
      // Only polygons the sequential engine calls valid: the others have their own tests.
      if (triangulate(polygon, {.algorithm = Algorithm::sequential}).status != Status::ok) continue;
      ++polygons;
      // Eurasia's 1.5M vertices at 2 and 8 partitions only (the coasts took 40 s of CI with
      // all five, 26 so); the other coasts and the sweep's thread counts cover the rest.
      const bool huge = testing::vertex_count(polygon) > testing::huge_vertices;
      fallbacks += huge ? expect_valid(polygon, {2, 8}, file.valid)
                        : expect_valid(polygon, {1, 2, 3, 4, 8}, file.valid);
      split_runs += huge ? 2 : 4;
    }
  }
  std::printf("%s: %d polygons, %d of %d runs with 2 or more partitions fell back\n",
              GetParam().c_str(), polygons, fallbacks, split_runs);
}

INSTANTIATE_TEST_SUITE_P(Shared, DivideAndConquerCorpus,
                         ::testing::Values("earcut", "countries", "glyphs", "synthetic", "counties",
                                           "coast"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace pear
