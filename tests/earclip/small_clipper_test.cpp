// The small-polygon path (src/earclip/small_clipper.cpp, chosen by the pipeline for one ring of
// at most 384 vertices): on simple rings of every synthetic family, with collinear runs added,
// and on rectilinear staircases, it must give n - 2 triangles that the validator accepts, for
// `top` and `fast`; through the public API its results must be as valid as the general
// engine's on the same polygons; on rings that are not simple it must end and either say so
// or leave a result (the check, which the pipeline runs first, is what promises validity).
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>

#include "earclip/small_clipper.hpp"
#include "pear/generate.hpp"
#include "pear/pear.hpp"
#include "pear/quality.hpp"
#include "pear/validate.hpp"
#include "clean/clean.hpp"

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

std::size_t polygon_size(const Polygon& polygon) {
  std::size_t n = 0;
  for (const Ring& ring : polygon) n += ring.size();
  return n;
}

/// The general engine: partition-and-cut with one partition.
Options general_engine(EarHeuristic heuristic) {
  Options general;
  general.algorithm = Algorithm::partition_and_cut;
  general.partitions = 1;
  general.threads = 1;
  general.heuristic = heuristic;
  return general;
}

/// The pipeline's choice against the general engine, with both heuristics: the same status
/// (ok) and count, both results valid, `top`'s angles within 10% (the same order up to the
/// general queue's buckets). Up to the small path's limit (its vertices and two per hole) it
/// did the work: the general path's phases are absent.
void expect_small_path_agrees(Triangulator& triangulator, const Polygon& polygon) {
  for (EarHeuristic h : {EarHeuristic::top, EarHeuristic::fast}) {
    Options small;
    small.heuristic = h;
    small.threads = 1;
    RunProfile profile;
    small.profile = &profile;
    const auto a = triangulator.triangulate(polygon, small);
    const auto b = triangulator.triangulate(polygon, general_engine(h));
    ASSERT_EQ(a.status, Status::ok);
    ASSERT_EQ(b.status, Status::ok);
    const bool general_ran = std::any_of(profile.phases.begin(), profile.phases.end(),
                                         [](const auto& p) { return p.name == "bridge holes"; });
    EXPECT_EQ(general_ran,
              polygon_size(polygon) + 2 * (polygon.size() - 1) > SmallClipper::max_nodes);
    EXPECT_EQ(a.triangles.size(), b.triangles.size());
    EXPECT_TRUE(validate(polygon, a.triangles).valid);
    EXPECT_TRUE(validate(polygon, b.triangles).valid);
    if (h == EarHeuristic::top) {
      EXPECT_GT(quality(polygon, a.triangles).min_angle_avg_deg,
                0.9 * quality(polygon, b.triangles).min_angle_avg_deg);
    }
  }
}

/// One ring, county-like sizes up to the limit and past it.
TEST(SmallPath, AgreesWithTheGeneralEngine) {
  Triangulator triangulator;
  int compared = 0;
  for (std::string_view kind : {"star", "random", "koch", "comb"}) {
    for (std::size_t n : {10u, 24u, 64u, 100u, 128u, 250u, 384u, 500u}) {
      Polygon polygon;
      try {
        polygon = generate_polygon(kind, n, 3);
      } catch (const std::invalid_argument&) {
        continue;
      }
      SCOPED_TRACE(std::string(kind) + " " + std::to_string(n));
      expect_small_path_agrees(triangulator, polygon);
      ++compared;
    }
  }
  EXPECT_GT(compared, 10);
}

/// Polygons with holes: bridged, then clipped as one ring with repeated bridge ends.
TEST(SmallPath, HolesAgreeWithTheGeneralEngine) {
  Triangulator triangulator;
  int compared = 0;
  for (std::string_view kind : {"holes", "random-holes"}) {
    for (std::size_t n : {12u, 20u, 40u, 80u, 150u, 300u}) {
      for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        Polygon polygon;
        try {
          polygon = generate_polygon(kind, n, seed);
        } catch (const std::invalid_argument&) {
          continue;
        }
        if (polygon.size() < 2) continue;
        SCOPED_TRACE(std::string(kind) + " " + std::to_string(n) + " seed " + std::to_string(seed));
        expect_small_path_agrees(triangulator, polygon);
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 10);
}

/// Holes where a hole may not be, and holes whose bridges share an outer vertex, through the
/// small path: the same statuses and diagnostics as the general engine's.
TEST(SmallPath, MisplacedAndCrowdedHoles) {
  const Ring square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const Ring hole{{2, 2}, {2, 8}, {8, 8}, {8, 2}};
  const Ring inner{{4, 4}, {4, 6}, {6, 6}, {6, 4}};
  const Ring beside{{12, 2}, {12, 8}, {18, 8}, {18, 2}};
  struct Case {
    const char* name;
    Polygon polygon;
    Status status;
    Issue issue;
    std::size_t ring;
  };
  const Case cases[] = {
      {"hole in a hole", {square, hole, inner}, Status::not_simple, Issue::hole_inside_hole, 2},
      {"hole beside the outer ring",
       {square, beside},
       Status::not_simple,
       Issue::hole_outside_outer_ring,
       1},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const auto small = triangulate(c.polygon);
    const auto reference = triangulate(c.polygon, general_engine(EarHeuristic::top));
    EXPECT_EQ(small.status, c.status);
    EXPECT_EQ(reference.status, c.status);
    ASSERT_FALSE(small.diagnostics.empty());
    EXPECT_EQ(small.diagnostics.back().issue, c.issue);
    EXPECT_EQ(small.diagnostics.back().ring, c.ring);
  }
  // Four triangular holes in a column, each leftmost vertex in sight of the outer ring's left
  // corner (0, 0): their bridges all end there, so that position repeats five times.
  Polygon crowded{{{0, 0}, {5, -6}, {10, 0}, {5, 6}}};
  for (double y : {-1.5, -0.5, 0.5, 1.5}) crowded.push_back({{2, y}, {3, y + 0.25}, {3, y - 0.25}});
  const auto result = triangulate(crowded);
  ASSERT_EQ(result.status, Status::ok);
  EXPECT_EQ(result.triangles.size(), 16u + 2 * 4 - 2);  // n + 2h - 2
  EXPECT_TRUE(validate(crowded, result.triangles).valid);
}

}  // namespace
}  // namespace pear::detail
