// The engine pool (src/pipeline/engine_pool.cpp): up to 64 small engines and the last large one
// (sized for more than 65,536 vertices), which only a large polygon takes; release frees them.
#include <gtest/gtest.h>

#include "pear/detail/flat_polygon.hpp"
#include "pear/generate.hpp"
#include "pear/pear.hpp"
#include "pipeline/engine_pool.hpp"

namespace pear::detail {
namespace {

constexpr std::size_t large_vertices = 70000;  ///< past the pool's 65,536

/// An engine that has triangulated a random polygon of `vertices`: its footprint is that size.
std::unique_ptr<Engine> engine_sized_for(std::size_t vertices) {
  FlatPolygon flat;
  flatten(generate_polygon("random", vertices, 7), flat);
  std::unique_ptr<Engine> engine = std::make_unique<Engine>();
  TriangleList triangles;
  std::vector<Diagnostic> diagnostics;
  DelaunayStatistics delaunay;
  EXPECT_EQ(engine->run(PolygonView{flat.points, flat.ring_starts}, Options{.threads = 2},
                        triangles, diagnostics, delaunay),
            Status::ok);
  EXPECT_EQ(triangles.size(), vertices - 2);
  return engine;
}

TEST(EnginePool, KeepsTheLastLargeEngineForLargePolygonsOnly) {
  release_pooled_engines();
  release_engine(engine_sized_for(large_vertices));
  release_engine(engine_sized_for(large_vertices + 20000));  // replaces the first
  release_engine(engine_sized_for(1000));
  // A small polygon gets the small engine, never the large one.
  std::unique_ptr<Engine> small = acquire_engine(1000);
  EXPECT_LT(small->footprint(), large_vertices);
  std::unique_ptr<Engine> fresh = acquire_engine(10);  // the pool has no other small one
  EXPECT_EQ(fresh->footprint(), 0u);
  std::unique_ptr<Engine> large = acquire_engine(large_vertices);
  EXPECT_GE(large->footprint(), large_vertices + 20000);
  EXPECT_EQ(acquire_engine(large_vertices)->footprint(), 0u);  // only one was kept
  release_engine(std::move(large));
  release_engine(std::move(small));
  release_engine(std::move(fresh));
}

/// A polygon below 65,536 vertices whose run still leaves a large engine (each vertex also
/// has room for the bridges' nodes) takes the kept one: it built a new engine at every call.
TEST(EnginePool, APolygonThatLeavesALargeEngineTakesTheKeptOne) {
  release_pooled_engines();
  constexpr std::size_t vertices = 30000;
  std::unique_ptr<Engine> used = engine_sized_for(vertices);
  ASSERT_GT(used->footprint(), std::size_t{1} << 16);
  const Engine* kept = used.get();
  release_engine(std::move(used));
  std::unique_ptr<Engine> again = acquire_engine(vertices);
  EXPECT_EQ(again.get(), kept);
  release_engine(std::move(again));
  EXPECT_NE(acquire_engine(1000).get(), kept);  // a small polygon never takes it
}

TEST(EnginePool, ReleaseFreesEveryKeptEngine) {
  release_engine(engine_sized_for(large_vertices));
  release_engine(engine_sized_for(1000));
  pear::release_cached_engines();
  EXPECT_EQ(acquire_engine(large_vertices)->footprint(), 0u);
  EXPECT_EQ(acquire_engine(1000)->footprint(), 0u);
}

TEST(EnginePool, LargeCallsThroughTheFreeFunctionGiveTheSameTriangles) {
  const Polygon polygon = generate_polygon("random-holes", large_vertices, 3);
  const Options options{.threads = 2};
  const auto first = pear::triangulate(polygon, options);  // leaves its engine in the pool
  ASSERT_EQ(first.status, Status::ok);
  EXPECT_EQ(pear::triangulate(polygon, options).triangles, first.triangles);  // reuses it
  pear::release_cached_engines();
  EXPECT_EQ(pear::triangulate(polygon, options).triangles, first.triangles);
}

}  // namespace
}  // namespace pear::detail
