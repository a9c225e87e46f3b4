#include "divide_conquer_repair.hpp"

#include <algorithm>
#include <numeric>

#include "geometry/sort.hpp"

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

/// What makes two corners the same point: an input node by its position, a Steiner point by its
/// line and the ends of its input edge (so both sides of a bridge give one point).
struct CornerKey {
  std::uint32_t line = 0;  ///< 0 for an input node, else the Steiner point's line + 1
  Point a{}, b{};
  friend bool operator<(const CornerKey& p, const CornerKey& q) {
    if (p.line != q.line) return p.line < q.line;
    if (p.a != q.a) return lexicographic_less(p.a, q.a);
    return lexicographic_less(p.b, q.b);
  }
  friend bool operator==(const CornerKey&, const CornerKey&) = default;
};

CornerKey key_of(const Boundary& b, const std::vector<SplitLine>& lines, PieceCorner c) {
  if (!is_steiner(c)) return {0, b.pos[corner_index(c)], {}};
  const SteinerPoint& s = lines[corner_line(c)].steiner[corner_index(c)];
  const Point& p = b.pos[s.from];
  const Point& q = b.pos[s.to];
  return lexicographic_less(p, q) ? CornerKey{corner_line(c) + 1, p, q}
                                  : CornerKey{corner_line(c) + 1, q, p};
}

/// Every Steiner point, as a corner.
std::vector<PieceCorner> all_steiner_points(const std::vector<SplitLine>& lines) {
  std::vector<PieceCorner> corners;
  for (std::uint32_t line = 0; line < lines.size(); ++line)
    for (std::uint32_t i = 0; i < lines[line].steiner.size(); ++i)
      corners.push_back(steiner_corner(line, i));
  return corners;
}

}  // namespace

void SteinerRepair::canonicalize(const Boundary& b, const std::vector<SplitLine>& lines,
                                 const std::vector<SteinerTriangle>& triangles) {
  std::vector<PieceCorner> corners = all_steiner_points(lines);
  for (std::size_t i = 0, steiner = corners.size(); i < steiner; ++i) {
    const SteinerPoint& s = lines[corner_line(corners[i])].steiner[corner_index(corners[i])];
    corners.push_back(s.from);
    corners.push_back(s.to);
  }
  for (const SteinerTriangle& t : triangles) corners.insert(corners.end(), t.begin(), t.end());
  detail::sort(corners.begin(), corners.end());
  corners.erase(std::unique(corners.begin(), corners.end()), corners.end());
  std::vector<std::pair<CornerKey, PieceCorner>> keyed;
  for (PieceCorner c : corners) keyed.push_back({key_of(b, lines, c), c});
  detail::sort(keyed.begin(), keyed.end());
  canonical_.clear();
  for (std::size_t i = 0, first = 0; i < keyed.size(); ++i) {
    if (keyed[i].first != keyed[first].first) first = i;
    canonical_.push_back({keyed[i].second, keyed[first].second});
  }
  detail::sort(canonical_.begin(), canonical_.end());
  triangles_.clear();
  for (const SteinerTriangle& t : triangles)
    triangles_.push_back({canonical(t[0]), canonical(t[1]), canonical(t[2])});
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

bool SteinerRepair::find_holes(const Boundary& b, const std::vector<SplitLine>& lines,
                               const std::vector<SteinerTriangle>& input,
                               std::vector<std::uint8_t> on_boundary) {
  canonicalize(b, lines, input);
  on_boundary_ = std::move(on_boundary);
  const std::vector<SteinerTriangle>& triangles = triangles_;
  edges_.clear();
  nodes_.clear();
  starts_.assign(1, 0);
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (std::uint32_t c = 0; c < 3; ++c)
      edges_.push_back({triangles[t][c], triangles[t][(c + 1) % 3], 3 * t + c});
  detail::sort(edges_.begin(), edges_.end(), [](const DirectedEdge& a, const DirectedEdge& b) {
    return a.from < b.from || (a.from == b.from && a.to < b.to);
  });
  for (std::size_t i = 1; i < edges_.size(); ++i)
    if (edges_[i].from == edges_[i - 1].from && edges_[i].to == edges_[i - 1].to) return false;
  across_.resize(edges_.size());
  for (std::uint32_t id = 0; id < across_.size(); ++id) across_[id] = glued(id);
  std::vector<std::uint8_t> visited(edges_.size(), 0);
  std::vector<std::uint32_t> hole_starts;
  for (std::uint32_t id = 0; id < visited.size(); ++id) {
    if (visited[id] || across(id) != none) continue;
    if (!walk_hole(id, visited)) return false;
    hole_starts.push_back(id);
  }
  return holes_are_disks(hole_starts);
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
    if (!scratch.clipper->clip(scratch.hole, 0, heuristic, scratch.local)) return false;
  }
  for (const auto& t : scratch.local) {
    if (!(orient2d(b.pos[nodes[t[0]]], b.pos[nodes[t[1]]], b.pos[nodes[t[2]]]) > 0)) return false;
    out.push_back({b.vertex[nodes[t[0]]], b.vertex[nodes[t[1]]], b.vertex[nodes[t[2]]]});
    corners.push_back({nodes[t[0]], nodes[t[1]], nodes[t[2]]});
  }
  return true;
}

bool SteinerRepair::check_chain(const Boundary& b, const std::vector<SplitLine>& lines,
                                const std::vector<SteinerTriangle>& fill) const {
  struct Use {
    PieceCorner lo, hi;
    int sign;
  };
  std::vector<Use> uses;
  uses.reserve(3 * (fill.size() + triangles_.size()));
  // Corners already canonical: the removed triangles' (canonicalize) and the fill's (its
  // corners are the holes' nodes, taken from those triangles).
  const auto add_canonical = [&](PieceCorner from, PieceCorner to, int sign) {
    if (from < to) uses.push_back({from, to, sign});
    if (to < from) uses.push_back({to, from, -sign});
  };
  const auto add = [&](PieceCorner from, PieceCorner to, int sign) {
    add_canonical(canonical(from), canonical(to), sign);
  };
  for (const SteinerTriangle& t : fill)
    for (int c = 0; c < 3; ++c) add_canonical(t[c], t[(c + 1) % 3], 1);
  for (const SteinerTriangle& t : triangles_)
    for (int c = 0; c < 3; ++c) add_canonical(t[c], t[(c + 1) % 3], -1);
  // Each split input edge: + (a -> s1 -> ... -> b) - (a -> b), Steiner points in edge order.
  std::vector<PieceCorner> steiner = all_steiner_points(lines);
  const auto& point = [&](PieceCorner c) -> const SteinerPoint& {
    return lines[corner_line(c)].steiner[corner_index(c)];
  };
  detail::sort(steiner.begin(), steiner.end(), [&](PieceCorner p, PieceCorner q) {
    const SteinerPoint &s = point(p), &t = point(q);
    if (s.from != t.from || s.to != t.to)
      return s.from < t.from || (s.from == t.from && s.to < t.to);
    return (s.pos.x < t.pos.x) == (b.pos[s.from].x < b.pos[s.to].x);
  });
  for (std::size_t i = 0; i < steiner.size(); ++i) {
    const SteinerPoint& s = point(steiner[i]);
    const bool first =
        i == 0 || point(steiner[i - 1]).from != s.from || point(steiner[i - 1]).to != s.to;
    const bool last = i + 1 == steiner.size() || point(steiner[i + 1]).from != s.from ||
                      point(steiner[i + 1]).to != s.to;
    add(first ? PieceCorner{s.from} : steiner[i - 1], steiner[i], 1);
    if (last) add(steiner[i], s.to, 1), add(s.from, s.to, -1);
  }
  detail::sort(uses.begin(), uses.end(), [](const Use& u, const Use& v) {
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

}  // namespace pear::detail
