#include "bitset_clipper.hpp"

#include <algorithm>
#include <bit>
#include <limits>

#include "core/ear_test.hpp"

namespace pear::detail {
namespace {

/// The bit of node v in its word when `on`, else 0, without a branch: whether a corner is
/// convex is as good as random to the branch predictor.
std::uint64_t bit_if(std::uint32_t v, bool on) {
  return (std::uint64_t{1} << (v % 64)) & (std::uint64_t{0} - on);
}

}  // namespace

void BitsetClipper::Slabs::build(std::span<const Point> points, double Point::*axis,
                                 std::uint32_t words) {
  double low = points[0].*axis, high = low;
  for (const Point& p : points) low = std::min(low, p.*axis), high = std::max(high, p.*axis);
  origin = low;
  scale = high > low ? count / (high - low) : 0;
  for (NodeSet& set : upto) std::fill_n(set.words.begin(), words, 0);
  for (std::uint32_t i = 0; i < points.size(); ++i) upto[slab(points[i].*axis)].add(i);
  for (std::uint32_t w = 0; w < words; ++w) {
    from[count - 1].words[w] = upto[count - 1].words[w];
    for (std::uint32_t s = count - 1; s-- > 0;)
      from[s].words[w] = upto[s].words[w] | from[s + 1].words[w];
    for (std::uint32_t s = 1; s < count; ++s) upto[s].words[w] |= upto[s - 1].words[w];
  }
}

/// One pass along the cycle: sides, and each corner's turn and key; the positions as columns
/// (one word) or slabs (more).
void BitsetClipper::load(std::uint32_t entry, const std::vector<std::uint8_t>* shared) {
  const Boundary& b = *b_;
  const std::uint32_t n = b.size();
  words_ = (n + 63) / 64;
  stale_words_ = ~0u;
  reflex_.words.fill(0);
  convex_.words.fill(0);
  shared_.words.fill(0);
  remaining_ = 0;
  std::uint32_t v = entry;
  double side_before = squared_distance(b.pos[b.prev[v]], b.pos[v]);
  do {
    const std::uint32_t p = b.prev[v], after = b.next[v];
    const Point &a = b.pos[p], &t = b.pos[v], &c = b.pos[after];
    const double side = squared_distance(t, c), turn = orient2d(a, t, c);
    side_[v] = side;
    convex_.words[v / 64] |= bit_if(v, turn > 0);
    reflex_.words[v / 64] |= bit_if(v, turn < 0);
    if (shared) shared_.words[v / 64] |= bit_if(v, (*shared)[v] != 0);
    if (keyed_) key_[v] = top_key(a, c, side_before, side, turn);
    side_before = side;
    ++remaining_;
    v = after;
  } while (v != entry && remaining_ <= n);
  candidates_ = convex_;
  slabbed_ = words_ > 1;
  if (!slabbed_) {
    std::fill_n(blocker_bit_.begin(), n, 0);
    blockers_ = 0;
    live_blockers_ = 0;
    for (std::uint64_t set = reflex_.words[0] | shared_.words[0]; set != 0; set &= set - 1)
      add_blocker(static_cast<std::uint32_t>(std::countr_zero(set)));
  } else {
    xs_.build(b.pos, &Point::x, words_);
    ys_.build(b.pos, &Point::y, words_);
  }
  anchor_ = entry;
}

/// v's angle is new (it shrank when a neighbour was clipped): convex, reflex or collinear, and
/// if convex a candidate again with its new key.
inline void BitsetClipper::refresh(std::uint32_t v, double turn) {
  const Boundary& b = *b_;
  const Point &a = b.pos[b.prev[v]], &c = b.pos[b.next[v]];
  const std::uint64_t bit = std::uint64_t{1} << (v % 64);
  const std::uint64_t convex = bit_if(v, turn > 0), reflex = bit_if(v, turn < 0);
  const std::uint32_t w = v / 64;
  reflex_.words[w] = (reflex_.words[w] & ~bit) | reflex;
  convex_.words[w] = (convex_.words[w] & ~bit) | convex;
  candidates_.words[w] = (candidates_.words[w] & ~bit) | convex;
  stale_words_ |= 1u << w;
  if (keyed_) key_[v] = top_key(a, c, side_[b.prev[v]], side_[v], turn);
}

/// ear_test.hpp's is_ear for a convex node, with the nodes that may block from bit sets: the
/// strictly reflex ones and those at a repeated position, near the ear's box.
bool BitsetClipper::is_ear(std::uint32_t v) {
  ++ear_tests_;
  const Boundary& b = *b_;
  const Point* pos = b.pos.data();
  const std::uint32_t p = b.prev[v], n = b.next[v];
  const Point a = pos[p], t = pos[v], c = pos[n];
  if (!diagonal_clear_at_ends(a, c, pos[b.prev[p]], pos[b.next[n]], turns_)) return false;
  const double x0 = std::min({a.x, t.x, c.x}), x1 = std::max({a.x, t.x, c.x});
  const double y0 = std::min({a.y, t.y, c.y}), y1 = std::max({a.y, t.y, c.y});
  // The nodes in the slabs the box meets that may block, every word at once (a loop without
  // branches), less the ear's own corners; each is tested for the box first: most lie outside.
  const std::uint32_t sx0 = xs_.slab(x0), sx1 = xs_.slab(x1);
  const std::uint32_t sy0 = ys_.slab(y0), sy1 = ys_.slab(y1);
  std::array<std::uint64_t, max_words> near;
  for (std::uint32_t w = 0; w < words_; ++w)
    near[w] = xs_.upto[sx1].words[w] & xs_.from[sx0].words[w] & ys_.upto[sy1].words[w] &
              ys_.from[sy0].words[w] & (reflex_.words[w] | shared_.words[w]);
  for (const std::uint32_t corner : {p, v, n})
    near[corner / 64] &= ~(std::uint64_t{1} << (corner % 64));
  for (std::uint32_t w = 0; w < words_; ++w) {
    for (std::uint64_t set = near[w]; set != 0; set &= set - 1) {
      const std::uint32_t q = w * 64 + static_cast<std::uint32_t>(std::countr_zero(set));
      const Point& x = pos[q];
      if (!((x.x >= x0) & (x.x <= x1) & (x.y >= y0) & (x.y <= y1))) continue;
      if (blocks(b, AllLinks{}, p, v, n, q, a, t, c, x)) return false;
    }
  }
  return true;
}

void BitsetClipper::clip_ear(std::uint32_t v, TriangleList& out) {
  Boundary& b = *b_;
  const std::uint32_t p = b.prev[v], n = b.next[v];
  out.push_back({b.vertex[p], b.vertex[v], b.vertex[n]});
  b.link(p, n);
  if (keyed_) side_[p] = squared_distance(b.pos[p], b.pos[n]);
  convex_.erase(v);
  shared_.erase(v);  // off the cycle: it blocks nothing now
  drop_candidate(v);
  anchor_ = n;
  --remaining_;
  refresh(p, turns_.before);
  refresh(n, turns_.after);
}

void BitsetClipper::drop_candidate(std::uint32_t v) {
  candidates_.erase(v);
  stale_words_ |= 1u << (v / 64);
}

/// The candidate of word w with the smallest key, the lowest node among equals; UINT32_MAX for
/// none.
std::uint32_t BitsetClipper::best_in_word(std::uint32_t w) const {
  std::uint64_t set = candidates_.words[w];
  if (set == 0) return UINT32_MAX;
  std::uint32_t best = w * 64 + static_cast<std::uint32_t>(std::countr_zero(set));
  std::int64_t best_key = key_[best];
  for (set &= set - 1; set != 0; set &= set - 1) {
    const std::uint32_t v = w * 64 + static_cast<std::uint32_t>(std::countr_zero(set));
    // Selects, not branches: which key is smaller is a coin toss for the predictor.
    const bool better = key_[v] < best_key;
    best = better ? v : best;
    best_key = better ? key_[v] : best_key;
  }
  return best;
}

/// The candidate with the smallest key, the lowest node among equals; UINT32_MAX for none.
std::uint32_t BitsetClipper::best_candidate() {
  std::uint32_t best = UINT32_MAX;
  for (std::uint32_t w = 0; w < words_; ++w) {
    if ((stale_words_ >> w) & 1) word_best_[w] = best_in_word(w);
    const std::uint32_t v = word_best_[w];
    if (v != UINT32_MAX && (best == UINT32_MAX || key_[v] < key_[best])) best = v;
  }
  stale_words_ = 0;
  return best;
}

/// The clip where one word holds every node (the counties, buildings, parcels): the same ears
/// in the same order as the general loops, with the sets in registers, the ear test and the
/// refreshes inlined and the triangles written in place: two thirds of the instructions a step.
template <bool keyed>
struct BitsetClipper::OneWord {
  BitsetClipper& self;
  Boundary& b;
  const Point* pos = b.pos.data();
  std::uint32_t *prev = b.prev.data(), *next = b.next.data();
  std::uint64_t reflex = self.reflex_.words[0], convex = self.convex_.words[0];
  std::uint64_t candidates = self.candidates_.words[0], shared = self.shared_.words[0];
  std::uint64_t live = self.live_blockers_;
  bool strayed = false;  ///< a node turned reflex that is no blocker (only past a crossing)
  const std::uint64_t* blocker_bit = self.blocker_bit_.data();
  std::uint32_t remaining = self.remaining_, anchor = self.anchor_;
  TriangleList& out;
  const std::size_t first = out.size();
  std::array<std::uint32_t, 3>* triangle = (out.resize(first + remaining - 2), out.data() + first);
  /// The turns the tested ear's neighbours will have once it is clipped, for their refreshes:
  /// most tested ears are clipped.
  DiagonalTurns turns;

  OneWord(BitsetClipper& clipper, TriangleList& triangles)
      : self(clipper), b(*clipper.b_), out(triangles) {}

  /// ear_test.hpp's is_ear (points_in_box tests the same closed box the general loop tests
  /// again).
  [[gnu::always_inline]] bool is_ear(std::uint32_t v) {
    ++self.ear_tests_;
    const std::uint32_t p = prev[v], n = next[v];
    const Point &a = pos[p], &t = pos[v], &c = pos[n];
    if (!diagonal_clear_at_ends(a, c, pos[prev[p]], pos[next[n]], turns)) return false;
    const Box box{std::min({a.x, t.x, c.x}), std::min({a.y, t.y, c.y}), std::max({a.x, t.x, c.x}),
                  std::max({a.y, t.y, c.y})};
    const std::uint64_t ear = blocker_bit[p] | blocker_bit[v] | blocker_bit[n];
    std::uint64_t near =
        self.points_in_box_(self.xs_column_.data(), self.ys_column_.data(), self.blockers_, box) &
        live & ~ear;
    for (; near != 0; near &= near - 1) {
      const std::uint32_t q = self.blocker_node_[std::countr_zero(near)];
      if (blocks(b, AllLinks{}, p, v, n, q, a, t, c, pos[q])) return false;
    }
    return true;
  }
  /// v's corner turns by `turn` now.
  void refresh(std::uint32_t v, double turn) {
    const std::uint64_t bit = std::uint64_t{1} << v;
    const std::uint64_t now_convex = bit_if(v, turn > 0);
    reflex = (reflex & ~bit) | bit_if(v, turn < 0);
    // A blocker blocks while reflex or shared. A reflex node that is no blocker (a crossing let
    // a clip turn it) stops the loop, which adds it (add_strays) and goes on.
    const std::uint64_t mine = blocker_bit[v];
    const bool blocking = (turn < 0) | ((shared >> v) & 1);
    live = (live & ~mine) | (mine & (std::uint64_t{0} - blocking));
    strayed |= (turn < 0) & (mine == 0);
    convex = (convex & ~bit) | now_convex;
    candidates = (candidates & ~bit) | now_convex;
    if constexpr (keyed)
      self.key_[v] = top_key(pos[prev[v]], pos[next[v]], self.side_[prev[v]], self.side_[v], turn);
  }
  /// Clips v, just found an ear by is_ear.
  void clip(std::uint32_t v) {
    const std::uint32_t p = prev[v], n = next[v];
    *triangle++ = {b.vertex[p], b.vertex[v], b.vertex[n]};
    next[p] = n;
    prev[n] = p;
    if constexpr (keyed) self.side_[p] = squared_distance(pos[p], pos[n]);
    const std::uint64_t bit = std::uint64_t{1} << v;
    convex &= ~bit;
    shared &= ~bit;  // off the cycle: it blocks nothing now
    live &= ~blocker_bit[v];
    candidates &= ~bit;
    anchor = n;
    --remaining;
    refresh(p, turns.before);
    refresh(n, turns.after);
  }
  /// The candidate with the smallest key, the lowest node among equals (candidates != 0).
  std::uint32_t best_candidate() const {
    std::uint32_t best = static_cast<std::uint32_t>(std::countr_zero(candidates));
    std::int64_t best_key = self.key_[best];
    for (std::uint64_t set = candidates & (candidates - 1); set != 0; set &= set - 1) {
      const auto v = static_cast<std::uint32_t>(std::countr_zero(set));
      const bool better = self.key_[v] < best_key;  // selects: a coin toss for the predictor
      best = better ? v : best;
      best_key = better ? self.key_[v] : best_key;
    }
    return best;
  }
  /// Hands the state back to the clipper.
  void store() {
    out.resize(static_cast<std::size_t>(triangle - out.data()));
    self.reflex_.words[0] = reflex, self.convex_.words[0] = convex;
    self.candidates_.words[0] = candidates, self.shared_.words[0] = shared;
    self.live_blockers_ = live;
    self.remaining_ = remaining, self.anchor_ = anchor;
  }
  /// store(), and the cycle's last triangle.
  bool finish() {
    store();
    return remaining == 3 && self.finish(out);
  }
};

/// clip_by_key on one word. The loop holds no store but to the cycle and the triangles (one to
/// the clipper's own arrays slowed the loop in node by a twentieth): a stray reflex node ends
/// it, and it starts again once the node is a blocker.
bool BitsetClipper::clip_one_word_by_key(TriangleList& out) {
  bool rescanned = false;
  for (;;) {
    OneWord<true> w(*this, out);
    while (w.remaining > 3 && !w.strayed) {
      if (w.candidates == 0) {
        if (rescanned) break;
        rescanned = true;
        w.candidates = w.convex;
        continue;
      }
      const std::uint32_t best = w.best_candidate();
      if (!w.is_ear(best)) {
        w.candidates &= ~(std::uint64_t{1} << best);
        continue;
      }
      rescanned = false;
      w.clip(best);
    }
    if (!w.strayed) return w.finish();
    w.store();
    add_strays();
  }
}

/// clip_by_walk on one word, started again as clip_one_word_by_key is.
bool BitsetClipper::clip_one_word_by_walk(TriangleList& out) {
  std::uint32_t v = anchor_, since_clip = 0;
  const std::uint64_t budget = std::uint64_t{walk_budget} * remaining_;
  std::uint64_t steps = 0;
  for (;;) {
    OneWord<false> w(*this, out);
    bool stuck = false;
    for (; w.remaining > 3 && !w.strayed; ++steps) {
      if (steps == budget) {
        w.store();
        anchor_ = v;
        return clip_by_key_after_walk(out);
      }
      if (((w.convex >> v) & 1) && w.is_ear(v)) {
        const std::uint32_t n = w.next[v];
        w.clip(v);
        v = n;
        since_clip = 0;
      } else {
        if (++since_clip > w.remaining) {
          stuck = true;
          break;
        }
        v = w.next[v];
      }
    }
    if (!w.strayed || stuck) return w.finish();
    w.store();
    add_strays();
  }
}

/// The reflex nodes that are not blockers join them (one word).
void BitsetClipper::add_strays() {
  for (std::uint64_t set = reflex_.words[0]; set != 0; set &= set - 1) {
    const auto q = static_cast<std::uint32_t>(std::countr_zero(set));
    if (blocker_bit_[q] == 0) add_blocker(q);
  }
}

/// Node q (one word, not yet a blocker) at the blockers' end, blocking.
void BitsetClipper::add_blocker(std::uint32_t q) {
  xs_column_[blockers_] = b_->pos[q].x, ys_column_[blockers_] = b_->pos[q].y;
  blocker_node_[blockers_] = q;
  blocker_bit_[q] = std::uint64_t{1} << blockers_;
  live_blockers_ |= std::uint64_t{1} << blockers_++;
}

/// `top`: the candidate with the smallest key that is an ear. A node found blocked waits until
/// its angle changes; when none is left, one pass over every convex node (a blocker may have
/// left) before giving up.
bool BitsetClipper::clip_by_key(TriangleList& out) {
  if (words_ == 1) return clip_one_word_by_key(out);
  bool rescanned = false;
  while (remaining_ > 3) {
    const std::uint32_t best = best_candidate();
    if (best == UINT32_MAX) {
      if (rescanned) return false;
      rescanned = true;
      candidates_ = convex_;
      stale_words_ = ~0u;
      continue;
    }
    if (!is_ear(best)) {
      drop_candidate(best);
      continue;
    }
    rescanned = false;
    clip_ear(best, out);
  }
  return finish(out);
}

/// The walk's cycle from anchor_ on in `top`'s order: the sides and keys `fast` does not keep.
bool BitsetClipper::clip_by_key_after_walk(TriangleList& out) {
  const Boundary& b = *b_;
  keyed_ = true;
  std::uint32_t v = anchor_;
  do {
    side_[v] = squared_distance(b.pos[v], b.pos[b.next[v]]);
    v = b.next[v];
  } while (v != anchor_);
  do {
    const Point &a = b.pos[b.prev[v]], &t = b.pos[v], &c = b.pos[b.next[v]];
    key_[v] = top_key(a, c, side_[b.prev[v]], side_[v], orient2d(a, t, c));
    v = b.next[v];
  } while (v != anchor_);
  candidates_ = convex_;
  stale_words_ = ~0u;
  return clip_by_key(out);
}

/// `fast`: walk the cycle and clip each ear met; a whole lap without a clip means no ear. A
/// walk that keeps passing nodes that are not ears (a spiral's walls, a Hilbert curve's: ears
/// only near the ends, a lap for each few) takes `top`'s order after walk_budget steps a node.
bool BitsetClipper::clip_by_walk(TriangleList& out) {
  if (words_ == 1) return clip_one_word_by_walk(out);
  std::uint32_t v = anchor_, since_clip = 0;
  const std::uint64_t budget = std::uint64_t{walk_budget} * remaining_;
  for (std::uint64_t steps = 0; remaining_ > 3; ++steps) {
    if (steps == budget) {
      anchor_ = v;
      return clip_by_key_after_walk(out);
    }
    if (convex_.contains(v) && is_ear(v)) {
      const std::uint32_t n = b_->next[v];
      clip_ear(v, out);
      v = n;
      since_clip = 0;
    } else {
      if (++since_clip > remaining_) return false;
      v = b_->next[v];
    }
  }
  return finish(out);
}

bool BitsetClipper::finish(TriangleList& out) {
  if (!convex_.contains(anchor_)) return false;
  const Boundary& b = *b_;
  out.push_back({b.vertex[b.prev[anchor_]], b.vertex[anchor_], b.vertex[b.next[anchor_]]});
  return true;
}

bool BitsetClipper::clip(Boundary& b, std::uint32_t entry, EarHeuristic heuristic,
                         TriangleList& out, const std::vector<std::uint8_t>* shared) {
  b_ = &b;
  keyed_ = heuristic == EarHeuristic::top;
  ear_tests_ = 0;
  load(entry, shared);
  if (remaining_ < 3 || remaining_ > b.size()) return false;
  return keyed_ ? clip_by_key(out) : clip_by_walk(out);
}

}  // namespace pear::detail
