// Divide-and-conquer's first cut in parts (src/parallel/split_pieces.cpp,
// PieceSplitter::split_in_parts): the whole bridged cycle cut along one line by tasks must
// give split()'s pieces, corner for corner, and its Steiner points in the same order, at every
// thread and partition count; where split() fails (crossings that do not pair), so must it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../earclip/boundary_support.hpp"
#include "clean/clean.hpp"
#include "earclip/bridge.hpp"
#include "parallel/split_pieces.hpp"
#include "pear/config.hpp"
#include "pear/generate.hpp"
#include "run_contexts.hpp"

namespace pear::detail {
namespace {

/// The polygon cleaned and bridged, and its one cycle as a piece of node corners.
struct Cycle {
  Boundary boundary;
  Pieces piece;
};

Cycle bridged_cycle(const Polygon& polygon) {
  const CleanPolygon clean = testing::cleaned(polygon);
  Cycle cycle{testing::rings_as_cycles(clean), {}};
  HoleBridger bridger;
  EXPECT_TRUE(bridger.join(clean, cycle.boundary).empty());
  std::uint32_t v = 0;
  do {
    cycle.piece.corners.push_back(v);
    v = cycle.boundary.next[v];
  } while (v != 0 && cycle.piece.corners.size() <= cycle.boundary.size());
  cycle.piece.close_piece();
  return cycle;
}

/// The x of the cycle's corner at `share` of its x order: where a split line goes after.
double x_at(const Cycle& cycle, double share) {
  std::vector<double> xs;
  for (PieceCorner c : cycle.piece.corners) xs.push_back(cycle.boundary.pos[corner_index(c)].x);
  std::sort(xs.begin(), xs.end());
  return xs[static_cast<std::size_t>(share * static_cast<double>(xs.size() - 1))];
}

void expect_same_cut(const Polygon& polygon) {
  const Cycle cycle = bridged_cycle(polygon);
  for (double share : {0.25, 0.5, 0.9}) {
    SCOPED_TRACE("line after the x at " + std::to_string(share));
    std::vector<SplitLine> serial_lines(1);
    serial_lines[0].after = x_at(cycle, share);
    Pieces left, right;
    PieceSplitter splitter;
    const bool ok = splitter.split(cycle.boundary, serial_lines, 0, cycle.piece, left, right);
    ASSERT_TRUE(ok);
    ASSERT_GT(serial_lines[0].steiner.size(), 0u);
    for_each_context({1u, 2u, 4u}, {2u, 5u, 16u}, [&](const RunContext& ctx, const RunProfile&) {
      std::vector<SplitLine> lines(1);
      lines[0].after = serial_lines[0].after;
      Pieces in_left, in_right;
      PieceSplitter parts;
      EXPECT_TRUE(
          parts.split_in_parts(cycle.boundary, lines, 0, cycle.piece, in_left, in_right, ctx));
      EXPECT_EQ(lines[0].x, serial_lines[0].x);
      EXPECT_EQ(in_left.corners, left.corners);
      EXPECT_EQ(in_left.starts, left.starts);
      EXPECT_EQ(in_right.corners, right.corners);
      EXPECT_EQ(in_right.starts, right.starts);
      ASSERT_EQ(lines[0].steiner.size(), serial_lines[0].steiner.size());
      for (std::size_t i = 0; i < lines[0].steiner.size(); ++i) {
        EXPECT_EQ(lines[0].steiner[i].from, serial_lines[0].steiner[i].from);
        EXPECT_EQ(lines[0].steiner[i].to, serial_lines[0].steiner[i].to);
        EXPECT_TRUE(lines[0].steiner[i].pos == serial_lines[0].steiner[i].pos);
      }
    });
  }
}

TEST(SplitInParts, RandomPolygon) {
  expect_same_cut(generate_polygon("random", 30000, 7));
}

TEST(SplitInParts, RandomHolesBridged) {
  expect_same_cut(generate_polygon("random-holes", 30000, 3));
}

TEST(SplitInParts, CombTeethCrossTheLine) {
  expect_same_cut(generate_polygon("comb", 20000, 1));
}

TEST(SplitInParts, Spiral) {
  expect_same_cut(generate_polygon("spiral", 20000, 1));
}

TEST(SplitInParts, PhasesAreTasks) {
  const Cycle cycle = bridged_cycle(generate_polygon("random", 30000, 7));
  for_each_context({2u}, {16u}, [&](const RunContext& ctx, const RunProfile& profile) {
    std::vector<SplitLine> lines(1);
    lines[0].after = x_at(cycle, 0.5);
    Pieces left, right;
    PieceSplitter splitter;
    ASSERT_TRUE(splitter.split_in_parts(cycle.boundary, lines, 0, cycle.piece, left, right, ctx));
    for (const char* name : {"split: place", "split: crossings", "split: pieces"}) {
      std::size_t tasks = 0;
      for (const auto& phase : profile.phases)
        if (phase.name == name) tasks = std::max(tasks, phase.task_seconds.size());
      // A build without threads keeps one path: split(), no phases of its own.
      EXPECT_EQ(tasks > 1, PEAR_HAS_THREADS != 0) << name;
    }
  });
}

}  // namespace
}  // namespace pear::detail
