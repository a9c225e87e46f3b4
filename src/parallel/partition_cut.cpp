// Paper §2.2, partition and cut: landmarks cut the boundary into chains; each chain is clipped
// by its own task with its own ear queue (so "top" applies per chain); landmarks are never
// clipped. Beyond the paper: while a round clips enough, another round with the landmarks moved
// along the boundary clips what the last one left near the chain ends; the sequential engine
// then finishes the rest with all its fallbacks.
#include <algorithm>

#include "variant_scratch.hpp"
#include "variants.hpp"

namespace pear::detail {
namespace {

constexpr std::size_t min_chain_nodes = 256;  ///< below this a task costs more than it saves
/// Chains of one polygon's boundary clip at unequal costs (the 100k star's 16: the longest 1.2x
/// their mean), and the round waits for the longest; two a partition let the scheduler even
/// them out. Projected at 16 threads, the fastest of 5 runs on one thread (2026-11-28): the
/// star 12.3 -> 11.9 ms, Koch-8 3.48 -> 3.28, Australia 4.67 -> 4.34, New Guinea 1.53 -> 1.48;
/// at 4 Borneo 3.58 -> 3.42, New Guinea 5.43 -> 5.20. Three or four a partition gained no more.
/// Each chain's queue orders only its own ears: `top`'s average smallest angle moved by at most
/// 0.2% (Borneo at 16 partitions 12.53 -> 12.50 degrees, Koch-8 30.96 -> 30.92).
constexpr std::size_t chains_per_partition = 2;
/// Where the CDT flips the triangles after, in sets that are runs of the chains' order, one chain
/// a partition: with two, Koch-8's flips across the sets' borders at 16 partitions cascaded
/// (Lawson's loop on one thread 1.5 -> 4.0 ms; the CDT projected at 16 threads 8.4 -> 10.9 ms),
/// and the coasts' CDT moved within the runs' noise.
constexpr std::size_t chains_per_partition_for_flips = 1;
constexpr int max_rounds = 4;
/// Where round r puts its first landmark, in chain lengths: corridors whose two walls lie in
/// different chains (a spiral, a thickened curve) are zipped up from their dead ends, so each
/// round moves the landmarks to where the last round's chain ends had to stop.
constexpr double landmark_shift[max_rounds] = {0, 0.5, 0.25, 0.75};

/// Appends the parts in order, copying them in parallel.
void gather(std::vector<TriangleList>& parts, std::size_t count, const RunContext& ctx,
            TriangleList& out) {
  std::vector<std::size_t> offset(count + 1, out.size());
  for (std::size_t c = 0; c < count; ++c) offset[c + 1] = offset[c] + parts[c].size();
  out.resize(offset[count]);
  ctx.run_tasks("gather triangles", count, [&](std::size_t c) {
    std::copy(parts[c].begin(), parts[c].end(), out.begin() + static_cast<long>(offset[c]));
  });
}

}  // namespace

void VariantScratchDeleter::operator()(VariantScratch* scratch) const noexcept {
  delete scratch;
}

std::uint32_t partition_and_cut(Boundary& b, std::uint32_t entry, EarHeuristic heuristic,
                                const RunContext& ctx, TriangleList& out,
                                VariantScratchPtr& scratch, SharedPositions shared,
                                bool flipped_after) {
  const std::size_t partitions = ctx.partitions;
  const std::size_t per_partition =
      flipped_after ? chains_per_partition_for_flips : chains_per_partition;
  if (partitions < 2) return entry;
  if (!scratch) scratch.reset(new VariantScratch);
  SharedBoundary& s = scratch->shared;
  std::size_t nodes = s.start(b, entry, ctx, shared);
  // A clipper (with its queue) for each chain there can be, not for each partition asked for.
  const std::size_t most = std::min(per_partition * partitions, nodes / min_chain_nodes);
  std::vector<ChainClipper>& clippers = scratch->clippers;
  std::vector<TriangleList>& parts = scratch->parts;
  if (clippers.size() < most) clippers.resize(most);
  if (parts.size() < most) parts.resize(most);
  for (int round = 0; round < max_rounds; ++round) {
    const std::size_t chains = std::min(per_partition * partitions, nodes / min_chain_nodes);
    if (chains < 2) break;
    const auto offset =
        static_cast<std::size_t>(landmark_shift[round] * static_cast<double>(nodes / chains));
    const std::vector<std::size_t> marks =
        s.place_landmarks(chains, offset, ctx, SharedBoundary::StartIndex::lists);
    ctx.run_tasks("clip chains", chains, [&](std::size_t c) {
      parts[c].clear();
      clippers[c].run(s, static_cast<std::uint32_t>(c), marks[c], marks[(c + 1) % chains],
                      heuristic, parts[c]);
    });
    std::size_t clipped = 0;
    for (std::size_t c = 0; c < chains; ++c) clipped += parts[c].size();
    gather(parts, chains, ctx, out);
    if (s.refresh_order(ctx) == no_node) return no_node;
    nodes = s.order.size();
    // The rest may be walls that face other chains; a shifted round may still zip them.
    if (round > 0 && clipped < nodes / 16) break;
  }
  return s.order.front();
}

}  // namespace pear::detail
