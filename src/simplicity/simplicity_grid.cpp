// The adaptive grid of SimplicityCheck. Every pair of edges that share a point has boxes that
// share that point, and cells are found by monotone functions of the coordinates, so both
// edges land in the cell holding the lower-left corner of their boxes' intersection: testing
// each pair there (and nowhere else) tests every pair that could conflict, exactly once. Among
// them, for two vertices at one position, the two edges that start there: so the same pass
// says whether a position repeats (unless a cell was swept instead).
#include <algorithm>

#include "simplicity.hpp"

namespace pear::detail {
namespace {

CellRange cells_of(const GridFrame& frame, const EdgeBox& box) {
  return {frame.column(box.x0), frame.column(box.x1), frame.row(box.y0), frame.row(box.y1)};
}

/// Counting sort of the edges into the cells their boxes cover; within a cell they stay in the
/// order given. False (buckets unusable) when that would make more than max_entries entries.
/// Each edge's cells are found once, kept in `ranges` between the count and the fill (on
/// Koch-8 finding them again was a quarter of the buckets' instructions).
template <class ForEachEdge>
bool bucket_edges(const GridFrame& frame, std::span<const EdgeBox> boxes,
                  ForEachEdge&& for_each_edge, std::size_t max_entries,
                  std::vector<std::uint32_t>& cell_start, std::vector<std::uint32_t>& items,
                  std::vector<CellRange>& ranges) {
  // Counts go two places up, so that filling with cell_start[c + 1]++ leaves the starts.
  cell_start.assign(frame.cell_count() + 2, 0);
  ranges.clear();
  std::size_t entries = 0;
  for_each_edge([&](std::uint32_t e) {
    if (entries > max_entries) return;
    const CellRange r = cells_of(frame, boxes[e]);
    ranges.push_back(r);
    entries += r.size();
    for (int row = r.r0; row <= r.r1; ++row)
      for (int col = r.c0; col <= r.c1; ++col) ++cell_start[frame.cell(col, row) + 2];
  });
  if (entries > max_entries) return false;
  for (std::size_t c = 2; c < cell_start.size(); ++c) cell_start[c] += cell_start[c - 1];
  items.resize(entries);
  const CellRange* range = ranges.data();
  for_each_edge([&](std::uint32_t e) {
    const CellRange r = *range++;
    for (int row = r.r0; row <= r.r1; ++row)
      for (int col = r.c0; col <= r.c1; ++col) items[cell_start[frame.cell(col, row) + 1]++] = e;
  });
  cell_start.pop_back();
  return true;
}

/// Cells about twice the edges' mean extent (boxes then span one or two cells each, and a
/// chain of edges puts a few in each cell it visits), at least 4 and at most 2 per edge.
std::size_t cells_for(Point lo, Point hi, double extent_sum, std::size_t edges) {
  const double side = 2 * extent_sum / static_cast<double>(edges);
  const double wanted = side > 0 ? (hi.x - lo.x) * (hi.y - lo.y) / (side * side) : 0;
  return static_cast<std::size_t>(std::clamp(wanted, 4.0, 2.0 * static_cast<double>(edges) + 4));
}

/// One grid on the path from the root to the cell being checked.
struct Level {
  GridFrame frame;
  int column = 0, row = 0;  ///< the cell of this grid the search is in
  std::vector<std::uint32_t> cell_start, items;
  std::vector<CellRange> ranges;  ///< bucket_edges' scratch
};

/// Checks cells of the root grid one after another, descending into finer grids; one per task.
class CellSearch {
 public:
  CellSearch(const RingEdges& edges, const GridLimits& limits, const GridFrame& root,
             std::size_t budget, SmallestViolation& found)
      : edges_(edges), limits_(limits), found_(found), levels_(limits.max_depth), budget_(budget) {
    levels_[0].frame = root;
  }

  /// What the cells searched so far say of repeated positions.
  Verdict::Touching touching() const {
    using enum Verdict::Touching;
    return repeated_ ? yes : swept_ ? unknown : no;
  }

  void check_root_cell(std::size_t cell, std::span<const std::uint32_t> list) {
    levels_[0].column = static_cast<int>(cell % levels_[0].frame.nx);
    levels_[0].row = static_cast<int>(cell / levels_[0].frame.nx);
    check_cell(0, list);
  }

 private:
  /// The list is in increasing edge order, so its front is the smallest edge a pair can name.
  void check_cell(std::uint32_t depth, std::span<const std::uint32_t> list) {
    if (list.size() < 2 || list.front() >= found_.get()) return;
    if (list.size() <= limits_.leaf_edges) return test_pairs(depth, list);
    if (depth + 1 < limits_.max_depth && subdivide(depth, list)) {
      Level& child = levels_[depth + 1];
      for (std::size_t c = 0; c + 1 < child.cell_start.size(); ++c) {
        child.column = static_cast<int>(c % child.frame.nx);
        child.row = static_cast<int>(c / child.frame.nx);
        check_cell(depth + 1, std::span(child.items)
                                  .subspan(child.cell_start[c],
                                           child.cell_start[c + 1] - child.cell_start[c]));
      }
      return;
    }
    if (list.size() <= limits_.all_pairs_edges || !limits_.allow_sweep)
      return test_pairs(depth, list);
    swept_ = true;  // the sweep does not say whether edges share an end
    if (const auto violation = sweep_edges(edges_, list)) found_.offer(*violation);
  }

  /// A finer grid over this cell, fitted to the boxes of its edges; false when it would not
  /// separate them (boxes spanning most of its cells) or the task's budget is spent.
  bool subdivide(std::uint32_t depth, std::span<const std::uint32_t> list) {
    const Level& level = levels_[depth];
    EdgeBox fit = edges_.boxes[list.front()];
    double extent = 0;
    for (std::uint32_t e : list) {
      const EdgeBox& b = edges_.boxes[e];
      fit = merged(fit, b);
      extent += std::max(b.x1 - b.x0, b.y1 - b.y0);
    }
    if (level.frame.inv_w > 0) {  // within this cell (roughly: clamping keeps it exact)
      fit.x0 = std::max(fit.x0, level.frame.x0 + level.column / level.frame.inv_w);
      fit.x1 = std::min(fit.x1, level.frame.x0 + (level.column + 1) / level.frame.inv_w);
    }
    if (level.frame.inv_h > 0) {
      fit.y0 = std::max(fit.y0, level.frame.y0 + level.row / level.frame.inv_h);
      fit.y1 = std::min(fit.y1, level.frame.y0 + (level.row + 1) / level.frame.inv_h);
    }
    Level& child = levels_[depth + 1];
    const Point lo{std::min(fit.x0, fit.x1), std::min(fit.y0, fit.y1)};
    const Point hi{std::max(fit.x0, fit.x1), std::max(fit.y0, fit.y1)};
    child.frame.fit(lo, hi, cells_for(lo, hi, extent, list.size()));
    if (child.frame.cell_count() < 2) return false;
    const auto max_entries = static_cast<std::size_t>(
        std::min(limits_.child_entries_per_edge * static_cast<double>(list.size()),
                 static_cast<double>(budget_)));
    const auto for_each_edge = [&](auto&& visit) {
      for (std::uint32_t e : list) visit(e);
    };
    if (!bucket_edges(child.frame, edges_.boxes, for_each_edge, max_entries, child.cell_start,
                      child.items, child.ranges))
      return false;
    budget_ -= child.items.size();
    // Worth it only if the pairs to test drop well: not so where the boxes overlap each other.
    std::size_t pairs = 0;
    for (std::size_t c = 0; c + 1 < child.cell_start.size(); ++c) {
      const std::size_t k = child.cell_start[c + 1] - child.cell_start[c];
      pairs += k * k;
    }
    return pairs * 2 <= list.size() * list.size();
  }

  /// Whether this cell, and each cell above it, holds the reference point of a pair.
  bool owns(double x, double y, std::uint32_t depth) const {
    for (std::uint32_t d = 0; d <= depth; ++d) {
      const Level& level = levels_[d];
      if (level.frame.column(x) != level.column || level.frame.row(y) != level.row) return false;
    }
    return true;
  }

  void test_pairs(std::uint32_t depth, std::span<const std::uint32_t> list) {
    const auto& boxes = edges_.boxes;
    const Point* pts = edges_.points->data();
    for (std::size_t i = 0; i < list.size(); ++i) {
      const std::uint32_t e = list[i];
      if (e >= found_.get()) return;  // no pair from here on can name a smaller edge
      const EdgeBox& s = boxes[e];
      for (std::size_t j = i + 1; j < list.size(); ++j) {
        const EdgeBox& t = boxes[list[j]];
        if (s.x1 < t.x0 || t.x1 < s.x0 || s.y1 < t.y0 || t.y1 < s.y0) continue;
        if (!owns(std::max(s.x0, t.x0), std::max(s.y0, t.y0), depth)) continue;
        // Edges start where they are numbered; cleaning left no point equal to the next, so
        // two edges starting at one position are never neighbours.
        repeated_ |= pts[e] == pts[list[j]];
        if (edges_.conflict(e, list[j])) {
          found_.offer(e);
          return;
        }
      }
    }
  }

  const RingEdges& edges_;
  const GridLimits& limits_;
  SmallestViolation& found_;
  std::vector<Level> levels_;
  std::size_t budget_;     ///< entries this task may still put into finer grids
  bool repeated_ = false;  ///< two edges tested start at one position
  bool swept_ = false;     ///< a cell was swept, not tested pair by pair
};

/// Root cells cut into runs of about equal entries: the tasks. Depends on counts only.
std::vector<std::size_t> task_cuts(const std::vector<std::uint32_t>& cell_start) {
  const std::size_t cells = cell_start.size() - 1, entries = cell_start.back();
  const std::size_t tasks = std::clamp<std::size_t>(entries / 4096, 1, 1024);
  // Cut k: the first cell end past cut k - 1 with k / tasks of the entries before it, found by
  // a binary search (a scan of every cell was 0.05 ms of Koch-8's check at 16 partitions,
  // between two phases).
  std::vector<std::size_t> cuts{0};
  for (std::size_t k = 1; k < tasks; ++k) {
    const auto end = cell_start.begin() + static_cast<std::ptrdiff_t>(cells) + 1;
    const auto at = std::partition_point(
        cell_start.begin() + static_cast<std::ptrdiff_t>(cuts.back()) + 1, end,
        [&](std::uint32_t before) { return std::size_t{before} * tasks < entries * k; });
    if (at == end) break;
    cuts.push_back(static_cast<std::size_t>(at - cell_start.begin()));
  }
  cuts.push_back(cells);
  return cuts;
}

/// The part [first, last) of [0, count) that piece i of `pieces` covers.
std::pair<std::size_t, std::size_t> piece(std::size_t i, std::size_t pieces, std::size_t count) {
  return {i * count / pieces, (i + 1) * count / pieces};
}

/// bucket_edges for all edges, in parallel: each chunk of edges counts its entries per cell,
/// the counts become per-chunk fill positions (cell by cell, chunk by chunk, so a cell lists
/// its edges in increasing order, as bucket_edges does), and each chunk fills its entries.
/// False as soon as a chunk has more than `entries_per_edge` entries per edge of its own. A
/// chunk a partition, of at least 8,192 edges: each chunk also clears and sums a count per
/// cell, so more chunks than tasks only add work; at most 8 on grids of over 2^18 cells (the
/// counts' memory).
bool bucket_root(const RingEdges& edges, double entries_per_edge, const RunContext& ctx,
                 RootGrid& root) {
  const std::size_t n = edges.size(), cells = root.frame.cell_count();
  const std::size_t most = cells <= (std::size_t{1} << 18) ? 16 : 8;
  const std::size_t chunks =
      std::clamp<std::size_t>(std::min<std::size_t>(n / 8192, ctx.partitions), 1, most);
  root.chunk_counts.resize(chunks * cells);
  std::vector<std::size_t> chunk_entries(chunks, 0);
  std::vector<char> too_many(chunks, false);
  // Visits each edge of a chunk (its entry count: false stops) and then its entries. The count
  // finds each edge's cells and keeps them for the fill (root.ranges).
  root.ranges.resize(n);
  const auto for_each_entry = [&](std::size_t chunk, bool counting, auto&& edge, auto&& entry) {
    const auto [first, last] = piece(chunk, chunks, n);
    for (std::size_t e = first; e < last; ++e) {
      const CellRange r =
          counting ? (root.ranges[e] = cells_of(root.frame, edges.boxes[e])) : root.ranges[e];
      if (!edge(r.size())) return;
      for (int row = r.r0; row <= r.r1; ++row)
        for (int col = r.c0; col <= r.c1; ++col)
          entry(root.chunk_counts[chunk * cells + root.frame.cell(col, row)],
                static_cast<std::uint32_t>(e));
    }
  };
  ctx.run_tasks("check simplicity: root grid count", chunks, [&](std::size_t chunk) {
    std::fill_n(root.chunk_counts.begin() + chunk * cells, cells, 0);
    const auto [first, last] = piece(chunk, chunks, n);
    const double max_entries = entries_per_edge * static_cast<double>(last - first);
    std::size_t entries = 0;
    for_each_entry(
        chunk, true,
        [&](std::size_t k) { return static_cast<double>(entries += k) <= max_entries; },
        [](std::uint32_t& count, std::uint32_t) { ++count; });
    chunk_entries[chunk] = entries;
    too_many[chunk] = static_cast<double>(entries) > max_entries;
  });
  if (std::find(too_many.begin(), too_many.end(), true) != too_many.end()) return false;
  std::size_t entries = 0;
  for (std::size_t e : chunk_entries) entries += e;
  root.cell_start.resize(cells + 1);
  std::vector<std::size_t> range_start(chunks + 1, 0);
  ctx.run_tasks("check simplicity: root grid offsets", chunks, [&](std::size_t range) {
    const auto [first, last] = piece(range, chunks, cells);
    std::size_t sum = 0;
    for (std::size_t c = first; c < last; ++c)
      for (std::size_t k = 0; k < chunks; ++k) sum += root.chunk_counts[k * cells + c];
    range_start[range + 1] = sum;
  });
  for (std::size_t r = 0; r < chunks; ++r) range_start[r + 1] += range_start[r];
  ctx.run_tasks("check simplicity: root grid offsets", chunks, [&](std::size_t range) {
    const auto [first, last] = piece(range, chunks, cells);
    auto offset = static_cast<std::uint32_t>(range_start[range]);
    for (std::size_t c = first; c < last; ++c) {
      root.cell_start[c] = offset;
      for (std::size_t k = 0; k < chunks; ++k)
        offset += std::exchange(root.chunk_counts[k * cells + c], offset);
    }
  });
  root.cell_start[cells] = static_cast<std::uint32_t>(entries);
  root.items.resize(entries);
  ctx.run_tasks("check simplicity: root grid fill", chunks, [&](std::size_t chunk) {
    for_each_entry(
        chunk, false, [](std::size_t) { return true; },
        [&](std::uint32_t& at, std::uint32_t e) { root.items[at++] = e; });
  });
  return true;
}

}  // namespace

bool check_on_grid(const RingEdges& edges, const GridLimits& limits, const RunContext& ctx,
                   RootGrid& root, SmallestViolation& found, Verdict::Touching* touching) {
  const std::uint32_t n = edges.size();
  const Point lo{edges.bounds.x0, edges.bounds.y0}, hi{edges.bounds.x1, edges.bounds.y1};
  // About two edges a cell over the bounding box, whatever the edges' lengths: where edges
  // are long against that (a star), the root holds too many entries and the slabs decide.
  root.frame.fit(lo, hi, std::size_t{n} / 2 + 1);
  if (!bucket_root(edges, limits.root_entries_per_edge, ctx, root)) return false;
  const std::vector<std::size_t> cuts = task_cuts(root.cell_start);
  std::vector<Verdict::Touching> seen(cuts.size() - 1);
  ctx.run_tasks("check simplicity: cells", cuts.size() - 1, [&](std::size_t task) {
    const std::size_t first = cuts[task], last = cuts[task + 1];
    const std::size_t entries = root.cell_start[last] - root.cell_start[first];
    CellSearch search(edges, limits, root.frame, 8 * entries + 1024, found);
    for (std::size_t c = first; c < last; ++c)
      search.check_root_cell(
          c, std::span(root.items)
                 .subspan(root.cell_start[c], root.cell_start[c + 1] - root.cell_start[c]));
    seen[task] = search.touching();
  });
  if (touching) {  // a repeat seen anywhere is one; else unknown where any task swept
    using enum Verdict::Touching;
    const auto has = [&](Verdict::Touching t) {
      return std::find(seen.begin(), seen.end(), t) != seen.end();
    };
    *touching = has(yes) ? yes : has(unknown) ? unknown : no;
  }
  return true;
}

}  // namespace pear::detail
