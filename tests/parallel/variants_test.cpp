// Partition-and-cut and mark-and-cut on every corpus polygon and the synthetic families, at
// several thread and partition counts: valid with exact area and n + 2h - 2 triangles, the same
// status contract as the sequential engine, and the same triangles whatever the thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string_view>

#include "gtest_corpus.hpp"
#include "pear/generate.hpp"
#include "sizes.hpp"

namespace pear {
namespace {

using testing::check_polygon;

constexpr Algorithm variants[] = {Algorithm::partition_and_cut, Algorithm::mark_and_cut};

struct Setting {
  unsigned threads, partitions;
};
constexpr Setting settings[] = {{1, 2}, {2, 2}, {2, 3}, {3, 4}, {8, 8}};

const char* name_of(Algorithm algorithm) {
  return algorithm == Algorithm::partition_and_cut ? "partition-and-cut" : "mark-and-cut";
}

/// Every variant and setting is valid; the output depends on the partitions only. `large`
/// inputs (coastlines) get the two settings that matter most, past a million vertices (Eurasia)
/// the one with the most parts.
void check_variants(const Polygon& polygon, bool expect_valid, bool large = false) {
  const std::vector<Setting> chosen =
      !large ? std::vector<Setting>(std::begin(settings), std::end(settings))
      : testing::vertex_count(polygon) > testing::huge_vertices
          ? std::vector<Setting>{{8, 8}}
          : std::vector<Setting>{{2, 2}, {8, 8}};
  for (Algorithm algorithm : variants) {
    for (EarHeuristic heuristic : {EarHeuristic::top, EarHeuristic::fast}) {
      if (large && heuristic == EarHeuristic::fast) continue;
      for (const Setting& s : chosen) {
        SCOPED_TRACE(std::string(name_of(algorithm)) + " threads " + std::to_string(s.threads) +
                     " partitions " + std::to_string(s.partitions) +
                     (heuristic == EarHeuristic::top ? " top" : " fast"));
        const Options options{.algorithm = algorithm,
                              .heuristic = heuristic,
                              .threads = s.threads,
                              .partitions = s.partitions};
        const auto triangles = check_polygon(polygon, expect_valid, options);
        if (s.threads == 1) continue;
        Options one_thread = options;
        one_thread.threads = 1;
        EXPECT_EQ(triangulate(polygon, one_thread).triangles, triangles) << "not deterministic";
      }
    }
  }
}

class Corpus : public testing::CorpusTest {};

TEST_P(Corpus, EveryVariantIsValidAndDeterministic) {
  const corpus::File& file = GetParam();
  const bool large = file.folder == "coast";
  for (const Polygon& polygon : testing::read_polygons(file))
    check_variants(polygon, file.valid, large);
}

PEAR_INSTANTIATE_CORPUS(Bundled, Corpus, corpus::bundled_root(), {"earcut", "countries", "glyphs"});
PEAR_INSTANTIATE_CORPUS(Shared, Corpus, corpus::shared_root(),
                        {"earcut", "countries", "glyphs", "synthetic"});
PEAR_INSTANTIATE_CORPUS(SharedCounties, Corpus, corpus::shared_root(), {"counties"}, 7);
PEAR_INSTANTIATE_CORPUS(SharedCoast, Corpus, corpus::shared_root(), {"coast"});

class Synthetic : public ::testing::TestWithParam<std::string> {};

TEST_P(Synthetic, EveryVariantIsValidAndDeterministic) {
  for (std::size_t n : {700, 5000, 40000})
    check_variants(generate_polygon(GetParam(), testing::family_size(n), 11), true);
}

std::vector<std::string> kinds() {
  std::vector<std::string> out;
  for (std::string_view kind : generator_kinds()) out.emplace_back(kind);
  return out;
}

INSTANTIATE_TEST_SUITE_P(Families, Synthetic, ::testing::ValuesIn(kinds()), [](const auto& info) {
  std::string name = info.param;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
});

Polygon regular(std::size_t n, double inner, double outer) {
  Ring ring;
  for (std::size_t i = 0; i < n; ++i) {
    const double angle = 6.283185307179586 * static_cast<double>(i) / static_cast<double>(n);
    const double r = i % 2 == 0 ? inner : outer;
    ring.push_back({std::round(r * std::cos(angle) * 1e6), std::round(r * std::sin(angle) * 1e6)});
  }
  return {ring};
}

TEST(Tricky, MorePartitionsThanVertices) {
  for (std::size_t n : {3, 4, 5, 8})
    for (unsigned partitions : {8u, 64u, 1000u})
      for (Algorithm algorithm : variants) {
        const auto result =
            triangulate(regular(n, 1, 1),
                        Options{.algorithm = algorithm, .threads = 4, .partitions = partitions});
        ASSERT_EQ(result.status, Status::ok);
        EXPECT_EQ(result.triangles.size(), n - 2);
        EXPECT_TRUE(validate(regular(n, 1, 1), result.triangles).valid);
      }
}

TEST(Tricky, LandmarksOnReflexVertices) {
  // Even positions are reflex (inner radius): with partitions dividing the vertex count, every
  // landmark is a reflex vertex.
  check_variants(regular(4096, 0.5, 1), true);
}

TEST(Tricky, CollinearRunsAcrossChainEnds) {
  Ring ring;  // a square with 2000 collinear vertices on every side
  for (int i = 0; i < 2000; ++i) ring.push_back({static_cast<double>(i), 0});
  for (int i = 0; i < 2000; ++i) ring.push_back({2000, static_cast<double>(i)});
  for (int i = 0; i < 2000; ++i) ring.push_back({2000.0 - i, 2000});
  for (int i = 0; i < 2000; ++i) ring.push_back({0, 2000.0 - i});
  check_variants({ring}, true);
}

// Partition-and-cut cuts the boundary into two chains a partition (the scheduler evens out
// chains of unequal cost), none under 256 nodes, and one a partition where the CDT flips the
// triangles after (its sets are runs of the chains' order): the first round's phase has that
// many tasks, and the triangles do not depend on the threads.
TEST(Tricky, TwoChainsAPartitionOneBeforeTheCdtEachOfAtLeast256Nodes) {
  const Polygon star = generate_polygon("star", 20'000, 5);
  for (const bool delaunay : {false, true})
    for (const auto& [partitions, chains] : {std::pair{2u, 4u}, {3u, 6u}, {16u, 32u}, {50u, 78u}}) {
      SCOPED_TRACE("partitions " + std::to_string(partitions) + (delaunay ? ", CDT" : ""));
      RunProfile profile;
      const Options options{.algorithm = Algorithm::partition_and_cut,
                            .delaunay = delaunay,
                            .threads = 2,
                            .partitions = partitions,
                            .profile = &profile};
      const auto triangles = check_polygon(star, true, options);
      const auto first_round = std::find_if(profile.phases.begin(), profile.phases.end(),
                                            [](const auto& p) { return p.name == "clip chains"; });
      ASSERT_NE(first_round, profile.phases.end());
      EXPECT_EQ(first_round->task_seconds.size(), delaunay ? std::min(partitions, 78u) : chains);
      Options one_thread = options;
      one_thread.threads = 1, one_thread.profile = nullptr;
      EXPECT_EQ(triangulate(star, one_thread).triangles, triangles) << "not deterministic";
    }
}

TEST(Tricky, CombsStripIsFannedInTasks) {
  // Mark-and-cut's rounds leave of a comb a strip (its teeth's feet on a line, the base across)
  // and a tooth at every landmark. The landmarks' ears are clipped after the rounds, the strip
  // is fanned in tasks: nothing is left for the sequential engine.
  const Polygon comb = generate_polygon("comb", 20'000, 11);
  for (unsigned partitions : {2u, 3u, 16u}) {
    SCOPED_TRACE("partitions " + std::to_string(partitions));
    RunProfile profile;
    const Options options{.algorithm = Algorithm::mark_and_cut,
                          .threads = 2,
                          .partitions = partitions,
                          .profile = &profile};
    const auto triangles = check_polygon(comb, true, options);
    const auto ran = [&](std::string_view phase) {
      return std::any_of(profile.phases.begin(), profile.phases.end(),
                         [&](const auto& p) { return p.name == phase; });
    };
    EXPECT_TRUE(ran("strip: fans"));
    EXPECT_FALSE(ran("clip sequentially"));
    Options one_thread = options;
    one_thread.threads = 1, one_thread.profile = nullptr;
    EXPECT_EQ(triangulate(comb, one_thread).triangles, triangles) << "not deterministic";
  }
}

TEST(Tricky, HolesTouchingAtVerticesAndBridges) {
  // A 40 x 40 checkerboard of square holes touching at their corners: pinches everywhere.
  Polygon polygon{{{0, 0}, {82, 0}, {82, 82}, {0, 82}}};
  for (int i = 0; i < 40; ++i)
    for (int j = 0; j < 40; ++j)
      if ((i + j) % 2 == 0) {
        const double x = 1 + 2.0 * i, y = 1 + 2.0 * j;
        polygon.push_back({{x, y}, {x, y + 2}, {x + 2, y + 2}, {x + 2, y}});
      }
  check_variants(polygon, true);
}

TEST(Tricky, ManyHolesBridgedInParts) {
  // Over 20,000 vertices, so the holes are bridged in parts (src/earclip/bridge.cpp): a shell
  // with a collinear run along its base and a spike; columns of holes beside the spike whose
  // bridges cross the rays of the holes above them and share the spike's bases as target;
  // holes touching the shell and each other at vertices; a staircase chain of holes.
  Ring shell;
  for (int i = 0; i < 20000; ++i) shell.push_back({i / 10.0, 0});
  for (const Point p :
       {Point{2000, 0}, {2000, 2000}, {0, 2000}, {0, 1040}, {800, 1000}, {0, 960}, {0, 600}})
    shell.push_back(p);
  Polygon polygon{shell};
  for (int k = 0; k < 40; ++k) {
    const double y = 1001 + 1.2 * k, below = 998 - 1.2 * k;
    polygon.push_back({{1000, y}, {1000, y + 0.5}, {1040, y + 0.7}, {1040, y - 0.2}});
    polygon.push_back(
        {{1000, below}, {1000, below + 0.5}, {1040, below + 0.7}, {1040, below - 0.2}});
  }
  polygon.push_back({{0, 600}, {40, 580}, {40, 620}});  // touching the shell at a vertex
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j)
      if ((i + j) % 2 == 0) {
        const double x = 100 + 20.0 * i, y = 100 + 20.0 * j;
        polygon.push_back({{x, y}, {x, y + 20}, {x + 20, y + 20}, {x + 20, y}});
      }
  for (int k = 0; k < 30; ++k)
    polygon.push_back({{1200.0 + 20 * k, 1100.0 + 19 * k},
                       {1207.0 + 20 * k, 1130.0 + 19 * k},
                       {1214.0 + 20 * k, 1100.0 + 19 * k}});
  check_variants(polygon, true);
}

TEST(Tricky, SelfIntersectingInputIsFlaggedAtEveryThreadCount) {
  Polygon polygon = regular(2000, 0.5, 1);
  std::swap(polygon[0][10], polygon[0][1500]);  // two crossing spikes
  for (Algorithm algorithm : variants)
    for (const Setting& s : settings) {
      const auto result = triangulate(
          polygon,
          Options{.algorithm = algorithm, .threads = s.threads, .partitions = s.partitions});
      EXPECT_EQ(result.status, Status::not_simple);
    }
}

TEST(Tricky, OneTriangulatorKeepsNothingBetweenRuns) {
  // Each engine keeps the variants' arrays between runs (src/parallel/variant_scratch.hpp):
  // one Triangulator runs the three variants over polygons of different sizes and partition
  // counts (more chains and parts than the run before, then fewer), and each run must give the
  // same valid triangles as another engine with another history.
  const Polygon polygons[] = {generate_polygon("random", 30000, 3),
                              generate_polygon("random-holes", 6000, 4), regular(3000, 0.5, 1),
                              generate_polygon("random", 30000, 5)};
  const unsigned partitions[] = {16, 3, 8, 5};
  Triangulator reused;
  for (std::size_t i = 0; i < std::size(polygons); ++i)
    for (Algorithm algorithm :
         {Algorithm::partition_and_cut, Algorithm::mark_and_cut, Algorithm::divide_and_conquer,
          Algorithm::partition_and_cut, Algorithm::divide_and_conquer}) {
      SCOPED_TRACE(std::string(name_of(algorithm)) + " run " + std::to_string(i));
      const Options options{.algorithm = algorithm, .threads = 2, .partitions = partitions[i]};
      const auto expected = check_polygon(polygons[i], true, options);
      EXPECT_EQ(reused.triangulate(polygons[i], options).triangles, expected);
    }
}

}  // namespace
}  // namespace pear
