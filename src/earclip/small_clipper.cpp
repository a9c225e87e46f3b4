#include "small_clipper.hpp"

#include <algorithm>
#include <bit>
#include <limits>

#include "core/ear_test.hpp"
#include "core/pinches.hpp"

namespace pear::detail {
namespace {

/// For x > 0: about 2^32 log2(x) plus a constant, monotone in x (the exponent and the top of
/// the mantissa, as EarQueue::length_bucket reads them, with finer steps).
std::int64_t log_scale(double x) {
  return std::bit_cast<std::int64_t>(x) >> 20;
}

double squared_distance(const Point& u, const Point& w) {
  const double dx = u.x - w.x, dy = u.y - w.y;
  return dx * dx + dy * dy;
}

/// `top`'s order (ear_bucket in ear_test.hpp) without roots or buckets: the squared diagonal
/// over the fourth root of the shape (twice the area over the squared sides), on the log scale.
/// `area` is twice the ear's area, `before` and `after` its sides' squared lengths; the key only
/// counts for convex corners (area > 0).
std::int64_t top_key(const Point& a, const Point& c, double before, double after, double area) {
  const double diagonal = squared_distance(a, c);
  const double sides = before + after + diagonal;
  const std::int64_t key = 4 * log_scale(diagonal) - log_scale(area) + log_scale(sides);
  // Zero or overflowing lengths: the ear waits, as the bucket queue's last bucket makes it.
  return diagonal > 0 && sides < INFINITY ? key : std::numeric_limits<std::int64_t>::max();
}

/// Node v's bit in word w of a NodeSet, 0 when v lies in another word.
std::uint64_t bit_in_word(std::uint32_t v, std::uint32_t w) {
  return v / 64 == w ? std::uint64_t{1} << (v % 64) : 0;
}

}  // namespace

void SmallClipper::Slabs::build(std::span<const Point> points, double Point::*axis,
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

/// shared_ marks every node whose position another node has (find_pinches, as the general
/// clipper marks its pinches).
void SmallClipper::mark_repeated_positions() {
  live_.assign(b_.size(), 1);
  find_pinches(b_, live_, b_.size(), pinch_, position_table_);
  for (std::uint32_t u = 0; u < b_.size(); ++u)
    if (pinch_[u]) shared_.add(u);
}

/// One pass over the ring: links, sides, and each corner's turn and key, the sets written a
/// word at a time (refresh() does the same for one node).
void SmallClipper::load(std::span<const Point> points, std::span<const std::uint32_t> original) {
  const auto n = static_cast<std::uint32_t>(points.size());
  b_.pos.assign(points.begin(), points.end());
  b_.vertex.assign(original.begin(), original.end());
  b_.prev.resize(n);
  b_.next.resize(n);
  key_.resize(n);
  side_.resize(n);
  words_ = (n + 63) / 64;
  stale_words_ = ~0u;
  reflex_.words.fill(0);
  convex_.words.fill(0);
  shared_.words.fill(0);
  const Point* p = points.data();
  Point before = p[n - 1];
  double side_before = squared_distance(before, p[0]);
  std::uint64_t reflex = 0, convex = 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t after = i + 1 == n ? 0 : i + 1;
    const Point &t = p[i], &c = p[after];
    b_.prev[i] = i == 0 ? n - 1 : i - 1;
    b_.next[i] = after;
    const double side = squared_distance(t, c), turn = orient2d(before, t, c);
    side_[i] = side;
    const std::uint64_t bit = std::uint64_t{1} << (i % 64);
    convex |= bit & (std::uint64_t{0} - (turn > 0));
    reflex |= bit & (std::uint64_t{0} - (turn < 0));
    if (keyed_) key_[i] = top_key(before, c, side_before, side, turn);
    if (i % 64 == 63 || after == 0) {
      convex_.words[i / 64] = convex;
      reflex_.words[i / 64] = reflex;
      convex = reflex = 0;
    }
    before = t;
    side_before = side;
  }
  candidates_ = convex_;
  slabbed_ = words_ > 1;
  if (!slabbed_) {
    for (std::uint32_t i = 0; i < n; ++i) columns_.x[i] = p[i].x, columns_.y[i] = p[i].y;
  } else {
    xs_.build(points, &Point::x, words_);
    ys_.build(points, &Point::y, words_);
  }
  remaining_ = n;
  anchor_ = 0;
}

/// v's angle is new (it shrank when a neighbour was clipped): convex, reflex or collinear, and
/// if convex a candidate again with its new key.
inline void SmallClipper::refresh(std::uint32_t v) {
  const Point &a = b_.pos[b_.prev[v]], &t = b_.pos[v], &c = b_.pos[b_.next[v]];
  const double turn = orient2d(a, t, c);
  // Without branches: whether a corner is convex is as good as random to the branch predictor.
  const std::uint64_t bit = std::uint64_t{1} << (v % 64);
  const std::uint64_t convex = bit & (std::uint64_t{0} - (turn > 0));
  const std::uint64_t reflex = bit & (std::uint64_t{0} - (turn < 0));
  const std::uint32_t w = v / 64;
  reflex_.words[w] = (reflex_.words[w] & ~bit) | reflex;
  convex_.words[w] = (convex_.words[w] & ~bit) | convex;
  candidates_.words[w] = (candidates_.words[w] & ~bit) | convex;
  stale_words_ |= 1u << w;
  if (keyed_) key_[v] = top_key(a, c, side_[b_.prev[v]], side_[v], turn);
}

/// detail::is_ear with the reflex nodes from a bit set: no collinear chain along the diagonal
/// from its ends, and no strictly reflex node that blocks (ear_test.hpp's blocks()).
bool SmallClipper::is_ear(std::uint32_t v) const {
  const std::uint32_t p = b_.prev[v], n = b_.next[v];
  const Point &a = b_.pos[p], &t = b_.pos[v], &c = b_.pos[n];
  const Point &before = b_.pos[b_.prev[p]], &after = b_.pos[b_.next[n]];
  // Both orientations, then one branch: whether a neighbour's neighbour lies in the diagonal's
  // box is a coin toss for the predictor (7% of a county's call), on its line it is rare.
  const double turn_after = orient2d(a, c, after), turn_before = orient2d(a, c, before);
  if ((turn_after == 0) | (turn_before == 0)) {
    if (turn_after == 0 && on_open_segment(after, a, c)) return false;
    if (turn_before == 0 && on_open_segment(before, a, c)) return false;
  }
  const double x0 = std::min({a.x, t.x, c.x}), x1 = std::max({a.x, t.x, c.x});
  const double y0 = std::min({a.y, t.y, c.y}), y1 = std::max({a.y, t.y, c.y});
  const Point* pos = b_.pos.data();
  // The ear's own corners cannot block it; nodes at a repeated position may, whatever their
  // angle. Each node left is tested for the box first: most lie outside.
  const auto blocked = [&](std::uint64_t near, std::uint32_t w) {
    near &= (reflex_.words[w] | shared_.words[w]) &
            ~(bit_in_word(p, w) | bit_in_word(v, w) | bit_in_word(n, w));
    for (std::uint64_t set = near; set != 0; set &= set - 1) {
      const std::uint32_t q = w * 64 + static_cast<std::uint32_t>(std::countr_zero(set));
      const Point& x = pos[q];
      if (!((x.x >= x0) & (x.x <= x1) & (x.y >= y0) & (x.y <= y1))) continue;
      if (blocks(b_, AllLinks{}, p, v, n, q, a, t, c, x)) return true;
    }
    return false;
  };
  // One word: the nodes in the box, found a few at a time without a branch, then only those.
  if (!slabbed_) return !blocked(points_in_box(columns_, b_.size(), {x0, y0, x1, y1}), 0);
  const std::uint32_t sx0 = xs_.slab(x0), sx1 = xs_.slab(x1);
  const std::uint32_t sy0 = ys_.slab(y0), sy1 = ys_.slab(y1);
  for (std::uint32_t w = 0; w < words_; ++w) {
    if (blocked(xs_.upto[sx1].words[w] & xs_.from[sx0].words[w] & ys_.upto[sy1].words[w] &
                    ys_.from[sy0].words[w],
                w))
      return false;
  }
  return true;
}

void SmallClipper::clip(std::uint32_t v, TriangleList& out) {
  const std::uint32_t p = b_.prev[v], n = b_.next[v];
  out.push_back({b_.vertex[p], b_.vertex[v], b_.vertex[n]});
  b_.link(p, n);
  if (keyed_) side_[p] = squared_distance(b_.pos[p], b_.pos[n]);
  convex_.erase(v);
  drop_candidate(v);
  anchor_ = n;
  --remaining_;
  refresh(p);
  refresh(n);
}

void SmallClipper::drop_candidate(std::uint32_t v) {
  candidates_.erase(v);
  stale_words_ |= 1u << (v / 64);
}

/// The candidate of word w with the smallest key, the lowest node among equals; UINT32_MAX for
/// none.
std::uint32_t SmallClipper::best_in_word(std::uint32_t w) const {
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
std::uint32_t SmallClipper::best_candidate() {
  if (words_ == 1) return best_in_word(0);
  std::uint32_t best = UINT32_MAX;
  for (std::uint32_t w = 0; w < words_; ++w) {
    if ((stale_words_ >> w) & 1) word_best_[w] = best_in_word(w);
    const std::uint32_t v = word_best_[w];
    if (v != UINT32_MAX && (best == UINT32_MAX || key_[v] < key_[best])) best = v;
  }
  stale_words_ = 0;
  return best;
}

/// `top`: the candidate with the smallest key that is an ear. A node found blocked waits until
/// its angle changes; when none is left, one pass over every convex node (a blocker may have
/// left) before giving up.
bool SmallClipper::clip_by_key(TriangleList& out) {
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
    clip(best, out);
  }
  return finish(out);
}

/// `fast`: walk the ring and clip each ear met; a whole lap without a clip means no ear.
bool SmallClipper::clip_by_walk(TriangleList& out) {
  std::uint32_t v = anchor_, since_clip = 0;
  while (remaining_ > 3) {
    if (convex_.contains(v) && is_ear(v)) {
      const std::uint32_t n = b_.next[v];
      clip(v, out);
      v = n;
      since_clip = 0;
    } else {
      if (++since_clip > remaining_) return false;
      v = b_.next[v];
    }
  }
  return finish(out);
}

bool SmallClipper::finish(TriangleList& out) {
  if (!convex_.contains(anchor_)) return false;
  out.push_back({b_.vertex[b_.prev[anchor_]], b_.vertex[anchor_], b_.vertex[b_.next[anchor_]]});
  return true;
}

bool SmallClipper::run(std::span<const Point> points, std::span<const std::uint32_t> original,
                       EarHeuristic heuristic, TriangleList& out, bool repeated) {
  if (points.size() < 3 || points.size() > max_nodes) return false;
  const std::size_t before = out.size();
  keyed_ = heuristic == EarHeuristic::top;
  load(points, original);
  if (repeated) mark_repeated_positions();
  const bool done = keyed_ ? clip_by_key(out) : clip_by_walk(out);
  if (!done) out.resize(before);
  return done;
}

}  // namespace pear::detail
