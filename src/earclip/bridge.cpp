#include "bridge.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

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
  // Each hole's ray and visibility search reads the cells it crosses. With few holes one cell
  // is cheapest: a few scans of the edges cost less than placing them in a fine grid (a glyph
  // with two holes spent a tenth of its run building one).
  const std::size_t holes = rings - 1;
  frame_.fit(lo, hi, holes <= few_holes ? 1 : polygon.points.size() / 2 + 1);
  build_grid(static_cast<std::uint32_t>(polygon.points.size()));
  merge_ring(polygon.ring_starts[0]);

  order_.clear();
  for (std::size_t r = 1; r < rings; ++r) order_.push_back(leftmost_node(polygon.ring_starts[r]));
  std::sort(order_.begin(), order_.end(), [&](std::uint32_t a, std::uint32_t c) {
    return lexicographic_less(boundary.pos[a], boundary.pos[c]) ||
           (boundary.pos[a] == boundary.pos[c] && a < c);
  });
  for (std::uint32_t hole : order_) {
    // Decide where the hole attaches before its own edges count, then splice.
    const Point h = boundary.pos[hole];
    const std::uint32_t touching = node_at(h, boundary.pos[boundary.next[hole]]);
    if (touching != UINT32_MAX) {
      merge_ring(hole);
      splice_touching(touching, hole);
      continue;
    }
    const RayHit hit = cast_left(h);
    if (hit.touching_edge != UINT32_MAX) {
      merge_ring(hole);
      splice_into_edge(hit.touching_edge, hole);
    } else if (hit.edge != UINT32_MAX) {
      const std::uint32_t target = node_at(visible_target(h, hit), h);
      merge_ring(hole);
      splice_bridge(target, hole);
    } else {
      unjoined.push_back(hole);  // nothing to the left: the hole lies outside the outer ring
    }
  }
  return unjoined;
}

/// Every ring's nodes and edges into the grid. Edge v runs from node v (the rings are linked as
/// cycles, nothing spliced yet).
void HoleBridger::build_grid(std::uint32_t nodes) {
  const std::size_t cells = frame_.cell_count();
  if (cells == 1) {  // every node and edge in the one cell, in order: nothing to count
    for (CellLists* lists : {&node_cells_, &edge_cells_}) {
      lists->start = {0, nodes};
      lists->head.assign(1, UINT32_MAX);
      lists->added.clear();
      lists->items.resize(nodes);
      std::iota(lists->items.begin(), lists->items.end(), 0u);
    }
  } else {
    fill_cells(nodes);
  }
  edge_start_.resize(nodes);
  out_edge_.resize(nodes);
  for (std::uint32_t v = 0; v < nodes; ++v) edge_start_[v] = out_edge_[v] = v;
  node_merged_.assign(nodes, 0);
  edge_merged_.assign(nodes, 0);
}

/// The nodes' and edges' cells by counting: (cell, item) pairs listed once, cells counted,
/// offsets summed, then filled.
void HoleBridger::fill_cells(std::uint32_t nodes) {
  const std::size_t cells = frame_.cell_count();
  const auto fill = [&](CellLists& lists) {
    lists.start.assign(cells + 1, 0);
    lists.head.assign(cells, UINT32_MAX);
    lists.added.clear();
    for (const auto& [cell, item] : pairs_) ++lists.start[cell + 1];
    for (std::size_t c = 0; c < cells; ++c) lists.start[c + 1] += lists.start[c];
    lists.items.resize(pairs_.size());
    for (const auto& [cell, item] : pairs_) lists.items[lists.start[cell]++] = item;
    // Each start[c] now is where cell c ends: shift back by one cell.
    for (std::size_t c = cells; c > 0; --c) lists.start[c] = lists.start[c - 1];
    lists.start[0] = 0;
  };
  pairs_.clear();
  for (std::uint32_t v = 0; v < nodes; ++v)
    pairs_.push_back({static_cast<std::uint32_t>(
                          frame_.cell(frame_.column(b_->pos[v].x), frame_.row(b_->pos[v].y))),
                      v});
  fill(node_cells_);
  pairs_.clear();
  for (std::uint32_t v = 0; v < nodes; ++v)
    frame_.for_each_cell_on_segment(b_->pos[v], b_->pos[b_->next[v]], [&](std::size_t cell) {
      pairs_.push_back({static_cast<std::uint32_t>(cell), v});
    });
  fill(edge_cells_);
}

std::uint32_t HoleBridger::leftmost_node(std::uint32_t first) const {
  std::uint32_t best = first;
  for (std::uint32_t v = b_->next[first]; v != first; v = b_->next[v])
    if (lexicographic_less(b_->pos[v], b_->pos[best])) best = v;
  return best;
}

/// A node a bridge adds (a copy): merged at once.
void HoleBridger::insert_node(std::uint32_t node) {
  const Point& p = b_->pos[node];
  node_cells_.add(frame_.cell(frame_.column(p.x), frame_.row(p.y)), node);
  if (node_merged_.size() <= node) node_merged_.resize(node + 1, 0);
  node_merged_[node] = 1;
}

/// An edge a bridge adds, from `start`: a new id, merged at once.
std::uint32_t HoleBridger::insert_edge(std::uint32_t start) {
  const auto id = static_cast<std::uint32_t>(edge_start_.size());
  edge_start_.push_back(start);
  edge_merged_.push_back(1);
  if (out_edge_.size() <= start) out_edge_.resize(start + 1, UINT32_MAX);
  out_edge_[start] = id;
  frame_.for_each_cell_on_segment(b_->pos[start], b_->pos[b_->next[start]],
                                  [&](std::size_t cell) { edge_cells_.add(cell, id); });
  return id;
}

/// The ring through `first` joins the boundary: its nodes and edges count from now on.
void HoleBridger::merge_ring(std::uint32_t first) {
  std::uint32_t v = first;
  do {
    node_merged_[v] = 1;
    edge_merged_[v] = 1;
    v = b_->next[v];
  } while (v != first);
}

/// The merged node at exactly p whose interior sector contains `towards`; UINT32_MAX if no
/// merged node lies at p. Falls back to any node at p when no sector contains it strictly.
std::uint32_t HoleBridger::node_at(const Point& p, const Point& towards) const {
  std::uint32_t any = UINT32_MAX, inside = UINT32_MAX;
  node_cells_.for_each(frame_.cell(frame_.column(p.x), frame_.row(p.y)), [&](std::uint32_t node) {
    if (inside != UINT32_MAX || !node_merged_[node] || !(b_->pos[node] == p)) return;
    if (b_->sector_contains(node, towards)) inside = node;
    if (any == UINT32_MAX) any = node;
  });
  return inside != UINT32_MAX ? inside : any;
}

HoleBridger::RayHit HoleBridger::cast_left(const Point& h) const {
  RayHit hit;
  hit.x = -std::numeric_limits<double>::infinity();
  const int row = frame_.row(h.y);
  for (int col = frame_.column(h.x); col >= 0; --col) {
    const double cell_right = frame_.inv_w > 0 ? frame_.x0 + (col + 2) / frame_.inv_w : h.x;
    if (hit.edge != UINT32_MAX && cell_right < hit.x) break;
    edge_cells_.for_each(frame_.cell(col, row), [&](std::uint32_t id) {
      if (!edge_merged_[id]) return;
      const std::uint32_t s = edge_start_[id];
      Point lo = b_->pos[s], hi = b_->pos[b_->next[s]];
      if (lo.y == hi.y) return;  // horizontal: its endpoints end other edges
      if (lo.y > hi.y) std::swap(lo, hi);
      if (h.y < lo.y || h.y > hi.y) return;
      const double side = orient2d(lo, hi, h);
      if (side > 0) return;  // the edge lies to the right of h
      if (side == 0) {
        if (!(h == lo) && !(h == hi)) hit.touching_edge = id;
        return;
      }
      const double x = h.y == lo.y   ? lo.x
                       : h.y == hi.y ? hi.x
                                     : lo.x + (h.y - lo.y) * (hi.x - lo.x) / (hi.y - lo.y);
      if (x > hit.x || (x == hit.x && id < hit.edge)) {
        hit.x = std::min(x, h.x);
        hit.edge = id;
      }
    });
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
      node_cells_.for_each(frame_.cell(col, r), [&](std::uint32_t node) {
        if (!node_merged_[node]) return;
        const Point& v = b_->pos[node];
        if (v == h || v.x > h.x || (v.y - h.y) * up < 0 || (v.y - m.y) * up > 0) return;
        const double es = orient2d(a, c, v);
        if (es != 0 && (es > 0) != (edge_side > 0)) return;  // beyond the hit edge
        const double hs = orient2d(h, m, v) * up;
        if (hs < 0) return;  // on the far side of segment h-M from the ray
        if (better(v)) best = v;
      });
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
