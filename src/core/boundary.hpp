// The boundary as the ear clipper sees it: a cyclic doubly linked list of nodes. A node is one
// occurrence of a vertex on the boundary; bridges and splits make several nodes of one vertex.
#pragma once

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/fill_vector.hpp"
#include "geometry/segments.hpp"
#include "pear/geometry.hpp"
#include "pear/predicates.hpp"

namespace pear::detail {

struct Boundary {
  // Filled in parts on large polygons: resize() leaves them to the tasks (fill_vector.hpp).
  FillVector<Point> pos;             ///< position of each node (copied for locality)
  FillVector<std::uint32_t> vertex;  ///< the caller's index of the node's vertex
  FillVector<std::uint32_t> prev, next;

  std::uint32_t size() const { return static_cast<std::uint32_t>(pos.size()); }
  void reserve(std::size_t nodes) {
    pos.reserve(nodes);
    vertex.reserve(nodes);
    prev.reserve(nodes);
    next.reserve(nodes);
  }
  void clear() {
    pos.clear();
    vertex.clear();
    prev.clear();
    next.clear();
  }
  /// `nodes` nodes; new ones unwritten (their ids handed out before they are filled).
  void resize(std::size_t nodes) {
    pos.resize(nodes);
    vertex.resize(nodes);
    prev.resize(nodes);
    next.resize(nodes);
  }
  std::uint32_t add(Point p, std::uint32_t caller_index) {
    pos.push_back(p);
    vertex.push_back(caller_index);
    prev.push_back(0);
    next.push_back(0);
    return size() - 1;
  }
  /// A new node at the same vertex as `node`, not yet linked.
  std::uint32_t copy(std::uint32_t node) { return add(pos[node], vertex[node]); }
  void link(std::uint32_t a, std::uint32_t b) {
    next[a] = b;
    prev[b] = a;
  }
  void unlink(std::uint32_t node) { link(prev[node], next[node]); }

  /// Adds the diagonal from -> to as a doubled edge: from's old successor moves to a copy of
  /// from, to's old predecessor to a copy of to. Between two cycles this joins them (a bridge
  /// to a hole); within one cycle it splits it in two (to -> ... -> from -> to, and the copies).
  /// Returns the copies {of from, of to}.
  std::pair<std::uint32_t, std::uint32_t> add_diagonal(std::uint32_t from, std::uint32_t to) {
    const std::uint32_t from_copy = copy(from), to_copy = copy(to);
    link_diagonal(from, to, from_copy, to_copy);
    return {from_copy, to_copy};
  }
  /// add_diagonal's links, with copies already made (their ids handed out beforehand).
  void link_diagonal(std::uint32_t from, std::uint32_t to, std::uint32_t from_copy,
                     std::uint32_t to_copy) {
    const std::uint32_t after_from = next[from], before_to = prev[to];
    link(from, to);
    link(before_to, to_copy);
    link(to_copy, from_copy);
    link(from_copy, after_from);
  }

  /// Turn at `node`: > 0 convex, < 0 reflex, 0 collinear (exact).
  double turn(std::uint32_t node) const {
    return orient2d(pos[prev[node]], pos[node], pos[next[node]]);
  }

  /// Whether point x lies strictly inside the interior sector of `node` (interior on the left of
  /// the boundary edges). Exact.
  bool sector_contains(std::uint32_t node, const Point& x) const {
    const Point& p = pos[prev[node]];
    const Point& v = pos[node];
    const Point& n = pos[next[node]];
    const bool left_of_in = orient2d(p, v, x) > 0;
    const bool left_of_out = orient2d(v, n, x) > 0;
    if (orient2d(p, v, n) > 0) return left_of_in && left_of_out;
    return left_of_in || left_of_out;
  }
};

}  // namespace pear::detail
