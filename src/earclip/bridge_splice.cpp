// The splice after the search in parts, where no two vertices share a position
// (HoleBridger::splice_apart): the holes are decided in rank order as splice_all decides them,
// but a bridge found in parallel is not made at once: it waits, with the node, edge and list
// ids the serial splice would give it, and the waiting ones are made as tasks at the end. A
// bridge writes the links of its target, of the node after the target, of the hole's vertex and
// of the node before it, and the target's input node's list of copies; no two waiting bridges
// share such a node, and where a later hole needs one (a node its splice or its node lookup
// reads or writes) that bridge is made first, at once. Bridges on different nodes commute, so
// the boundary is the serial splice's node for node. What stays serial per hole: the decision
// (the crossing walk of splice_all), a few marks, and the holes found again.
#include <algorithm>
#include <array>

#include "bridge.hpp"
#include "pear/config.hpp"

namespace pear::detail {
namespace {

constexpr std::uint32_t untouched = UINT32_MAX;
constexpr std::uint32_t touched = UINT32_MAX - 1;  ///< a splice changed it; none waits on it

}  // namespace

/// The input node at `node`'s position (itself, or the node a copy copies).
std::uint32_t HoleBridger::input_node(std::uint32_t node) const {
  return node < first_copy_ ? node : copy_input_[node - first_copy_];
}

/// Lists `copy`, a node at the position of `of` (an input node or a copy), first among its input
/// node's copies.
void HoleBridger::list_copy(std::uint32_t copy, std::uint32_t of) {
  const std::uint32_t input = input_node(of);
  copy_input_[copy - first_copy_] = input;
  copy_next_[copy - first_copy_] = copy_head_[input];
  copy_head_[input] = copy;
}

/// Of `input` (the one input node at its position) and the copies splices made of it, the
/// newest first (as the grid's lists give them), the first whose interior sector holds
/// `towards`, else `input`: node_at's choice. `settling`: the bridges waiting on each node are
/// made before its links are read.
std::uint32_t HoleBridger::node_holding(std::uint32_t input, const Point& towards, bool settling) {
  if (settling) settle(input);
  if (b_->sector_contains(input, towards)) return input;
  for (std::uint32_t copy = copy_head_[input]; copy != untouched;
       copy = copy_next_[copy - first_copy_]) {
    if (settling) settle(copy);
    if (b_->sector_contains(copy, towards)) return copy;
  }
  return input;
}

/// Makes the bridge that waits on `node`, if one does.
void HoleBridger::settle(std::uint32_t node) {
  const std::uint32_t waiting = pending_[node];
  if (waiting < touched) make_bridge(waiting_[waiting]);
}

/// Bridge `w` with its ids: Boundary::add_diagonal's links, splice_bridge's edges and copies,
/// the copies in their input node's list; its nodes touched, no longer waited on.
void HoleBridger::make_bridge(WaitingBridge& w) {
  Boundary& b = *b_;
  const std::uint32_t target = w.target, hole = w.hole;
  const std::uint32_t target_copy = w.node, hole_copy = w.node + 1;
  for (const auto& [copy, of] : {std::pair{target_copy, target}, std::pair{hole_copy, hole}}) {
    b.pos[copy] = b.pos[of];
    b.vertex[copy] = b.vertex[of];
    list_copy(copy, of);
  }
  b.link_diagonal(target, hole, target_copy, hole_copy);
  const std::array<std::uint32_t, 4> repeated{target, hole, target_copy, hole_copy};
  std::copy(repeated.begin(), repeated.end(), repeated_.begin() + w.repeat);
  hand_edge_to_copy(target, target_copy);
  edge_start_[w.edge] = target, out_edge_[target] = w.edge;
  edge_start_[w.edge + 1] = hole_copy, out_edge_[hole_copy] = w.edge + 1;
  for (const std::uint32_t node : w.marks) pending_[node] = touched;
  w.made = true;
}

/// node_at where positions do not repeat: the input node at p, or one of its copies.
std::uint32_t HoleBridger::node_at_apart(const Point& p, const Point& towards, std::uint32_t rank) {
  std::uint32_t input = UINT32_MAX;
  const std::size_t cell = frame_.cell_of(p);
  for (std::uint32_t i = node_cells_.start[cell]; i < node_cells_.start[cell + 1]; ++i) {
    const std::uint32_t node = node_cells_.items[i];
    if (merged(node, rank) && b_->pos[node] == p) {
      input = node;
      break;
    }
  }
  return input == UINT32_MAX ? UINT32_MAX : node_holding(input, towards, true);
}

/// find() on the boundary as the serial splice has it, where no node lies at a hole's vertex:
/// a waiting bridge the ray hits is made first (the visible vertex reads its links).
HoleBridger::Attachment HoleBridger::find_apart(std::uint32_t hole, std::uint32_t rank) {
  Attachment at;
  const Point h = b_->pos[hole];
  at.hit = cast_left(h, rank);
  if (at.hit.touching_edge != UINT32_MAX || at.hit.edge == UINT32_MAX) return at;
  if (at.hit.edge >= first_edge_) {
    const std::uint32_t w = edge_bridge_[(at.hit.edge - first_edge_) / 2];
    if (w != untouched && !waiting_[w].made) make_bridge(waiting_[w]);
  }
  at.target = visible_target(h, at.hit, rank);
  at.node = node_at_apart(at.target, h, rank);
  return at;
}

/// splice_all's loop for holes found in parallel on rings that are apart, from hole `k` on.
/// Returns false where a hole's vertex lies on an edge or at a node (only without the check,
/// whose touching test says apart on repeated positions alone): then every bridge is made, the
/// copies are in the grid's lists, the arrays at their sizes, and splice_all goes on from `k`.
bool HoleBridger::splice_apart(const CleanPolygon& polygon, std::vector<std::uint32_t>& unjoined,
                               std::size_t& k, bool& stale) {
  Boundary& b = *b_;
  const std::size_t holes = holes_.size();
  first_copy_ = b.size();
  first_edge_ = static_cast<std::uint32_t>(edge_start_.size());
  next_ids_ = {first_copy_, first_edge_, static_cast<std::uint32_t>(repeated_.size())};
  // Ids are handed out in rank order; the arrays are cut back to them at the end.
  b.resize(first_copy_ + 2 * holes);
  edge_start_.resize(first_edge_ + 2 * holes);
  repeated_.resize(next_ids_[2] + 4 * holes);
  regrow_unfilled(copy_input_, 2 * holes);  // each entry written before it is read
  regrow_unfilled(copy_next_, 2 * holes);
  regrow_unfilled(edge_bridge_, holes);
  waiting_.clear();
  waiting_.reserve(holes);
  for (; k < holes; ++k) {
    const std::uint32_t hole = holes_[k].leftmost, rank = static_cast<std::uint32_t>(k + 1);
    const std::size_t redone_before = redone_;
    Attachment at = found_[k];
    bool found_again = stale || at.touches || at.hit.touching_edge != UINT32_MAX ||
                       crossed_by_bridge(b.pos[hole], at.hit, maybe_crossed_[k] != 0);
    if (found_again) {
      at = find_apart(hole, rank);
      ++redone_;
    } else if (adds_bridge(at) && at.node != UINT32_MAX && pending_[at.node] != untouched) {
      at.node = node_at_apart(at.target, b.pos[hole], rank);  // a splice changed it
    }
    const auto joinable = [&] { return at.hit.edge != UINT32_MAX && at.node != UINT32_MAX; };
    if (!at.touches && at.hit.touching_edge == UINT32_MAX && !joinable()) {
      at = find_apart(hole, rank);  // nothing found: searched again, as splice_all does
      ++redone_;
      found_again = true;
    }
    if (at.touches || at.hit.touching_edge != UINT32_MAX) {
      redone_ = redone_before;  // splice_all counts hole k's searches again
      finish_waiting(nullptr);
      for (std::uint32_t copy = first_copy_; copy < next_ids_[0]; ++copy)
        insert_node(frame_.cell_of(b.pos[copy]), copy);
      changed_cells_.assign(node_cells_.head.size(), 1);
      return false;
    }
    if (!joinable()) {
      unjoined.push_back(hole);
      leave_out(polygon, holes_[k].ring);
      stale = true;
      continue;
    }
    wait_or_make(at.node, hole, found_again ? UINT32_MAX : static_cast<std::uint32_t>(k));
  }
  return true;
}

/// The bridge from `target` to `hole`, with the next ids: made now where it was found again
/// (`indexed` none: its edges enter the grid's lists, in order), else left waiting. Either way
/// the bridges waiting on its nodes are made first.
void HoleBridger::wait_or_make(std::uint32_t target, std::uint32_t hole, std::uint32_t indexed) {
  Boundary& b = *b_;
  settle(target);  // its next is read below; nothing else changes it
  for (const std::uint32_t node : {input_node(target), hole, b.prev[hole]}) settle(node);
  settle(b.next[target]);
  auto& [node, edge, repeat] = next_ids_;
  WaitingBridge w{target, hole, node, edge, repeat, {}, false};
  w.marks = {target, input_node(target), b.next[target], hole, b.prev[hole]};
  node += 2, edge += 2, repeat += 4;
  edge_bridge_[(w.edge - first_edge_) / 2] = static_cast<std::uint32_t>(waiting_.size());
  waiting_.push_back(w);
  if (indexed == UINT32_MAX) {
    make_bridge(waiting_.back());
    frame_.for_each_cell_on_segment(b.pos[target], b.pos[hole], [&](std::size_t cell) {
      list_added_edge(cell, w.edge);
      list_added_edge(cell, w.edge + 1);
    });
    return;
  }
  bridge_edge_[indexed] = w.edge;
  for (const std::uint32_t marked : w.marks)
    pending_[marked] = static_cast<std::uint32_t>(waiting_.size() - 1);
}

/// Makes every bridge still waiting, as ctx's tasks (none: serially), and cuts the arrays back
/// to the ids handed out.
void HoleBridger::finish_waiting(const RunContext* ctx) {
  const std::size_t count = waiting_.size();
  const auto make = [&](std::size_t from, std::size_t to) {
    for (std::size_t w = from; w < to; ++w)
      if (!waiting_[w].made) make_bridge(waiting_[w]);
  };
  if (ctx == nullptr) {
    make(0, count);
  } else {
    const std::size_t tasks = ctx->tasks_for(count, 256);
    ctx->run_tasks("bridge: splice in parts", tasks, [&](std::size_t t) {
      make(part_begin(count, tasks, t), part_begin(count, tasks, t + 1));
    });
  }
  b_->resize(next_ids_[0]);
  edge_start_.resize(next_ids_[1]);
  repeated_.resize(next_ids_[2]);
}

}  // namespace pear::detail
