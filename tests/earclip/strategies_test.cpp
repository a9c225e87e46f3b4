// The ear clipper's strategies: the bit sets (src/earclip/bitset_clipper.cpp, which EarClipper
// takes for boundaries of at most 1,024 nodes) and the queue. The bit sets on simple rings of
// every synthetic family, with collinear runs added, and on rectilinear staircases, must give
// n - 2 triangles that the validator accepts, for `top` and `fast`; on rings that are not simple
// they must end and either clip everything or leave the rest linked for the queue. Both
// strategies on the same bridged boundaries (holes included) must give valid triangulations of
// the same size and, for `top`, angles within 10% of each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "boundary_support.hpp"
#include "clean/clean.hpp"
#include "earclip/bitset_clipper.hpp"
#include "earclip/bridge.hpp"
#include "earclip/ear_clipper.hpp"
#include "pear/generate.hpp"
#include "pear/pear.hpp"
#include "pear/quality.hpp"
#include "pear/validate.hpp"

namespace pear::detail {
namespace {

using testing::cleaned;

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

/// The boundary of a cleaned polygon, its holes joined by bridges (as the engine builds it).
Boundary bridged(const CleanPolygon& clean) {
  Boundary b = testing::rings_as_cycles(clean);
  HoleBridger bridger;
  EXPECT_TRUE(bridger.join(clean, b).empty());
  return b;
}

void expect_valid_clip(const Polygon& polygon, EarHeuristic heuristic) {
  const CleanPolygon clean = cleaned(polygon);
  ASSERT_EQ(clean.ring_count(), 1u);
  ASSERT_LE(clean.points.size(), BitsetClipper::max_nodes);
  Boundary b = bridged(clean);
  BitsetClipper clipper;
  TriangleList out;
  ASSERT_TRUE(clipper.clip(b, 0, heuristic, out, nullptr));
  EXPECT_EQ(out.size(), clean.points.size() - 2);
  const ValidationReport report = validate(polygon, out);
  EXPECT_TRUE(report.valid) << (report.messages.empty() ? "" : report.messages.front());
}

TEST(BitsetClipper, SyntheticFamiliesAreClippedValidly) {
  int polygons = 0;
  for (std::string_view kind : {"star", "comb", "koch", "hilbert", "random"}) {
    for (std::size_t n :
         {8u, 12u, 20u, 33u, 64u, 100u, 128u, 200u, 300u, 384u, 500u, 768u, 1000u}) {
      for (std::uint64_t seed = 1; seed <= 5; ++seed) {
        Polygon polygon;
        try {
          polygon = generate_polygon(kind, n, seed);
        } catch (const std::invalid_argument&) {
          continue;  // the family has no polygon of this size
        }
        if (polygon.size() != 1 || polygon[0].size() > BitsetClipper::max_nodes) continue;
        SCOPED_TRACE(std::string(kind) + " " + std::to_string(n) + " seed " + std::to_string(seed));
        for (EarHeuristic h : {EarHeuristic::top, EarHeuristic::fast})
          expect_valid_clip(polygon, h);
        ++polygons;
      }
    }
  }
  EXPECT_GT(polygons, 100);
}

TEST(BitsetClipper, CollinearRunsAndStaircases) {
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

/// 3,000 rings of 4 to 40 random points of a 7 x 7 lattice (most not simple): visit(clean,
/// round) for each that cleaning accepts.
template <class Visit>
void for_each_lattice_ring(unsigned seed, Visit&& visit) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> coordinate(0, 6), count(4, 40);
  for (int round = 0; round < 3000; ++round) {
    Ring ring;
    const int k = count(rng);
    for (int i = 0; i < k; ++i) ring.push_back({double(coordinate(rng)), double(coordinate(rng))});
    FlatPolygon flat;
    flatten(Polygon{ring}, flat);
    CleanPolygon clean;
    std::vector<Diagnostic> diagnostics;
    if (clean_polygon(PolygonView{flat.points, flat.ring_starts}, clean, diagnostics) == Status::ok)
      visit(clean, round);
  }
}

TEST(BitsetClipper, RingsThatAreNotSimpleEndAndLeaveTheRestLinked) {
  int refused = 0;
  for_each_lattice_ring(7, [&](const CleanPolygon& clean, int) {
    for (EarHeuristic h : {EarHeuristic::top, EarHeuristic::fast}) {
      Boundary b = bridged(clean);
      BitsetClipper clipper;
      TriangleList out{{7, 7, 7}};
      const std::size_t n = clean.points.size();
      if (clipper.clip(b, 0, h, out, nullptr)) {
        EXPECT_EQ(out.size(), n - 1);  // the sentinel and n - 2 triangles
      } else {
        ++refused;
        EXPECT_EQ(out[0][0], 7u);
        // One node left the cycle per triangle; the rest is still linked, for the queue.
        EXPECT_EQ(testing::cycle_length(b, clipper.anchor()), n - (out.size() - 1));
      }
    }
  });
  EXPECT_GT(refused, 0);
}

/// The one-word loops (at most 64 nodes) clip the same ears in the same order as the general
/// loops, which a boundary of more than 64 nodes takes (the ring, then nodes on no cycle), on
/// rings that are not simple too: there a clip past a crossing can turn a neighbour reflex that
/// the one-word ear test's list of blockers did not hold.
TEST(BitsetClipper, OneWordLoopsClipAsTheGeneralOnesPastCrossings) {
  int differed_from_simple = 0;
  for_each_lattice_ring(11, [&](const CleanPolygon& clean, int round) {
    for (EarHeuristic h : {EarHeuristic::top, EarHeuristic::fast}) {
      Boundary one_word = bridged(clean), general = one_word;
      for (std::uint32_t extra = general.size(); extra < 65; ++extra) {
        general.pos.push_back({100.0 + extra, 100.0});
        general.vertex.push_back(extra);
        general.prev.push_back(extra);
        general.next.push_back(extra);
      }
      BitsetClipper first, second;
      TriangleList by_word, by_words;
      const bool done = first.clip(one_word, 0, h, by_word, nullptr);
      EXPECT_EQ(second.clip(general, 0, h, by_words, nullptr), done);
      EXPECT_EQ(by_word, by_words) << "round " << round;
      differed_from_simple += !done || by_word.size() != clean.points.size() - 2;
    }
  });
  EXPECT_GT(differed_from_simple, 0);
}

/// `fast`'s walk on rings whose ears lie only near their ends (a spiral's walls, a Hilbert
/// curve's) hands over to `top`'s order: its ear tests stay linear in the nodes, where a lap of
/// the walk for every few clips made them quadratic (a 760-node spiral took 41 tests a node).
TEST(BitsetClipper, WalkHandsOverWhereEarsAreFew) {
  const std::pair<std::string_view, std::size_t> rings[] = {
      {"spiral", 640}, {"spiral", 760}, {"hilbert", 60}, {"hilbert", 250}, {"hilbert", 700}};
  for (const auto& [kind, n] : rings) {
    const Polygon polygon = generate_polygon(kind, n, 1);
    const CleanPolygon clean = cleaned(polygon);
    ASSERT_LE(clean.points.size(), BitsetClipper::max_nodes);
    {
      SCOPED_TRACE(std::string(kind) + " " + std::to_string(clean.points.size()));
      Boundary b = bridged(clean);
      BitsetClipper clipper;
      TriangleList out;
      ASSERT_TRUE(clipper.clip(b, 0, EarHeuristic::fast, out, nullptr));
      EXPECT_EQ(out.size(), clean.points.size() - 2);
      EXPECT_TRUE(validate(polygon, out).valid);
      EXPECT_LE(clipper.ear_tests(), 6 * clean.points.size());
    }
  }
}

/// Both strategies of EarClipper on the bridged boundary, with both heuristics: valid
/// triangulations of the same size, `top`'s angles within 10% (the same order up to the
/// queue's buckets).
void expect_strategies_agree(const Polygon& polygon) {
  const CleanPolygon clean = cleaned(polygon);
  for (EarHeuristic h : {EarHeuristic::top, EarHeuristic::fast}) {
    Boundary for_bits = bridged(clean), for_queue = for_bits;
    ASSERT_LE(for_bits.size(), BitsetClipper::max_nodes);
    EarClipper clipper;
    TriangleList bits, queue;
    ASSERT_TRUE(clipper.run(for_bits, 0, h, bits));
    ASSERT_TRUE(clipper.run_queue(for_queue, 0, h, queue));
    EXPECT_EQ(bits.size(), queue.size());
    EXPECT_TRUE(validate(polygon, bits).valid);
    EXPECT_TRUE(validate(polygon, queue).valid);
    if (h == EarHeuristic::top) {
      EXPECT_GT(quality(polygon, bits).min_angle_avg_deg,
                0.9 * quality(polygon, queue).min_angle_avg_deg);
    }
  }
}

/// One ring, county-like sizes up to the bit sets' limit.
TEST(Strategies, AgreeOnOneRing) {
  int compared = 0;
  for (std::string_view kind : {"star", "random", "koch", "comb"}) {
    for (std::size_t n : {10u, 24u, 64u, 100u, 128u, 250u, 384u, 600u, 768u, 1000u}) {
      Polygon polygon;
      try {
        polygon = generate_polygon(kind, n, 3);
      } catch (const std::invalid_argument&) {
        continue;
      }
      if (polygon[0].size() > BitsetClipper::max_nodes) continue;
      SCOPED_TRACE(std::string(kind) + " " + std::to_string(n));
      expect_strategies_agree(polygon);
      ++compared;
    }
  }
  EXPECT_GT(compared, 10);
}

/// Polygons with holes: one boundary with repeated bridge ends.
TEST(Strategies, AgreeWithHoles) {
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
        std::size_t nodes = 0;
        for (const Ring& ring : polygon) nodes += ring.size() + 2;
        if (polygon.size() < 2 || nodes > BitsetClipper::max_nodes) continue;
        SCOPED_TRACE(std::string(kind) + " " + std::to_string(n) + " seed " + std::to_string(seed));
        expect_strategies_agree(polygon);
        ++compared;
      }
    }
  }
  EXPECT_GT(compared, 10);
}

/// Holes where a hole may not be, and holes whose bridges share an outer vertex, through the
/// pipeline: named as not_simple with the hole's ring, or triangulated validly.
TEST(Strategies, MisplacedAndCrowdedHoles) {
  const Ring square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const Ring hole{{2, 2}, {2, 8}, {8, 8}, {8, 2}};
  const Ring inner{{4, 4}, {4, 6}, {6, 6}, {6, 4}};
  const Ring beside{{12, 2}, {12, 8}, {18, 8}, {18, 2}};
  struct Case {
    const char* name;
    Polygon polygon;
    Issue issue;
    std::size_t ring;
  };
  const Case cases[] = {
      {"hole in a hole", {square, hole, inner}, Issue::hole_inside_hole, 2},
      {"hole beside the outer ring", {square, beside}, Issue::hole_outside_outer_ring, 1},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    for (EarHeuristic h : {EarHeuristic::top, EarHeuristic::fast}) {
      const auto result = triangulate(c.polygon, {.heuristic = h});
      EXPECT_EQ(result.status, Status::not_simple);
      ASSERT_EQ(result.diagnostics.size(), 1u);
      EXPECT_EQ(result.diagnostics.back().issue, c.issue);
      EXPECT_EQ(result.diagnostics.back().ring, c.ring);
    }
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

/// The queue and `fast`'s walk, once no reflex node is left on a long cycle, finish a strip
/// (what a comb becomes once its teeth are clipped) in two fans (core/strip_fans.hpp) instead
/// of an ear at a time: valid, n - 2 triangles, half of them joining two feet to one of the
/// comb's two bottom corners. A comb too short for fans, and a long polygon that never becomes a
/// strip (a 20,000-gon: no reflex node from the start), are clipped ear by ear.
TEST(Strips, TheQueueAndTheWalkFinishAStripInFans) {
  struct Case {
    const char* name;
    Polygon polygon;
    std::size_t strips;
  };
  Ring circle;
  for (int i = 0; i < 20000; ++i)
    circle.push_back({std::cos(i * 2 * M_PI / 20000), std::sin(i * 2 * M_PI / 20000)});
  const Case cases[] = {
      {"comb of 20,000", generate_polygon("comb", 20000), 1},
      {"comb of 4,000", generate_polygon("comb", 4000), 0},
      {"20,000-gon", {circle}, 0},
  };
  for (const Case& c : cases)
    for (EarHeuristic h : {EarHeuristic::top, EarHeuristic::fast}) {
      SCOPED_TRACE(std::string(c.name) + (h == EarHeuristic::top ? ", top" : ", fast"));
      const CleanPolygon clean = cleaned(c.polygon);
      Boundary b = testing::rings_as_cycles(clean);
      EarClipper clipper;
      TriangleList triangles;
      ASSERT_TRUE(clipper.run_queue(b, 0, h, triangles));
      EXPECT_EQ(clipper.strips(), c.strips);
      ASSERT_EQ(triangles.size(), clean.points.size() - 2);
      EXPECT_TRUE(validate(c.polygon, triangles).valid);
      if (c.strips == 0) continue;
      // The comb's ring starts with its bottom corners (0, 0) and (right, 0); the strip is the
      // teeth's feet (y = 1), every one of its triangles two feet and one of those corners.
      std::size_t strip_triangles = 0;
      for (const auto& t : triangles) {
        const auto y = [&](std::uint32_t k) { return c.polygon[0][t[k]].y; };
        strip_triangles += std::min({t[0], t[1], t[2]}) <= 1u && y(0) + y(1) + y(2) == 2.0;
      }
      EXPECT_GE(strip_triangles, clean.points.size() / 2 - 4);
    }
}

}  // namespace
}  // namespace pear::detail
