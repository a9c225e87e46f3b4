// pear::triangulate_batch: the same result as one pear::triangulate call per polygon (same
// triangles, statuses and diagnostics), at 1, 2 and 8 threads; every status, empty polygons,
// bad offsets and a polygon that fails amid good ones; index overflow with a narrow index type;
// the GeoArrow slice layout (offsets that do not start at 0) and the range-of-polygons form.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "pear/config.hpp"
#include "pear/generate.hpp"
#include "pear/pear.hpp"
#if PEAR_HAS_THREADS
#include "pear/scheduler.hpp"
#endif
#include "pear/validate.hpp"

namespace pear {
namespace {

/// A batch's flat arrays, built polygon by polygon.
struct Flat {
  std::vector<double> coordinates;
  std::vector<std::int64_t> ring_offsets{0}, polygon_offsets{0};
  void add(const Polygon& polygon) {
    for (const Ring& ring : polygon) {
      for (const Point& p : ring) coordinates.insert(coordinates.end(), {p.x, p.y});
      ring_offsets.push_back(static_cast<std::int64_t>(coordinates.size() / 2));
    }
    polygon_offsets.push_back(static_cast<std::int64_t>(ring_offsets.size() - 1));
  }
  PolygonBatch view() const { return {coordinates, ring_offsets, polygon_offsets}; }
};

/// Small, large, with holes, touching, not simple, degenerate: what a dataset mixes.
std::vector<Polygon> mixed_polygons() {
  std::vector<Polygon> polygons;
  for (std::string_view kind : {"star", "random", "koch", "comb", "holes", "random-holes"})
    for (std::size_t n : {16u, 60u, 500u}) try {
        polygons.push_back(generate_polygon(kind, n, n));
      } catch (const std::invalid_argument&) {
      }
  polygons.push_back(generate_polygon("star", 30000, 5));  // takes the parallel path
  polygons.push_back({{{0, 0}, {2, 2}, {2, 0}, {0, 2}}});  // a bowtie: not simple
  polygons.push_back({{{0, 0}, {1, 1}, {2, 2}}});          // zero area: invalid
  polygons.push_back({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 1}, {1, 2}}});  // a hole dropped
  polygons.push_back({{{0, 0}, {NAN, 0}, {4, 4}}});                          // NaN
  polygons.push_back({});                                                    // no rings
  polygons.push_back({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{0, 0}, {2, 1}, {1, 2}}});  // touching
  return polygons;
}

/// Checks that polygon p of the batch is what pear::triangulate gives for it alone.
void expect_same_as_single(const BatchTriangulation<>& batch, std::size_t p, const Polygon& polygon,
                           std::uint32_t first_point, const Options& options) {
  SCOPED_TRACE("polygon " + std::to_string(p));
  const Triangulation<> single = triangulate(polygon, options);
  ASSERT_EQ(batch.status[p], single.status);
  const auto t0 = batch.triangle_offsets[p], t1 = batch.triangle_offsets[p + 1];
  ASSERT_EQ(static_cast<std::size_t>(t1 - t0), single.triangles.size());
  for (auto t = t0; t < t1; ++t)
    for (int k = 0; k < 3; ++k)
      ASSERT_EQ(batch.triangles[t][k], single.triangles[t - t0][k] + first_point);
  const auto d0 = batch.diagnostic_offsets[p], d1 = batch.diagnostic_offsets[p + 1];
  ASSERT_EQ(static_cast<std::size_t>(d1 - d0), single.diagnostics.size());
  for (auto d = d0; d < d1; ++d) {
    EXPECT_EQ(batch.diagnostics[d].issue, single.diagnostics[d - d0].issue);
    EXPECT_EQ(batch.diagnostics[d].ring, single.diagnostics[d - d0].ring);
    EXPECT_EQ(batch.diagnostics[d].vertex, single.diagnostics[d - d0].vertex);
  }
}

TEST(Batch, SameAsOneCallPerPolygonAtEveryThreadCount) {
  const std::vector<Polygon> polygons = mixed_polygons();
  Flat flat;
  for (const Polygon& polygon : polygons) flat.add(polygon);
  for (EarHeuristic heuristic : {EarHeuristic::top, EarHeuristic::fast}) {
    for (unsigned threads : {1u, 2u, 8u}) {
      SCOPED_TRACE("threads " + std::to_string(threads));
      Options options;
      options.heuristic = heuristic;
      options.threads = threads;
      options.partitions = 4;  // fixed: the large polygon's output must not follow the threads
      const BatchTriangulation<> batch = triangulate_batch(flat.view(), options);
      ASSERT_EQ(batch.size(), polygons.size());
      ASSERT_EQ(batch.triangle_offsets.size(), polygons.size() + 1);
      ASSERT_EQ(batch.triangle_offsets.back(), static_cast<std::int64_t>(batch.triangles.size()));
      for (std::size_t p = 0; p < polygons.size(); ++p) {
        const auto first = static_cast<std::uint32_t>(flat.ring_offsets[flat.polygon_offsets[p]]);
        expect_same_as_single(batch, p, polygons[p], first, options);
      }
    }
  }
}

TEST(Batch, EveryStatusAndAFailureAmidGoodPolygons) {
  const std::vector<Polygon> polygons = mixed_polygons();
  const BatchTriangulation<> batch = triangulate_batch(polygons);
  std::size_t ok = 0;
  bool seen_not_simple = false, seen_invalid = false;
  for (std::size_t p = 0; p < batch.size(); ++p) {
    ok += batch.status[p] == Status::ok;
    seen_not_simple |= batch.status[p] == Status::not_simple;
    seen_invalid |= batch.status[p] == Status::invalid_input;
  }
  EXPECT_TRUE(seen_not_simple);
  EXPECT_TRUE(seen_invalid);
  // Every ok polygon's triangles are a valid triangulation of it (after the failures before).
  Flat flat;
  for (const Polygon& polygon : polygons) flat.add(polygon);
  for (std::size_t p = 0; p < batch.size(); ++p) {
    if (batch.status[p] != Status::ok) continue;
    const auto base = static_cast<std::uint32_t>(flat.ring_offsets[flat.polygon_offsets[p]]);
    std::vector<std::array<std::uint32_t, 3>> local;
    for (auto t = batch.triangle_offsets[p]; t < batch.triangle_offsets[p + 1]; ++t)
      local.push_back({batch.triangles[t][0] - base, batch.triangles[t][1] - base,
                       batch.triangles[t][2] - base});
    EXPECT_TRUE(validate(polygons[p], local).valid) << "polygon " << p;
  }
  EXPECT_GE(ok, polygons.size() - 5);
  // The polygon with no rings says so.
  const std::size_t empty = polygons.size() - 2;
  ASSERT_EQ(batch.status[empty], Status::invalid_input);
  EXPECT_EQ(batch.diagnostics[batch.diagnostic_offsets[empty]].issue, Issue::empty_input);
}

TEST(Batch, EmptyBatches) {
  const BatchTriangulation<> none = triangulate_batch(PolygonBatch{});
  EXPECT_EQ(none.size(), 0u);
  EXPECT_EQ(none.triangle_offsets, std::vector<std::int64_t>{0});
  const std::vector<std::int64_t> one_polygon{0, 0};
  const BatchTriangulation<> empty = triangulate_batch(PolygonBatch{{}, {}, one_polygon});
  ASSERT_EQ(empty.size(), 1u);
  EXPECT_EQ(empty.status[0], Status::invalid_input);
}

TEST(Batch, BadOffsetsFailOnlyTheirPolygon) {
  Flat flat;
  for (int i = 0; i < 4; ++i) flat.add({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}});
  flat.ring_offsets[2] = 100;  // ring 1 (polygon 1) ends past the points, ring 2 starts there
  flat.polygon_offsets.push_back(2);  // polygon 4: rings [4, 2), backwards
  const BatchTriangulation<> batch = triangulate_batch(flat.view());
  ASSERT_EQ(batch.size(), 5u);
  EXPECT_EQ(batch.status[0], Status::ok);
  EXPECT_EQ(batch.status[1], Status::invalid_input);
  EXPECT_EQ(batch.status[2], Status::invalid_input);
  EXPECT_EQ(batch.status[3], Status::ok);
  EXPECT_EQ(batch.status[4], Status::invalid_input);
  for (std::size_t p : {1u, 2u, 4u})
    EXPECT_EQ(batch.diagnostics[batch.diagnostic_offsets[p]].issue, Issue::invalid_offsets);
  EXPECT_EQ(batch.triangle_offsets[2] - batch.triangle_offsets[1], 0);
}

// Issue 30, item 2: the chunking summed and subtracted offsets before they were checked, a
// signed overflow (undefined behaviour, UBSan halts) for offsets at the ends of int64.
TEST(Batch, OffsetsAtTheEndsOfInt64AreInvalidNotOverflow) {
  constexpr std::int64_t min = std::numeric_limits<std::int64_t>::min();
  constexpr std::int64_t max = std::numeric_limits<std::int64_t>::max();
  const std::vector<double> square{0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 1, 2, 3};
  const std::vector<std::int64_t> polygon_offsets{0, 1, 2};
  // Each: the bad ring's polygon is invalid, the other one a triangulated ring if its own
  // offsets are good.
  const std::vector<std::vector<std::int64_t>> bad_rings = {
      {min, 4, 7}, {0, 4, max}, {0, max, 7}, {max, min, max}, {min, max, min}, {0, 4, min}};
  for (const std::vector<std::int64_t>& ring_offsets : bad_rings) {
    SCOPED_TRACE(::testing::PrintToString(ring_offsets));
    for (unsigned threads : {1u, 2u}) {
      Options options;
      options.threads = threads;
      const BatchTriangulation<> batch =
          triangulate_batch(PolygonBatch{square, ring_offsets, polygon_offsets}, options);
      ASSERT_EQ(batch.size(), 2u);
      for (std::size_t p = 0; p < 2; ++p) {
        const bool good = ring_offsets[p] >= 0 && ring_offsets[p] < ring_offsets[p + 1] &&
                          ring_offsets[p + 1] <= 7;
        EXPECT_EQ(batch.status[p], good ? Status::ok : Status::invalid_input) << "polygon " << p;
        if (!good) {
          EXPECT_EQ(batch.diagnostics[batch.diagnostic_offsets[p]].issue, Issue::invalid_offsets);
        }
      }
      EXPECT_EQ(batch.triangle_offsets.back(), static_cast<std::int64_t>(batch.triangles.size()));
    }
  }
  // Polygon offsets at the ends of int64 too.
  const std::vector<std::int64_t> rings{0, 4, 7};
  for (const std::vector<std::int64_t>& polygons :
       std::vector<std::vector<std::int64_t>>{{min, 1, max}, {0, max, 1}, {max, min}}) {
    const BatchTriangulation<> batch = triangulate_batch(PolygonBatch{square, rings, polygons});
    ASSERT_EQ(batch.size(), polygons.size() - 1);
    for (std::size_t p = 0; p < batch.size(); ++p)
      EXPECT_EQ(batch.status[p], Status::invalid_input) << "polygon " << p;
  }
}

TEST(Batch, SlicesWhoseOffsetsDoNotStartAtZero) {
  Flat flat;
  const std::vector<Polygon> polygons = mixed_polygons();
  for (const Polygon& polygon : polygons) flat.add(polygon);
  // Polygons 3.. of the same arrays, as a GeoArrow slice hands them over.
  const PolygonBatch slice{flat.coordinates, flat.ring_offsets,
                           std::span(flat.polygon_offsets).subspan(3)};
  const BatchTriangulation<> batch = triangulate_batch(slice);
  ASSERT_EQ(batch.size(), polygons.size() - 3);
  for (std::size_t p = 0; p < batch.size(); ++p) {
    const auto first = static_cast<std::uint32_t>(flat.ring_offsets[flat.polygon_offsets[p + 3]]);
    expect_same_as_single(batch, p, polygons[p + 3], first, {});
  }
}

// The batch saves room for each polygon's triangles from its points and rings, within a budget
// of the batch's points and rings; polygons that share one ring (polygon offsets may repeat
// it) outgrow that budget and spill past it, in order, on one thread and on several.
TEST(Batch, PolygonsSharingOneRingSpillPastTheRoomInOrder) {
  const Polygon comb = generate_polygon("comb", 60, 60);
  Flat flat;
  flat.add(comb);
  std::vector<std::int64_t> polygon_offsets{0};
  for (int copy = 0; copy < 200; ++copy) polygon_offsets.insert(polygon_offsets.end(), {1, 0});
  polygon_offsets.back() = 1;  // polygons 0, 2, 4, ...: the comb; 1, 3, ...: rings [1, 0)
  const PolygonBatch batch{flat.coordinates, flat.ring_offsets, polygon_offsets};
  for (unsigned threads : {1u, 2u}) {
    Options options;
    options.threads = threads;
    const BatchTriangulation<> result = triangulate_batch(batch, options);
    ASSERT_EQ(result.size(), polygon_offsets.size() - 1);
    ASSERT_EQ(result.triangle_offsets.back(), static_cast<std::int64_t>(result.triangles.size()));
    EXPECT_GT(result.triangles.size(), 10 * comb[0].size());  // far past points + 2 * rings
    for (std::size_t p = 0; p < result.size(); p += 2)
      expect_same_as_single(result, p, comb, 0, options);
    EXPECT_EQ(result.status[1], Status::invalid_input);
  }
}

TEST(Batch, NarrowIndicesOverflowPerPolygon) {
  // Two polygons of 40,000 points: the second one's indices do not fit 16 bits.
  const std::vector<Polygon> polygons = {generate_polygon("star", 40000, 1),
                                         generate_polygon("star", 40000, 2)};
  Options options;
  options.threads = 2;
  const BatchTriangulation<std::uint16_t> batch =
      triangulate_batch<std::uint16_t>(polygons, options);
  ASSERT_EQ(batch.size(), 2u);
  EXPECT_EQ(batch.status[0], Status::ok);
  EXPECT_EQ(batch.status[1], Status::index_overflow);
  EXPECT_EQ(batch.triangle_offsets[2], batch.triangle_offsets[1]);
  EXPECT_TRUE(
      validate(polygons[0], std::vector(batch.triangles.begin(),
                                        batch.triangles.begin() + batch.triangle_offsets[1]))
          .valid);
}

TEST(Batch, TooManyThreadsIsAStatusNotAnException) {
  Options options;
  options.threads = max_threads + 1;
  const BatchTriangulation<> batch = triangulate_batch(mixed_polygons(), options);
  for (std::size_t p = 0; p < batch.size(); ++p) {
    EXPECT_EQ(batch.status[p], Status::invalid_input);
    EXPECT_EQ(batch.diagnostics[batch.diagnostic_offsets[p]].issue, Issue::invalid_options);
  }
  // And the same for one polygon.
  const Triangulation<> one = triangulate(mixed_polygons().front(), options);
  EXPECT_EQ(one.status, Status::invalid_input);
}

TEST(Batch, ProfileTimesEveryPolygon) {
  RunProfile profile;
  Options options;
  options.profile = &profile;
  const std::vector<Polygon> polygons = mixed_polygons();
  triangulate_batch(polygons, options);
  ASSERT_EQ(profile.phases.size(), 1u);
  ASSERT_EQ(profile.phases[0].task_seconds.size(), polygons.size());
  EXPECT_GT(profile.work(), 0);
}

#if PEAR_HAS_THREADS
TEST(Batch, OnTheCallersExecutor) {
  Executor executor(3);
  Options options;
  options.executor = &executor;
  const std::vector<Polygon> polygons = mixed_polygons();
  const BatchTriangulation<> a = triangulate_batch(polygons, options);
  options.executor = nullptr;
  options.threads = 1;
  const BatchTriangulation<> b = triangulate_batch(polygons, options);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.triangle_offsets, b.triangle_offsets);
}
#endif

}  // namespace
}  // namespace pear
