// FIST's fallback cascade for when no ear is left although more than three nodes remain.
// Each step removes at least one node, so clipping always ends, in at most n steps.
#include <cmath>

#include "ear_clipper.hpp"

namespace pear::detail {
namespace {

bool segments_cross(const Point& a, const Point& b, const Point& c, const Point& d) {
  const double o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  const double o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  return ((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0));
}

}  // namespace

/// 1. Degenerate remnants of a valid boundary: a spike that returns to its start (the last bit
///    of a lobe of a self-touching ring) or a zero-length edge goes away without a triangle.
/// 2. A local self-crossing (edges before and after an ear cross): clip that ear (best effort).
/// 3. Otherwise clip the best-shaped convex corner (best effort); with none, drop a node.
bool EarClipper::fall_back(std::uint32_t near) {
  Boundary& b = *b_;
  std::uint32_t crossing = UINT32_MAX, convex = UINT32_MAX;
  double best_quality = -1;
  std::uint32_t v = near;
  do {
    const std::uint32_t p = b.prev[v], n = b.next[v];
    if (b.pos[p] == b.pos[n] || b.pos[v] == b.pos[n]) {
      const std::uint32_t gone = b.pos[v] == b.pos[n] ? n : v;
      const std::uint32_t also = gone == v ? n : UINT32_MAX;
      for (std::uint32_t u : {gone, also})
        if (u != UINT32_MAX && remaining_ > 2) remove(u);
      touched_ = p;
      return remaining_ >= 3;
    }
    const double turn = b.turn(v);
    if (turn > 0) {
      if (crossing == UINT32_MAX &&
          segments_cross(b.pos[b.prev[p]], b.pos[p], b.pos[n], b.pos[b.next[n]]))
        crossing = v;
      const double q = quality(v);
      if (q > best_quality) best_quality = q, convex = v;
    }
    v = n;
  } while (v != near);

  if (!best_effort_) best_effort_vertex_ = b.vertex[near];
  best_effort_ = true;
  const std::uint32_t chosen = crossing != UINT32_MAX ? crossing : convex;
  if (chosen != UINT32_MAX) {
    touched_ = b.prev[chosen];
    clip(chosen);
  } else {
    touched_ = b.prev[near];
    remove(near);
  }
  return remaining_ >= 3;
}

/// The last three nodes form the last triangle, unless they are degenerate.
void EarClipper::finish(std::uint32_t any) {
  if (remaining_ != 3) return;
  Boundary& b = *b_;
  const double turn = b.turn(any);
  if (turn > 0)
    out_->push_back({b.vertex[b.prev[any]], b.vertex[any], b.vertex[b.next[any]]});
  else if (turn < 0 && !best_effort_)
    best_effort_ = true, best_effort_vertex_ = b.vertex[any];
  remaining_ = 0;
}

}  // namespace pear::detail
