#include "bridge.hpp"

#include <algorithm>
#include <limits>

namespace pear::detail {
std::vector<std::uint32_t> HoleBridger::join(const CleanPolygon& polygon, Boundary& boundary) {
  std::vector<std::uint32_t> unjoined;
  const std::size_t rings = polygon.ring_count();
  if (rings < 2) return unjoined;
  b_ = &boundary;
  Point lo = boundary.pos[0], hi = boundary.pos[0];
  for (const Point& p : polygon.points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  frame_.fit(lo, hi, polygon.points.size() / 2 + 1);
  node_cells_.assign(frame_.cell_count(), {});
  edge_cells_.assign(frame_.cell_count(), {});
  edge_start_.clear();
  out_edge_.assign(polygon.points.size() + 2 * rings, UINT32_MAX);
  insert_ring(polygon.ring_starts[0]);

  order_.clear();
  for (std::size_t r = 1; r < rings; ++r) order_.push_back(leftmost_node(polygon.ring_starts[r]));
  std::sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t c) {
    return lexicographic_less(boundary.pos[a], boundary.pos[c]) ||
           (boundary.pos[a] == boundary.pos[c] && a < c);
  });
  for (std::uint32_t hole : order_) {
    // Decide where the hole attaches before its own edges enter the grid, then splice.
    const Point h = boundary.pos[hole];
    const std::uint32_t touching = node_at(h, boundary.pos[boundary.next[hole]]);
    if (touching != UINT32_MAX) {
      insert_ring(hole);
      splice_touching(touching, hole);
      continue;
    }
    const RayHit hit = cast_left(h);
    if (hit.touching_edge != UINT32_MAX) {
      insert_ring(hole);
      splice_into_edge(hit.touching_edge, hole);
    } else if (hit.edge != UINT32_MAX) {
      const std::uint32_t target = node_at(visible_target(h, hit), h);
      insert_ring(hole);
      splice_bridge(target, hole);
    } else {
      unjoined.push_back(hole);  // nothing to the left: the hole lies outside the outer ring
    }
  }
  return unjoined;
}

std::uint32_t HoleBridger::leftmost_node(std::uint32_t first) const {
  std::uint32_t best = first;
  for (std::uint32_t v = b_->next[first]; v != first; v = b_->next[v])
    if (lexicographic_less(b_->pos[v], b_->pos[best])) best = v;
  return best;
}

void HoleBridger::insert_node(std::uint32_t node) {
  const Point& p = b_->pos[node];
  node_cells_[frame_.cell(frame_.column(p.x), frame_.row(p.y))].push_back(node);
}

std::uint32_t HoleBridger::insert_edge(std::uint32_t start) {
  const auto id = static_cast<std::uint32_t>(edge_start_.size());
  edge_start_.push_back(start);
  if (out_edge_.size() <= start) out_edge_.resize(start + 1, UINT32_MAX);
  out_edge_[start] = id;
  frame_.for_each_cell_on_segment(b_->pos[start], b_->pos[b_->next[start]],
                                  [&](std::size_t cell) { edge_cells_[cell].push_back(id); });
  return id;
}

void HoleBridger::insert_ring(std::uint32_t first) {
  std::uint32_t v = first;
  do {
    insert_node(v);
    if (out_edge_.size() <= v || out_edge_[v] == UINT32_MAX) insert_edge(v);
    v = b_->next[v];
  } while (v != first);
}

/// The merged node at exactly p whose interior sector contains `towards`; UINT32_MAX if no
/// merged node lies at p. Falls back to any node at p when no sector contains it strictly.
std::uint32_t HoleBridger::node_at(const Point& p, const Point& towards) const {
  std::uint32_t any = UINT32_MAX;
  for (std::uint32_t node : node_cells_[frame_.cell(frame_.column(p.x), frame_.row(p.y))]) {
    if (!(b_->pos[node] == p)) continue;
    if (b_->sector_contains(node, towards)) return node;
    if (any == UINT32_MAX) any = node;
  }
  return any;
}

HoleBridger::RayHit HoleBridger::cast_left(const Point& h) const {
  RayHit hit;
  hit.x = -std::numeric_limits<double>::infinity();
  const int row = frame_.row(h.y);
  for (int col = frame_.column(h.x); col >= 0; --col) {
    const double cell_right = frame_.inv_w > 0 ? frame_.x0 + (col + 2) / frame_.inv_w : h.x;
    if (hit.edge != UINT32_MAX && cell_right < hit.x) break;
    for (std::uint32_t id : edge_cells_[frame_.cell(col, row)]) {
      const std::uint32_t s = edge_start_[id];
      Point lo = b_->pos[s], hi = b_->pos[b_->next[s]];
      if (lo.y == hi.y) continue;  // horizontal: its endpoints end other edges
      if (lo.y > hi.y) std::swap(lo, hi);
      if (h.y < lo.y || h.y > hi.y) continue;
      const double side = orient2d(lo, hi, h);
      if (side > 0) continue;  // the edge lies to the right of h
      if (side == 0) {
        if (!(h == lo) && !(h == hi)) hit.touching_edge = id;
        continue;
      }
      const double x = h.y == lo.y   ? lo.x
                       : h.y == hi.y ? hi.x
                                     : lo.x + (h.y - lo.y) * (hi.x - lo.x) / (hi.y - lo.y);
      if (x > hit.x || (x == hit.x && id < hit.edge)) {
        hit.x = std::min(x, h.x);
        hit.edge = id;
      }
    }
  }
  return hit;
}

/// Eberly's method: an endpoint M of the hit edge, unless vertices lie in the triangle
/// (h, crossing, M); then the one seen at the smallest angle from the ray (nearest on ties).
/// Every decision is an exact orientation or comparison; the crossing x only bounds the search.
Point HoleBridger::visible_target(const Point& h, const RayHit& hit) const {
  const std::uint32_t s = edge_start_[hit.edge];
  const Point a = b_->pos[s], c = b_->pos[b_->next[s]];
  if (a.y == h.y && a.x <= h.x) return a;
  if (c.y == h.y && c.x <= h.x) return c;
  // The endpoint with the smaller x: the triangle (h, crossing, M) then lies left of h, where
  // the hole being joined cannot reach.
  const Point m = a.x < c.x || (a.x == c.x && a.y < c.y) ? a : c;
  const double up = m.y > h.y ? 1 : -1;
  const double edge_side = orient2d(a, c, h);
  Point best = m;
  const auto better = [&](const Point& v) {
    const double turn = orient2d(h, best, v) * up;  // > 0: v is closer to the ray
    if (turn != 0) return turn > 0;
    return std::abs(v.x - h.x) + std::abs(v.y - h.y) <
           std::abs(best.x - h.x) + std::abs(best.y - h.y);
  };
  const int c0 = frame_.column(std::min(hit.x, m.x)), c1 = frame_.column(h.x);
  const int r0 = frame_.row(std::min(h.y, m.y)), r1 = frame_.row(std::max(h.y, m.y));
  for (int r = r0; r <= r1; ++r) {
    for (int col = c0; col <= c1; ++col) {
      for (std::uint32_t node : node_cells_[frame_.cell(col, r)]) {
        const Point& v = b_->pos[node];
        if (v == h || v.x > h.x || (v.y - h.y) * up < 0 || (v.y - m.y) * up > 0) continue;
        const double es = orient2d(a, c, v);
        if (es != 0 && (es > 0) != (edge_side > 0)) continue;  // beyond the hit edge
        const double hs = orient2d(h, m, v) * up;
        if (hs < 0) continue;  // on the far side of segment h-M from the ray
        if (better(v)) best = v;
      }
    }
  }
  return best;
}

void HoleBridger::splice_bridge(std::uint32_t target, std::uint32_t hole) {
  Boundary& b = *b_;
  const auto [target_copy, hole_copy] = b.add_diagonal(target, hole);
  // The edge that left `target` now leaves its copy; the bridge leaves `target`.
  out_edge_.resize(b.size(), UINT32_MAX);
  const std::uint32_t old_edge = out_edge_[target];
  edge_start_[old_edge] = target_copy;
  out_edge_[target_copy] = old_edge;
  out_edge_[target] = UINT32_MAX;
  insert_edge(target);
  insert_node(target_copy);
  insert_node(hole_copy);
  insert_edge(hole_copy);
}

/// The hole shares a point with the merged boundary: link the rings there, no bridge needed.
void HoleBridger::splice_touching(std::uint32_t target, std::uint32_t hole) {
  Boundary& b = *b_;
  const std::uint32_t after_target = b.next[target], after_hole = b.next[hole];
  b.link(target, after_hole);
  b.link(hole, after_target);
  // `target` now leaves along the hole's first edge, `hole` along target's old edge.
  const std::uint32_t target_edge = out_edge_[target], hole_edge = out_edge_[hole];
  edge_start_[target_edge] = hole;
  edge_start_[hole_edge] = target;
  std::swap(out_edge_[target], out_edge_[hole]);
}

/// The hole's vertex lies inside a merged edge (a T-junction): run the boundary through it.
void HoleBridger::splice_into_edge(std::uint32_t edge, std::uint32_t hole) {
  Boundary& b = *b_;
  const std::uint32_t start = edge_start_[edge], end = b.next[start];
  const std::uint32_t entry = b.copy(hole), before_hole = b.prev[hole];
  b.link(start, entry);
  b.link(entry, b.next[hole]);
  b.link(before_hole, hole);
  b.link(hole, end);
  out_edge_.resize(b.size(), UINT32_MAX);
  // The edge from `hole` keeps its id but now leaves the copy; `hole` leaves towards `end`.
  const std::uint32_t hole_edge = out_edge_[hole];
  if (hole_edge != UINT32_MAX) edge_start_[hole_edge] = entry, out_edge_[entry] = hole_edge;
  out_edge_[hole] = UINT32_MAX;
  insert_node(entry);
  insert_edge(hole);
}

}  // namespace pear::detail
