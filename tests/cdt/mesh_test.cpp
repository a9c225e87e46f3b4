// The CDT's adjacency build (src/cdt/mesh.cpp) in parallel: at 1, 2, 3, 8 and 16 threads and
// partitions it must give the same twins, and twins that are right by counting: every half-edge
// of a triangulation of n ring edges is a ring edge (no twin) or one of (3t - n) / 2 pairs, each
// pair the same two vertices in opposite directions. And the CDT built on it valid and the same
// at every thread count.
#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <utility>

#include "cdt/borders.hpp"
#include "cdt/mesh.hpp"
#include "cdt/partition.hpp"
#include "clean/clean.hpp"
#include "pear/config.hpp"
#include "pear/generate.hpp"
#include "run_contexts.hpp"
#include "support.hpp"

namespace pear::detail {
namespace {

struct Triangulated {
  Polygon polygon;
  std::vector<Point> points;  ///< the caller's points, ring after ring
  CleanPolygon clean;
  TriangleList triangles;
};

Triangulated triangulated(Polygon polygon) {
  Triangulated t{std::move(polygon), {}, {}, {}};
  for (const Ring& ring : t.polygon) t.points.insert(t.points.end(), ring.begin(), ring.end());
  std::vector<std::uint32_t> offsets{0};
  for (const Ring& ring : t.polygon) offsets.push_back(offsets.back() + ring.size());
  std::vector<Diagnostic> diagnostics;
  EXPECT_EQ(clean_polygon(InputPolygon(PolygonView{t.points, offsets}), t.clean, diagnostics),
            Status::ok);
  const auto result = triangulate(t.polygon, Options{.algorithm = Algorithm::sequential});
  EXPECT_EQ(result.status, Status::ok);
  t.triangles = result.triangles;
  return t;
}

/// Twins by counting and by direction, independent of how they were matched.
void expect_twins_right(const Mesh& mesh, std::size_t ring_edges) {
  std::size_t unpaired = 0;
  for (std::uint32_t h = 0; h < mesh.twin.size(); ++h) {
    const std::uint32_t g = mesh.twin[h];
    if (g == no_twin) {
      ++unpaired;
      continue;
    }
    ASSERT_EQ(mesh.twin[g], h);
    ASSERT_EQ(mesh.origin(h), mesh.destination(g));
    ASSERT_EQ(mesh.destination(h), mesh.origin(g));
  }
  EXPECT_EQ(unpaired, ring_edges);
  EXPECT_EQ(2 * mesh.interior_edges, mesh.twin.size() - ring_edges);
}

class MeshBuild : public ::testing::TestWithParam<const char*> {};

TEST_P(MeshBuild, SameTwinsAtEveryThreadAndPartitionCount) {
  // 30,000 vertices: about 120,000 edges, enough for 16 tasks of mesh_edges_per_task.
  Triangulated t = triangulated(generate_polygon(GetParam(), 30'000, 11));
  const std::size_t edges = 3 * t.triangles.size() + t.clean.points.size();
  ASSERT_GE(edges, 16 * mesh_edges_per_task);
  Mesh reference;
  ASSERT_TRUE(build_mesh(t.points, t.clean, t.triangles, reference, RunContext{}));
  expect_twins_right(reference, t.clean.points.size());
  for_each_context({1u, 2u, 3u, 8u, 16u}, {1u, 2u, 3u, 8u, 16u, 4096u},
                   [&](const RunContext& ctx, const RunProfile& profile) {
                     Mesh mesh;
                     ASSERT_TRUE(build_mesh(t.points, t.clean, t.triangles, mesh, ctx));
                     EXPECT_EQ(mesh.twin, reference.twin);
                     EXPECT_EQ(mesh.interior_edges, reference.interior_edges);
                     // The matching phase really is cut into the partitions' tasks (4,096
                     // partitions: as many as the edges fill, mesh_edges_per_task each).
                     const auto match = std::find_if(
                         profile.phases.begin(), profile.phases.end(),
                         [](const auto& p) { return p.name == "cdt adjacency: match"; });
                     ASSERT_NE(match, profile.phases.end());
                     EXPECT_EQ(match->task_seconds.size(), mesh_parts(edges, ctx.partitions));
                   });
}

// A mesh keeps its build's arrays: built again for a larger and a smaller triangulation, at
// other partition counts, it holds each one's own twins (a stale entry would pair edges of the
// last triangulation).
TEST(MeshBuild, BuiltAgainInItsOwnArraysEachTriangulationGetsItsTwins) {
  Triangulated large = triangulated(generate_polygon("random-holes", 30'000, 3));
  Triangulated small = triangulated(generate_polygon("star", 2'000, 4));
  Mesh kept;
  for_each_context({2u}, {1u, 16u}, [&](const RunContext& ctx, const RunProfile&) {
    for (Triangulated* t : {&large, &small, &large}) {
      Mesh fresh;
      ASSERT_TRUE(build_mesh(t->points, t->clean, t->triangles, fresh, ctx));
      ASSERT_TRUE(build_mesh(t->points, t->clean, t->triangles, kept, ctx));
      EXPECT_EQ(kept.twin, fresh.twin);
      EXPECT_EQ(kept.interior_edges, fresh.interior_edges);
      expect_twins_right(kept, t->clean.points.size());
    }
  });
}

INSTANTIATE_TEST_SUITE_P(Families, MeshBuild,
                         ::testing::Values("random", "random-holes", "star", "spiral", "comb"));

// A convex polygon triangulated as one fan from vertex 0: its thousands of edges at one low
// vertex take the radix sort (one pass of 11 bits at 2,000 vertices, two at 5,000).
TEST(MeshBuild, FanFromOneVertexPairsEveryDiagonal) {
  for (std::uint32_t n : {2'000u, 5'000u}) {
    SCOPED_TRACE(n);
    Ring ring{{0, 1e9}};  // the apex, then n points on a parabola: convex, counterclockwise
    for (std::uint32_t i = 0; i < n; ++i) {
      const double x = static_cast<double>(i);
      ring.push_back({x, x * x});
    }
    Triangulated t{{ring}, ring, {}, {}};
    const std::vector<std::uint32_t> offsets{0, n + 1};
    std::vector<Diagnostic> diagnostics;
    ASSERT_EQ(clean_polygon(InputPolygon(PolygonView{t.points, offsets}), t.clean, diagnostics),
              Status::ok);
    // In a scrambled order, so that no edge's two uses come together unsorted.
    for (std::uint32_t k = 0; k + 1 < n; ++k) {
      const std::uint32_t i = 1 + (k * 7919) % (n - 1);
      t.triangles.push_back({0, i, i + 1});
    }
    for (const RunContext& ctx : {RunContext{}, RunContext{nullptr, 16, nullptr}}) {
      Mesh mesh;
      ASSERT_TRUE(build_mesh(t.points, t.clean, t.triangles, mesh, ctx));
      expect_twins_right(mesh, n + 1);
      EXPECT_EQ(mesh.interior_edges, n - 2);
    }
  }
}

TEST(SortByHigh, OrdersByTheHighWordAndKeepsEveryValue) {
  std::uint64_t state = 88172645463325252u;
  const auto next = [&] { return state ^= state << 13, state ^= state >> 7, state ^= state << 17; };
  std::vector<std::uint64_t> scratch;
  for (unsigned bits : {1u, 11u, 12u, 22u, 23u, 32u}) {
    SCOPED_TRACE(bits);
    std::vector<std::uint64_t> values(3000);
    for (std::uint64_t& v : values) v = (next() >> (64 - bits)) << 32 | (next() >> 40);
    std::vector<std::uint64_t> sorted = values;
    sort_by_high(sorted.data(), sorted.data() + sorted.size(), scratch);
    EXPECT_TRUE(std::is_sorted(sorted.begin(), sorted.end(),
                               [](std::uint64_t a, std::uint64_t b) { return a >> 32 < b >> 32; }));
    std::sort(values.begin(), values.end());
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, values);
  }
}

TEST(MeshParts, APowerOfTwoAtLeastThePartitionsWhereEdgesFillThem) {
  EXPECT_EQ(mesh_parts(100 * mesh_edges_per_task, 1), 1u);
  EXPECT_EQ(mesh_parts(100 * mesh_edges_per_task, 3), 4u);
  EXPECT_EQ(mesh_parts(100 * mesh_edges_per_task, 16), 16u);
  EXPECT_EQ(mesh_parts(100 * mesh_edges_per_task, 4096), 64u);  // bit_floor(100)
  EXPECT_EQ(mesh_parts(1000 * mesh_edges_per_task, 4096), max_mesh_parts);
  EXPECT_EQ(mesh_parts(mesh_edges_per_task - 1, 16), 1u);
}

// Every vertex gets its own slot in its bucket, and the spiral's edges, whose low vertices all
// lie in the first half of the numbering, fill the buckets evenly (a bucket per range of
// vertices gave the first one all of them at 2 parts).
TEST(VertexBuckets, EveryVertexItsOwnSlotAndTheSpiralsEdgesSpreadEvenly) {
  const Triangulated t = triangulated(generate_polygon("spiral", 30'000, 5));
  const std::size_t n = t.points.size();
  for (std::size_t parts : {2u, 4u, 16u, 256u}) {
    SCOPED_TRACE(parts);
    const VertexBuckets buckets(n, parts);
    std::vector<std::vector<std::uint8_t>> taken(parts, std::vector<std::uint8_t>(buckets.width()));
    for (std::uint32_t v = 0; v < n; ++v) {
      ASSERT_LT(buckets.bucket(v), parts);
      ASSERT_LT(buckets.slot(v), buckets.width());
      ASSERT_EQ(std::exchange(taken[buckets.bucket(v)][buckets.slot(v)], 1), 0) << v;
    }
    std::vector<std::size_t> edges(parts, 0);
    for (const auto& tri : t.triangles)
      for (std::size_t k = 0; k < 3; ++k)
        ++edges[buckets.bucket(std::min(tri[k], tri[(k + 1) % 3]))];
    const std::size_t total = 3 * t.triangles.size();
    if (parts <= 16) {
      EXPECT_LE(*std::max_element(edges.begin(), edges.end()) * parts, total * 3 / 2);
    }
  }
}

// Through the public API: the CDT of a polygon whose mesh is built in 16 buckets is valid
// (the validator's exact Delaunay check) and the same at 1, 2, 3, 8 and 16 threads.
TEST(MeshBuildCdt, ValidAndTheSameAtEveryThreadCount) {
  const Polygon polygon = generate_polygon("random-holes", 30'000, 3);
  const auto one = testing::constrained_delaunay(polygon, Algorithm::sequential, 1, 16);
  ASSERT_EQ(one.status, Status::ok);
  testing::expect_delaunay(polygon, one.triangles);
  for (unsigned threads : {2u, 3u, 8u, 16u}) {
    const auto many = testing::constrained_delaunay(polygon, Algorithm::sequential, threads, 16);
    EXPECT_EQ(many.triangles, one.triangles) << threads << " threads";
  }
}

// The parallel flips' border relinking, with more border half-edges than one task pairs: with
// every border twin wiped, it must restore exactly the twins the build made (no flips ran, so
// they are still right), at every thread count, and list one half-edge of each pair in the
// order of their ends, as one sort of them all gives it.
TEST(RelinkBorders, PairsEveryBorderInRangesInTheOrderOfTheirEnds) {
  Triangulated t = triangulated(generate_polygon("random-holes", 60'000, 7));
  Mesh reference;
  ASSERT_TRUE(build_mesh(t.points, t.clean, t.triangles, reference, RunContext{}));
  TrianglePartition partition;
  partition_triangles(reference, 64, partition);
  std::vector<std::vector<std::uint32_t>> borders(partition.sets());
  std::vector<std::uint32_t> all;
  for (std::uint32_t s = 0; s < partition.sets(); ++s) {
    collect_borders(reference, partition, s, borders[s]);
    all.insert(all.end(), borders[s].begin(), borders[s].end());
  }
  ASSERT_GE(all.size(), 3u * 4096) << "too few borders for several ranges";
  const auto ends = [&](std::uint32_t h) {
    return EdgeEnds(reference.points[reference.origin(h)],
                    reference.points[reference.destination(h)]);
  };
  std::sort(all.begin(), all.end(), [&](std::uint32_t h, std::uint32_t g) {
    return ends(h) != ends(g) ? ends(h) < ends(g) : h < g;
  });
  std::vector<std::uint32_t> expected;
  for (std::size_t i = 0; i < all.size(); i += 2) expected.push_back(all[i]);
  for (unsigned threads : {1u, 4u}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    Workers workers;
    RunProfile profile;
    const RunContext ctx{.runner = workers.runner(Options{.threads = threads}),
                         .partitions = 64,
                         .profile = &profile};
    Mesh mesh = reference;
    for (std::uint32_t h : all) mesh.twin[h] = no_twin;
    EXPECT_EQ(relink_borders(mesh, borders, ctx), expected);
    EXPECT_EQ(mesh.twin, reference.twin);
    EXPECT_GE(testing::tasks_of(profile, "cdt relink borders: pair"), PEAR_HAS_THREADS ? 3u : 1u)
        << "one range without threads";
  }
}

// Runs of the clip order are sets when at most 1/32 of the triangles came out otherwise (1/8
// where the rest lies on the seams), at any number of sets.
TEST(PartitionInRuns, OnlyWhenNearlyAllAreOrdered) {
  for (const std::uint32_t sets : {2u, 3u, 16u}) {
    EXPECT_TRUE(runs_make_sets({1024, false}, 1024, sets));
    EXPECT_TRUE(runs_make_sets({992, false}, 1024, sets));   // 32 left: 1/32
    EXPECT_FALSE(runs_make_sets({991, false}, 1024, sets));  // 33 left
    EXPECT_TRUE(runs_make_sets({896, true}, 1024, sets));    // 128 left on the seams: 1/8
    EXPECT_FALSE(runs_make_sets({895, true}, 1024, sets));
    EXPECT_FALSE(runs_make_sets({800, false}, 1024, sets));  // a spiral's chains at 2 partitions
  }
  EXPECT_FALSE(runs_make_sets({1024, false}, 1024, 1));
  EXPECT_FALSE(runs_make_sets({1025, false}, 1024, 4));
}

/// Every triangle in exactly one set, the sets' pieces of `order` in triangle order, each
/// set's share of the first `ordered` triangles one run of equal size give or take one.
void expect_runs_then_rest(const TrianglePartition& partition, std::size_t count,
                           std::size_t ordered, std::uint32_t sets) {
  ASSERT_EQ(partition.sets(), sets);
  ASSERT_EQ(partition.part.size(), count);
  ASSERT_EQ(partition.order.size(), count);
  EXPECT_EQ(partition.begin.front(), 0u);
  EXPECT_EQ(partition.begin.back(), count);
  std::vector<int> seen(count, 0);
  for (std::uint32_t s = 0; s < sets; ++s) {
    const std::size_t first = partition.begin[s], last = partition.begin[s + 1];
    const std::size_t run = ordered * (s + 1) / sets - ordered * s / sets;
    ASSERT_GE(last - first, run);
    EXPECT_TRUE(std::is_sorted(partition.order.begin() + first, partition.order.begin() + last));
    for (std::size_t i = first; i < last; ++i) {
      const std::uint32_t t = partition.order[i];
      ASSERT_LT(t, count);
      ++seen[t];
      EXPECT_EQ(partition.part[t], s);
      if (i < first + run) {
        EXPECT_EQ(t, ordered * s / sets + (i - first));
      } else {
        EXPECT_GE(t, ordered);
      }
    }
  }
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), static_cast<std::ptrdiff_t>(count));
}

// Without the rest on the seams, set s is the run [count * s / sets, count * (s + 1) / sets)
// of all the triangles (the rest in the last set), as partition-and-cut's finish wants.
TEST(PartitionInRuns, EqualRunsInOrderOfAllTheTriangles) {
  Triangulated t = triangulated(generate_polygon("random-holes", 20'000, 5));
  Mesh mesh;
  ASSERT_TRUE(build_mesh(t.points, t.clean, t.triangles, mesh, RunContext{}));
  const std::size_t count = t.triangles.size();
  for (const std::uint32_t sets : {2u, 7u, 16u}) {
    for (const unsigned threads : {1u, 4u}) {
      SCOPED_TRACE(std::to_string(sets) + " sets, " + std::to_string(threads) + " threads");
      Workers workers;
      const RunContext ctx{.runner = workers.runner(Options{.threads = threads}),
                           .partitions = sets};
      TrianglePartition partition;
      partition_in_runs(mesh, {count - count / 40, false}, sets, ctx, partition);
      expect_runs_then_rest(partition, count, count, sets);
    }
  }
}

// With the rest on the seams (divide-and-conquer's repair patches), each triangle of the rest
// joins a set beside it: where it has a neighbour among the ordered triangles, the first one's. In
// ranges of their own: the same sets at every thread count, the rest in one range or several.
TEST(PartitionInRuns, TheRestJoinsASetBesideIt) {
  Triangulated t = triangulated(generate_polygon("random-holes", 20'000, 5));
  Mesh mesh;
  ASSERT_TRUE(build_mesh(t.points, t.clean, t.triangles, mesh, RunContext{}));
  const std::size_t count = t.triangles.size();
  for (const std::size_t ordered : {count, count - 1'000, count - count / 8}) {
    for (const std::uint32_t sets : {2u, 7u, 16u}) {
      SCOPED_TRACE(std::to_string(count - ordered) + " left, " + std::to_string(sets) + " sets");
      TrianglePartition one;
      for (const unsigned threads : {1u, 4u}) {
        Workers workers;
        const RunContext ctx{.runner = workers.runner(Options{.threads = threads}),
                             .partitions = sets};
        TrianglePartition partition;
        partition_in_runs(mesh, {ordered, true}, sets, ctx, partition);
        expect_runs_then_rest(partition, count, ordered, sets);
        if (threads == 1) {
          one = partition;
          continue;
        }
        EXPECT_EQ(partition.part, one.part);
        EXPECT_EQ(partition.order, one.order);
      }
      std::size_t beside = 0;
      for (std::size_t tri = ordered; tri < count; ++tri) {
        for (std::size_t h = 3 * tri; h < 3 * tri + 3; ++h) {
          const std::uint32_t g = mesh.twin[h];
          if (g == no_twin || g / 3 >= ordered) continue;
          EXPECT_EQ(one.part[tri], one.part[g / 3]) << "triangle " << tri;
          ++beside;
          break;
        }
      }
      if (ordered < count) {
        EXPECT_GT(beside, 0u);
      }
    }
  }
}

TEST(MeshBuildErrors, AnEdgeWithThreeTrianglesIsNoTriangulation) {
  Triangulated t = triangulated({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}});
  t.triangles.push_back(t.triangles.front());  // the same triangle twice: its edges thrice
  Mesh mesh;
  EXPECT_FALSE(build_mesh(t.points, t.clean, t.triangles, mesh, RunContext{}));
}

TEST(MeshBuildErrors, ACornerPastThePointsIsNoTriangulation) {
  Triangulated t = triangulated({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}});
  t.triangles.front()[1] = 4;
  Mesh mesh;
  EXPECT_FALSE(build_mesh(t.points, t.clean, t.triangles, mesh, RunContext{}));
}

}  // namespace
}  // namespace pear::detail
