// Paper §2.3, mark and cut: "every second ear along the boundary does not overlap with any
// other evenly-numbered ear". Each round has three phases separated by barriers, so no task
// reads what another writes in the same phase and the output depends on the partitions only:
//   1. mark and test (read-only): each chunk walks its nodes, marks every second strictly
//      convex node and keeps the marked ones that are ears;
//   2. cut: each chunk clips its ears; marked nodes are never adjacent, so every link has one
//      writer, and each triangle belongs to its base node's chunk;
//   3. update: each chunk re-classifies the neighbours of its clipped nodes.
// Rounds go on while they clip enough; then the landmarks that are ears are clipped, a strip
// (what is left of a comb) is fanned in tasks (core/strip_fans.hpp), and the sequential engine
// finishes anything else.
#include <algorithm>

#include "core/ear_test.hpp"
#include "core/strip_fans.hpp"
#include "variant_scratch.hpp"
#include "variants.hpp"

namespace pear::detail {
namespace {

constexpr std::size_t min_chunk_nodes = 256;  ///< below this a task costs more than it saves

class MarkAndCut {
 public:
  MarkAndCut(VariantScratch& scratch, std::size_t chunks, const RunContext& ctx)
      : s_(scratch.shared),
        b_(*s_.b),
        ctx_(ctx),
        chunks_(chunks),
        ears_(scratch.ears),
        triangles_(scratch.parts) {
    if (ears_.size() < chunks) ears_.resize(chunks);
    if (triangles_.size() < chunks) triangles_.resize(chunks);
    marks_ = s_.place_landmarks(chunks, 0, ctx, SharedBoundary::StartIndex::grids);
  }

  /// One round; returns the number of ears clipped.
  std::size_t round(TriangleList& out) {
    const std::size_t chunks = chunks_;
    ctx_.run_tasks("mark and test", chunks, [&](std::size_t c) { mark_and_test(c); });
    ctx_.run_tasks("cut", chunks, [&](std::size_t c) { cut(c); });
    ctx_.run_tasks("update", chunks, [&](std::size_t c) { update(c); });
    std::size_t clipped = 0;
    for (std::size_t c = 0; c < chunks; ++c) {
      out.insert(out.end(), triangles_[c].begin(), triangles_[c].end());
      clipped += triangles_[c].size();
    }
    return clipped;
  }

  /// Landmarks are never marked, so no round clips them: what the rounds leave of a comb is a
  /// strip with a tooth at every landmark. Those that are ears are clipped here, one by one
  /// (but the last triangle, left to the sequential engine).
  void clip_landmark_ears(TriangleList& out) {
    ctx_.run_serial("landmark ears", [&] {
      for (std::size_t chunk = 0; chunk < chunks_; ++chunk) {
        const std::uint32_t v = landmark(chunk), p = b_.prev[v], n = b_.next[v];
        if (!s_.alive[v] || b_.next[n] == p || s_.pinch[p] || s_.pinch[v] || s_.pinch[n] ||
            !is_ear(v))
          continue;
        out.push_back({b_.vertex[p], b_.vertex[v], b_.vertex[n]});
        b_.unlink(v);
        s_.alive[v] = 0;
        // A neighbour that turned convex stays hashed: it can only make a later landmark's ear
        // test stricter, and no round tests again.
      }
    });
  }

 private:
  std::uint32_t landmark(std::size_t chunk) const {
    return s_.order[marks_[chunk % marks_.size()]];
  }

  bool is_ear(std::uint32_t v) const {
    const auto near = [this](const Point& a, const Point& t, const Point& c, const Box& box,
                             auto&& visit) { return s_.any_hashed_near(a, t, c, box, visit); };
    return detail::is_ear(b_, AllLinks{}, v, near);
  }

  void mark_and_test(std::size_t chunk) {
    std::vector<std::uint32_t>& ears = ears_[chunk];
    ears.clear();
    const std::uint32_t end = landmark(chunk + 1);
    bool marked_previous = false;
    for (std::uint32_t v = b_.next[landmark(chunk)]; v != end; v = b_.next[v]) {
      const std::uint32_t p = b_.prev[v], n = b_.next[v];
      // Pinches and their spikes are left to the sequential engine (see chain_clipper.cpp).
      const bool candidate = !marked_previous && !s_.pinch[p] && !s_.pinch[v] && !s_.pinch[n] &&
                             orient2d(b_.pos[p], b_.pos[v], b_.pos[n]) > 0;
      marked_previous = candidate;
      if (candidate && is_ear(v)) ears.push_back(v);
    }
  }

  void cut(std::size_t chunk) {
    TriangleList& triangles = triangles_[chunk];
    triangles.clear();
    ReflexGrid& grid = s_.start_grids[chunk];
    for (std::uint32_t v : ears_[chunk]) {
      const std::uint32_t p = b_.prev[v], n = b_.next[v];
      triangles.push_back({b_.vertex[p], b_.vertex[v], b_.vertex[n]});
      b_.unlink(v);
      s_.alive[v] = 0;
      if (s_.hashed[v]) s_.hashed[v] = 0, grid.remove(v, b_.pos[v]);
    }
  }

  void update(std::size_t chunk) {
    ReflexGrid& grid = s_.start_grids[chunk];
    for (std::uint32_t v : ears_[chunk]) {
      for (std::uint32_t u : {b_.prev[v], b_.next[v]}) {
        if (s_.owner[u] != chunk || !s_.hashed[u] || s_.pinch[u] || b_.turn(u) < 0) continue;
        s_.hashed[u] = 0;
        grid.remove(u, b_.pos[u]);
      }
    }
  }

  SharedBoundary& s_;
  Boundary& b_;
  const RunContext& ctx_;
  std::size_t chunks_;
  std::vector<std::size_t> marks_;
  std::vector<std::vector<std::uint32_t>>& ears_;  ///< per chunk (the first chunks_ of them)
  std::vector<TriangleList>& triangles_;
};

}  // namespace

std::uint32_t mark_and_cut(Boundary& b, std::uint32_t entry, const RunContext& ctx,
                           TriangleList& out, VariantScratchPtr& scratch, SharedPositions shared) {
  if (!scratch) scratch.reset(new VariantScratch);
  SharedBoundary& s = scratch->shared;
  const std::size_t nodes = s.start(b, entry, ctx, shared);
  const std::size_t chunks = std::min<std::size_t>(ctx.partitions, nodes / min_chunk_nodes);
  if (chunks < 2) return entry;
  MarkAndCut rounds(*scratch, chunks, ctx);
  // The paper stops when a cut phase clips fewer than 20 ears; a polygon that clips a few
  // hundred per round (a spiral) would otherwise walk all its nodes thousands of times.
  std::size_t live = nodes;
  for (;;) {
    const std::size_t clipped = rounds.round(out);
    live -= clipped;
    if (clipped < 20 || clipped * 64 < live) break;
  }
  rounds.clip_landmark_ears(out);
  // What is left of a comb: one strip, whose ears would come one at a time.
  const std::uint32_t rest = s.refresh_order(ctx);
  if (rest != no_node && finish_strip_in_fans(b, s.order, s.pinch, ctx, out)) return no_node;
  return rest;
}

}  // namespace pear::detail
