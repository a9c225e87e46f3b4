#include "divide_conquer_repair.hpp"

#include <algorithm>
#include <numeric>

#include "core/sort_in_parts.hpp"
#include "geometry/sort.hpp"
#include "pear/config.hpp"

namespace pear::detail {
namespace {

/// Union-find over triangles, for the connected groups of removed triangles.
struct Groups {
  std::vector<std::uint32_t> parent;
  explicit Groups(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0u); }
  std::uint32_t root(std::uint32_t t) {
    while (parent[t] != t) t = parent[t] = parent[parent[t]];
    return t;
  }
  void unite(std::uint32_t a, std::uint32_t b) { parent[root(a)] = root(b); }
};

SteinerRepair::CornerKey key_of(const Boundary& b, const std::vector<SplitLine>& lines,
                                PieceCorner c) {
  using CornerKey = SteinerRepair::CornerKey;
  if (!is_steiner(c)) return {0, b.pos[corner_index(c)], {}};
  const SteinerPoint& s = lines[corner_line(c)].steiner[corner_index(c)];
  const Point& p = b.pos[s.from];
  const Point& q = b.pos[s.to];
  return lexicographic_less(p, q) ? CornerKey{corner_line(c) + 1, p, q}
                                  : CornerKey{corner_line(c) + 1, q, p};
}

/// Items a task of the repair's passes and sorts takes at least. The repair's arrays are a few
/// thousand long where many lines cross many holes (the holes grid at 16 partitions: 4,000-6,000
/// corners, edges and uses): a task per 1,024 left 3-6 tasks a pass, and the passes' longest
/// tasks were a tenth of the projected time at 16 threads.
constexpr std::size_t repair_grain = 256;

/// The tasks a pass of the repair over `items` triangles or edges takes: one per repair_grain,
/// at most one a partition.
std::size_t repair_tasks(std::size_t items, const RunContext& ctx) {
  if (!PEAR_HAS_THREADS) return 1;  // one loop a pass, and the bucketed check left out
  return std::clamp<std::size_t>(items / repair_grain, 1, std::max(1u, ctx.partitions));
}

/// Appends every Steiner point, as a corner, to `corners`.
void append_steiner_points(const std::vector<SplitLine>& lines, std::vector<PieceCorner>& corners) {
  for (std::uint32_t line = 0; line < lines.size(); ++line)
    for (std::uint32_t i = 0; i < lines[line].steiner.size(); ++i)
      corners.push_back(steiner_corner(line, i));
}

}  // namespace

/// triangles_ [from, to): the input triangles in canonical corners.
void SteinerRepair::canonicalize(const std::vector<SteinerTriangle>& triangles, std::size_t from,
                                 std::size_t to) {
  for (std::size_t i = from; i < to; ++i)
    triangles_[i] = {canonical(triangles[i][0]), canonical(triangles[i][1]),
                     canonical(triangles[i][2])};
}

/// canonical_: every corner of the triangles and of the Steiner points' edges, with the first
/// corner at its point. The sorts in tasks of ctx (phases "find Steiner holes: ...").
void SteinerRepair::canonical_corners(const Boundary& b, const std::vector<SplitLine>& lines,
                                      const std::vector<SteinerTriangle>& triangles,
                                      const RunContext& ctx) {
  std::vector<PieceCorner>& corners = corners_;
  ctx.run_serial_if_threads("find Steiner holes: corners", [&] {
    corners.clear();  // kept, not replaced: its pages stay from run to run
    append_steiner_points(lines, corners);
    for (std::size_t i = 0, steiner = corners.size(); i < steiner; ++i) {
      const SteinerPoint& s = lines[corner_line(corners[i])].steiner[corner_index(corners[i])];
      corners.push_back(s.from);
      corners.push_back(s.to);
    }
    for (const SteinerTriangle& t : triangles) corners.insert(corners.end(), t.begin(), t.end());
  });
  sort_in_parts(ctx, "find Steiner holes: sort corners", "find Steiner holes: merge corners",
                corners, std::less<>{}, repair_grain);
  std::vector<std::pair<CornerKey, PieceCorner>>& keyed = keyed_;
  ctx.run_serial_if_threads("find Steiner holes: unique", [&] {
    corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
    keyed.resize(corners.size());
  });
  const std::size_t key_tasks = repair_tasks(corners.size(), ctx);
  ctx.run_tasks_if_threads("find Steiner holes: keys", key_tasks, [&](std::size_t task) {
    const std::size_t end = part_begin(corners.size(), key_tasks, task + 1);
    for (std::size_t i = part_begin(corners.size(), key_tasks, task); i < end; ++i)
      keyed[i] = {key_of(b, lines, corners[i]), corners[i]};
  });
  sort_in_parts(ctx, "find Steiner holes: sort keys", "find Steiner holes: merge keys", keyed,
                std::less<>{}, repair_grain);
  ctx.run_serial_if_threads("find Steiner holes: group", [&] {
    canonical_.resize(keyed.size());
    for (std::size_t i = 0, first = 0; i < keyed.size(); ++i) {
      if (keyed[i].first != keyed[first].first) first = i;
      canonical_[i] = {keyed[i].second, keyed[first].second};
    }
  });
  sort_in_parts(ctx, "find Steiner holes: sort canonical", "find Steiner holes: merge canonical",
                canonical_, std::less<>{}, repair_grain);
}

PieceCorner SteinerRepair::canonical(PieceCorner c) const {
  const auto it =
      std::lower_bound(canonical_.begin(), canonical_.end(), std::pair{c, PieceCorner{0}});
  return it != canonical_.end() && it->first == c ? it->second : c;
}

std::uint32_t SteinerRepair::find(PieceCorner from, PieceCorner to) const {
  const auto it =
      std::lower_bound(edges_.begin(), edges_.end(), std::pair{from, to},
                       [](const DirectedEdge& e, const auto& key) {
                         return e.from < key.first || (e.from == key.first && e.to < key.second);
                       });
  return it != edges_.end() && it->from == from && it->to == to ? it->id : none;
}

/// The edge glued to `edge` in the other removed triangle on it; none when it bounds the hole:
/// no such triangle, or the edge lies on the input boundary (the two sides of a bridge are
/// reverse edges between the same points, but stay apart).
std::uint32_t SteinerRepair::glued(std::uint32_t edge) const {
  if (on_boundary_[edge / 3] >> (edge % 3) & 1) return none;
  const SteinerTriangle& t = triangles_[edge / 3];
  const std::uint32_t reverse = find(t[(edge % 3 + 1) % 3], t[edge % 3]);
  return reverse == none || (on_boundary_[reverse / 3] >> (reverse % 3) & 1) ? none : reverse;
}

/// glued(edge), looked up once per edge (the walks and the groups ask again and again).
std::uint32_t SteinerRepair::across(std::uint32_t edge) const {
  return across_[edge];
}

/// The hole's boundary edge after `edge` (hole on the left): turn around its end through the
/// removed triangles until an edge has no removed triangle on its other side.
std::uint32_t SteinerRepair::next_on_boundary(std::uint32_t edge) const {
  const auto& triangles = triangles_;
  std::uint32_t candidate = edge / 3 * 3 + (edge % 3 + 1) % 3;
  for (std::size_t turns = 0; turns <= triangles.size(); ++turns) {
    const std::uint32_t reverse = across(candidate);
    if (reverse == none) return candidate;
    candidate = reverse / 3 * 3 + (reverse % 3 + 1) % 3;
  }
  return none;
}

/// Records the cycle of boundary edges through `start`, input nodes only: the Steiner points
/// on it are dropped, which joins the two halves of each split input edge again.
bool SteinerRepair::walk_hole(std::uint32_t start, std::vector<std::uint8_t>& visited) {
  std::uint32_t edge = start;
  for (std::size_t steps = 0; steps < visited.size(); ++steps) {
    visited[edge] = 1;
    const PieceCorner from = triangles_[edge / 3][edge % 3];
    if (!is_steiner(from)) nodes_.push_back(corner_index(from));
    edge = next_on_boundary(edge);
    if (edge == none) return false;
    if (edge == start) {
      starts_.push_back(static_cast<std::uint32_t>(nodes_.size()));
      return starts_.back() - starts_[starts_.size() - 2] >= 2;
    }
  }
  return false;
}

/// One boundary cycle per connected group of triangles: no group encloses triangles that stay.
bool SteinerRepair::holes_are_disks(const std::vector<std::uint32_t>& hole_starts) const {
  Groups groups(triangles_.size());
  for (const DirectedEdge& e : edges_) {
    const std::uint32_t reverse = across(e.id);
    if (reverse != none) groups.unite(e.id / 3, reverse / 3);
  }
  std::vector<std::uint8_t> has_hole(triangles_.size(), 0);
  for (std::uint32_t start : hole_starts) {
    const std::uint32_t group = groups.root(start / 3);
    if (has_hole[group]) return false;
    has_hole[group] = 1;
  }
  return true;
}

/// edges_, sorted (in tasks of ctx), and across_ sized for glue(); false when a directed edge
/// repeats (the triangles overlap).
bool SteinerRepair::index_edges(const RunContext& ctx) {
  ctx.run_serial_if_threads("find Steiner holes: edges", [&] {
    edges_.resize(3 * triangles_.size());
    for (std::uint32_t t = 0; t < triangles_.size(); ++t)
      for (std::uint32_t c = 0; c < 3; ++c)
        edges_[3 * t + c] = {triangles_[t][c], triangles_[t][(c + 1) % 3], 3 * t + c};
  });
  sort_in_parts(
      ctx, "find Steiner holes: sort edges", "find Steiner holes: merge edges", edges_,
      [](const DirectedEdge& p, const DirectedEdge& q) {
        return p.from < q.from || (p.from == q.from && p.to < q.to);
      },
      repair_grain);
  bool repeats = false;
  ctx.run_serial_if_threads("find Steiner holes: repeats", [&] {
    for (std::size_t i = 1; i < edges_.size() && !repeats; ++i)
      repeats = edges_[i].from == edges_[i - 1].from && edges_[i].to == edges_[i - 1].to;
    across_.resize(edges_.size());
  });
  return !repeats;
}

/// across_ [from, to).
void SteinerRepair::glue(std::size_t from, std::size_t to) {
  for (std::size_t id = from; id < to; ++id) across_[id] = glued(static_cast<std::uint32_t>(id));
}

/// Every hole's cycle (nodes_, starts_); false unless each is a disk.
bool SteinerRepair::walk_holes() {
  nodes_.clear();
  starts_.assign(1, 0);
  std::vector<std::uint8_t> visited(edges_.size(), 0);
  std::vector<std::uint32_t> hole_starts;
  for (std::uint32_t id = 0; id < visited.size(); ++id) {
    if (visited[id] || across(id) != none) continue;
    if (!walk_hole(id, visited)) return false;
    hole_starts.push_back(id);
  }
  return holes_are_disks(hole_starts);
}

bool SteinerRepair::find_holes(const Boundary& b, const std::vector<SplitLine>& lines,
                               const std::vector<SteinerTriangle>& input,
                               std::vector<std::uint8_t> on_boundary, const RunContext& ctx) {
  on_boundary_ = std::move(on_boundary);
  triangles_.resize(input.size());
  bool found = false;
  if (!PEAR_HAS_THREADS) {  // one phase: a build without threads keeps no task passes (.wasm)
    // Without threads their steps are plain calls inside this phase (run_*_if_threads).
    ctx.run_serial("find Steiner holes", [&] {
      canonical_corners(b, lines, input, ctx);
      canonicalize(input, 0, input.size());
      found = index_edges(ctx) && (glue(0, edges_.size()), walk_holes());
    });
    return found;
  }
  // The passes over every triangle and edge and the sorts in tasks; the walks stay serial.
  canonical_corners(b, lines, input, ctx);
  const std::size_t tasks = repair_tasks(input.size(), ctx);
  ctx.run_tasks("find Steiner holes: canonical", tasks, [&](std::size_t task) {
    canonicalize(input, part_begin(input.size(), tasks, task),
                 part_begin(input.size(), tasks, task + 1));
  });
  if (!index_edges(ctx)) return false;
  const std::size_t edge_tasks = repair_tasks(edges_.size(), ctx);
  ctx.run_tasks("find Steiner holes: glue", edge_tasks, [&](std::size_t task) {
    glue(part_begin(edges_.size(), edge_tasks, task),
         part_begin(edges_.size(), edge_tasks, task + 1));
  });
  ctx.run_serial("find Steiner holes: walk", [&] { found = walk_holes(); });
  return found;
}

bool SteinerRepair::triangulate_hole(std::size_t h, const Boundary& b, EarHeuristic heuristic,
                                     HoleClipper& scratch, TriangleList& out,
                                     std::vector<SteinerTriangle>& corners) const {
  const std::uint32_t first = starts_[h], count = starts_[h + 1] - first;
  if (count < 3) return true;  // a -> s -> b against b -> a: the hole had no area
  const std::uint32_t* nodes = &nodes_[first];
  scratch.local.clear();
  if (count == 3) {
    scratch.local.push_back({0, 1, 2});
  } else {
    scratch.hole.clear();
    for (std::uint32_t i = 0; i < count; ++i) scratch.hole.add(b.pos[nodes[i]], i);
    for (std::uint32_t i = 0; i < count; ++i) scratch.hole.link(i, i + 1 == count ? 0 : i + 1);
    if (!scratch.clipper->clip(scratch.hole, 0, heuristic, scratch.local, {})) return false;
  }
  for (const auto& t : scratch.local) {
    if (!(orient2d(b.pos[nodes[t[0]]], b.pos[nodes[t[1]]], b.pos[nodes[t[2]]]) > 0)) return false;
    out.push_back({b.vertex[nodes[t[0]]], b.vertex[nodes[t[1]]], b.vertex[nodes[t[2]]]});
    corners.push_back({nodes[t[0]], nodes[t[1]], nodes[t[2]]});
  }
  return true;
}

namespace {

/// Which of `buckets` groups an edge's uses go to: every use of an edge lands in one.
std::size_t bucket_of(const ChainUse& u, std::size_t buckets) {
  const std::uint64_t mixed = (u.lo * 0x9E3779B97F4A7C15u) ^ (u.hi * 0xC2B2AE3D27D4EB4Fu);
  return static_cast<std::size_t>((mixed >> 32) % buckets);
}

/// Whether every edge's uses among `uses` add up to 0.
bool every_sum_zero(std::vector<ChainUse>& uses) {
  detail::sort(uses.begin(), uses.end(), [](const ChainUse& u, const ChainUse& v) {
    return u.lo < v.lo || (u.lo == v.lo && u.hi < v.hi);
  });
  for (std::size_t i = 0, j = 0; i < uses.size(); i = j) {
    int sum = 0;
    for (j = i; j < uses.size() && uses[j].lo == uses[i].lo && uses[j].hi == uses[i].hi; ++j)
      sum += uses[j].sign;
    if (sum != 0) return false;
  }
  return true;
}

/// Adds the use of the directed edge from -> to (canonical corners) with `sign`.
void add_use(std::vector<ChainUse>& uses, PieceCorner from, PieceCorner to, int sign) {
  if (from < to) uses.push_back({from, to, sign});
  if (to < from) uses.push_back({to, from, -sign});
}

}  // namespace

/// steiner_: every Steiner point by the input edge it splits, then along that edge (a total
/// order: the points of one edge lie on different lines, so their x differ), sorted in parts.
void SteinerRepair::sort_steiner_points(const Boundary& b, const std::vector<SplitLine>& lines,
                                        const RunContext& ctx) {
  steiner_.clear();
  append_steiner_points(lines, steiner_);
  const auto point = [&](PieceCorner c) -> const SteinerPoint& {
    return lines[corner_line(c)].steiner[corner_index(c)];
  };
  sort_in_parts(
      ctx, "check Steiner holes: sort", "check Steiner holes: merge", steiner_,
      [&](PieceCorner p, PieceCorner q) {
        const SteinerPoint &s = point(p), &t = point(q);
        if (s.from != t.from || s.to != t.to)
          return s.from < t.from || (s.from == t.from && s.to < t.to);
        return s.pos.x != t.pos.x && (s.pos.x < t.pos.x) == (b.pos[s.from].x < b.pos[s.to].x);
      },
      repair_grain);
}

/// The chains' terms of steiner_[from, to): each split input edge + (a -> s1 -> ... -> b) -
/// (a -> b) with its Steiner points in edge order, in canonical corners (each term at the point
/// it starts from, the edge's last point adding the rest).
void SteinerRepair::add_split_edges(const std::vector<SplitLine>& lines, std::size_t from,
                                    std::size_t to, std::vector<ChainUse>& uses) const {
  const auto add = [&](PieceCorner a, PieceCorner c, int sign) {
    add_use(uses, canonical(a), canonical(c), sign);
  };
  const auto point = [&](PieceCorner c) -> const SteinerPoint& {
    return lines[corner_line(c)].steiner[corner_index(c)];
  };
  const std::vector<PieceCorner>& steiner = steiner_;
  for (std::size_t i = from; i < to; ++i) {
    const SteinerPoint& s = point(steiner[i]);
    const bool first =
        i == 0 || point(steiner[i - 1]).from != s.from || point(steiner[i - 1]).to != s.to;
    const bool last = i + 1 == steiner.size() || point(steiner[i + 1]).from != s.from ||
                      point(steiner[i + 1]).to != s.to;
    add(first ? PieceCorner{s.from} : steiner[i - 1], steiner[i], 1);
    if (last) add(steiner[i], s.to, 1), add(s.from, s.to, -1);
  }
}

/// The uses go to buckets by edge (the removed triangles and the fills split among tasks), and
/// each bucket's sums are checked by a task of its own: the check adds up edge by edge, so the
/// verdict is the same for any number of buckets. The corners of the removed triangles and of
/// the fills are canonical already (the fills' are the holes' nodes, taken from those
/// triangles); only the split edges' are looked up.
bool SteinerRepair::check_chain(const Boundary& b, const std::vector<SplitLine>& lines,
                                const std::vector<std::vector<SteinerTriangle>>& fills,
                                const RunContext& ctx) {
  std::vector<ChainUse> uses;
  // The triangles in one numbering, fills first: +1 for a fill's edges, -1 for a removed one's.
  std::vector<std::size_t> starts(1, 0);
  for (const auto& fill : fills) starts.push_back(starts.back() + fill.size());
  const std::size_t filled = starts.back(), total = filled + triangles_.size();
  // The uses of the triangles [from, to) of that numbering.
  const auto add_triangles = [&](std::vector<ChainUse>& to_uses, std::size_t from, std::size_t to) {
    const auto add_share = [&](const std::vector<SteinerTriangle>& list, std::size_t first,
                               int sign) {
      for (std::size_t i = std::max(from, first); i < std::min(to, first + list.size()); ++i)
        for (int c = 0; c < 3; ++c)
          add_use(to_uses, list[i - first][c], list[i - first][(c + 1) % 3], sign);
    };
    for (std::size_t f = 0; f < fills.size(); ++f) add_share(fills[f], starts[f], 1);
    add_share(triangles_, filled, -1);
  };
  const std::size_t buckets = repair_tasks(total, ctx);
  bool zero = false;
  if (!PEAR_HAS_THREADS || buckets == 1) {  // a build without threads keeps only this path
    ctx.run_serial("check Steiner holes", [&] {
      sort_steiner_points(b, lines, RunContext{});
      add_split_edges(lines, 0, steiner_.size(), uses);
      add_triangles(uses, 0, total);
      zero = every_sum_zero(uses);
    });
    return zero;
  }
  // The split edges' terms in parts too: their sort was the longest task of the check (the
  // holes grid at 16 partitions: 0.34 ms, serial).
  sort_steiner_points(b, lines, ctx);
  const std::size_t points = steiner_.size();
  std::vector<std::vector<std::vector<ChainUse>>> bucketed(
      buckets, std::vector<std::vector<ChainUse>>(buckets));
  ctx.run_tasks("check Steiner holes: edges", buckets, [&](std::size_t task) {
    std::vector<ChainUse> share;
    add_split_edges(lines, part_begin(points, buckets, task), part_begin(points, buckets, task + 1),
                    share);
    add_triangles(share, part_begin(total, buckets, task), part_begin(total, buckets, task + 1));
    for (const ChainUse& u : share) bucketed[task][bucket_of(u, buckets)].push_back(u);
  });
  std::vector<std::uint8_t> zeros(buckets, 0);
  ctx.run_tasks("check Steiner holes: sums", buckets, [&](std::size_t bucket) {
    std::vector<ChainUse> gathered;
    for (std::size_t task = 0; task < buckets; ++task)
      gathered.insert(gathered.end(), bucketed[task][bucket].begin(), bucketed[task][bucket].end());
    zeros[bucket] = every_sum_zero(gathered);
  });
  return std::find(zeros.begin(), zeros.end(), 0) == zeros.end();
}

}  // namespace pear::detail
