// The ear test (paper §1.1, FIST's handling of coincident nodes), shared by the sequential
// clipper and the parallel variants. `Links` says whose links may be read: a parallel task
// reads only the links of nodes it owns, and counts any other node on the triangle's boundary
// as blocking, which only ever rejects an ear (never accepts a wrong one).
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>

#include "boundary.hpp"
#include "ear_queue.hpp"
#include "pear/pear.hpp"
#include "reflex_grid.hpp"

namespace pear::detail {

/// Every node's links may be read (one thread owns the whole boundary).
struct AllLinks {
  bool readable(std::uint32_t) const { return true; }
};

/// q sits exactly on a corner of the ear; the corner's wedge is bounded by the rays towards
/// wedge_a and wedge_b. q spoils the ear if one of its edges runs into the wedge. (Whether the
/// diagonal runs into q's own sector need not be asked: in a valid boundary that would put the
/// corner's own edge into the wedge, and a strictly reflex node into the triangle. Asking it
/// blocked every ear of lobes chained at one point, whose local sectors overlap.)
inline bool coincident_blocks(const Boundary& b, std::uint32_t q, const Point& wedge_a,
                              const Point& wedge_b) {
  const Point& corner = b.pos[q];
  const auto in_wedge = [&](const Point& y) {
    return orient2d(corner, wedge_a, y) > 0 && orient2d(wedge_b, corner, y) > 0;
  };
  return in_wedge(b.pos[b.prev[q]]) || in_wedge(b.pos[b.next[q]]);
}

/// blocks() for q on the boundary of the ear's triangle (o1, o3: its orientation against the
/// ear's sides a-t and c-a, both >= 0, one of the three orientations 0). Rare: kept out of line.
template <class Links>
bool blocks_on_boundary(const Boundary& b, const Links& links, std::uint32_t p, std::uint32_t v,
                        std::uint32_t n, std::uint32_t q, double o1, double o3) {
  const Point &a = b.pos[p], &t = b.pos[v], &c = b.pos[n], &x = b.pos[q];
  if (o3 == 0 && x != a && x != c) return true;  // on the open diagonal
  if (!links.readable(q)) return true;
  if (x == a) return coincident_blocks(b, q, t, c);
  if (x == c) return coincident_blocks(b, q, a, t);
  if (x == t) return coincident_blocks(b, q, c, a);
  const Point &qp = b.pos[b.prev[q]], &qn = b.pos[b.next[q]];
  if (o1 == 0) return orient2d(a, t, qp) > 0 || orient2d(a, t, qn) > 0;
  return orient2d(t, c, qp) > 0 || orient2d(t, c, qn) > 0;
}

/// Whether hashed node q at x spoils the ear (p, v, n) with corners a, t, c. Strictly inside
/// always does; on the triangle's boundary it does when its edges reach into the triangle
/// (paper Fig. 1(b)). The common answers (outside, inside) are inline.
template <class Links>
inline bool blocks(const Boundary& b, const Links& links, std::uint32_t p, std::uint32_t v,
                   std::uint32_t n, std::uint32_t q, const Point& a, const Point& t, const Point& c,
                   const Point& x) {
  const double o1 = orient2d(a, t, x);
  if (o1 < 0) return false;
  const double o2 = orient2d(t, c, x);
  if (o2 < 0) return false;
  const double o3 = orient2d(c, a, x);
  if (o3 < 0) return false;
  if (o1 > 0 && o2 > 0 && o3 > 0) return true;
  return blocks_on_boundary(b, links, p, v, n, q, o1, o3);
}

/// The turns `before` and `after` will have at a and c once the ear is clipped, computed as a
/// refresh of those corners computes them: the bit-set clipper hands them on to its refreshes.
struct DiagonalTurns {
  double before = 0;  ///< orient2d(before, a, c)
  double after = 0;   ///< orient2d(a, c, after)
};

/// Whether the diagonal a-c of an ear is clear at its ends: no boundary edge runs along it from
/// one of them (a collinear chain there is not hashed as reflex); `before` precedes a on the
/// boundary, `after` follows c. Both orientations (into `turns`), then one branch: whether a
/// neighbour's neighbour lies on the diagonal's line is rare, whether it lies in its box a coin
/// toss for the branch predictor.
inline bool diagonal_clear_at_ends(const Point& a, const Point& c, const Point& before,
                                   const Point& after, DiagonalTurns& turns) {
  turns = {orient2d(before, a, c), orient2d(a, c, after)};
  if ((turns.after == 0) | (turns.before == 0)) {
    if (turns.after == 0 && on_open_segment(after, a, c)) return false;
    if (turns.before == 0 && on_open_segment(before, a, c)) return false;
  }
  return true;
}

/// The same with the points by value: orient2d's exact stage is a call, after which anything
/// read through a reference would be read again.
inline bool diagonal_clear_at_ends_of(Point a, Point c, Point before, Point after,
                                      DiagonalTurns& turns) {
  return diagonal_clear_at_ends(a, c, before, after, turns);
}

/// Whether v is an ear: strictly convex, the diagonal clear at its ends, and no hashed node
/// blocks it. `near(a, t, c, box, visit)` calls visit(entry) for the hashed nodes within `box`,
/// the triangle's bounding box (no node outside it can block), until visit returns true, and
/// returns whether it did. Reads the links of v, its neighbours and of blocking candidates
/// that `links` allows. When v is an ear, `turns` holds the turns its neighbours will have once
/// it is clipped: their refreshes need not compute them again.
template <class Links, class Near>
bool is_ear(const Boundary& b, const Links& links, std::uint32_t v, Near&& near,
            DiagonalTurns& turns) {
  const std::uint32_t p = b.prev[v], n = b.next[v];
  const Point a = b.pos[p], t = b.pos[v], c = b.pos[n];
  if (!(orient2d(a, t, c) > 0) ||
      !diagonal_clear_at_ends_of(a, c, b.pos[b.prev[p]], b.pos[b.next[n]], turns))
    return false;
  const Box box{std::min({a.x, t.x, c.x}), std::min({a.y, t.y, c.y}), std::max({a.x, t.x, c.x}),
                std::max({a.y, t.y, c.y})};
  return !near(a, t, c, box, [&](const ReflexGrid::Entry& e) {
    if (e.node == p || e.node == v || e.node == n) return false;
    return blocks(b, links, p, v, n, e.node, a, t, c, e.pos);
  });
}

/// is_ear without the turns.
template <class Links, class Near>
bool is_ear(const Boundary& b, const Links& links, std::uint32_t v, Near&& near) {
  DiagonalTurns turns;
  return is_ear(b, links, v, near, turns);
}

/// `top` pops ears in key order across the whole polygon, and waits for memory, not arithmetic.
/// The bucket just popped holds the next candidates (last in, first out): fetch the arrays of
/// the one `distance` pops ahead, and (`follow_links`: only where no other thread writes links)
/// the neighbours' positions of the one half as far, whose links are in cache by then.
/// Always inlined: GCC 12 takes a function made only of prefetches for one without effects
/// and drops the call (no prefetch was left in libpear from 1411fd1 on: `top`'s clip on
/// Eurasia lost the 20% the prefetch had won).
[[gnu::always_inline]] inline void prefetch_upcoming(const EarQueue& queue, const Boundary& b,
                                                     const std::uint32_t* stamps,
                                                     bool follow_links) {
  constexpr std::size_t distance = 8;
  const std::span<const EarQueue::Candidate> rest = queue.bucket_rest();
  if (rest.size() >= distance) {
    const std::uint32_t far = rest[rest.size() - distance].node;
    __builtin_prefetch(&b.pos[far]);
    __builtin_prefetch(&b.prev[far]);
    __builtin_prefetch(&b.next[far]);
    __builtin_prefetch(&stamps[far]);
  }
  if (follow_links && rest.size() >= distance / 2) {
    const std::uint32_t near = rest[rest.size() - distance / 2].node;
    __builtin_prefetch(&b.pos[b.prev[near]]);
    __builtin_prefetch(&b.pos[b.next[near]]);
  }
}

/// The shape of ear v: twice the area over the sum of the squared sides, 1/sqrt(3) for an
/// equilateral triangle, tending to 0 for slivers.
inline double ear_shape(const Boundary& b, std::uint32_t v) {
  const Point &a = b.pos[b.prev[v]], &t = b.pos[v], &c = b.pos[b.next[v]];
  const auto sq = [](const Point& u, const Point& w) {
    const double dx = u.x - w.x, dy = u.y - w.y;
    return dx * dx + dy * dy;
  };
  const double sides = sq(a, t) + sq(t, c) + sq(c, a);
  return sides > 0 ? orient2d_inexact(a, t, c) / sides : 0;
}

inline double squared_distance(const Point& u, const Point& w) {
  const double dx = u.x - w.x, dy = u.y - w.y;
  return dx * dx + dy * dy;
}

/// For x > 0: 2^32 (log2(x) + 1023), piecewise linear between powers of two (the exponent and
/// the top of the mantissa read from the bits), monotone in x.
inline std::int64_t log_scale(double x) {
  return std::bit_cast<std::int64_t>(x) >> 20;
}

/// `top`'s order of the ear whose diagonal runs from a to c: the squared diagonal over the
/// fourth root of the ear's shape (twice its area over its squared sides: 1/sqrt(3) for an
/// equilateral triangle, tending to 0 for slivers), on log_scale's scale (4 x 2^32 per power of
/// two of that ratio); smaller first. So short diagonals go first, and a sliver waits until
/// its diagonal is the short one among its peers. Measured on the corpus (3,022 polygons) this
/// gives the CDT's average smallest angle (24.8 against 24.5 degrees) and less deviation from
/// 60 degrees than either order alone (33.1; shortest diagonal 34.4; FIST's best shape first
/// 36.0 and only 21.3 degrees). `area` is orient2d(a, t, c), `before` and `after` the sides'
/// squared lengths; a key only counts for a convex corner (area > 0). Both clippers order by
/// it: the bit-set clipper compares keys, the queue buckets them (ear_bucket).
inline std::int64_t top_key(const Point& a, const Point& c, double before, double after,
                            double area) {
  const double diagonal = squared_distance(a, c);
  const double sides = before + after + diagonal;
  const std::int64_t key = 4 * log_scale(diagonal) - log_scale(area) + log_scale(sides);
  // Zero or overflowing lengths: the ear waits (the queue's last bucket).
  return diagonal > 0 && sides < INFINITY ? key : std::numeric_limits<std::int64_t>::max();
}

/// The queue bucket of the convex ear v, whose corner turns by `turn` (orient2d): "top" its
/// key, 16 buckets per power of two of the ratio top_key orders by (4 x 2^32 a power of two,
/// so 2^30 a bucket), the offset placing an equilateral ear with a unit diagonal where the
/// length_bucket of 1 lies; "fast" (when its walk hands over, and in partition-and-cut's
/// chains) the squared diagonal's length_bucket, so short diagonals go first, which keeps
/// triangles and ear tests small.
inline int ear_bucket(const Boundary& b, std::uint32_t v, EarHeuristic heuristic, double turn) {
  const Point &a = b.pos[b.prev[v]], &t = b.pos[v], &c = b.pos[b.next[v]];
  if (heuristic == EarHeuristic::fast) return EarQueue::length_bucket(squared_distance(a, c));
  const std::int64_t key = top_key(a, c, squared_distance(a, t), squared_distance(t, c), turn);
  if (key == std::numeric_limits<std::int64_t>::max()) return EarQueue::bucket_count - 1;
  constexpr std::int64_t offset = (std::int64_t{4 * 1023} << 2) - 2041;
  return static_cast<int>(
      std::clamp<std::int64_t>((key >> 30) - offset, 0, EarQueue::bucket_count - 1));
}

}  // namespace pear::detail
