#include "chain_clipper.hpp"

#include "core/ear_test.hpp"

namespace pear::detail {

namespace {

/// Foreign entries in an ear's box one ear test may look at. The start grids keep what other
/// chains have clipped since the phase began, so a big triangle late in a chain's work would
/// look at many dead nodes; such an ear is left to the next round or the sequential finish,
/// with a fresh grid.
constexpr int foreign_budget = 48;

}  // namespace

bool ChainClipper::is_ear(std::uint32_t v, DiagonalTurns& turns) const {
  return own_grid_.scans_cells() ? test_ear<true>(v, turns) : test_ear<false>(v, turns);
}

template <bool scanned>
bool ChainClipper::test_ear(std::uint32_t v, DiagonalTurns& turns) const {
  const auto near = [this](const Point& a, const Point& t, const Point& c, const Box& box,
                           auto&& visit) {
    int looked_at = 0;
    return own_grid_.any_in_box_near_triangle<scanned>(
        a, t, c, box, [&](const ReflexGrid::Entry& e) {
          if (!own(e.node) && ++looked_at > foreign_budget) return true;
          return visit(e);
        });
  };
  return detail::is_ear(*s_->b, OwnLinks{s_, chain_}, v, near, turns);
}

/// The grid the ear tests read: the chain's hashed nodes (taken out as they stop being reflex)
/// and, never taken out, the nodes other chains and the landmarks held hashed at the phase's
/// start within the chain's bounding box (an ear's corners are the chain's own, so nothing
/// outside it can lie in an ear). One grid to ask instead of one per chain: Australia's ear
/// tests at 16 chains took 1,612 instructions each, with one grid 952.
/// The same walk over the chain's nodes finds the range of their numbers, which the queue's
/// blocks span.
std::uint32_t ChainClipper::build_grid(std::size_t first, std::size_t last) {
  const SharedBoundary& s = *s_;
  const Boundary& b = *s.b;
  Point lo{INFINITY, INFINITY}, hi{-INFINITY, -INFINITY};
  std::uint32_t lowest = UINT32_MAX, highest = 0;
  scratch_.clear();
  for (const auto run : s.between(first, last))
    for (const std::uint32_t v : run) {
      const Point& p = b.pos[v];
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
      lowest = std::min(lowest, v), highest = std::max(highest, v);
      if (s.hashed[v]) scratch_.push_back(v);
    }
  first_node_ = lowest == UINT32_MAX ? 0 : lowest;
  const auto take = [&](const Point& p, std::uint32_t v) {
    if (p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y) scratch_.push_back(v);
  };
  for (std::uint32_t mark : s.landmarks) take(b.pos[mark], mark);
  for (std::size_t other = 0; other < s.chains; ++other)
    if (other != chain_)
      s.start_lists[other].for_each_in_box(
          lo, hi, [&](const ReflexGrid::Entry& e) { scratch_.push_back(e.node); });
  own_grid_.build(b, scratch_);
  return lowest == UINT32_MAX ? 0 : highest - lowest + 1;
}

/// Queues v if it may be clipped: convex, with neighbours of its own chain. The ear test waits
/// until v is popped (see EarClipper::offer).
void ChainClipper::offer(std::uint32_t v, double turn) {
  const Boundary& b = *s_->b;
  if (!own(b.prev[v]) || !own(b.next[v]) || !(turn > 0)) return;
  queue_.push(ear_bucket(b, v, heuristic_, turn), {v, s_->stamp[v]},
              (v - first_node_) / EarQueue::block_nodes);
}

/// Whether popped v is an ear this chain may clip now.
bool ChainClipper::clippable(std::uint32_t v, DiagonalTurns& turns) const {
  const Boundary& b = *s_->b;
  const std::uint32_t p = b.prev[v], n = b.next[v];
  if (!own(p) || !own(n)) return false;
  // Next to a spike that could not be dissolved (it reaches into another chain) the ear test's
  // argument does not hold; the sequential engine will dissolve it first.
  if (b.pos[b.prev[p]] == b.pos[v] || b.pos[b.next[n]] == b.pos[v]) return false;
  return is_ear(v, turns);
}

void ChainClipper::unhash(std::uint32_t v) {
  if (!s_->hashed[v]) return;
  s_->hashed[v] = 0;
  own_grid_.remove(v, s_->b->pos[v]);
}

void ChainClipper::update(std::uint32_t v, double turn) {
  if (s_->hashed[v] && !s_->pinch[v] && turn >= 0) unhash(v);
  ++s_->stamp[v];
}

void ChainClipper::remove(std::uint32_t v) {
  s_->b->unlink(v);
  s_->alive[v] = 0;
  unhash(v);
}

/// As the sequential engine does: a node whose neighbours coincide is the tip of a zero-area
/// spike (what clipping leaves of a lobe where rings touch); it and its successor leave without
/// a triangle. Only where all the nodes involved are the chain's own. Returns a live node where
/// the last change happened, or v.
std::uint32_t ChainClipper::dissolve_spikes(std::uint32_t v) {
  const Boundary& b = *s_->b;
  while (own(v)) {
    const std::uint32_t p = b.prev[v], n = b.next[v];
    if (!(b.pos[p] == b.pos[n]) || !own(p) || !own(n) || !own(b.next[n])) break;
    remove(v);
    remove(n);
    v = p;
  }
  return v;
}

/// After a clip next to v: dissolve spikes, refresh the convexity and ear status around v.
void ChainClipper::settle(std::uint32_t v, const double* turn) {
  if (!s_->alive[v]) return;
  const std::uint32_t u = dissolve_spikes(v);
  const Boundary& b = *s_->b;
  // Another chain's node: its links are that chain's to write, not to be read here.
  const auto refresh = [&](std::uint32_t w, const double* known) {
    if (!own(w)) return;
    const double now = known != nullptr ? *known : b.turn(w);
    update(w, now), offer(w, now);
  };
  if (u == v) return refresh(v, turn);
  for (std::uint32_t w : {b.prev[u], u, b.next[u]}) refresh(w, nullptr);
}

void ChainClipper::run(SharedBoundary& s, std::uint32_t chain, std::size_t first, std::size_t last,
                       EarHeuristic heuristic, TriangleList& out) {
  s_ = &s;
  chain_ = chain;
  heuristic_ = heuristic;
  Boundary& b = *s.b;
  // As the sequential clipper's queue does on large boundaries: key level, then block of
  // consecutive nodes (over the chain's span of node numbers), then key.
  const std::uint32_t span = build_grid(first, last);
  constexpr std::uint32_t block = EarQueue::block_nodes;
  queue_.clear(span >= 2 * block ? (span + block - 1) / block : 1);
  for (const auto run : s.between(first, last))
    for (const std::uint32_t v : run) offer(v);
  EarQueue::Candidate top;
  while (queue_.pop(top)) {
    // Links of nodes near other chains may be written by their tasks: no following them.
    prefetch_upcoming(queue_, b, s.stamp.data(), false);
    const std::uint32_t v = top.node;
    DiagonalTurns turns;
    if (!s.alive[v] || s.stamp[v] != top.stamp || !clippable(v, turns)) continue;
    const std::uint32_t p = b.prev[v], n = b.next[v];
    out.push_back({b.vertex[p], b.vertex[v], b.vertex[n]});
    remove(v);
    // The ear test's turns at the diagonal's ends; p's only while n (settled first, which may
    // dissolve spikes) is still its neighbour.
    settle(n, &turns.after);
    settle(p, b.next[p] == n ? &turns.before : nullptr);
  }
}

}  // namespace pear::detail
