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

/// The same grid in parts: chunks of ids list their (cell, item) pairs and count them per band
/// of cells (rows); the pairs are scattered by band, chunk after chunk; each band is then
/// sorted by cell on its own. Stable throughout, so every cell lists its items by id.
void HoleBridger::build_grid_in_parts(const CleanPolygon& polygon, const RunContext& ctx) {
  const auto nodes = static_cast<std::uint32_t>(polygon.points.size());
  const std::size_t tasks = tasks_for(nodes, 4096, ctx.partitions);
  const auto first = [&](std::size_t t) { return static_cast<std::uint32_t>(nodes * t / tasks); };
  std::vector<std::pair<Point, Point>> extents(tasks);
  edge_start_.resize(nodes);
  out_edge_.resize(nodes);
  ctx.run_tasks("bridge: grid extent", tasks, [&](std::size_t t) {
    Point lo = polygon.points[first(t)], hi = lo;
    for (std::uint32_t v = first(t); v < first(t + 1); ++v) {
      const Point& p = polygon.points[v];
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
      edge_start_[v] = out_edge_[v] = v;
    }
    extents[t] = {lo, hi};
  });
  Point lo = extents[0].first, hi = extents[0].second;
  for (const auto& [l, h] : extents) {
    lo = {std::min(lo.x, l.x), std::min(lo.y, l.y)};
    hi = {std::max(hi.x, h.x), std::max(hi.y, h.y)};
  }
  frame_.fit(lo, hi, nodes / 2 + 1);
  const std::size_t cells = frame_.cell_count();
  const std::size_t per_band = (cells + tasks - 1) / tasks;
  const std::size_t bands = (cells + per_band - 1) / per_band;

  grid_chunks_.resize(2 * tasks);
  ctx.run_tasks("bridge: grid pairs", 2 * tasks, [&](std::size_t t) {
    GridChunk& chunk = grid_chunks_[t];
    chunk.pairs.clear();
    chunk.in_band.assign(bands, 0);
    const auto list = [&](std::size_t cell, std::uint32_t item) {
      chunk.pairs.push_back({static_cast<std::uint32_t>(cell), item});
      ++chunk.in_band[cell / per_band];
    };
    const std::size_t chunk_of_ids = t % tasks;
    for (std::uint32_t v = first(chunk_of_ids); v < first(chunk_of_ids + 1); ++v) {
      const Point& p = b_->pos[v];
      if (t < tasks)
        list(frame_.cell_of(p), v);
      else
        frame_.for_each_cell_on_segment(p, b_->pos[b_->next[v]],
                                        [&](std::size_t cell) { list(cell, v); });
    }
  });
  // Where each chunk's pairs of each band go: bands in order, within a band chunks in order.
  CellLists* const lists[2] = {&node_cells_, &edge_cells_};
  for (std::size_t l = 0; l < 2; ++l) {
    std::uint32_t total = 0;
    band_start_[l].resize(bands + 1);
    for (std::size_t band = 0; band < bands; ++band) {
      band_start_[l][band] = total;
      for (std::size_t t = l * tasks; t < (l + 1) * tasks; ++t)
        total += std::exchange(grid_chunks_[t].in_band[band], total);
    }
    band_start_[l][bands] = total;
    by_band_[l].resize(total);
    lists[l]->items.resize(total);
    lists[l]->start.resize(cells + 1);
    lists[l]->start[cells] = total;
    lists[l]->head.resize(cells);
    lists[l]->added.clear();
  }
  ctx.run_tasks("bridge: grid scatter", 2 * tasks, [&](std::size_t t) {
    GridChunk& chunk = grid_chunks_[t];
    auto& out = by_band_[t / tasks];
    for (const auto& pair : chunk.pairs) out[chunk.in_band[pair.first / per_band]++] = pair;
  });
  ctx.run_tasks("bridge: grid fill", 2 * bands, [&](std::size_t t) {
    sort_band(*lists[t / bands], t / bands, t % bands, per_band);
  });
}

/// One band's pairs (by id) into its cells by counting: start[c] counts, then is where cell c
/// starts, then (filling) where it ends, then is shifted back within the band.
void HoleBridger::sort_band(CellLists& lists, std::size_t list, std::size_t band,
                            std::size_t per_band) {
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
