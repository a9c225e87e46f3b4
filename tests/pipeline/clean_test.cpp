// Cleaning a large input in parallel passes (src/clean/clean.cpp, clean_in_parts) must give what
// the serial pass gives, to the point and the diagnostic: on inputs of several chunks whose
// repeated points, closing points, rings and reversals fall on the chunks' borders, at 1, 2 and
// 4 threads and on one thread with 4 partitions. Inputs it does not handle (a spike, a ring with
// no area, an empty ring, a coordinate that is not finite) must be handed to the serial pass,
// with the same result and the same named diagnostics. The same whether the points come as
// one array, as interleaved coordinates or as each ring's own array.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "clean/clean.hpp"
#include "pear/config.hpp"
#include "pear/generate.hpp"
#include "pipeline/threading.hpp"
#include "run_contexts.hpp"

namespace pear::detail {
namespace {

constexpr std::size_t chunk = pear::detail::clean_chunk;

struct Input {
  std::vector<Point> points;
  std::vector<std::uint32_t> offsets{0};

  void add_ring(const Ring& ring) {
    points.insert(points.end(), ring.begin(), ring.end());
    offsets.push_back(static_cast<std::uint32_t>(points.size()));
  }
};

Input flat(const Polygon& polygon) {
  Input input;
  for (const Ring& ring : polygon) input.add_ring(ring);
  return input;
}

/// A polygon of 100,000 vertices with holes, made dirty where the chunks meet: points repeated
/// across the borders, every ring closed by its first point (some twice), the outer ring
/// clockwise and every other hole counterclockwise (both reversed by cleaning).
Input dirty_polygon() {
  Polygon polygon = generate_polygon("random-holes", 100000, 11);
  std::reverse(polygon[0].begin(), polygon[0].end());
  for (std::size_t h = 1; h < polygon.size(); h += 2)
    std::reverse(polygon[h].begin(), polygon[h].end());
  for (std::size_t r = 0; r < polygon.size(); ++r) {
    polygon[r].push_back(polygon[r].front());
    if (r % 3 == 0) polygon[r].push_back(polygon[r].front());
  }
  Input input = flat(polygon);
  // Repeats at and around each chunk border, wherever they fall (inside a ring or at its start).
  for (std::size_t border = chunk; border + 2 < input.points.size(); border += chunk)
    for (std::size_t i : {border - 1, border, border + 1}) input.points[i] = input.points[i - 1];
  return input;
}

struct Cleaned {
  Status status;
  CleanPolygon clean;
  std::vector<Diagnostic> diagnostics;
  std::vector<std::string> phases;
};

/// How the caller hands the points over: one array, interleaved coordinates, or each ring's
/// own array (pear::Polygon's rings, read where they are).
enum class Layout { points, coordinates, rings };

Cleaned clean(const Input& input, const RunContext& context, std::size_t in_parts_from,
              Layout layout = Layout::points) {
  Cleaned out;
  RunProfile profile;
  RunContext ctx = context;
  ctx.profile = &profile;
  std::vector<double> xy;
  for (const Point& p : input.points) xy.insert(xy.end(), {p.x, p.y});
  // Each ring copied to an array of its own, so that no ring follows another in memory.
  std::vector<std::vector<Point>> rings;
  std::vector<std::span<const Point>> spans;
  for (std::size_t r = 0; r + 1 < input.offsets.size(); ++r) {
    const auto first = input.points.begin() + input.offsets[r];
    rings.emplace_back(first, input.points.begin() + input.offsets[r + 1]);
  }
  for (const auto& ring : rings) spans.emplace_back(ring);
  const InputPolygon in =
      layout == Layout::points        ? InputPolygon(PolygonView{input.points, input.offsets})
      : layout == Layout::coordinates ? InputPolygon(CoordinateView{xy, input.offsets})
                                      : InputPolygon(RingSpans{spans, input.offsets});
  out.status = clean_polygon(in, out.clean, out.diagnostics, ctx, in_parts_from);
  for (const auto& phase : profile.phases) out.phases.push_back(phase.name);
  return out;
}

/// The same status and diagnostics; the same clean polygon where it is one (an invalid input
/// leaves it half made).
void expect_same(const Cleaned& got, const Cleaned& expected) {
  EXPECT_EQ(got.status, expected.status);
  if (expected.status == Status::ok) {
    EXPECT_TRUE(got.clean.points == expected.clean.points);
    EXPECT_TRUE(got.clean.original == expected.clean.original);
    EXPECT_EQ(got.clean.ring_starts, expected.clean.ring_starts);
    EXPECT_EQ(got.clean.ring_source, expected.clean.ring_source);
  }
  ASSERT_EQ(got.diagnostics.size(), expected.diagnostics.size());
  for (std::size_t i = 0; i < got.diagnostics.size(); ++i) {
    EXPECT_EQ(got.diagnostics[i].issue, expected.diagnostics[i].issue);
    EXPECT_EQ(got.diagnostics[i].ring, expected.diagnostics[i].ring);
    EXPECT_EQ(got.diagnostics[i].vertex, expected.diagnostics[i].vertex);
  }
}

bool has(const std::vector<std::string>& phases, const char* name) {
  return std::find(phases.begin(), phases.end(), name) != phases.end();
}

/// Threads 1, 2 and 4 with as many partitions, and one thread with 4 partitions.
struct Contexts : ThreadContexts {
  Contexts() : ThreadContexts(true) { list.push_back(RunContext{.partitions = 4}); }
};

/// `parts`: whether the parallel passes must have decided where they may run (more than one
/// thread or partition); else the serial pass must have.
void expect_as_serial(const Input& input, bool parts) {
  const Cleaned expected = clean(input, RunContext{}, std::numeric_limits<std::size_t>::max());
  // The inputs left to the serial pass are those it has something to say about.
  EXPECT_EQ(expected.diagnostics.empty(), parts);
  const Contexts contexts;
  for (const RunContext& ctx : contexts.list) {
    SCOPED_TRACE("partitions " + std::to_string(ctx.partitions));
    // The same from interleaved coordinates and from each ring's own array, whose chunks start
    // inside rings and at their borders alike.
    for (Layout layout : {Layout::points, Layout::coordinates, Layout::rings}) {
      SCOPED_TRACE(layout == Layout::rings         ? "rings' arrays"
                   : layout == Layout::coordinates ? "coordinates"
                                                   : "points");
      const Cleaned got = clean(input, ctx, 1000, layout);
      expect_same(got, expected);
      // A build without threads always cleans serially (the same result).
      const bool decided_in_parts = PEAR_HAS_THREADS && parts && ctx.partitions > 1;
      EXPECT_EQ(has(got.phases, "clean"), !decided_in_parts);
      if (decided_in_parts) {
        EXPECT_TRUE(has(got.phases, "clean: copy"));
      }
    }
  }
}

TEST(CleanInParts, DirtyPolygonOfManyChunksAsSerially) {
  const Input input = dirty_polygon();
  ASSERT_GT(input.points.size(), 3 * chunk);
  expect_as_serial(input, true);
  // What the parallel passes had to do: drop repeats, reverse the outer ring and every other
  // hole (the serial pass is the reference for the rest).
  const Cleaned cleaned = clean(input, RunContext{.partitions = 4}, 1000);
  EXPECT_LT(cleaned.clean.points.size(), input.points.size());
  EXPECT_EQ(cleaned.clean.ring_count(), input.offsets.size() - 1);
}

TEST(CleanInParts, OneLargeRingAsSerially) {
  Input input = flat(generate_polygon("koch", 200000, 3));
  std::reverse(input.points.begin(), input.points.end());
  expect_as_serial(input, true);
}

TEST(CleanInParts, WhatTheSerialPassNamesIsLeftToIt) {
  const Input dirty = dirty_polygon();
  const std::size_t hole = 5, at = dirty.offsets[hole] + 2;
  {
    SCOPED_TRACE("a spike in a hole");
    Input input = dirty;
    const Point tip = input.points[at], back = input.points[at - 1];
    input.points.insert(input.points.begin() + static_cast<std::ptrdiff_t>(at) + 1,
                        {Point{2 * tip.x - back.x, 2 * tip.y - back.y}, tip});
    for (std::size_t r = hole + 1; r < input.offsets.size(); ++r) input.offsets[r] += 2;
    expect_as_serial(input, false);
  }
  {
    SCOPED_TRACE("a hole with no area");
    Input input = dirty;
    for (std::uint32_t i = dirty.offsets[hole]; i < dirty.offsets[hole + 1]; ++i)
      input.points[i] = {dirty.points[dirty.offsets[hole]].x + (i % 7), 0.0};
    expect_as_serial(input, false);
  }
  {
    SCOPED_TRACE("an empty ring");
    Input input = dirty;
    input.offsets.insert(input.offsets.begin() + 3, input.offsets[2]);
    expect_as_serial(input, false);
  }
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), 1e300}) {
    SCOPED_TRACE("coordinate " + std::to_string(bad));
    Input input = dirty;
    input.points[2 * chunk + 5].y = bad;
    expect_as_serial(input, false);
    EXPECT_EQ(clean(input, RunContext{.partitions = 4}, 1000).status, Status::invalid_input);
  }
}

}  // namespace
}  // namespace pear::detail
