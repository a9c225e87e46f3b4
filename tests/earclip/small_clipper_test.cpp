// The small-polygon path (src/earclip/small_clipper.cpp, chosen by the pipeline for one ring of
// at most 384 vertices): on simple rings of every synthetic family, with collinear runs added,
// and on rectilinear staircases, it must give n - 2 triangles that the validator accepts, for
// `top` and `fast`; through the public API its results must be as valid as the general
// engine's on the same polygons; on rings that are not simple it must end and either say so
// or leave a result (the check, which the pipeline runs first, is what promises validity).
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "earclip/small_clipper.hpp"
#include "pear/generate.hpp"
#include "pear/pear.hpp"
#include "pear/quality.hpp"
#include "pear/validate.hpp"
#include "pipeline/clean.hpp"

namespace pear::detail {
namespace {

CleanPolygon cleaned(const Polygon& polygon) {
  FlatPolygon flat;
  flatten(polygon, flat);
  CleanPolygon clean;
  std::vector<Diagnostic> diagnostics;
  EXPECT_EQ(clean_polygon(PolygonView{flat.points, flat.ring_starts}, clean, diagnostics),
            Status::ok);
  return clean;
}

/// Every edge gets `extra` points inside it: collinear runs, the clipper's degenerate case.
Polygon with_collinear_runs(const Polygon& polygon, int extra) {
  Polygon out;
  for (const Ring& ring : polygon) {
    Ring& r = out.emplace_back();
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point a = ring[i], b = ring[(i + 1) % ring.size()];
      r.push_back(a);
      // Points with exact coordinates on the edge: only where the edge is axis-parallel or
      // the step is exact (integer coordinates, halving).
      for (int k = 1; k <= extra && (a.x == b.x || a.y == b.y); ++k)
        r.push_back({a.x + (b.x - a.x) * k / (extra + 1), a.y + (b.y - a.y) * k / (extra + 1)});
    }
  }
  return out;
}

/// A rectilinear staircase with `steps` steps: many collinear reflex corners in a row.
Polygon staircase(int steps) {
  Ring ring{{0, 0}, {double(steps), 0}};
  for (int s = steps; s > 0; --s) {
    ring.push_back({double(s), double(steps - s + 1)});
    ring.push_back({double(s - 1), double(steps - s + 1)});
  }
  return {ring};
}

void expect_valid_clip(const Polygon& polygon, EarHeuristic heuristic) {
  const CleanPolygon clean = cleaned(polygon);
  ASSERT_EQ(clean.ring_count(), 1u);
  ASSERT_LE(clean.points.size(), SmallClipper::max_nodes);
  SmallClipper clipper;
  TriangleList out;
  ASSERT_TRUE(clipper.run(clean.points, clean.original, heuristic, out));
  EXPECT_EQ(out.size(), clean.points.size() - 2);
  const ValidationReport report = validate(polygon, out);
  EXPECT_TRUE(report.valid) << (report.messages.empty() ? "" : report.messages.front());
}

TEST(SmallClipper, SyntheticFamiliesAreClippedValidly) {
  int polygons = 0;
  for (std::string_view kind : {"star", "comb", "koch", "hilbert", "random"}) {
    for (std::size_t n : {8u, 12u, 20u, 33u, 64u, 100u, 128u, 200u, 300u, 384u}) {
      for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        Polygon polygon;
        try {
          polygon = generate_polygon(kind, n, seed);
        } catch (const std::invalid_argument&) {
          continue;  // the family has no polygon of this size
        }
        if (polygon.size() != 1 || polygon[0].size() > SmallClipper::max_nodes) continue;
        SCOPED_TRACE(std::string(kind) + " " + std::to_string(n) + " seed " + std::to_string(seed));
        for (EarHeuristic h : {EarHeuristic::top, EarHeuristic::fast})
          expect_valid_clip(polygon, h);
        ++polygons;
      }
    }
  }
  EXPECT_GT(polygons, 100);
}

TEST(SmallClipper, CollinearRunsAndStaircases) {
  for (int steps : {1, 2, 5, 15, 31}) {
    SCOPED_TRACE("staircase " + std::to_string(steps));
    for (EarHeuristic h : {EarHeuristic::top, EarHeuristic::fast}) {
      expect_valid_clip(staircase(steps), h);  // 2 + 2 steps points
      if (steps <= 15) expect_valid_clip(with_collinear_runs(staircase(steps), 3), h);  // x4
    }
  }
  // A square with points along every side: every corner's ear has a chain along it.
  const Polygon square = with_collinear_runs({{{0, 0}, {8, 0}, {8, 8}, {0, 8}}}, 7);
  for (EarHeuristic h : {EarHeuristic::top, EarHeuristic::fast}) expect_valid_clip(square, h);
}

TEST(SmallClipper, RingsThatAreNotSimpleEndAndLeaveOutputAloneWhenRefused) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> coordinate(0, 6), count(4, 40);
  int refused = 0;
  for (int round = 0; round < 3000; ++round) {
    Ring ring;
    const int k = count(rng);
    for (int i = 0; i < k; ++i) ring.push_back({double(coordinate(rng)), double(coordinate(rng))});
    FlatPolygon flat;
    flatten(Polygon{ring}, flat);
    CleanPolygon clean;
    std::vector<Diagnostic> diagnostics;
    if (clean_polygon(PolygonView{flat.points, flat.ring_starts}, clean, diagnostics) != Status::ok)
      continue;
    for (EarHeuristic h : {EarHeuristic::top, EarHeuristic::fast}) {
      SmallClipper clipper;
      TriangleList out{{7, 7, 7}};
      if (clipper.run(clean.points, clean.original, h, out)) {
        EXPECT_EQ(out.size(), clean.points.size() - 1);  // the sentinel and n - 2 triangles
      } else {
        ++refused;
        ASSERT_EQ(out.size(), 1u);
        EXPECT_EQ(out[0][0], 7u);
      }
    }
  }
  EXPECT_GT(refused, 0);
}

/// The pipeline's choice: one ring up to the limit goes the small way; the general engine
/// (forced by partition-and-cut with one partition) must agree on status and count, and both
/// results must be valid, on the county-like sizes.
TEST(SmallPath, AgreesWithTheGeneralEngine) {
  Triangulator triangulator;
  Options general;
  general.algorithm = Algorithm::partition_and_cut;
  general.partitions = 1;
  general.threads = 1;
  int compared = 0;
  for (std::string_view kind : {"star", "random", "koch", "comb"}) {
    for (std::size_t n : {10u, 24u, 64u, 100u, 128u, 250u, 384u}) {
      Polygon polygon;
      try {
        polygon = generate_polygon(kind, n, 3);
      } catch (const std::invalid_argument&) {
        continue;
      }
      SCOPED_TRACE(std::string(kind) + " " + std::to_string(n));
      for (EarHeuristic h : {EarHeuristic::top, EarHeuristic::fast}) {
        Options small;
        small.heuristic = general.heuristic = h;
        small.threads = 1;
        const auto a = triangulator.triangulate(polygon, small);
        const auto b = triangulator.triangulate(polygon, general);
        ASSERT_EQ(a.status, Status::ok);
        ASSERT_EQ(b.status, Status::ok);
        EXPECT_EQ(a.triangles.size(), b.triangles.size());
        EXPECT_TRUE(validate(polygon, a.triangles).valid);
        EXPECT_TRUE(validate(polygon, b.triangles).valid);
        if (h == EarHeuristic::top) {
          // The same order up to the general queue's buckets: angles within a few percent.
          const double qa = quality(polygon, a.triangles).min_angle_avg_deg;
          const double qb = quality(polygon, b.triangles).min_angle_avg_deg;
          EXPECT_GT(qa, 0.9 * qb);
        }
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 20);
}

}  // namespace
}  // namespace pear::detail
