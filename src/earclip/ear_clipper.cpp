#include "ear_clipper.hpp"

#include "core/ear_test.hpp"
#include "core/pinches.hpp"
#include "core/strip_fans.hpp"

#include <algorithm>
#include <cmath>

namespace pear::detail {
void EarClipper::classify(std::uint32_t entry, SharedPositions shared) {
  Boundary& b = *b_;
  reflex_.assign(b.size(), 0);
  grid_built_ = false;
  alive_.assign(b.size(), 0);
  stamp_.assign(b.size(), 0);
  scratch_.clear();
  remaining_ = 0;
  std::uint32_t v = entry;
  do {
    alive_[v] = 1;
    ++remaining_;
    v = b.next[v];
  } while (v != entry);
  // A spike in the input (a ring running out and back along one segment) is a ring
  // self-intersection: it is dissolved, and the result is flagged as a best effort.
  const std::size_t before = remaining_;
  for (std::uint32_t u = 0; u < b.size(); ++u) {
    if (!alive_[u]) continue;
    const std::uint32_t vertex = b.vertex[u];
    dissolve_spikes(u);
    if (remaining_ != before && !best_effort_) best_effort_ = true, best_effort_vertex_ = vertex;
  }
  mark_pinches(shared);
  for (std::uint32_t u = 0; u < b.size(); ++u) {
    if (alive_[u] && (pinch_[u] || b.turn(u) < 0)) {
      reflex_[u] = 1;
      scratch_.push_back(u);
    }
  }
  grid_.build(b, scratch_);
  grid_built_ = true;
  strip_check_at_ = SIZE_MAX;
  strips_ = 0;
}

/// A node that shares its position with one of another cycle, or one that a spike took away,
/// is marked too: an extra hashed node can only make an ear test stricter.
void EarClipper::mark_pinches(SharedPositions shared) {
  fill_pinches(*b_, alive_, remaining_, shared, pinch_, position_table_);
}

const std::vector<std::uint8_t>* EarClipper::shared_marks(std::uint32_t entry,
                                                          SharedPositions shared) {
  if (shared.marks != nullptr && shared.marks->size() == b_->size()) return shared.marks;
  if (shared.none) return nullptr;
  alive_.assign(b_->size(), 0);
  std::size_t live = 0;
  std::uint32_t v = entry;
  do {
    alive_[v] = 1;
    ++live;
    v = b_->next[v];
  } while (v != entry && live <= b_->size());
  find_pinches(*b_, alive_, live, pinch_, position_table_);
  return &pinch_;
}

void EarClipper::remove(std::uint32_t v) {
  if (v == anchor_) anchor_ = b_->next[v];
  b_->unlink(v);
  alive_[v] = 0;
  drop_reflex(v);
  --remaining_;
}

void EarClipper::drop_reflex(std::uint32_t v) {
  if (!reflex_[v]) return;
  reflex_[v] = 0;
  if (grid_built_) grid_.remove(v, b_->pos[v]);
}

/// A node whose neighbours coincide is the tip of a zero-area spike: the remnant of a lobe of
/// a self-touching ring, or an antenna in the input. It and its successor (which duplicates
/// its predecessor) leave without a triangle. Returns a live node where the change happened.
std::uint32_t EarClipper::dissolve_spikes(std::uint32_t v) {
  Boundary& b = *b_;
  while (remaining_ >= 4 && b.pos[b.prev[v]] == b.pos[b.next[v]]) {
    const std::uint32_t p = b.prev[v], n = b.next[v];
    remove(v);
    remove(n);
    v = p;
  }
  return v;
}

/// After a clip next to v: dissolve spikes, refresh the convexity and ear status around v.
std::uint32_t EarClipper::settle(std::uint32_t v, bool queue, const double* turn) {
  if (!alive_[v]) return UINT32_MAX;
  const std::uint32_t u = dissolve_spikes(v);
  if (u != v) {
    for (std::uint32_t w : {b_->prev[u], u, b_->next[u]}) {
      const double now = b_->turn(w);
      update_neighbour(w, now);
      if (queue) offer(w, now);
    }
    return u;
  }
  const double now = turn != nullptr ? *turn : b_->turn(v);
  update_neighbour(v, now);
  if (queue) offer(v, now);
  return v;
}

std::array<std::uint32_t, 2> EarClipper::settle_clipped(std::uint32_t p, std::uint32_t n,
                                                        const DiagonalTurns& turns, bool queue) {
  const std::uint32_t n_left = settle(n, queue, &turns.after);
  const std::uint32_t p_left = settle(p, queue, b_->next[p] == n ? &turns.before : nullptr);
  return {p_left, n_left};
}

bool EarClipper::is_ear(std::uint32_t v) const {
  DiagonalTurns turns;
  return is_ear(v, turns);
}

bool EarClipper::is_ear(std::uint32_t v, DiagonalTurns& turns) const {
  return grid_.scans_cells() ? test_ear<true>(v, turns) : test_ear<false>(v, turns);
}

template <bool scanned>
bool EarClipper::test_ear(std::uint32_t v, DiagonalTurns& turns) const {
  const auto near = [this](const Point& a, const Point& t, const Point& c, const Box& box,
                           auto&& visit) {
    // Counts the hashed nodes in the triangle's box: the ear test's work.
    return grid_.any_in_box_near_triangle<scanned>(a, t, c, box, [&](const ReflexGrid::Entry& e) {
      ++boxed_;
      return visit(e);
    });
  };
  return detail::is_ear(*b_, AllLinks{}, v, near, turns);
}

double EarClipper::quality(std::uint32_t v) const {
  return ear_shape(*b_, v);
}

void EarClipper::clip(std::uint32_t v) {
  const Boundary& b = *b_;
  out_->push_back({b.vertex[b.prev[v]], b.vertex[v], b.vertex[b.next[v]]});
  remove(v);
}

/// Where no reflex node is left on a long cycle (a comb once its teeth are gone: tens of
/// thousands of nodes on a line, whose ears come one at a time, each spanning the strip: half
/// the comb's clip), the cycle may be a strip: two fans finish it (core/strip_fans.hpp).
/// Looked at again only once half its nodes have gone, so a long cycle that is none costs O(n)
/// in all. Returns whether it finished the cycle.
bool EarClipper::finish_strip() {
  if (grid_.live() != 0 || remaining_ < min_strip_nodes || remaining_ > strip_check_at_ ||
      pinch_.size() < b_->size())
    return false;
  strip_check_at_ = remaining_ / 2;
  scratch_.clear();
  std::uint32_t v = anchor_;
  do {
    scratch_.push_back(v);
    v = b_->next[v];
  } while (v != anchor_ && scratch_.size() <= remaining_);
  if (scratch_.size() != remaining_ ||
      !finish_strip_in_fans(*b_, scratch_, pinch_, RunContext{}, *out_))
    return false;
  for (std::uint32_t u : scratch_) alive_[u] = 0;
  remaining_ = 0;
  ++strips_;
  return true;
}

/// After a clip: v's angle shrank, so it may have turned convex; its ear status may change.
void EarClipper::update_neighbour(std::uint32_t v, double turn) {
  if (reflex_[v] && !pinch_[v] && turn >= 0) drop_reflex(v);
  ++stamp_[v];
}

/// Queues v if it is convex: by shape for "top", by diagonal length for "fast". The ear test
/// waits until v is popped: most queued nodes change (a neighbour is clipped, the stamp moves
/// on) before their turn, and an ear's status changes only when its neighbours do, so testing
/// at the pop clips the same ears in the same order with about half the tests.
void EarClipper::offer(std::uint32_t v, double turn) {
  if (!(turn > 0)) return;
  queue_.push(ear_bucket(*b_, v, heuristic_, turn), {v, stamp_[v]}, v / EarQueue::block_nodes);
}

/// The best queued node that is still current and an ear.
bool EarClipper::pop(std::uint32_t& v, DiagonalTurns& turns) {
  EarQueue::Candidate top;
  while (queue_.pop(top)) {
    prefetch_upcoming(queue_, *b_, stamp_.data(), true);
    if (alive_[top.node] && stamp_[top.node] == top.stamp && is_ear(top.node, turns)) {
      v = top.node;
      return true;
    }
  }
  return false;
}

void EarClipper::clip_ears(std::uint32_t entry) {
  anchor_ = entry;
  std::uint32_t last = entry;
  std::uint32_t v = entry;
  do {
    offer(v);
    v = b_->next[v];
  } while (v != entry);
  DiagonalTurns turns;
  for (;;) {
    while (remaining_ > 3) {
      if (!pop(v, turns)) {
        if (!fall_back(anchor_)) break;
        last = touched_;
        for (std::uint32_t u : {b_->prev[last], last, b_->next[last]}) {
          const double now = b_->turn(u);
          update_neighbour(u, now), offer(u, now);
        }
        continue;
      }
      const std::uint32_t p = b_->prev[v], n = b_->next[v];
      clip(v);
      const auto [p_left, n_left] = settle_clipped(p, n, turns, true);
      last = p_left != UINT32_MAX ? p_left : n_left != UINT32_MAX ? n_left : p;
      finish_strip();
    }
    finish(anchor_);
    if (pending_.empty()) return;
    // The next part of a split cycle.
    const PendingCycle part = pending_.back();
    pending_.pop_back();
    remaining_ = part.nodes;
    anchor_ = part.entry;
    strip_check_at_ = SIZE_MAX;
    last = part.entry;
    v = part.entry;
    do {
      ++stamp_[v];
      offer(v);
      v = b_->next[v];
    } while (v != part.entry);
  }
}

void EarClipper::prepare(Boundary& b, std::uint32_t entry, EarHeuristic heuristic,
                         TriangleList& out, SharedPositions shared) {
  b_ = &b;
  out_ = &out;
  heuristic_ = heuristic;
  best_effort_ = false;
  fallback_budget_ = fallback_budget(b.size());
  fallback_work_ = 0;
  // Blocks of consecutive nodes (runs of the boundary) for the queue, on boundaries past the
  // caches (see EarQueue::clear).
  queue_.clear(b.size() >= 2 * EarQueue::block_nodes
                   ? (b.size() + EarQueue::block_nodes - 1) / EarQueue::block_nodes
                   : 1);
  pending_.clear();
  classify(entry, shared);
}

bool EarClipper::clip_prepared(std::uint32_t entry) {
  if (remaining_ < 3) return !best_effort_;
  std::uint32_t start = live(entry);
  // "fast" walks the boundary; where the walk does not pay (below), the queue takes over.
  if (heuristic_ == EarHeuristic::top || !walk_ears(start)) clip_ears(start);
  return !best_effort_;
}

bool EarClipper::run(Boundary& b, std::uint32_t entry, EarHeuristic heuristic, TriangleList& out,
                     SharedPositions shared) {
  if (b.size() <= BitsetClipper::max_nodes) {
    b_ = &b;
    const std::vector<std::uint8_t>* marks = shared_marks(entry, shared);
    if (bits_.clip(b, entry, heuristic, out, marks)) return true;
    // No ear the bit sets could find: the queue's fallbacks take what is left.
    entry = bits_.anchor();
    shared = {marks, marks == nullptr};
  }
  return run_queue(b, entry, heuristic, out, shared);
}

void EarClipper::enqueue_cycle(std::uint32_t entry) {
  std::uint32_t v = entry;
  do {
    walk_.push_back(v);
    v = b_->next[v];
  } while (v != entry);
}

/// "fast": ears in boundary order, like a walk along the ring. After a clip the walk goes on at
/// the next node, and the previous one joins the end of the walk: clipping stays local (the
/// nodes and grid cells it touches are in cache; a bucket queue jumps across the polygon) and
/// builds no fans (going back at once fans out from one vertex, quadratic on a comb). A node
/// that failed is tested again only after its neighbourhood changed (stamp_), and once more in
/// a last full pass before the fallback cascade, since a blocking reflex node may have left.
/// Gives up, returning false with `entry` a live node, after 8 visits per node or 4 hashed
/// nodes per node in the boxes of its ear tests: the queue then finishes the cycle. (Walk-order
/// ears can be long slivers along rows of collinear reflex corners, a grid of square holes:
/// 41 s for 4M vertices where the queue takes 6.)
bool EarClipper::walk_ears(std::uint32_t& entry) {
  anchor_ = entry;
  failed_.assign(b_->size(), 0);
  std::size_t budget = 8 * remaining_ + 64;
  boxed_ = 0;
  const std::size_t boxed_budget = 4 * remaining_ + 1024;
  for (;;) {
    walk_.clear();
    enqueue_cycle(anchor_);
    std::size_t head = 0;
    std::uint32_t up_next = UINT32_MAX;
    bool recheck = false;
    while (remaining_ > 3) {
      if (budget-- == 0 || boxed_ > boxed_budget) {
        entry = anchor_;
        return false;
      }
      std::uint32_t v;
      if (up_next != UINT32_MAX) {
        v = up_next;
        up_next = UINT32_MAX;
      } else if (head < walk_.size()) {
        v = walk_[head++];
      } else if (!recheck) {
        recheck = true;
        walk_.clear();
        head = 0;
        enqueue_cycle(anchor_);
        continue;
      } else {
        if (!fall_back(anchor_)) break;
        failed_.resize(b_->size(), 0);  // a split adds copies of nodes
        recheck = false;
        const std::uint32_t t = touched_;
        for (std::uint32_t u : {b_->prev[t], t, b_->next[t]})
          update_neighbour(u, b_->turn(u)), walk_.push_back(u);
        continue;
      }
      if (!alive_[v] || (!recheck && failed_[v] == stamp_[v] + 1)) continue;
      DiagonalTurns turns;
      if (!is_ear(v, turns)) {
        failed_[v] = stamp_[v] + 1;
        continue;
      }
      const std::uint32_t p = b_->prev[v], n = b_->next[v];
      clip(v);
      const auto [p_left, n_left] = settle_clipped(p, n, turns, false);
      up_next = n_left;
      if (p_left != UINT32_MAX) walk_.push_back(p_left);
      recheck = false;
      finish_strip();
    }
    finish(anchor_);
    if (pending_.empty()) return true;
    const PendingCycle part = pending_.back();
    pending_.pop_back();
    remaining_ = part.nodes;
    anchor_ = part.entry;
    strip_check_at_ = SIZE_MAX;
  }
}

EarStatistics EarClipper::statistics(Boundary& b, std::uint32_t entry) {
  b_ = &b;
  classify(entry, {});
  EarStatistics stats;
  if (remaining_ < 3) return stats;
  // Dissolving spikes may have removed `entry` itself (a hole that repeats the outer ring).
  const std::uint32_t first = live(entry);
  std::uint32_t v = first;
  do {
    ++stats.vertices;
    if (b.turn(v) > 0)
      ++stats.convex;
    else
      ++stats.reflex;
    if (remaining_ > 3 && is_ear(v)) ++stats.ears;
    v = b.next[v];
  } while (v != first);
  if (remaining_ == 3) stats.ears = stats.convex;
  return stats;
}

}  // namespace pear::detail
