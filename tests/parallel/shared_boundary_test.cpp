// SharedBoundary::start (src/parallel/shared_boundary.cpp), an internal: the cycle's order, the
// live marks and the hashed nodes it finds in parallel parts from the runs of consecutive node
// numbers must be what a walk node by node finds, at every thread and partition count, on
// boundaries made of rings and bridges (runs), scrambled ones (the walk node by node) and ones
// with dead nodes and a second cycle beside the one walked.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "parallel/shared_boundary.hpp"
#include "pear/config.hpp"
#include "run_contexts.hpp"

namespace pear::detail {
namespace {

/// A ring of `count` nodes on a circle (counterclockwise, or clockwise for a hole), linked in
/// node order.
std::uint32_t add_ring(Boundary& b, std::uint32_t count, Point center, double radius, bool hole) {
  const auto first = b.size();
  for (std::uint32_t i = 0; i < count; ++i) {
    const double angle = (hole ? -2.0 : 2.0) * M_PI * i / count;
    // A wobble makes about a third of the corners reflex.
    const double r = radius * (i % 3 == 0 ? 0.9 : 1.0);
    b.add({center.x + r * std::cos(angle), center.y + r * std::sin(angle)}, b.size());
  }
  for (std::uint32_t i = 0; i < count; ++i) b.link(first + i, first + (i + 1) % count);
  return first;
}

/// The cycle through `entry`, node by node.
std::vector<std::uint32_t> walk(const Boundary& b, std::uint32_t entry) {
  std::vector<std::uint32_t> order;
  std::uint32_t v = entry;
  do {
    order.push_back(v);
    v = b.next[v];
  } while (v != entry);
  return order;
}

/// Whether start() takes the runs where jumps are few: without threads it always walks node by
/// node (the runs would only add code).
constexpr bool takes_runs = PEAR_HAS_THREADS != 0;

/// Whether start() took the runs (its "classify: order" phase) or walked node by node.
bool took_runs(const RunProfile& profile) {
  return std::any_of(profile.phases.begin(), profile.phases.end(),
                     [](const auto& phase) { return phase.name == "classify: order"; });
}

/// start() at 1, 2 and 8 threads and 1, 2, 3 and 16 partitions against the walk: the same
/// order, alive exactly on the cycle, hashed exactly its reflex nodes and pinches, every owner
/// a landmark and every stamp 0. Returns whether the runs were taken (the same every time).
bool expect_start_walks(Boundary& b, std::uint32_t entry) {
  const std::vector<std::uint32_t> expected = walk(b, entry);
  std::vector<std::uint8_t> on_cycle(b.size(), 0);
  for (std::uint32_t v : expected) on_cycle[v] = 1;
  std::vector<int> runs_taken;
  for_each_context(
      {1u, 2u, 8u}, {1u, 2u, 3u, 16u}, [&](const RunContext& ctx, RunProfile& profile) {
        SharedBoundary s;
        EXPECT_EQ(s.start(b, entry, ctx), expected.size());
        EXPECT_TRUE(std::equal(s.order.begin(), s.order.end(), expected.begin(), expected.end()));
        std::size_t wrong = 0;
        for (std::uint32_t v = 0; v < b.size(); ++v) {
          const bool reflex = on_cycle[v] && (s.pinch[v] || b.turn(v) < 0);
          const bool right = s.alive[v] == on_cycle[v] && s.hashed[v] == (reflex ? 1 : 0) &&
                             s.owner[v] == SharedBoundary::landmark && s.stamp[v] == 0;
          if (!right && wrong++ == 0) ADD_FAILURE() << "node " << v << " marked wrong";
        }
        EXPECT_EQ(wrong, 0u);
        runs_taken.push_back(took_runs(profile));
      });
  EXPECT_TRUE(std::all_of(runs_taken.begin(), runs_taken.end(),
                          [&](int taken) { return taken == runs_taken.front(); }));
  return runs_taken.front() != 0;
}

TEST(SharedBoundaryStart, RingsAndBridgesAreWalkedInRuns) {
  Boundary b;
  const std::uint32_t outer = add_ring(b, 100'000, {0, 0}, 1000, false);
  for (int h = 0; h < 40; ++h) {
    const std::uint32_t hole =
        add_ring(b, 500 + 37 * h, {-600.0 + 30 * h, 20.0 * (h % 5)}, 10, true);
    b.add_diagonal(outer + 2'000 * h + 7, hole + 11);  // a bridge: two copies at the end
  }
  // Entry in the middle of a run, as the variants' entries may be.
  EXPECT_EQ(expect_start_walks(b, outer + 12'345), takes_runs);
  EXPECT_EQ(expect_start_walks(b, b.size() - 1), takes_runs);  // a bridge's copy
}

TEST(SharedBoundaryStart, DeadNodesAndAnotherCycleAreLeftOut) {
  Boundary b;
  const std::uint32_t outer = add_ring(b, 60'000, {0, 0}, 1000, false);
  const std::uint32_t other = add_ring(b, 30'000, {5000, 0}, 1000, false);  // not walked
  // Unlinked nodes keep their links into the cycle: stale, and never followed.
  for (std::uint32_t v = outer + 100; v < outer + 60'000; v += 997) b.unlink(v);
  EXPECT_EQ(expect_start_walks(b, outer + 50), takes_runs);
  EXPECT_EQ(expect_start_walks(b, other + 29'999), takes_runs);
}

TEST(SharedBoundaryStart, ScrambledLinksAreWalkedNodeByNode) {
  Boundary b;
  add_ring(b, 50'000, {0, 0}, 1000, false);
  std::vector<std::uint32_t> cycle(b.size());
  std::iota(cycle.begin(), cycle.end(), 0u);
  std::shuffle(cycle.begin() + 1, cycle.end(), std::mt19937(5));
  for (std::size_t i = 0; i < cycle.size(); ++i) b.link(cycle[i], cycle[(i + 1) % cycle.size()]);
  EXPECT_FALSE(expect_start_walks(b, cycle[777]));
}

TEST(SharedBoundaryStart, SmallCyclesAreOnePart) {
  Boundary b;
  add_ring(b, 10, {0, 0}, 1, false);
  EXPECT_EQ(expect_start_walks(b, 3), takes_runs);  // one jump: one run
}

}  // namespace
}  // namespace pear::detail
