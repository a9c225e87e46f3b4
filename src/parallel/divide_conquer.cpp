// Paper §2.1, divide and conquer: vertical split lines at x quantiles cut the boundary into
// parts (split_pieces.hpp), the parts are clipped in parallel by the sequential engine, and the
// Steiner points are removed again (divide_conquer_repair.hpp). Anything that cannot be done
// exactly falls back to the sequential engine on the whole boundary, which is never modified
// before that point.
#include <algorithm>
#include <array>
#include <span>

#include "core/link_runs.hpp"
#include "geometry/segments.hpp"
#include "geometry/sort.hpp"
#include "pear/config.hpp"

#include "divide_conquer_fans.hpp"
#include "divide_conquer_repair.hpp"
#include "split_pieces.hpp"
#include "variant_scratch.hpp"
#include "variants.hpp"

namespace pear::detail {
namespace {

/// Recursive halving (paper §2.1): the middle line first, then the middles of both halves, and
/// so on; the slabs of one level are cut in parallel. Level 0 is the cycle, one slab; returns
/// the slabs left to right (a prefix of the last level's array), empty when a cut failed.
std::span<const DivideSlab> split_into_parts(const Boundary& b, std::vector<SplitLine>& lines,
                                             const RunContext& ctx, VariantScratch& scratch) {
  std::vector<std::vector<DivideSlab>>& levels = scratch.slab_levels;
  DivideSlab& whole = levels[0][0];
  whole.pieces.starts.assign(1, 0);
  whole.pieces.close_piece();
  whole.lo = 0, whole.hi = static_cast<std::uint32_t>(lines.size());
  std::size_t level = 0, count = 1;
  const auto uncut = [&] {
    return std::any_of(levels[level].begin(),
                       levels[level].begin() + static_cast<std::ptrdiff_t>(count),
                       [](const DivideSlab& s) { return s.lo < s.hi; });
  };
  for (; uncut(); ++level) {
    std::vector<std::size_t> first_child(count);
    std::size_t children = 0;
    for (std::size_t s = 0; s < count; ++s) {
      const DivideSlab& slab = levels[level][s];
      first_child[s] = std::exchange(children, children + (slab.lo < slab.hi ? 2 : 1));
    }
    if (levels.size() == level + 1) levels.emplace_back();
    if (levels[level + 1].size() < children) levels[level + 1].resize(children);
    std::vector<DivideSlab>& slabs = levels[level];
    std::vector<DivideSlab>& next = levels[level + 1];
    std::vector<std::uint8_t> ok(count, 1);
    // The first cut, of the whole cycle, would be one serial task: its passes run in parts.
    const bool whole = PEAR_HAS_THREADS && count == 1 && ctx.partitions > 1;
    const auto cut = [&](std::size_t s) {
      const DivideSlab& slab = slabs[s];
      if (slab.lo == slab.hi) {
        next[first_child[s]] = slab;  // a copy into an array that keeps its size
        return;
      }
      const std::uint32_t mid = slab.lo + (slab.hi - slab.lo) / 2;
      DivideSlab& left = next[first_child[s]];
      DivideSlab& right = next[first_child[s] + 1];
      left.lo = slab.lo, left.hi = mid, right.lo = mid + 1, right.hi = slab.hi;
      for (Pieces* p : {&left.pieces, &right.pieces}) p->corners.clear(), p->starts.assign(1, 0);
      PieceSplitter splitter;
      ok[s] = whole ? splitter.split_in_parts(b, lines, mid, slab.pieces, left.pieces, right.pieces,
                                              ctx)
                    : splitter.split(b, lines, mid, slab.pieces, left.pieces, right.pieces);
    };
    if (whole)
      cut(0);  // its phases are the splitter's own
    else
      ctx.run_tasks("split", count, cut);
    if (std::find(ok.begin(), ok.end(), 0) != ok.end()) return {};
    count = children;
  }
  return {levels[level].data(), count};
}

/// Which edges of a piece's triangle lie on the input boundary: those along a boundary edge of
/// the piece (by point, as the clipper may use either node at a pinch) that is not a split
/// segment (two Steiner points of one line). `count` is the piece's corner count: the
/// clipper's fallback may have added copies of nodes after them.
std::uint8_t boundary_edges(const Boundary& piece, const PieceCorner* corners, std::uint32_t count,
                            const std::array<std::uint32_t, 3>& t) {
  std::uint8_t mask = 0;
  for (int c = 0; c < 3; ++c) {
    const std::uint32_t from = t[c], to = t[(c + 1) % 3];
    const std::uint32_t after = from + 1 == count ? 0 : from + 1;  // as linked
    const bool split_segment = is_steiner(corners[from]) && is_steiner(corners[after]) &&
                               corner_line(corners[from]) == corner_line(corners[after]);
    if (piece.pos[after] == piece.pos[to] && !split_segment) mask |= 1 << c;
  }
  return mask;
}

/// The nodes of a piece that share a position with another node of it (what the clipper would
/// find by hashing every position, which cost Koch-8's two parts 2.6% of the run's time), or
/// unknown where `shared` does not know the input's. Only two kinds of nodes can: input
/// vertices that `shared` marks (they share a position on the whole boundary), and nodes on the
/// piece's split lines (a Steiner point's x is exactly its line's); those are compared. Left to
/// the clipper in a build without threads (the same marks; the WebAssembly module's size).
SharedPositions piece_pinches(const Boundary& piece, const PieceCorner* corners,
                              SharedPositions shared, DividePart& part) {
  if (!PEAR_HAS_THREADS || (shared.marks == nullptr && !shared.none)) return {};
  const std::uint32_t count = piece.size();
  std::array<double, 2> line_x{};
  std::size_t lines = 0;  // a piece lies in one slab: at most two lines
  const auto on_a_line = [&](double x) {
    return std::find(line_x.begin(), line_x.begin() + lines, x) != line_x.begin() + lines;
  };
  for (std::uint32_t i = 0; i < count; ++i) {
    if (!is_steiner(corners[i]) || on_a_line(piece.pos[i].x)) continue;
    if (lines == line_x.size()) return {};
    line_x[lines++] = piece.pos[i].x;
  }
  std::vector<std::uint32_t>& candidates = part.on_line;
  candidates.clear();
  for (std::uint32_t i = 0; i < count; ++i)
    if (on_a_line(piece.pos[i].x) ||
        (!is_steiner(corners[i]) && shared.marks && (*shared.marks)[corner_index(corners[i])]))
      candidates.push_back(i);
  detail::sort(candidates.begin(), candidates.end(), [&](std::uint32_t u, std::uint32_t v) {
    return lexicographic_less(piece.pos[u], piece.pos[v]);
  });
  std::vector<std::uint8_t>& pinch = part.pinch;
  pinch.assign(count, 0);
  for (std::size_t k = 1; k < candidates.size(); ++k)
    if (piece.pos[candidates[k]] == piece.pos[candidates[k - 1]])
      pinch[candidates[k]] = pinch[candidates[k - 1]] = 1;
  return {&pinch, false};
}

/// Clips every piece of a part with the sequential engine, on the rounded Steiner points.
void clip_part(const Boundary& b, const std::vector<SplitLine>& lines, const Pieces& pieces,
               EarHeuristic heuristic, MakeClipper make_clipper, SharedPositions shared,
               DividePart& part) {
  part.kept.clear(), part.at_steiner.clear(), part.on_boundary.clear();
  part.ok = true;
  CycleClipper& clipper = part.clipper_from(make_clipper);
  Boundary& piece = part.piece;
  TriangleList& local = part.local;
  for (std::size_t p = 0; p < pieces.count(); ++p) {
    const PieceCorner* corners = &pieces.corners[pieces.starts[p]];
    const std::uint32_t count = pieces.starts[p + 1] - pieces.starts[p];
    piece.clear();
    for (std::uint32_t i = 0; i < count; ++i) piece.add(corner_pos(b, lines, corners[i]), i);
    for (std::uint32_t i = 0; i < count; ++i) piece.link(i, i + 1 == count ? 0 : i + 1);
    local.clear();
    if (count < 3 ||
        !clipper.clip(piece, 0, heuristic, local, piece_pinches(piece, corners, shared, part))) {
      part.ok = false;
      return;
    }
    part.fans.reduce(piece, corners, count, local);
    for (const auto& t : local) {
      const SteinerTriangle corner = {corners[t[0]], corners[t[1]], corners[t[2]]};
      if (is_steiner(corner[0]) || is_steiner(corner[1]) || is_steiner(corner[2])) {
        part.at_steiner.push_back(corner);
        part.on_boundary.push_back(boundary_edges(piece, corners, count, t));
        continue;
      }
      const std::uint32_t u = corner_index(corner[0]), v = corner_index(corner[1]),
                          w = corner_index(corner[2]);
      // Exact: a triangle of input vertices the rounding made flat or turned cannot stay.
      if (!(orient2d(b.pos[u], b.pos[v], b.pos[w]) > 0)) {
        part.ok = false;
        return;
      }
      part.kept.push_back({b.vertex[u], b.vertex[v], b.vertex[w]});
    }
  }
}

/// Redoes the triangles at Steiner points from input vertices: the search for the holes and
/// the check in tasks where their passes allow, the holes spread over tasks.
bool remove_steiner_points(const Boundary& b, const std::vector<SplitLine>& lines,
                           const std::vector<DividePart*>& parts, EarHeuristic heuristic,
                           MakeClipper make_clipper, const RunContext& ctx,
                           std::unique_ptr<SteinerRepair>& kept,
                           std::vector<TriangleList>& patches) {
  std::vector<SteinerTriangle> at_steiner;
  std::vector<std::uint8_t> on_boundary;
  // One copy, not a phase of its own (profiled as time outside the phases): cheap beside the
  // search, and a phase's wrapper costs the .wasm.
  for (const DividePart* part : parts) {
    at_steiner.insert(at_steiner.end(), part->at_steiner.begin(), part->at_steiner.end());
    on_boundary.insert(on_boundary.end(), part->on_boundary.begin(), part->on_boundary.end());
  }
  if (!kept) kept = std::make_unique<SteinerRepair>();
  SteinerRepair& repair = *kept;
  if (!repair.find_holes(b, lines, at_steiner, std::move(on_boundary), ctx)) return false;
  const std::size_t holes = repair.hole_count();
  const std::size_t tasks = std::min<std::size_t>(std::max(1u, ctx.partitions), holes);
  patches.assign(tasks, {});
  std::vector<std::vector<SteinerTriangle>> fills(tasks);
  std::vector<std::uint8_t> ok(tasks, 1);
  // Tasks get runs of holes with about equal node counts (one hole may be most of the work).
  const auto first_hole = [&](std::size_t task) {
    const std::size_t nodes = task * repair.nodes_before(holes) / tasks;
    std::size_t lo = 0, hi = holes;  // the first hole with at least `nodes` nodes before it
    while (lo < hi) {
      const std::size_t mid = (lo + hi) / 2;
      if (repair.nodes_before(mid) < nodes)
        lo = mid + 1;
      else
        hi = mid;
    }
    return lo;
  };
  ctx.run_tasks("fill Steiner holes", tasks, [&](std::size_t task) {
    HoleClipper scratch(make_clipper);
    for (std::size_t h = first_hole(task); h < first_hole(task + 1) && ok[task]; ++h)
      ok[task] = repair.triangulate_hole(h, b, heuristic, scratch, patches[task], fills[task]);
  });
  if (std::find(ok.begin(), ok.end(), 0) != ok.end()) return false;
  return repair.check_chain(b, lines, fills, ctx);
}

/// Splits, clips the parts in parallel and removes the Steiner points; appends to `out`.
/// Returns false (with `out` possibly extended) when the sequential engine must do it instead.
bool split_clip_repair(const Boundary& b, std::vector<SplitLine>& lines, EarHeuristic heuristic,
                       MakeClipper make_clipper, SharedPositions shared, const RunContext& ctx,
                       TriangleList& out, std::size_t& region_ordered, VariantScratch& scratch) {
  const std::span<const DivideSlab> slabs = split_into_parts(b, lines, ctx, scratch);
  const std::size_t count = slabs.size();
  if (count == 0) return false;
  std::vector<std::unique_ptr<DividePart>>& kept = scratch.divide_parts;
  while (kept.size() < count) kept.push_back(std::make_unique<DividePart>());
  std::vector<DividePart*> parts(count);
  for (std::size_t s = 0; s < count; ++s) parts[s] = kept[s].get();
  ctx.run_tasks("clip parts", count, [&](std::size_t s) {
    clip_part(b, lines, slabs[s].pieces, heuristic, make_clipper, shared, *parts[s]);
  });
  if (std::any_of(parts.begin(), parts.end(), [](const DividePart* p) { return !p->ok; }))
    return false;
  std::vector<TriangleList> patches;
  if (!remove_steiner_points(b, lines, parts, heuristic, make_clipper, ctx, scratch.steiner_repair,
                             patches))
    return false;
  // The parts' triangles, then the holes', each copied by its own task to its place in `out`.
  std::vector<const TriangleList*> lists;
  for (const DividePart* part : parts) lists.push_back(&part->kept);
  for (const TriangleList& patch : patches) lists.push_back(&patch);
  std::vector<std::size_t> offset(1, out.size());
  for (const TriangleList* list : lists) offset.push_back(offset.back() + list->size());
  out.resize(offset.back());
  ctx.run_tasks("gather", lists.size(), [&](std::size_t i) {
    std::copy(lists[i]->begin(), lists[i]->end(), out.begin() + offset[i]);
  });
  region_ordered = offset[parts.size()];
  return true;
}

/// The cycle through `entry` into `cycle` from its runs of consecutive nodes, found and copied
/// in tasks (a polygon's rings before clipping are a few long runs: the walk node by node was
/// a serial phase of every run in parts); where links jump too often for runs, by rulers from 4
/// partitions (their walks and copies are twice the serial walk's work; random holes at 16
/// partitions 0.28 -> 0.03 ms, the holes grid 0.08 -> 0.04, at 4 0.28 -> 0.11 and level).
/// False, `cycle` untouched, where neither pays (one task, a build without threads) or the
/// links do not close: the caller walks.
bool walk_cycle_in_parts(const Boundary& b, std::uint32_t entry, const RunContext& ctx,
                         FillVector<PieceCorner>& cycle) {
  const std::size_t parts = link_tasks(b.size(), ctx.partitions);
  if (!PEAR_HAS_THREADS || parts < 2) return false;
  std::vector<std::uint32_t> jumps;
  if (!find_link_jumps(b, ctx, "cycle: jumps", parts, jumps, [](std::size_t, std::size_t) {}))
    return ctx.partitions >= 4 && walk_cycle_by_rulers(b, entry, ctx, cycle);
  JumpLinks links;
  link_jumps(b, jumps, ctx, "cycle: jump links", parts, links);
  CycleLayout layout;
  ctx.run_serial("cycle: runs", [&] {
    layout.assign(cycle_runs(b, entry, jumps, links));
    if (!layout.runs.empty()) cycle.resize(layout.size);
  });
  if (layout.runs.empty()) return false;
  ctx.run_tasks("cycle: copy", parts, [&](std::size_t part) {
    layout.for_positions(part_begin(cycle.size(), parts, part),
                         part_begin(cycle.size(), parts, part + 1),
                         [&](std::size_t i, std::uint32_t node) { cycle[i] = node; });
  });
  return true;
}

}  // namespace

bool divide_and_conquer(Boundary& b, std::uint32_t entry, EarHeuristic heuristic,
                        MakeClipper make_clipper, const RunContext& ctx, TriangleList& out,
                        std::uint32_t& best_effort_vertex, std::size_t& region_ordered,
                        VariantScratchPtr& scratch, SharedPositions shared, double last_share) {
  if (!scratch) scratch.reset(new VariantScratch);
  if (scratch->slab_levels.empty()) scratch->slab_levels.emplace_back(1);
  FillVector<PieceCorner>& cycle = scratch->slab_levels[0][0].pieces.corners;
  std::vector<SplitLine> lines;
  const bool walked = walk_cycle_in_parts(b, entry, ctx, cycle);
  if (!walked) {
    ctx.run_serial("cycle: walk", [&] {
      cycle.clear();
      cycle.reserve(b.size());
      std::uint32_t v = entry;
      do {
        cycle.push_back(v);
        v = b.next[v];
      } while (v != entry && cycle.size() <= b.size());
    });
  }
  if (ctx.partitions >= 2 && cycle.size() >= 4 && cycle.size() <= b.size())
    for (double after : split_positions(b, cycle, ctx.partitions, ctx, last_share))
      lines.emplace_back().after = after;
  const char* phase = "clip sequentially";
  if (!lines.empty()) {
    const std::size_t start = out.size();
    if (split_clip_repair(b, lines, heuristic, make_clipper, shared, ctx, out, region_ordered,
                          *scratch))
      return true;
    out.resize(start);
    phase = "fall back to sequential";  // RunProfile shows how often this happens
  }
  if (scratch->divide_parts.empty())
    scratch->divide_parts.push_back(std::make_unique<DividePart>());
  CycleClipper& clipper = scratch->divide_parts[0]->clipper_from(make_clipper);
  bool complete = true;
  ctx.run_serial(phase, [&] { complete = clipper.clip(b, entry, heuristic, out, shared); });
  best_effort_vertex = clipper.best_effort_vertex();
  return complete;
}

}  // namespace pear::detail
