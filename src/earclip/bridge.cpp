#include "bridge.hpp"

#include <algorithm>
#include <limits>
#include <numeric>

#include "core/sort_in_parts.hpp"
#include "geometry/sort.hpp"
#include "pear/config.hpp"
#include "ray_crossing.hpp"

namespace pear::detail {

std::vector<std::uint32_t> HoleBridger::join(const CleanPolygon& polygon, Boundary& boundary,
                                             const RunContext& ctx, bool in_parts, bool apart) {
  std::vector<std::uint32_t> unjoined;
  redone_ = 0;
  edges_split_ = false;
  bridges_indexed_ = false;
  repeated_.clear();
  changed_cells_.clear();
  if (polygon.ring_count() < 2) return unjoined;
  b_ = &boundary;
  apart_ = apart;
  bridges_waiting_ = false;
  // Not in a build without threads: the WebAssembly module's budget (9 KB; the same boundary).
  if (PEAR_HAS_THREADS && apart && polygon.ring_count() - 1 <= scan_limit_) {
    join_scanned(polygon, ctx, in_parts, unjoined);
    return unjoined;
  }
  // Without threads the joining in parts would give the same boundary at more cost (and
  // code: the .wasm).
  if (!PEAR_HAS_THREADS || !in_parts || polygon.ring_count() - 1 <= few_holes) {
    ctx.run_serial("bridge holes", [&] {
      order_holes(polygon, ctx, false);
      build_grid(polygon, ctx, false);
      splice_all(polygon, false, unjoined);
    });
    return unjoined;
  }
  order_holes(polygon, ctx, true);
  build_grid(polygon, ctx, true);
  find_all(ctx);
  index_found_bridges(ctx);
  ctx.run_serial("bridge: splice", [&] { splice_all(polygon, true, unjoined); });
  if (bridges_waiting_) finish_waiting(&ctx);
  return unjoined;
}

/// holes_ by leftmost vertex (ties by node: the order the holes join in), then every node's
/// and edge's rank.
void HoleBridger::order_holes(const CleanPolygon& polygon, const RunContext& ctx, bool parallel) {
  const std::size_t holes = polygon.ring_count() - 1;
  holes_.resize(holes);
  const auto leftmost = [&](std::size_t k) {
    const std::uint32_t first = polygon.ring_starts[k + 1], end = polygon.ring_starts[k + 2];
    std::uint32_t best = first;  // the ring is still the contiguous cycle first..end - 1
    for (std::uint32_t v = first + 1; v < end; ++v)
      if (lexicographic_less(b_->pos[v], b_->pos[best])) best = v;
    holes_[k] = {best, static_cast<std::uint32_t>(k + 1)};
  };
  if (parallel) {
    const std::size_t tasks = ctx.tasks_for(holes, 64);
    ctx.run_tasks("bridge: leftmost vertices", tasks, [&](std::size_t t) {
      for (std::size_t k = holes * t / tasks; k < holes * (t + 1) / tasks; ++k) leftmost(k);
    });
  } else {
    for (std::size_t k = 0; k < holes; ++k) leftmost(k);
  }
  const auto before = [&](const Hole& a, const Hole& c) {
    const Point &p = b_->pos[a.leftmost], &q = b_->pos[c.leftmost];
    return lexicographic_less(p, q) || (p == q && a.leftmost < c.leftmost);
  };
  if (!PEAR_HAS_THREADS || !parallel) {  // a build without threads keeps no tasks (.wasm)
    detail::sort(holes_.begin(), holes_.end(), before);
    rank_.reserve(most_ids());
    rank_.resize(polygon.points.size());
    assign_ranks(polygon, 0, holes);
    return;
  }
  // A total order (ties by node): the same order in any number of parts.
  sort_in_parts(ctx, "bridge: sort holes", "bridge: merge holes", holes_, before, 256);
  ctx.run_serial("bridge: rank array", [&] {
    rank_.reserve(most_ids());
    rank_.resize(polygon.points.size());
  });
  const std::size_t tasks = ctx.tasks_for(holes, 64);
  ctx.run_tasks("bridge: ranks", tasks, [&](std::size_t t) {
    assign_ranks(polygon, holes * t / tasks, holes * (t + 1) / tasks);
  });
}

/// Ranks the nodes of holes_[from, to) (and the outer ring's, 0, with the first).
void HoleBridger::assign_ranks(const CleanPolygon& polygon, std::size_t from, std::size_t to) {
  if (from == 0) std::fill(rank_.begin(), rank_.begin() + polygon.ring_starts[1], 0u);
  for (std::size_t k = from; k < to; ++k) {
    const std::uint32_t ring = holes_[k].ring;
    std::fill(rank_.begin() + polygon.ring_starts[ring],
              rank_.begin() + polygon.ring_starts[ring + 1], static_cast<std::uint32_t>(k + 1));
  }
}

/// Every hole's attachment against the rings ranked below it, as tasks: each reads the grid,
/// the boundary and the ranks, and writes its own entries of found_.
void HoleBridger::find_all(const RunContext& ctx) {
  const std::size_t holes = holes_.size();
  found_.resize(holes);
  const std::size_t tasks = ctx.tasks_for(holes, 4);
  ctx.run_tasks("bridge: find attachments", tasks, [&](std::size_t t) {
    for (std::size_t k = holes * t / tasks; k < holes * (t + 1) / tasks; ++k)
      found_[k] = find(holes_[k].leftmost, static_cast<std::uint32_t>(k + 1));
  });
}

/// Joins the holes in rank order. A hole found in parallel keeps what was found unless the
/// serial search would now see something else: a bridge added since crossing its ray at or
/// before the edge it hit (bridges add no node positions, so the visible vertex depends only
/// on that edge), or a splice that moved edge ids or left a ring out. Which found bridges may
/// cross its ray was worked out in parallel (maybe_crossed_); only the bridges of holes found
/// again are looked up here in any case.
void HoleBridger::splice_all(const CleanPolygon& polygon, bool found_in_parallel,
                             std::vector<std::uint32_t>& unjoined) {
  bool stale = false;  // found_ was computed with a ring that is now left out
  found_in_parallel = PEAR_HAS_THREADS && found_in_parallel;  // the .wasm keeps no such path
  reserve_for_splices();
  std::size_t first = 0;
  if (found_in_parallel) {  // no column lists an added edge yet
    row_words_ = (static_cast<std::size_t>(frame_.nx) + 63) / 64;
    added_columns_.assign(row_words_ * static_cast<std::size_t>(frame_.ny), 0);
  } else {
    added_columns_.clear();
  }
  if (found_in_parallel && apart_) {
    // The bridges wait and are made as tasks after (join); where the rings turn out to touch,
    // the rest from hole `first` on as below.
    bridges_waiting_ = splice_apart(polygon, unjoined, first, stale);
    if (bridges_waiting_) return;
  } else if (found_in_parallel) {
    changed_cells_.assign(node_cells_.head.size(), 0);
  }
  for (std::size_t k = first; k < holes_.size(); ++k) {
    const std::uint32_t hole = holes_[k].leftmost, rank = static_cast<std::uint32_t>(k + 1);
    Attachment at;
    bool node_known = true;              // at.node is what node_at would say now
    std::uint32_t indexed = UINT32_MAX;  // k, where the splice adds the bridge found for it
    if (!found_in_parallel) {
      at = find(hole, rank);
    } else {
      at = found_[k];
      if (stale || edges_split_ || at.hit.touching_edge != UINT32_MAX ||
          (!at.touches && crossed_by_bridge(b_->pos[hole], at.hit, maybe_crossed_[k] != 0))) {
        at = find(hole, rank);
        ++redone_;
      } else {
        const Point& p = at.touches ? b_->pos[hole] : at.target;
        node_known = changed_cells_[frame_.cell_of(p)] == 0;
        if (adds_bridge(at)) indexed = static_cast<std::uint32_t>(k);
      }
    }
    // Nothing to the left: the hole lies outside the outer ring. A target the splice could
    // not find (no merged node there: the search and the splice disagree) is found again
    // serially rather than trusted, and a hole is never spliced blindly.
    bool joined = attach(hole, at, rank, node_known, indexed);
    if (!joined && found_in_parallel) {
      ++redone_;
      joined = attach(hole, find(hole, rank), rank, true, UINT32_MAX);
    }
    if (!joined) {
      unjoined.push_back(hole);
      leave_out(polygon, holes_[k].ring);
      stale = true;
    }
  }
}

HoleBridger::Attachment HoleBridger::find(std::uint32_t hole, std::uint32_t rank) const {
  Attachment at;
  const Point h = b_->pos[hole];
  at.node = node_at(h, b_->pos[b_->next[hole]], rank);
  at.touches = at.node != UINT32_MAX;
  if (at.touches) return at;
  at.hit = cast_left(h, rank);
  if (at.hit.touching_edge == UINT32_MAX && at.hit.edge != UINT32_MAX) {
    at.target = visible_target(h, at.hit, rank);
    at.node = node_at(at.target, h, rank);
  }
  return at;
}

/// Whether segment a-b crosses the leftward ray from h where a search that hit `hit` would
/// meet it: at or right of the edge it hit, or exactly through h.
bool HoleBridger::crosses_before_hit(const Point& h, const RayHit& hit, const Point& a,
                                     const Point& b) {
  double x = 0;
  const Crossing c = edge_crossing(h, a, b, x);
  return c == Crossing::through || (c == Crossing::left && (hit.edge == UINT32_MAX || x >= hit.x));
}

/// Walks the cells the serial search from h reads (right to left, up to the edge it hit) until
/// crosses_in_cell(cell) is true; returns whether it was.
template <class Crosses>
bool HoleBridger::any_on_ray(const Point& h, const RayHit& hit, Crosses&& crosses_in_cell) const {
  const int row = frame_.row(h.y);
  // The columns whose right edge, one column out, reaches the hit (cast_left's walk), the
  // last of them found once rather than with a division a column.
  int last = 0;
  if (hit.edge != UINT32_MAX && frame_.inv_w > 0) {
    const auto short_of_hit = [&](int col) { return frame_.x0 + (col + 2) / frame_.inv_w < hit.x; };
    last = std::max(0, frame_.column(hit.x) - 3);
    while (last > 0 && !short_of_hit(last - 1)) --last;
    while (last <= frame_.nx && short_of_hit(last)) ++last;
  }
  for (int col = frame_.column(h.x); col >= last; --col)
    if (crosses_in_cell(frame_.cell(col, row))) return true;
  return false;
}

/// Visits (edge id, one end, other end) of the bridges spliced as found in `cell`.
template <class Visit>
void HoleBridger::for_each_indexed_bridge(std::size_t cell, Visit&& visit) const {
  for (std::uint32_t i = bridge_cells_.start[cell]; i < bridge_cells_.start[cell + 1]; ++i) {
    const std::uint32_t k = bridge_cells_.items[i];
    if (bridge_edge_[k] != UINT32_MAX)
      visit(bridge_edge_[k], found_[k].target, b_->pos[holes_[k].leftmost]);
  }
}

/// Before any splice, in parallel: whether the bridge found for some hole ranked below hole k
/// crosses k's ray where its search would meet it (so a splice may have to find k again).
bool HoleBridger::any_found_bridge_crosses(std::uint32_t k) const {
  const Point& h = b_->pos[holes_[k].leftmost];
  const RayHit& hit = found_[k].hit;
  return any_on_ray(h, hit, [&](std::size_t cell) {
    for (std::uint32_t i = bridge_cells_.start[cell]; i < bridge_cells_.start[cell + 1]; ++i) {
      const std::uint32_t j = bridge_cells_.items[i];
      if (j < k && crosses_before_hit(h, hit, found_[j].target, b_->pos[holes_[j].leftmost]))
        return true;
    }
    return false;
  });
}

/// Whether a cell the walk from h would read (any_on_ray's, with room to spare: down to three
/// columns short of the hit's) lists an added edge: the added lists hold only the bridges of
/// holes found again, in a few cells, so most walks need not be made.
bool HoleBridger::any_added_near_ray(const Point& h, const RayHit& hit) const {
  const int first = hit.edge == UINT32_MAX ? 0 : std::max(0, frame_.column(hit.x) - 4);
  const int last = frame_.column(h.x);
  if (first > last) return false;
  // The row's bits of the columns whose cells list an added edge, a word at a time.
  const std::uint64_t* row = added_columns_.data() + std::size_t(frame_.row(h.y)) * row_words_;
  const int w0 = first / 64, w1 = last / 64;
  const std::uint64_t low = ~std::uint64_t{0} << (first % 64);
  const std::uint64_t high = ~std::uint64_t{0} >> (63 - last % 64);
  if (w0 == w1) return (row[w0] & low & high) != 0;
  bool any = (row[w0] & low) != 0 || (row[w1] & high) != 0;
  for (int w = w0 + 1; w < w1 && !any; ++w) any = row[w] != 0;
  return any;
}

/// Lists added edge `id` in `cell`, and notes the cell's column in its row for
/// any_added_near_ray.
void HoleBridger::list_added_edge(std::size_t cell, std::uint32_t id) {
  edge_cells_.add(cell, id);
  if (!PEAR_HAS_THREADS || added_columns_.empty()) return;
  const std::size_t row = cell / static_cast<std::size_t>(frame_.nx);
  const std::size_t column = cell % static_cast<std::size_t>(frame_.nx);
  added_columns_[row * row_words_ + column / 64] |= std::uint64_t{1} << (column % 64);
}

/// Whether a bridge (an added edge) crosses the ray from h where the serial search would meet
/// it: at or right of the edge the search hit, in the cells that search reads. The bridges
/// spliced as found only where `found_bridges` (maybe_crossed_ says none of them can).
bool HoleBridger::crossed_by_bridge(const Point& h, const RayHit& hit, bool found_bridges) const {
  if (!found_bridges && !any_added_near_ray(h, hit)) return false;
  return any_on_ray(h, hit, [&](std::size_t cell) {
    bool crossed = false;
    if (found_bridges)
      for_each_indexed_bridge(cell, [&](std::uint32_t, const Point& a, const Point& c) {
        crossed = crossed || crosses_before_hit(h, hit, a, c);
      });
    edge_cells_.for_each_added(cell, [&](std::uint32_t id) {
      const std::uint32_t s = edge_start_[id];
      crossed = crossed || crosses_before_hit(h, hit, b_->pos[s], b_->pos[b_->next[s]]);
    });
    return crossed;
  });
}

/// Splices the hole where `at` says; false (nothing changed) if the ray hit nothing or no
/// merged node is at the target. `node_known`: at.node is still what node_at would find (no
/// splice since the search changed a node in its cell); else it is looked up again.
bool HoleBridger::attach(std::uint32_t hole, const Attachment& at, std::uint32_t rank,
                         bool node_known, std::uint32_t indexed) {
  const Point h = b_->pos[hole];
  if (!at.touches && at.hit.touching_edge != UINT32_MAX) {
    splice_into_edge(at.hit.touching_edge, hole);
    return true;
  }
  if (!at.touches && at.hit.edge == UINT32_MAX) return false;
  const std::uint32_t target = node_known   ? at.node
                               : at.touches ? node_at(h, b_->pos[b_->next[hole]], rank)
                                            : node_at(at.target, h, rank);
  if (target == UINT32_MAX) return false;
  if (at.touches)
    splice_touching(target, hole);
  else
    splice_bridge(target, hole, indexed);
  return true;
}

/// Room for what the splices add (10,000 holes grew these arrays a few hundred times in the
/// serial splice; the arrays indexed by id were reserved for most_ids() when first sized, so
/// this copies nothing): new nodes and edges join at once (rank 0).
void HoleBridger::reserve_for_splices() {
  const std::size_t most = most_ids();
  if (rank_.size() < most) rank_.resize(most, 0);
  if (out_edge_.size() < most) out_edge_.resize(most, UINT32_MAX);
  edge_start_.reserve(most);
  node_cells_.added.reserve(2 * holes_.size());
  edge_cells_.added.reserve(4 * holes_.size());
  repeated_.reserve(4 * holes_.size());
}

/// A hole that could not be joined never counts for the holes after it.
void HoleBridger::leave_out(const CleanPolygon& polygon, std::uint32_t ring) {
  std::fill(rank_.begin() + polygon.ring_starts[ring],
            rank_.begin() + polygon.ring_starts[ring + 1], UINT32_MAX);
}

/// A node a bridge adds (a copy, in `cell`): merged at once, in its cell's list.
void HoleBridger::insert_node(std::size_t cell, std::uint32_t node) {
  if (!PEAR_HAS_THREADS || gridded_) node_cells_.add(cell, node);
}

/// An edge a bridge adds, from `start`: a new id, merged at once (entered in no cell yet).
std::uint32_t HoleBridger::new_edge(std::uint32_t start) {
  const auto id = static_cast<std::uint32_t>(edge_start_.size());
  edge_start_.push_back(start);
  out_edge_[start] = id;
  return id;
}

/// Edges a bridge adds, entered in every cell they cross: the one from `start`, and the one
/// from `back` unless that is UINT32_MAX (a bridge's other side: the same segment the other
/// way, so one walk of the cells enters both, each cell's list ending as two walks leave it).
void HoleBridger::insert_edges(std::uint32_t start, std::uint32_t back) {
  const std::uint32_t first = new_edge(start);
  const std::uint32_t second = back == UINT32_MAX ? UINT32_MAX : new_edge(back);
  if (PEAR_HAS_THREADS && !gridded_) {
    added_edges_.push_back(first);
    if (second != UINT32_MAX) added_edges_.push_back(second);
    return;
  }
  frame_.for_each_cell_on_segment(b_->pos[start], b_->pos[b_->next[start]], [&](std::size_t cell) {
    list_added_edge(cell, first);
    if (second != UINT32_MAX) list_added_edge(cell, second);
  });
}

/// The merged node at exactly p whose interior sector contains `towards`; UINT32_MAX if no
/// merged node lies at p. Falls back to any node at p when no sector contains it strictly.
std::uint32_t HoleBridger::node_at(const Point& p, const Point& towards, std::uint32_t rank) const {
  std::uint32_t any = UINT32_MAX, inside = UINT32_MAX;
  node_cells_.for_each(frame_.cell_of(p), [&](std::uint32_t node) {
    if (inside != UINT32_MAX || !merged(node, rank) || !(b_->pos[node] == p)) return;
    if (b_->sector_contains(node, towards)) inside = node;
    if (any == UINT32_MAX) any = node;
  });
  return inside != UINT32_MAX ? inside : any;
}

/// The nearest edge the leftward ray from h crosses (the largest crossing x, then the smallest
/// id), and the smallest id of an edge through h: the same whatever order the cells list them.
HoleBridger::RayHit HoleBridger::cast_left(const Point& h, std::uint32_t rank) const {
  RayHit hit;
  hit.x = -std::numeric_limits<double>::infinity();
  const auto visit = [&](std::uint32_t id, const Point& a, const Point& b) {
    visit_edge(hit, h, id, a, b);
  };
  const int row = frame_.row(h.y);
  for (int col = frame_.column(h.x); col >= 0; --col) {
    const double cell_right = frame_.inv_w > 0 ? frame_.x0 + (col + 2) / frame_.inv_w : h.x;
    if (hit.edge != UINT32_MAX && cell_right < hit.x) break;
    const std::size_t cell = frame_.cell(col, row);
    edge_cells_.for_each(cell, [&](std::uint32_t id) {
      if (!merged(id, rank)) return;
      const std::uint32_t s = edge_start_[id];
      visit(id, b_->pos[s], b_->pos[b_->next[s]]);
    });
    if (PEAR_HAS_THREADS && bridges_indexed_) for_each_indexed_bridge(cell, visit);
  }
  hit.x = std::min(hit.x, h.x);  // rounding may put a crossing a hair right of h
  return hit;
}

/// Eberly's method (Sight) over the merged nodes in the cells of the triangle's rows.
Point HoleBridger::visible_target(const Point& h, const RayHit& hit, std::uint32_t rank) const {
  Sight sight;
  sight.start(h, edge_start_[hit.edge], *b_);
  if (!sight.open) return sight.best;
  const int c0 = frame_.column(std::min(hit.x, sight.m.x)), c1 = frame_.column(h.x);
  const int r0 = frame_.row(sight.y0), r1 = frame_.row(sight.y1);
  for (int r = r0; r <= r1; ++r) {
    for (int col = c0; col <= c1; ++col) {
      node_cells_.for_each(frame_.cell(col, r), [&](std::uint32_t node) {
        if (merged(node, rank)) sight.consider(b_->pos[node], node);
      });
    }
  }
  return sight.best;
}

/// A splice turned node's sector or put a copy at its position: what the search found in its
/// cell is looked up again.
void HoleBridger::mark_changed(std::size_t cell) {
  // A serial join: each hole is found right before its splice.
  if (!PEAR_HAS_THREADS || changed_cells_.empty()) return;
  changed_cells_[cell] = 1;
}

/// The grid cell of node v's position (0 while joining without a grid: nothing is listed).
std::size_t HoleBridger::cell_of(std::uint32_t v) const {
  return !PEAR_HAS_THREADS || gridded_ ? frame_.cell_of(b_->pos[v]) : 0;
}

/// A bridge leaves `target` now: the edge that left it leaves its copy.
void HoleBridger::hand_edge_to_copy(std::uint32_t target, std::uint32_t target_copy) {
  const std::uint32_t old_edge = out_edge_[target];
  edge_start_[old_edge] = target_copy;
  out_edge_[target_copy] = old_edge;
  out_edge_[target] = UINT32_MAX;
}

/// `indexed_hole`: the hole whose bridge as found this is (bridge_cells_ lists it), or none.
void HoleBridger::splice_bridge(std::uint32_t target, std::uint32_t hole,
                                std::uint32_t indexed_hole) {
  Boundary& b = *b_;
  const std::size_t target_cell = cell_of(target), hole_cell = cell_of(hole);
  mark_changed(target_cell);
  mark_changed(hole_cell);
  const auto [target_copy, hole_copy] = b.add_diagonal(target, hole);
  note_copy(target_copy, target);
  note_copy(hole_copy, hole);
  repeated_.insert(repeated_.end(), {target, hole, target_copy, hole_copy});
  hand_edge_to_copy(target, target_copy);
  if (!PEAR_HAS_THREADS || indexed_hole == UINT32_MAX) {
    insert_edges(target, hole_copy);
  } else {  // the same ids as insert_edges gives, the cells already listed
    bridge_edge_[indexed_hole] = new_edge(target);
    new_edge(hole_copy);
  }
  insert_node(target_cell, target_copy);
  insert_node(hole_cell, hole_copy);
}

/// The hole shares a point with the merged boundary: link the rings there, no bridge needed.
void HoleBridger::splice_touching(std::uint32_t target, std::uint32_t hole) {
  Boundary& b = *b_;
  mark_changed(cell_of(target));
  mark_changed(cell_of(hole));
  const std::uint32_t after_target = b.next[target], after_hole = b.next[hole];
  repeated_.insert(repeated_.end(), {target, hole});
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
  for (const std::uint32_t node : {start, end, hole}) mark_changed(cell_of(node));
  const std::uint32_t entry = b.copy(hole), before_hole = b.prev[hole];
  note_copy(entry, hole);
  repeated_.insert(repeated_.end(), {hole, entry});
  b.link(start, entry);
  b.link(entry, b.next[hole]);
  b.link(before_hole, hole);
  b.link(hole, end);
  // The edge from `hole` keeps its id but now leaves the copy; `hole` leaves towards `end`.
  const std::uint32_t hole_edge = out_edge_[hole];
  if (hole_edge != UINT32_MAX) edge_start_[hole_edge] = entry, out_edge_[entry] = hole_edge;
  out_edge_[hole] = UINT32_MAX;
  insert_node(cell_of(entry), entry);
  insert_edges(hole, UINT32_MAX);
  edges_split_ = true;  // edge `edge` is shorter now: what the parallel search saw of it is stale
}

}  // namespace pear::detail
