// The bridger's grid: every ring's nodes and edges by cell, by counting; in parts, a counting
// sort in three parallel steps whose cells list their items in the same order as the serial
// one's (by id), so the searches and the bridges do not depend on how it was built.
#include <algorithm>
#include <numeric>

#include "bridge.hpp"

namespace pear::detail {

/// Every ring's nodes and edges into the grid. Edge v runs from node v (the rings are linked as
/// cycles, nothing spliced yet).
void HoleBridger::build_grid(const CleanPolygon& polygon, const RunContext& ctx, bool parallel) {
  if (parallel) return build_grid_in_parts(polygon, ctx);
  const auto nodes = static_cast<std::uint32_t>(polygon.points.size());
  Point lo = polygon.points[0], hi = polygon.points[0];
  for (const Point& p : polygon.points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  // Each hole's ray and visibility search reads the cells it crosses. With few holes one cell
  // is cheapest: a few scans of the edges cost less than placing them in a fine grid (a glyph
  // with two holes spent a tenth of its run building one).
  frame_.fit(lo, hi, holes_.size() <= few_holes ? 1 : nodes / 2 + 1);
  edge_start_.reserve(most_ids());
  out_edge_.reserve(most_ids());
  edge_start_.resize(nodes);
  out_edge_.resize(nodes);
  std::iota(edge_start_.begin(), edge_start_.end(), 0u);
  std::iota(out_edge_.begin(), out_edge_.end(), 0u);
  if (frame_.cell_count() > 1) return fill_cells(nodes);
  for (CellLists* lists : {&node_cells_, &edge_cells_}) {  // one cell: every item, in order
    lists->start = {0, nodes};
    lists->head.assign(1, UINT32_MAX);
    lists->added.clear();
    lists->items.resize(nodes);
    std::iota(lists->items.begin(), lists->items.end(), 0u);
  }
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
    pairs_.push_back({static_cast<std::uint32_t>(frame_.cell_of(b_->pos[v])), v});
  fill(node_cells_);
  pairs_.clear();
  for (std::uint32_t v = 0; v < nodes; ++v)
    frame_.for_each_cell_on_segment(b_->pos[v], b_->pos[b_->next[v]], [&](std::size_t cell) {
      pairs_.push_back({static_cast<std::uint32_t>(cell), v});
    });
  fill(edge_cells_);
}

/// Lists [first_list, first_list + count) of cell_lists() filled from `items` ids in chunks:
/// each chunk lists its (cell, item) pairs (`cells(list, item, add)` calls add(cell) for each)
/// and counts them per band of cells (rows); the pairs are scattered by band, chunk after chunk;
/// each band is then sorted by cell on its own. Stable throughout, so every cell lists its items
/// by id.
template <class Cells>
void HoleBridger::fill_lists_in_parts(std::size_t first_list, std::size_t count,
                                      std::uint32_t items, std::size_t tasks, const RunContext& ctx,
                                      const PhaseNames& phases, Cells&& cells) {
  const auto first = [&](std::size_t t) { return static_cast<std::uint32_t>(items * t / tasks); };
  const std::size_t cell_count = frame_.cell_count();
  const std::size_t per_band = (cell_count + tasks - 1) / tasks;
  const std::size_t bands = (cell_count + per_band - 1) / per_band;

  grid_chunks_.resize(count * tasks);
  ctx.run_tasks(phases[0], count * tasks, [&](std::size_t t) {
    GridChunk& chunk = grid_chunks_[t];
    chunk.pairs.clear();
    chunk.in_band.assign(bands, 0);
    const auto list = [&](std::size_t cell, std::uint32_t item) {
      chunk.pairs.push_back({static_cast<std::uint32_t>(cell), item});
      ++chunk.in_band[cell / per_band];
    };
    const std::size_t chunk_of_ids = t % tasks, of_list = first_list + t / tasks;
    const std::uint32_t end = first(chunk_of_ids + 1);
    for (std::uint32_t v = first(chunk_of_ids); v < end; ++v)
      cells(of_list, v, [&](std::size_t cell) { list(cell, v); });
  });
  // Where each chunk's pairs of each band go: bands in order, within a band chunks in order.
  for (std::size_t l = 0; l < count; ++l) {
    std::uint32_t total = 0;
    std::vector<std::uint32_t>& band_start = band_start_[first_list + l];
    band_start.resize(bands + 1);
    for (std::size_t band = 0; band < bands; ++band) {
      band_start[band] = total;
      for (std::size_t t = l * tasks; t < (l + 1) * tasks; ++t)
        total += std::exchange(grid_chunks_[t].in_band[band], total);
    }
    band_start[bands] = total;
    by_band_[first_list + l].resize(total);
    CellLists& lists = cell_lists(first_list + l);
    lists.items.resize(total);
    lists.start.resize(cell_count + 1);
    lists.start[cell_count] = total;
    lists.head.resize(cell_count);
    lists.added.clear();
  }
  ctx.run_tasks(phases[1], count * tasks, [&](std::size_t t) {
    GridChunk& chunk = grid_chunks_[t];
    auto& out = by_band_[first_list + t / tasks];
    for (const auto& pair : chunk.pairs) out[chunk.in_band[pair.first / per_band]++] = pair;
  });
  ctx.run_tasks(phases[2], count * bands,
                [&](std::size_t t) { sort_band(first_list + t / bands, t % bands, per_band); });
}

/// The same grid in parts: the extent in tasks, then both lists by fill_lists_in_parts.
void HoleBridger::build_grid_in_parts(const CleanPolygon& polygon, const RunContext& ctx) {
  const auto nodes = static_cast<std::uint32_t>(polygon.points.size());
  const std::size_t tasks = ctx.tasks_for(nodes, 4096);
  const auto first = [&](std::size_t t) { return static_cast<std::uint32_t>(nodes * t / tasks); };
  std::vector<std::pair<Point, Point>> extents(tasks);
  edge_start_.reserve(most_ids());
  out_edge_.reserve(most_ids());
  edge_start_.resize(nodes);
  out_edge_.resize(nodes);
  // The splice on rings apart marks nodes (bridge_splice.cpp): every node and copy unmarked.
  const std::size_t copies = apart_ ? most_ids() - nodes : 0;
  if (apart_) {
    regrow_unfilled(pending_, nodes + copies);
    regrow_unfilled(copy_head_, nodes);
  }
  ctx.run_tasks("bridge: grid extent", tasks, [&](std::size_t t) {
    Point lo = polygon.points[first(t)], hi = lo;
    for (std::uint32_t v = first(t); v < first(t + 1); ++v) {
      const Point& p = polygon.points[v];
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
      edge_start_[v] = out_edge_[v] = v;
    }
    extents[t] = {lo, hi};
    if (!apart_) return;
    std::fill(pending_.begin() + first(t), pending_.begin() + first(t + 1), UINT32_MAX);
    std::fill(copy_head_.begin() + first(t), copy_head_.begin() + first(t + 1), UINT32_MAX);
    std::fill(
        pending_.begin() + static_cast<std::ptrdiff_t>(nodes + part_begin(copies, tasks, t)),
        pending_.begin() + static_cast<std::ptrdiff_t>(nodes + part_begin(copies, tasks, t + 1)),
        UINT32_MAX);
  });
  Point lo = extents[0].first, hi = extents[0].second;
  for (const auto& [l, h] : extents) {
    lo = {std::min(lo.x, l.x), std::min(lo.y, l.y)};
    hi = {std::max(hi.x, h.x), std::max(hi.y, h.y)};
  }
  frame_.fit(lo, hi, nodes / 2 + 1);
  fill_lists_in_parts(0, 2, nodes, tasks, ctx,
                      {"bridge: grid pairs", "bridge: grid scatter", "bridge: grid fill"},
                      [&](std::size_t list, std::uint32_t v, auto&& add) {
                        const Point& p = b_->pos[v];
                        if (list == 0)
                          add(frame_.cell_of(p));
                        else
                          frame_.for_each_cell_on_segment(p, b_->pos[b_->next[v]], add);
                      });
}

/// In parts, after the search: the cells of each hole's bridge as found, and for each hole
/// whether one of those bridges before it may cross its ray where the serial search would meet
/// it (crossed_by_bridge's walk, over every found bridge ranked below). The splices then enter
/// none of those bridges in edge_cells_: the serial joining spent most of its time on that
/// walk and on entering every bridge in its cells (a polygon with 12,499 holes: 1,600
/// instructions a hole).
void HoleBridger::index_found_bridges(const RunContext& ctx) {
  const auto holes = static_cast<std::uint32_t>(holes_.size());
  const std::size_t tasks = ctx.tasks_for(holes, 64);
  fill_lists_in_parts(
      2, 1, holes, tasks, ctx,
      {"bridge: found bridges", "bridge: found bridges scatter", "bridge: found bridges fill"},
      [&](std::size_t, std::uint32_t k, auto&& add) {
        if (adds_bridge(found_[k]))
          frame_.for_each_cell_on_segment(found_[k].target, b_->pos[holes_[k].leftmost], add);
      });
  bridges_indexed_ = true;
  bridge_edge_.assign(holes, UINT32_MAX);
  maybe_crossed_.resize(holes);
  ctx.run_tasks("bridge: crossing checks", tasks, [&](std::size_t t) {
    for (std::uint32_t k = holes * t / tasks; k < holes * (t + 1) / tasks; ++k) {
      const Attachment& at = found_[k];
      maybe_crossed_[k] = adds_bridge(at) && any_found_bridge_crosses(k);
    }
  });
}

/// One band's pairs (by id) into its cells by counting: start[c] counts, then is where cell c
/// starts, then (filling) where it ends, then is shifted back within the band.
void HoleBridger::sort_band(std::size_t list, std::size_t band, std::size_t per_band) {
  CellLists& lists = cell_lists(list);
  const std::size_t cells = lists.head.size();
  const std::size_t c0 = band * per_band, c1 = std::min(cells, c0 + per_band);
  const std::uint32_t begin = band_start_[list][band], end = band_start_[list][band + 1];
  std::uint32_t* start = lists.start.data();
  std::fill(start + c0, start + c1, 0u);
  std::fill(lists.head.begin() + c0, lists.head.begin() + c1, UINT32_MAX);
  const auto& pairs = by_band_[list];
  for (std::uint32_t i = begin; i < end; ++i) ++start[pairs[i].first];
  std::uint32_t offset = begin;
  for (std::size_t c = c0; c < c1; ++c) offset += std::exchange(start[c], offset);
  for (std::uint32_t i = begin; i < end; ++i)
    lists.items[start[pairs[i].first]++] = pairs[i].second;
  for (std::size_t c = c1 - 1; c > c0; --c) start[c] = start[c - 1];
  start[c0] = begin;
}

}  // namespace pear::detail
