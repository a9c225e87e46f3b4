// The exact simplicity check: its adaptive grid and its sweep must agree with a brute-force
// reference on small polygons full of degeneracies (integer grid: collinear runs, touching,
// overlaps), on perturbed large polygons at 1, 2 and 4 threads (same answer at every thread
// count), and on every polygon of ../shared/corpus (never a violation where the MANIFEST
// calls the polygon valid).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>
#include <numeric>
#include <optional>
#include <random>
#include <span>

#include "clean/clean.hpp"
#include "gtest_corpus.hpp"
#include "pear/config.hpp"
#include "pear/generate.hpp"
#include "pear/predicates.hpp"
#include "pipeline/threading.hpp"
#include "run_contexts.hpp"
#include "simplicity/simplicity.hpp"

namespace pear::detail {
namespace {

using Method = SimplicityCheck::Method;

bool between(const Point& p, const Point& a, const Point& b) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

/// Closed segments a-b and c-d share a point.
bool intersect(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  const double o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
    return true;
  return (o1 == 0 && between(c, a, b)) || (o2 == 0 && between(d, a, b)) ||
         (o3 == 0 && between(a, c, d)) || (o4 == 0 && between(b, c, d));
}

/// Two edges may only meet in endpoints they share, and only in that one point.
bool segments_violate(const Point& a, const Point& b, const Point& c, const Point& d) {
  if (!intersect(a, b, c, d)) return false;
  // Meeting is fine only when it is exactly one shared endpoint: then no other endpoint of
  // either lies on the other segment, and they are not collinear overlapping.
  const bool share = a == c || a == d || b == c || b == d;
  if (!share) return true;
  const Point shared = (a == c || a == d) ? a : b;
  const Point other_ab = shared == a ? b : a;
  const Point other_cd = (c == shared) ? d : c;
  if (orient2d(shared, other_ab, other_cd) == 0 &&
      (between(other_cd, shared, other_ab) || between(other_ab, shared, other_cd)))
    return true;                                    // folding back along each other
  return (a == c || a == d) && (b == c || b == d);  // the same segment twice
}

/// The reference: every pair of edges whose x- and y-ranges overlap (all others cannot meet),
/// by segments_violate. Returns the smallest edge in any violating pair.
class Reference {
 public:
  explicit Reference(const CleanPolygon& polygon) : pts_(polygon.points), next_(pts_.size()) {
    for (std::size_t r = 0; r < polygon.ring_count(); ++r)
      for (std::uint32_t i = polygon.ring_starts[r]; i < polygon.ring_starts[r + 1]; ++i)
        next_[i] = i + 1 < polygon.ring_starts[r + 1] ? i + 1 : polygon.ring_starts[r];
  }
  /// Edges whose y-ranges do not overlap cannot meet either.
  bool violate(std::uint32_t e, std::uint32_t f) const {
    const Point &a = pts_[e], &b = pts_[next_[e]], &c = pts_[f], &d = pts_[next_[f]];
    if (std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y))
      return false;
    return segments_violate(a, b, c, d);
  }
  double lo(std::uint32_t e) const { return std::min(pts_[e].x, pts_[next_[e]].x); }
  double hi(std::uint32_t e) const { return std::max(pts_[e].x, pts_[next_[e]].x); }

  std::optional<std::uint32_t> smallest_violation() const {
    std::vector<std::uint32_t> by_x(pts_.size());
    std::iota(by_x.begin(), by_x.end(), 0u);
    std::sort(by_x.begin(), by_x.end(), [&](auto e, auto f) { return lo(e) < lo(f); });
    std::uint32_t best = UINT32_MAX;
    for (std::size_t i = 0; i < by_x.size(); ++i)
      for (std::size_t j = i + 1; j < by_x.size() && lo(by_x[j]) <= hi(by_x[i]); ++j)
        if (std::min(by_x[i], by_x[j]) < best && violate(by_x[i], by_x[j]))
          best = std::min(by_x[i], by_x[j]);
    if (best == UINT32_MAX) return std::nullopt;
    return best;
  }
  /// Whether two edges that are not neighbours share an endpoint (a point the rings pass twice).
  bool touching() const {
    for (std::uint32_t e = 0; e < pts_.size(); ++e)
      for (std::uint32_t f = e + 1; f < pts_.size(); ++f)
        if (next_[e] != f && next_[f] != e &&
            (pts_[e] == pts_[f] || pts_[e] == pts_[next_[f]] || pts_[next_[e]] == pts_[f] ||
             pts_[next_[e]] == pts_[next_[f]]))
          return true;
    return false;
  }
  /// Whether edge e crosses, overlaps or folds back over another edge: a violation that is
  /// not one end lying strictly inside the other edge (a T-junction, which a split repairs).
  bool unresolvable_at(std::uint32_t e) const {
    for (std::uint32_t f = 0; f < pts_.size(); ++f) {
      if (f == e || !violate(e, f)) continue;
      const Point &a = pts_[e], &b = pts_[next_[e]], &c = pts_[f], &d = pts_[next_[f]];
      const double o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
      const double o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
      const bool collinear = o1 == 0 && o2 == 0;
      const bool proper = o1 * o2 < 0 && o3 * o4 < 0;
      const bool share = a == c || a == d || b == c || b == d;
      if (collinear || proper || share) return true;
    }
    return false;
  }
  /// Whether edge e takes part in a violation.
  bool involved(std::uint32_t e) const {
    for (std::uint32_t f = 0; f < pts_.size(); ++f)
      if (f != e && lo(f) <= hi(e) && lo(e) <= hi(f) && violate(e, f)) return true;
    return false;
  }

 private:
  std::span<const Point> pts_;
  std::vector<std::uint32_t> next_;
};

CleanPolygon cleaned(const Polygon& polygon) {
  FlatPolygon flat;
  flatten(polygon, flat);
  CleanPolygon clean;
  std::vector<Diagnostic> diagnostics;
  clean_polygon(PolygonView{flat.points, flat.ring_starts}, clean, diagnostics);
  return clean;
}

CleanPolygon random_polygon(std::mt19937& rng, int rings, int max_vertices, int grid) {
  std::uniform_int_distribution<int> coordinate(0, grid), count(3, max_vertices);
  Polygon polygon(static_cast<std::size_t>(rings));
  for (Ring& ring : polygon) {
    const int k = count(rng);
    for (int i = 0; i < k; ++i) ring.push_back({double(coordinate(rng)), double(coordinate(rng))});
  }
  return cleaned(polygon);
}

using Contexts = ThreadContexts;  // the answer must not depend on the thread count

/// What every method must give: the grid the smallest violating edge (it sees every pair);
/// the sweep and the automatic choice some violating edge, when there is a violation; all of
/// them the same answer at every thread count.
void expect_agreement(const CleanPolygon& polygon, const Contexts& contexts) {
  const Reference reference(polygon);
  const auto expected = reference.smallest_violation();
  SimplicityCheck check;
  for (Method method : {Method::grid_only, Method::sweep_only, Method::automatic}) {
    SCOPED_TRACE("method " + std::to_string(static_cast<int>(method)));
    const auto first = check.find_violation(polygon, contexts.list[0], method);
    ASSERT_EQ(first.has_value(), expected.has_value());
    if (method == Method::grid_only) {
      EXPECT_EQ(first, expected);
    }
    if (first) {
      EXPECT_TRUE(reference.involved(*first)) << *first;
    }
    for (const RunContext& ctx : contexts.list)
      EXPECT_EQ(check.find_violation(polygon, ctx, method), first) << "deterministic";
  }
  // The strategies for few edges see every pair too (all pairs up to 128 edges in all rings,
  // runs monotone in x up to 384), and say whether the rings pass a point twice.
  const Verdict verdict = check.check(polygon, contexts.list[0], true);
  ASSERT_EQ(verdict.violation.has_value(), expected.has_value()) << "check";
  if (polygon.points.size() > SimplicityCheck::chains_limit) {
    // The runs (the smallest edge in a conflict) or the grid's search; the rings' touching
    // known exactly when the runs decided.
    EXPECT_TRUE(verdict.violation == expected ||
                verdict.violation == check.find_violation(polygon, contexts.list[0]));
    if (!expected && verdict.touching != Verdict::Touching::unknown) {
      EXPECT_EQ(verdict.touching == Verdict::Touching::yes, reference.touching());
    }
    return;
  }
  EXPECT_EQ(verdict.violation, expected) << "check";
  if (!expected) {
    const auto touching = reference.touching() ? Verdict::Touching::yes : Verdict::Touching::no;
    EXPECT_EQ(verdict.touching, touching) << "check's touching";
    EXPECT_EQ(check.check(polygon, contexts.list[0], false).touching, touching) << "touching only";
  }
}

/// The small check's box scan (geometry/box_scan.hpp) gives the same rows with AVX2 (where
/// the processor has it), SSE2 and plain comparisons, and each row's bit says exactly whether a
/// box in its ranges meets it: ranges of every length from 0 to the capacity (eight-wide steps
/// and their masked ends), touching boxes, coordinates of every magnitude a float has.
TEST(BoxScan, InstructionSetsAgreeWithBruteForce) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> coordinate(0, 40), length(0, 6);
  constexpr std::uint32_t capacity = 128;
  std::array<std::array<float, capacity + 8>, 4> columns{};
  auto& [x0, y0, x1, y1] = columns;
  const BoxColumns c{x0.data(), y0.data(), x1.data(), y1.data()};
  for (int round = 0; round < 300; ++round) {
    const std::uint32_t n = 1 + static_cast<std::uint32_t>(rng() % capacity);
    const float scale = round % 3 == 0 ? 0x1p-120f : round % 3 == 1 ? 1.0f : 0x1p100f;
    for (std::uint32_t i = 0; i < n; ++i) {
      const auto x = static_cast<float>(coordinate(rng)), y = static_cast<float>(coordinate(rng));
      x0[i] = x * scale, x1[i] = (x + static_cast<float>(length(rng))) * scale;
      y0[i] = y * scale, y1[i] = (y + static_cast<float>(length(rng))) * scale;
    }
    // Past n: boxes that meet everything, which the masks must keep out.
    for (std::uint32_t i = n; i < x0.size(); ++i) x0[i] = y0[i] = -1e30f, x1[i] = y1[i] = 1e30f;
    std::vector<RowRanges> rows;
    for (std::uint32_t k = 0; k < 2 * n; ++k) {
      const std::uint32_t a = rng() % (n + 1), b = rng() % (n + 1), d = rng() % (n + 1);
      rows.push_back({static_cast<std::uint32_t>(rng() % n), std::min(a, b), std::max(a, b), d,
                      k % 4 == 0 ? n : d});
    }
    if (rows.size() > capacity) rows.resize(capacity);
    std::array<std::uint64_t, capacity / 64> best, sse2, scalar;
    rows_meeting(c, rows, best, BoxScan::best);
    rows_meeting(c, rows, sse2, BoxScan::sse2);
    rows_meeting(c, rows, scalar, BoxScan::scalar);
    const auto meets = [&](std::uint32_t e, std::uint32_t f) {
      return c.x0[f] <= c.x1[e] && c.x0[e] <= c.x1[f] && c.y0[f] <= c.y1[e] && c.y0[e] <= c.y1[f];
    };
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const RowRanges& r = rows[k];
      bool expected = false;
      for (std::uint32_t f = r.from; f < r.to; ++f) expected |= meets(r.row, f);
      for (std::uint32_t f = r.from2; f < r.to2; ++f) expected |= meets(r.row, f);
      SCOPED_TRACE("round " + std::to_string(round) + " row " + std::to_string(k));
      ASSERT_EQ((best[k / 64] >> (k % 64)) & 1, expected);
      ASSERT_EQ((sse2[k / 64] >> (k % 64)) & 1, expected);
      ASSERT_EQ((scalar[k / 64] >> (k % 64)) & 1, expected);
    }
  }
}

/// Boxes in doubles rounded to floats, as the check rounds them (relative to a first point,
/// then to nearest): every pair that meets in doubles still meets, however close the boxes
/// (touching exactly, apart or overlapping by one unit of a double), however large the
/// coordinates against the distances (2^-200 to 2^200, far from the first point), and pairs
/// apart by more than a float's rounding stay apart, so the float rows filter.
TEST(BoxScan, FloatBoxesMeetWhereDoubleBoxesMeet) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t met = 0, apart_kept = 0, apart = 0;
  for (int round = 0; round < 20000; ++round) {
    const double scale = std::ldexp(1.0, static_cast<int>(rng() % 401) - 200);
    const double offset = (round % 3 == 0 ? 1e6 : round % 3 == 1 ? -3.5 : 0.0) * scale;
    const Point origin{offset + unit(rng) * scale, offset - unit(rng) * scale};
    Box s{offset + unit(rng) * scale, offset + unit(rng) * scale, 0, 0};
    s.x1 = s.x0 + unit(rng) * scale, s.y1 = s.y0 + unit(rng) * scale;
    // t starts where s ends, one double unit before or after, or anywhere.
    Box t = s;
    const int kind = static_cast<int>(rng() % 4);
    const double start = kind == 3 ? offset + unit(rng) * 2 * scale : s.x1;
    t.x0 = kind == 1   ? std::nextafter(start, -INFINITY)
           : kind == 2 ? std::nextafter(start, INFINITY)
                       : start;
    t.x1 = t.x0 + unit(rng) * scale;
    const bool meet = t.x0 <= s.x1 && s.x0 <= t.x1 && t.y0 <= s.y1 && s.y0 <= t.y1;
    std::array<std::array<float, 16>, 4> columns{};  // read up to 7 past the range
    auto& [x0, y0, x1, y1] = columns;
    for (const auto& [i, b] : {std::pair(0, s), std::pair(1, t)}) {
      x0[i] = static_cast<float>(b.x0 - origin.x), y0[i] = static_cast<float>(b.y0 - origin.y);
      x1[i] = static_cast<float>(b.x1 - origin.x), y1[i] = static_cast<float>(b.y1 - origin.y);
    }
    const std::array<RowRanges, 1> rows{{{0, 1, 2, 2, 2}}};
    std::array<std::uint64_t, 1> flagged{};
    rows_meeting(BoxColumns{x0.data(), y0.data(), x1.data(), y1.data()}, rows, flagged);
    SCOPED_TRACE(round);
    if (meet) {
      ++met;
      ASSERT_EQ(flagged[0], 1u) << "boxes that meet in doubles must meet in floats";
    } else {
      // Apart by more than a float's rounding of either side (and within a float's range).
      const double u = std::fabs(s.x1 - origin.x), v = std::fabs(t.x0 - origin.x);
      if (std::max(u, v) < 0x1p120 && t.x0 - s.x1 > (u + v) * 0x1p-22 + 0x1p-148) {
        ++apart;
        apart_kept += flagged[0] == 0;
      }
    }
  }
  EXPECT_GT(met, 5000u);
  EXPECT_GT(apart, 1000u);
  EXPECT_EQ(apart_kept, apart) << "boxes well apart stay apart in floats";
}

/// points_in_box (the small clipper's ear test) sets exactly the bits of the points in the
/// closed box, with every instruction set: counts 0 to 64 (the lanes past the count hold
/// stale points that must not show), points on the box's sides, NaN never inside.
TEST(BoxScan, PointsInBoxAgreeWithBruteForce) {
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> coordinate(0, 12);
  std::array<double, 64 + 4> xs{}, ys{};
  for (int round = 0; round < 400; ++round) {
    const std::uint32_t n = static_cast<std::uint32_t>(round % 65);
    const double scale = round % 3 == 0 ? 0x1p-180 : round % 3 == 1 ? 1.0 : 0x1p180;
    for (std::uint32_t i = 0; i < n; ++i)
      xs[i] = coordinate(rng) * scale, ys[i] = coordinate(rng) * scale;
    for (std::uint32_t i = n; i < xs.size(); ++i) xs[i] = ys[i] = 5 * scale;  // in the box
    if (n > 3) xs[n / 2] = std::numeric_limits<double>::quiet_NaN();
    const Box box{4 * scale, 3 * scale, 8 * scale, 9 * scale};
    std::uint64_t expected = 0;
    for (std::uint32_t i = 0; i < n; ++i)
      if (xs[i] >= box.x0 && xs[i] <= box.x1 && ys[i] >= box.y0 && ys[i] <= box.y1)
        expected |= std::uint64_t{1} << i;
    SCOPED_TRACE("round " + std::to_string(round));
    ASSERT_EQ(points_in_box(xs.data(), ys.data(), n, box, BoxScan::best), expected);
    ASSERT_EQ(points_in_box(xs.data(), ys.data(), n, box, BoxScan::sse2), expected);
    ASSERT_EQ(points_in_box(xs.data(), ys.data(), n, box, BoxScan::scalar), expected);
  }
}

TEST(Simplicity, MethodsAgreeWithBruteForce) {
  std::mt19937 rng(12345);
  const Contexts contexts;
  int violations = 0, simple = 0;
  for (int round = 0; round < 4000; ++round) {
    // One ring in every other round, up to three otherwise; up to 140 vertices a ring in some,
    // past the small check's all-pairs limit of 128 edges in all.
    const int rings = round % 2 == 0 ? 1 : 1 + round % 3;
    const int vertices = round % 5 == 0 ? 3 + round % 140 : 3 + round % 7;
    const CleanPolygon polygon = random_polygon(rng, rings, vertices, 3 + round % 6);
    if (polygon.ring_count() == 0 || polygon.points.size() < 3) continue;
    SCOPED_TRACE("round " + std::to_string(round));
    expect_agreement(polygon, contexts);
    (Reference(polygon).smallest_violation() ? violations : simple) += 1;
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(violations, 100);  // both outcomes were exercised
  EXPECT_GT(simple, 100);
}

/// Grids over boxes whose sizes overflow or underflow (the exact predicates' whole range), and
/// a polygon mixing both: the grids must still miss no pair.
TEST(Simplicity, ExtremeCoordinatesAgreeWithBruteForce) {
  std::mt19937 rng(99);
  const Contexts contexts;
  for (int round = 0; round < 300; ++round) {
    CleanPolygon polygon = random_polygon(rng, 2, 8, 6);
    if (polygon.ring_count() == 0 || polygon.points.size() < 3) continue;
    const double scale = round % 3 == 1 ? 0x1p-190 : 0x1p190;  // round % 3 == 2: holes tiny
    for (std::size_t i = 0; i < polygon.points.size(); ++i) {
      const bool tiny = round % 3 == 2 && i >= polygon.ring_starts[1];
      polygon.points[i].x *= tiny ? 0x1p-190 : scale;
      polygon.points[i].y *= tiny ? 0x1p-190 : scale;
    }
    SCOPED_TRACE("round " + std::to_string(round));
    expect_agreement(polygon, contexts);
    if (::testing::Test::HasFailure()) break;
  }
}

TEST(Simplicity, SyntheticFamiliesAreSimpleByEveryMethod) {
  const Contexts contexts;
  for (std::string_view kind : generator_kinds()) {
    SCOPED_TRACE(std::string(kind));
    expect_agreement(cleaned(generate_polygon(kind, 3000, 3)), contexts);
  }
}

/// Small triangles as holes in a Koch outline, each in the wedge of the outline's vertex k: from
/// that vertex itself (`touching`: the rings share a position) or from a little inside it.
Polygon koch_with_wedge_holes(std::size_t vertices, int seed, bool touching) {
  Polygon polygon = generate_polygon("koch", vertices, seed);
  const Ring outline = polygon[0];
  const std::size_t n = outline.size();
  const auto unit = [](Point v) {
    const double length = std::hypot(v.x, v.y);
    return Point{v.x / length, v.y / length};
  };
  // The outline is counterclockwise or clockwise as generated: the sign of its area says which.
  double area = 0;
  for (std::size_t i = 0; i < n; ++i)
    area += outline[i].x * outline[(i + 1) % n].y - outline[(i + 1) % n].x * outline[i].y;
  const double counterclockwise = area > 0 ? 1 : -1;
  for (std::size_t k = 0; k < n; k += n / 7) {
    const Point a = outline[(k + n - 1) % n], p = outline[k], c = outline[(k + 1) % n];
    const Point u = unit({a.x - p.x, a.y - p.y}), w = unit({c.x - p.x, c.y - p.y});
    // The bisector of the corner, turned inward where the corner is reflex.
    const double inward = (orient2d(a, p, c) > 0 ? 1 : -1) * counterclockwise;
    const Point d = unit({inward * (u.x + w.x), inward * (u.y + w.y)});
    const double r = 0.2 * std::hypot(c.x - p.x, c.y - p.y);
    const Point from = touching ? p : Point{p.x + 0.05 * r * d.x, p.y + 0.05 * r * d.y};
    const double turn = 0.15;  // radians either side of the bisector: inside a 60-degree tip
    const auto at = [&](double angle) {
      return Point{from.x + r * (d.x * std::cos(angle) - d.y * std::sin(angle)),
                   from.y + r * (d.x * std::sin(angle) + d.y * std::cos(angle))};
    };
    polygon.push_back({from, at(turn), at(-turn)});
  }
  return polygon;
}

/// Past chains_limit, on an outline the runs leave to the grid, the grid's pairs say whether a
/// position repeats, as every pair of edges does (before, the engine hashed every position
/// again): holes that touch the outline and holes that do not, at every thread count.
TEST(Simplicity, GridSaysWhetherRingsTouch) {
  const Contexts contexts;
  SimplicityCheck check;
  int touching = 0, apart = 0;
  for (int seed = 0; seed < 6; ++seed) {
    for (bool touches : {false, true}) {
      SCOPED_TRACE("seed " + std::to_string(seed) + (touches ? ", touching" : ", apart"));
      const CleanPolygon polygon = cleaned(koch_with_wedge_holes(3000, seed, touches));
      const Reference reference(polygon);
      ASSERT_FALSE(reference.smallest_violation()) << "the holes were meant to fit";
      ASSERT_EQ(reference.touching(), touches);
      for (const RunContext& ctx : contexts.list) {
        RunProfile profile;
        RunContext profiled = ctx;
        profiled.profile = &profile;
        const Verdict verdict = check.check(polygon, profiled, true);
        EXPECT_FALSE(verdict.violation);
        EXPECT_EQ(verdict.touching, touches ? Verdict::Touching::yes : Verdict::Touching::no);
        const bool on_grid =
            std::any_of(profile.phases.begin(), profile.phases.end(),
                        [](const auto& phase) { return phase.name == "check simplicity: cells"; });
        EXPECT_TRUE(on_grid) << "the grid decided";
      }
      ++(touches ? touching : apart);
    }
  }
  EXPECT_EQ(touching, 6);
  EXPECT_EQ(apart, 6);
}

/// Large enough for many parallel tasks and finer grids; a few vertices moved so that edges
/// cross far apart in the index order (the smallest must win whichever task finds it).
TEST(Simplicity, PerturbedLargePolygonsGiveTheSameAnswerAtEveryThreadCount) {
  const Contexts contexts;
  std::mt19937 rng(7);
  for (std::string_view kind : {"koch", "spiral", "comb", "hilbert"}) {
    Polygon polygon = generate_polygon(kind, 60000, 5);
    Ring& ring = polygon[0];
    for (int moved = 0; moved < 3; ++moved) {
      std::uniform_int_distribution<std::size_t> pick(0, ring.size() - 1);
      std::swap(ring[pick(rng)], ring[pick(rng)]);
    }
    SCOPED_TRACE(std::string(kind));
    expect_agreement(cleaned(polygon), contexts);
  }
}

/// A circle of radius 1,000 through n points, its radius rippled by `amplitude` with a period
/// of `period` points: runs of about period edges monotone in x, coast-like.
Ring rippled_circle(std::size_t n, double amplitude, std::size_t period) {
  Ring ring;
  for (std::size_t i = 0; i < n; ++i) {
    const double phase = static_cast<double>(i % period) / static_cast<double>(period);
    const double r = 1000 + amplitude * std::sin(2 * M_PI * phase);
    const double angle = 2 * M_PI * static_cast<double>(i) / static_cast<double>(n);
    ring.push_back({r * std::cos(angle), r * std::sin(angle)});
  }
  return ring;
}

/// The root grid's buckets are filled in a chunk of edges a partition (at least 8,192 edges
/// each): the same conflict at every partition and thread count, the counting in tasks.
TEST(Simplicity, RootGridInChunksFindsTheSameConflict) {
  constexpr std::size_t n = 50000;
  const Ring made = rippled_circle(n, 0.3, 10);
  const ThreadContexts contexts;
  for (int moved = 0; moved <= 2; ++moved) {
    Ring ring = made;
    for (int m = 0; m < moved; ++m) std::swap(ring[(m * 7919 + 17) % n], ring[n / 3 + 101 * m]);
    SCOPED_TRACE(std::to_string(moved) + " swaps");
    const CleanPolygon clean = cleaned(Polygon{ring});
    SimplicityCheck check;
    const auto one_chunk = check.find_violation(clean, RunContext{}, Method::grid_only);
    ASSERT_EQ(one_chunk.has_value(), moved > 0);
    for (const RunContext& given : contexts.list) {
      for (std::uint32_t partitions : {2u, 3u, 16u}) {
        RunProfile profile;
        RunContext ctx = given;
        ctx.partitions = partitions;
        ctx.profile = &profile;
        EXPECT_EQ(check.find_violation(clean, ctx, Method::grid_only), one_chunk)
            << partitions << " partitions";
        const auto count = std::find_if(profile.phases.begin(), profile.phases.end(), [](auto& p) {
          return p.name == "check simplicity: root grid count";
        });
        ASSERT_NE(count, profile.phases.end());
        EXPECT_EQ(count->task_seconds.size(), std::min<std::size_t>(partitions, n / 8192));
      }
    }
  }
}

/// check.check of `clean` on `given` at `partitions`: the smallest edge in a conflict is
/// `expected` (the grid's), and without one no edges touch. Returns the tasks of its pairs of
/// runs (0 where the runs did not decide).
std::size_t expect_runs_find(SimplicityCheck& check, const CleanPolygon& clean, RunContext given,
                             std::uint32_t partitions, std::optional<std::uint32_t> expected) {
  RunProfile profile;
  given.partitions = partitions;
  given.profile = &profile;
  const Verdict verdict = check.check(clean, given, true);
  EXPECT_EQ(verdict.violation, expected) << partitions << " partitions";
  if (!expected) {
    EXPECT_EQ(verdict.touching, Verdict::Touching::no) << partitions << " partitions";
  }
  const auto pairs = std::find_if(profile.phases.begin(), profile.phases.end(),
                                  [](auto& p) { return p.name == "check simplicity: run pairs"; });
  return pairs == profile.phases.end() ? 0 : pairs->task_seconds.size();
}

/// Up to two partitions a coast-like outline (here a circle with a ripple: runs of about 12
/// edges monotone in x) is checked by its runs, the pairs of runs in tasks: on 1, 2 and 4
/// threads, with 1 and 2 partitions, the smallest edge in any conflict as the grid alone finds
/// it, and no conflict (nor touching) on the polygon as made.
TEST(Simplicity, RunPairsInTasksFindTheSmallestConflict) {
  constexpr std::size_t n = 60000;
  const Ring made = rippled_circle(n, 0.2, 12);
  ASSERT_LE(x_reversals(cleaned(Polygon{made})) * 3, n) << "coast-like, as the test means";
  const ThreadContexts contexts;
  std::mt19937 rng(11);
  for (int moved = 0; moved <= 3; ++moved) {
    Ring ring = made;
    for (int m = 0; m < moved; ++m)
      std::swap(ring[(m * 7919 + 17) % n],
                ring[std::uniform_int_distribution<std::size_t>(n / 4, 3 * n / 4)(rng)]);
    SCOPED_TRACE(std::to_string(moved) + " swaps");
    const CleanPolygon clean = cleaned(Polygon{ring});
    SimplicityCheck check;
    const auto by_grid = check.find_violation(clean, RunContext{}, Method::grid_only);
    ASSERT_EQ(by_grid.has_value(), moved > 0);
    for (const RunContext& given : contexts.list) {
      for (std::uint32_t partitions : {1u, 2u}) {
        const std::size_t tasks = expect_runs_find(check, clean, given, partitions, by_grid);
        ASSERT_NE(tasks, 0u) << "decided by the runs";
        // On one partition one walk; in parts tasks of equal pair counts.
        EXPECT_EQ(tasks > 1, PEAR_HAS_THREADS && partitions > 1);
      }
    }
  }
}

/// The pairs of runs cut into tasks inside one run's pairs: an outer square, whose two runs
/// span every hole's in x and y, around a grid of octagons (two runs each). With a crossing near
/// the first runs, one near the last and none, at 2 to 64 partitions (up to 62 tasks of about
/// 4,100 pairs, the square's 6,400 pairs cut among them), the smallest edge in any conflict as
/// the grid alone finds it.
TEST(Simplicity, RunPairsCutInsideARunsPairsFindTheSmallestConflict) {
  constexpr int side = 40;
  Polygon made{Ring{{0, 0}, {100, 0}, {100, 100}, {0, 100}}};
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      Ring hole;
      for (int k = 8; k > 0; --k) {  // clockwise
        const double angle = k * std::numbers::pi / 4 + 0.1;
        hole.push_back(
            {2.5 * i + 1.25 + 0.8 * std::cos(angle), 2.5 * j + 1.25 + 0.8 * std::sin(angle)});
      }
      made.push_back(hole);
    }
  ASSERT_LE(x_reversals(cleaned(made)) * 3, cleaned(made).points.size()) << "the runs are tried";
  const ThreadContexts contexts;
  for (int variant = 0; variant < 3; ++variant) {
    Polygon polygon = made;
    if (variant == 1) polygon[1][2] = {1.25, -1};       // the first hole reaches below the square
    if (variant == 2) polygon.back()[4] = {99.5, 101};  // the last one above it
    SCOPED_TRACE("variant " + std::to_string(variant));
    const CleanPolygon clean = cleaned(polygon);
    SimplicityCheck check;
    const auto by_grid = check.find_violation(clean, RunContext{}, Method::grid_only);
    ASSERT_EQ(by_grid.has_value(), variant > 0);
    for (const RunContext& given : contexts.list)
      for (std::uint32_t partitions : {2u, 3u, 16u, 64u})
        ASSERT_NE(expect_runs_find(check, clean, given, partitions, by_grid), 0u)
            << "decided by the runs";
  }
}

/// The runs' preparation in parts (runs_in_parts.cpp) against the serial one: an outline with
/// runs of about 12 edges, vertical steps (edges of no direction in x, some at a ring's first
/// point) and three holes, of sizes that move the tasks' ranges, checked on one partition
/// serially and on two partitions in parts on 1, 2 and 4 threads: the same runs, the same
/// count of reversals (also in 1 to 64 tasks), and with vertices swapped far apart the
/// smallest conflict the grid finds; without, none and no touching. Both times the runs
/// decide (their pairs are walked), in parts where asked.
TEST(Simplicity, RunsPreparedInPartsDecideAsTheSerialRuns) {
  const auto ripple = [](std::size_t n, double radius, double x, bool clockwise) {
    Ring ring;
    for (std::size_t i = 0; i < n; ++i) {
      const double r = radius * (1 + 2e-4 * std::sin(2 * M_PI * static_cast<double>(i % 12) / 12));
      const double angle = (clockwise ? -2 : 2) * M_PI * static_cast<double>(i) / n;
      const Point p{x + r * std::cos(angle), r * std::sin(angle)};
      // Every 50th point is reached by a vertical step and a level one.
      if (i % 50 == 0 && !ring.empty()) ring.push_back({ring.back().x, p.y});
      ring.push_back(p);
    }
    // And the ring closes with one: its first edge comes after a vertical one.
    ring.push_back({ring.front().x, ring.back().y});
    return ring;
  };
  const ThreadContexts contexts;
  std::mt19937 rng(5);
  for (int moved = 0; moved <= 6; ++moved) {
    // Sizes that move the tasks' ranges against the runs.
    const std::size_t n = 60000 + 7 * static_cast<std::size_t>(moved);
    Polygon polygon{ripple(n, 1000, 0, false), ripple(4000, 100, -500, true),
                    ripple(4000 + moved, 100, 0, true), ripple(4000, 100, 500, true)};
    for (int m = 0; m < moved; ++m) {
      Ring& ring = polygon[static_cast<std::size_t>(m % 2 == 0 ? 0 : 1 + m % 3)];
      std::uniform_int_distribution<std::size_t> pick(0, ring.size() - 1);
      std::swap(ring[pick(rng)], ring[pick(rng)]);
    }
    SCOPED_TRACE(std::to_string(moved) + " swaps");
    const CleanPolygon clean = cleaned(polygon);
    ASSERT_LE(x_reversals(clean) * 3, clean.points.size()) << "runs long enough to be tried";
    for (std::size_t tasks = 1; tasks <= 64; ++tasks)
      ASSERT_EQ(x_reversals(clean, contexts.list.back(), tasks), x_reversals(clean)) << tasks;
    SimplicityCheck check;
    const auto by_grid = check.find_violation(clean, RunContext{}, Method::grid_only);
    ASSERT_EQ(by_grid.has_value(), moved > 0);
    const auto decide = [&](RunContext ctx, std::uint32_t partitions, bool in_parts) {
      RunProfile profile;
      ctx.partitions = partitions;
      ctx.profile = &profile;
      const Verdict verdict = check.check(clean, ctx, true);
      const auto ran = [&](std::string_view phase) {
        return std::any_of(profile.phases.begin(), profile.phases.end(),
                           [&](const auto& p) { return p.name == phase; });
      };
      EXPECT_TRUE(ran("check simplicity: run pairs")) << "the runs decided";
      EXPECT_EQ(ran("check simplicity: runs"), in_parts);
      return verdict;
    };
    const Verdict serial = decide(RunContext{}, 1, false);
    const std::size_t runs = check.runs();
    EXPECT_EQ(check.x_reversals_counted(), x_reversals(clean));
    EXPECT_EQ(serial.violation, by_grid);
    if (!by_grid) {
      EXPECT_EQ(serial.touching, Verdict::Touching::no);
    }
    for (const RunContext& given : contexts.list) {
      const Verdict parts = decide(given, 2, PEAR_HAS_THREADS != 0);
      EXPECT_EQ(parts.violation, serial.violation);
      EXPECT_EQ(parts.touching, serial.touching);
      EXPECT_EQ(check.runs(), runs) << "no run cut at a ring's first point";
      EXPECT_EQ(check.x_reversals_counted(), x_reversals(clean)) << "counted in parts";
    }
  }
}

/// Runs of four edges each (a snake: up the left in steps that zigzag in x, down the right),
/// twelve sizes, so that the border between the preparation's two tasks falls on every place
/// in a run, also where the direction turns: the same runs in parts as serially. (Their pairs
/// are too many here, all the left side's runs span one x-range: the grid decides.)
TEST(Simplicity, RunsPreparedInPartsCutWhereTheTasksMeet) {
  const auto zig = [](std::size_t i) { return static_cast<double>(4 - std::abs(int(i % 8) - 4)); };
  for (std::size_t extra = 0; extra < 12; ++extra) {
    const std::size_t m = 20000 + extra;
    Ring ring;
    for (std::size_t i = 0; i < m; ++i) ring.push_back({zig(i), static_cast<double>(i)});
    for (std::size_t i = m; i-- > 0;) ring.push_back({10 + zig(i), static_cast<double>(i)});
    const CleanPolygon clean = cleaned(Polygon{ring});
    SCOPED_TRACE(std::to_string(m) + " points a side");
    SimplicityCheck check;
    const Verdict serial = check.check(clean, RunContext{}, true);
    const std::size_t runs = check.runs();
    ASSERT_GT(runs, clean.points.size() / 5) << "runs of four edges, prepared";
    const Verdict parts = check.check(clean, RunContext{.partitions = 2}, true);
    EXPECT_EQ(check.runs(), runs);
    EXPECT_FALSE(parts.violation.has_value());
    EXPECT_EQ(parts.violation, serial.violation);
    EXPECT_EQ(parts.touching, serial.touching);
  }
}

TEST(Simplicity, SweepFindsOneCrossingAmongManyEdges) {
  // A random star (long edges packed close: the grid gives up) with two radii swapped.
  Polygon star = generate_polygon("star", 20000, 5);
  std::swap(star[0][100], star[0][9000]);
  const CleanPolygon clean = cleaned(star);
  const Reference reference(clean);
  SimplicityCheck check;
  for (Method method : {Method::automatic, Method::sweep_only}) {
    const auto found = check.find_violation(clean, RunContext{}, method);
    ASSERT_TRUE(found);
    EXPECT_TRUE(reference.involved(*found));
  }
}

/// At every partition count the runs go first; on a comb of 100,000 vertices (whose teeth are
/// long against the grid's cells: it would give up) they decide in parts: the same answer as
/// the sweep alone, valid or with two teeth crossed, and neither the grid nor a slab swept.
TEST(Simplicity, RunsDecideInPartsWhereTheGridWouldGiveUp) {
  Polygon comb = generate_polygon("comb", 100000, 3);
  SimplicityCheck check;
  for (bool crossed : {false, true}) {
    SCOPED_TRACE(crossed ? "crossed" : "valid");
    Polygon polygon = comb;
    if (crossed) std::swap(polygon[0][2001], polygon[0][70001]);
    const CleanPolygon clean = cleaned(polygon);
    RunProfile profile;
    const Verdict verdict =
        check.check(clean, RunContext{.partitions = 4, .profile = &profile}, true);
    const auto by_sweep = check.find_violation(clean, RunContext{}, Method::sweep_only);
    ASSERT_EQ(verdict.violation.has_value(), crossed);
    ASSERT_EQ(by_sweep.has_value(), crossed);
    if (crossed) {
      EXPECT_TRUE(check.unresolvable_conflict_at(clean, *verdict.violation, RunContext{}));
    } else {
      EXPECT_EQ(verdict.touching, Verdict::Touching::no);  // the runs know
    }
    std::vector<std::string> phases;
    for (const auto& phase : profile.phases) phases.push_back(phase.name);
    EXPECT_EQ(std::find(phases.begin(), phases.end(), "check simplicity: root grid count"),
              phases.end());
    // The runs, prepared in parts on partitions (serially in a build without threads).
    const char* runs = PEAR_HAS_THREADS ? "check simplicity: runs" : "check simplicity";
    EXPECT_NE(std::find(phases.begin(), phases.end(), runs), phases.end());
    EXPECT_EQ(std::find(phases.begin(), phases.end(), "check simplicity: sweep slabs"),
              phases.end());
  }
}

/// The T-junctions by brute force: a conflict when two edges cross, overlap or fold back; else
/// every (edge, vertex strictly inside it), sorted along the edge, the smallest vertex per point.
TJunctionSearch t_junctions_by_brute_force(const CleanPolygon& polygon) {
  const auto& pts = polygon.points;
  std::vector<std::uint32_t> next(pts.size());
  for (std::size_t r = 0; r < polygon.ring_count(); ++r)
    for (std::uint32_t i = polygon.ring_starts[r]; i < polygon.ring_starts[r + 1]; ++i)
      next[i] = i + 1 < polygon.ring_starts[r + 1] ? i + 1 : polygon.ring_starts[r];
  const auto inside = [&](std::uint32_t v, std::uint32_t e) {
    return orient2d(pts[e], pts[next[e]], pts[v]) == 0 && pts[v] != pts[e] &&
           pts[v] != pts[next[e]] && between(pts[v], pts[e], pts[next[e]]);
  };
  TJunctionSearch search;
  for (std::uint32_t e = 0; e < pts.size(); ++e) {
    for (std::uint32_t f = e + 1; f < pts.size(); ++f) {
      const Point &a = pts[e], &b = pts[next[e]], &c = pts[f], &d = pts[next[f]];
      if (!segments_violate(a, b, c, d)) continue;
      const bool collinear = orient2d(a, b, c) == 0 && orient2d(a, b, d) == 0;
      const bool neighbours = next[e] == f || next[f] == e;
      bool t = false;
      for (auto [v, edge] :
           {std::pair(f, e), std::pair(next[f], e), std::pair(e, f), std::pair(next[e], f)})
        if (!collinear && !neighbours && inside(v, edge)) {
          search.junctions.push_back({edge, v});
          t = true;
        }
      if (!t) search.conflict = std::min(search.conflict.value_or(e), e);
    }
  }
  if (search.conflict) search.junctions.clear();
  std::sort(search.junctions.begin(), search.junctions.end(), [&](auto s, auto t) {
    if (s.edge != t.edge) return s.edge < t.edge;
    const Point &p = pts[s.vertex], &q = pts[t.vertex], &a = pts[s.edge];
    const double along_p = std::abs(p.x - a.x) + std::abs(p.y - a.y);  // exact on small grids
    const double along_q = std::abs(q.x - a.x) + std::abs(q.y - a.y);
    return along_p != along_q ? along_p < along_q : s.vertex < t.vertex;
  });
  search.junctions.erase(std::unique(search.junctions.begin(), search.junctions.end(),
                                     [&](auto s, auto t) {
                                       return s.edge == t.edge && pts[s.vertex] == pts[t.vertex];
                                     }),
                         search.junctions.end());
  return search;
}

/// A square with rectangular holes and triangular holes whose apex lies on a lattice point of
/// an edge of the square or of a rectangle, pointing away from it: T-junctions of every kind,
/// sometimes overlapping each other (conflicts).
CleanPolygon touching_holes(std::mt19937& rng) {
  constexpr int size = 12;
  std::uniform_int_distribution<int> coordinate(1, size - 3), extent(1, 3), pick(0, 99);
  Polygon polygon = {{{0, 0}, {size, 0}, {size, size}, {0, size}}};
  const int holes = 1 + pick(rng) % 4;
  for (int k = 0; k < holes; ++k) {
    if (pick(rng) < 40) {
      const double x = coordinate(rng), y = coordinate(rng), w = extent(rng), h = extent(rng);
      polygon.push_back({{x, y}, {x, y + h}, {x + w, y + h}, {x + w, y}});
      continue;
    }
    // An edge of the square or of a hole, a lattice point inside it, the side away from it.
    const Ring& ring = polygon[static_cast<std::size_t>(pick(rng)) % polygon.size()];
    const std::size_t i = static_cast<std::size_t>(pick(rng)) % ring.size();
    const Point a = ring[i], b = ring[(i + 1) % ring.size()];
    const double length = std::abs(b.x - a.x) + std::abs(b.y - a.y);
    if (length < 2 || ring.size() != 4) continue;
    const double t = 1 + pick(rng) % static_cast<int>(length - 1);
    const Point d = {(b.x - a.x) / length, (b.y - a.y) / length};
    const Point apex = {a.x + t * d.x, a.y + t * d.y};
    // The square runs counterclockwise (inside on the left), the rectangles clockwise (their
    // outside on the left): either way the triangle goes to the left of a -> b.
    const Point left = {-d.y, d.x};
    polygon.push_back({apex,
                       {apex.x + 2 * left.x + d.x, apex.y + 2 * left.y + d.y},
                       {apex.x + 2 * left.x - d.x, apex.y + 2 * left.y - d.y}});
  }
  return cleaned(polygon);
}

/// find_t_junctions finds every T-junction (the sweep goes on past touching edges) and a
/// conflict exactly when one exists, the same at 1, 2 and 4 threads and in three slabs.
TEST(Simplicity, TJunctionsAgreeWithBruteForce) {
  std::mt19937 rng(2024);
  const Contexts contexts;
  SimplicityCheck check;
  int junctions = 0, conflicts = 0;
  for (int round = 0; round < 4000; ++round) {
    const int rings = 1 + round % 3;
    const CleanPolygon polygon =
        round % 2 ? touching_holes(rng) : random_polygon(rng, rings, 3 + round % 9, 2 + round % 6);
    if (polygon.ring_count() == 0 || polygon.points.size() < 3) continue;
    SCOPED_TRACE("round " + std::to_string(round));
    const TJunctionSearch expected = t_junctions_by_brute_force(polygon);
    for (const RunContext& ctx : contexts.list) {
      const Method method = &ctx == &contexts.list[1] ? Method::sweep_only : Method::automatic;
      const TJunctionSearch found = check.find_t_junctions(polygon, ctx, method);
      ASSERT_EQ(found.conflict.has_value(), expected.conflict.has_value());
      if (found.conflict) {
        EXPECT_TRUE(Reference(polygon).involved(*found.conflict));
        continue;
      }
      ASSERT_EQ(found.junctions.size(), expected.junctions.size());
      for (std::size_t k = 0; k < found.junctions.size(); ++k) {
        EXPECT_EQ(found.junctions[k].edge, expected.junctions[k].edge);
        EXPECT_EQ(found.junctions[k].vertex, expected.junctions[k].vertex);
      }
    }
    (expected.conflict ? conflicts : junctions) += expected.conflict || !expected.junctions.empty();
    if (::testing::Test::HasFailure()) break;
  }
  EXPECT_GT(junctions, 500) << "T-junctions only";  // both outcomes were exercised
  EXPECT_GT(conflicts, 500);
}

/// A polygon past chains_limit made of long runs monotone in x: a shell whose top is one run
/// of `top` vertices (x falling by 2, y in [60, 100]) over a flat bottom, and small triangular
/// holes below, 4 apart. `flaw` 0 leaves it simple; 1 lifts a hole's apex onto a top vertex
/// (touching, still simple); 2 drops a top vertex below the bottom (crossings); 3 puts a
/// vertical fold-back into the top; 4 lifts a hole's apex above the top (crossing the shell);
/// 5 puts a hole's corner inside the bottom edge (a T-junction).
CleanPolygon long_runs(std::mt19937& rng, int top, int holes, int flaw) {
  std::uniform_int_distribution<int> height(60, 100);
  CleanPolygon polygon;
  auto& pts = polygon.points;
  const double width = 2.0 * top;
  pts.push_back({0, 0});
  pts.push_back({width, 0});
  for (int i = 0; i < top; ++i) pts.push_back({width - 2.0 * i, double(height(rng))});
  const std::size_t pick = 3 + rng() % static_cast<std::size_t>(top - 6);
  if (flaw == 2) pts[pick].y = -5;
  if (flaw == 3) {
    const Point at = pts[pick];
    pts.insert(pts.begin() + static_cast<std::ptrdiff_t>(pick) + 1,
               {Point{at.x, at.y + 7}, Point{at.x, at.y + 3}});
  }
  polygon.ring_starts = {0, static_cast<std::uint32_t>(pts.size())};
  const int flawed = static_cast<int>(rng() % static_cast<std::size_t>(holes));
  for (int h = 0; h < holes; ++h) {
    const double x = 4.0 * (1 + h * (top / 2 - 2) / holes);
    Point apex{x + 2, 20};
    if (h == flawed && flaw == 1) apex = pts[2 + static_cast<std::size_t>((width - apex.x) / 2)];
    if (h == flawed && flaw == 4) apex.y = 120;
    pts.push_back({x + 1, h == flawed && flaw == 5 ? 0.0 : 10.0});
    pts.push_back(apex);
    pts.push_back({x + 3, 10});
    polygon.ring_starts.push_back(static_cast<std::uint32_t>(pts.size()));
  }
  polygon.original.resize(pts.size());
  std::iota(polygon.original.begin(), polygon.original.end(), 0u);
  polygon.ring_source.resize(polygon.ring_count());
  std::iota(polygon.ring_source.begin(), polygon.ring_source.end(), 0u);
  return polygon;
}

/// Past chains_limit the runs decide where they stay cheap: the smallest edge in a conflict,
/// and whether the rings touch, exactly as every pair of edges says; where a ring folds back,
/// the grid's search. The partitions change nothing of it.
TEST(Simplicity, RunsPastChainsLimitAgreeWithReferenceAndGrid) {
  std::mt19937 rng(77);
  SimplicityCheck check;
  std::array<int, 6> seen{};
  for (int round = 0; round < 48; ++round) {
    const int flaw = round % 6;
    const CleanPolygon polygon = long_runs(rng, 400 + 97 * round, 8 + round, flaw);
    ASSERT_GT(polygon.points.size(), SimplicityCheck::chains_limit);
    SCOPED_TRACE("round " + std::to_string(round));
    const Reference reference(polygon);
    const auto expected = reference.smallest_violation();
    ASSERT_EQ(expected.has_value(), flaw >= 2) << "the flaw is what the test meant";
    const Verdict verdict = check.check(polygon, RunContext{}, true);
    const auto by_grid = check.find_violation(polygon, RunContext{});
    EXPECT_EQ(verdict.violation, flaw == 3 ? by_grid : expected);
    ASSERT_EQ(verdict.violation.has_value(), expected.has_value());
    if (expected) {
      EXPECT_TRUE(reference.involved(*verdict.violation));
    } else {
      EXPECT_EQ(verdict.touching, flaw == 1 ? Verdict::Touching::yes : Verdict::Touching::no);
      EXPECT_EQ(reference.touching(), flaw == 1);
    }
    for (std::uint32_t partitions : {2u, 4u, 16u}) {
      const Verdict in_parts = check.check(polygon, RunContext{.partitions = partitions}, true);
      EXPECT_EQ(in_parts.violation, verdict.violation) << partitions << " partitions";
      EXPECT_EQ(in_parts.touching, verdict.touching) << partitions << " partitions";
    }
    ++seen[static_cast<std::size_t>(flaw)];
  }
  for (int count : seen) EXPECT_EQ(count, 8);
}

/// Without the check, past few_edges_limit, whether rings touch is whether a position repeats:
/// the same answer as the reference's every pair of edges, crossing or not, both ways.
TEST(Simplicity, TouchingOnlyAgreesWithReferenceBetweenTheStrategies) {
  std::mt19937 rng(31);
  SimplicityCheck check;
  int touching = 0, apart = 0;
  for (int round = 0; round < 300; ++round) {
    const CleanPolygon polygon =
        random_polygon(rng, 1 + round % 3, 380 / (1 + round % 3), round % 2 ? 60 : 100000);
    const std::size_t n = polygon.points.size();
    if (n <= SimplicityCheck::few_edges_limit || n > SimplicityCheck::chains_limit) continue;
    SCOPED_TRACE("round " + std::to_string(round));
    const bool expected = Reference(polygon).touching();
    EXPECT_EQ(check.check(polygon, RunContext{}, false).touching,
              expected ? Verdict::Touching::yes : Verdict::Touching::no);
    ++(expected ? touching : apart);
  }
  EXPECT_GT(touching, 30);  // both outcomes were exercised
  EXPECT_GT(apart, 30);
}

/// unresolvable_conflict_at agrees with the reference on the edge find_violation reports, and
/// where it says no split helps, the T-junction sweep it spares stops at a conflict too (the
/// engine's answer, not_simple, is the same either way).
TEST(Simplicity, UnresolvableConflictAgreesWithReferenceAndSweep) {
  std::mt19937 rng(2026);
  SimplicityCheck check;
  int unresolvable = 0, resolvable = 0;
  for (int round = 0; round < 4000; ++round) {
    const CleanPolygon polygon =
        round % 2 ? touching_holes(rng)
                  : random_polygon(rng, 1 + round % 3, 3 + round % 9, 2 + round % 6);
    if (polygon.ring_count() == 0 || polygon.points.size() < 3) continue;
    const auto violation = check.find_violation(polygon, RunContext{});
    if (!violation) continue;
    SCOPED_TRACE("round " + std::to_string(round));
    const bool expected = Reference(polygon).unresolvable_at(*violation);
    ASSERT_EQ(check.unresolvable_conflict_at(polygon, *violation, RunContext{}), expected);
    if (expected) {
      EXPECT_TRUE(check.find_t_junctions(polygon, RunContext{}).conflict.has_value());
    }
    ++(expected ? unresolvable : resolvable);
  }
  EXPECT_GT(unresolvable, 300);  // both outcomes were exercised
  EXPECT_GT(resolvable, 300);
}

/// Every corpus polygon up to 400k vertices (the largest coastline, 1.5M, is left to the
/// engine's coast suite): the automatic check finds nothing in what the MANIFEST calls valid,
/// agrees with the reference (up to 50k vertices), names an edge that is in a conflict, and
/// gives the same answer at 1, 2 and 4 threads.
TEST(Simplicity, CorpusAgreesWithReferenceAndManifest) {
  std::vector<corpus::Folder> folders;
  for (const char* name : {"earcut", "countries", "glyphs", "synthetic", "counties", "coast"}) {
    folders.push_back(corpus::read_folder(corpus::shared_root(), name));
    PEAR_SKIP_IF_MISSING(folders.back());
  }
  const Contexts contexts;
  SimplicityCheck check;
  std::size_t checked = 0, found = 0;
  for (const corpus::Folder& folder : folders) {
    for (const corpus::File& file : folder.files) {
      if (file.vertices > 400'000) continue;
      PEAR_SKIP_IF_MISSING(file);
      for (const Polygon& polygon : testing::read_polygons(file)) {
        const CleanPolygon clean = cleaned(polygon);
        if (clean.ring_count() == 0) continue;
        SCOPED_TRACE(file.name());
        const auto violation = check.find_violation(clean, contexts.list[0]);
        EXPECT_TRUE(!file.valid || !violation) << "edge " << violation.value_or(0);
        const Reference reference(clean);
        // The reference is slow on a long-edged star; above this, the MANIFEST decides.
        const bool small = file.vertices <= 50'000;
        EXPECT_TRUE(!small || violation.has_value() == reference.smallest_violation().has_value());
        EXPECT_TRUE(!violation || reference.involved(*violation));
        EXPECT_EQ(check.find_violation(clean, contexts.list[1]), violation);
        EXPECT_EQ(check.find_violation(clean, contexts.list[2]), violation);
        ++checked;
        found += violation.has_value();
      }
    }
  }
  EXPECT_GT(checked, 3000u);
  EXPECT_GT(found, 5u);  // the invalid fixtures were caught
}

TEST(Simplicity, SlabBordersGiveEachSlabAboutAsManyEdges) {
  // An edge counts in every slab its x-range meets (what a slab's sweep costs). On a star,
  // whose long edges cross many borders, quantiles of the left ends gave 12 slabs 8,332 to
  // 19,890 edges (the largest 1.41x the mean); the borders must keep each within 15% of it.
  const Polygon star = generate_polygon("star", 100000, 1);
  const Ring& ring = star.front();
  RingEdges edges;
  edges.next.resize(ring.size());
  edges.boxes.resize(ring.size());
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point a = ring[i], b = ring[(i + 1) % ring.size()];
    edges.boxes[i] = {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x),
                      std::max(a.y, b.y)};
  }
  const ThreadContexts contexts;
  for (std::uint32_t slabs : {2u, 5u, 12u, 16u}) {
    SCOPED_TRACE(std::to_string(slabs) + " slabs");
    const std::vector<double> borders = slab_borders(edges, slabs);
    ASSERT_EQ(borders.size(), slabs - 1);
    // The sample is read and sorted in tasks: the same borders on any threads and partitions.
    for (RunContext ctx : contexts.list)
      for (std::uint32_t partitions : {3u, 16u}) {
        ctx.partitions = partitions;
        EXPECT_EQ(slab_borders(edges, slabs, ctx), borders) << partitions << " partitions";
      }
    EXPECT_TRUE(std::is_sorted(borders.begin(), borders.end()));
    const auto slab_of = [&](double x) {
      return static_cast<std::size_t>(std::upper_bound(borders.begin(), borders.end(), x) -
                                      borders.begin());
    };
    std::vector<std::size_t> count(slabs, 0);
    for (std::uint32_t e = 0; e < edges.size(); ++e)
      for (std::size_t s = slab_of(edges.boxes[e].x0); s <= slab_of(edges.boxes[e].x1); ++s)
        ++count[s];
    const double mean =
        static_cast<double>(std::accumulate(count.begin(), count.end(), std::size_t{0})) / slabs;
    EXPECT_LE(static_cast<double>(*std::max_element(count.begin(), count.end())), 1.15 * mean);
    EXPECT_GE(static_cast<double>(*std::min_element(count.begin(), count.end())), 0.85 * mean);
  }
}

}  // namespace
}  // namespace pear::detail
