// pear: the triangulation validator (include/pear/validate.hpp).
//
// Why these checks prove validity: with every triangle counterclockwise, the triangles' boundary
// chain equal to the polygon's boundary chain (each boundary edge used once on its inner side,
// every other edge zero times or once in each direction) makes the triangles a covering of the
// plane whose degree at a point is the winding number of the polygon's boundary there: 1 inside,
// 0 outside. The chains are compared as segments: a zero-width spike's two edges cancel (so
// spikes are dissolved first), and where a vertex lies inside a boundary edge the triangles'
// edges along its parts make up the same segment (repairs.hpp checks what does not balance edge
// by edge, line by line). The exact area equality then follows algebraically and is checked as
// an independent guard on the edge bookkeeping. Areas are summed exactly (exact_sum.hpp), so the
// area check has no tolerance: a valid triangulation has area_rel_error == 0 exactly.
//
// Triangle count: n + 2h - 2 counts angle sums (the boundary's turning), where n is the number of
// kept vertices and h the kept holes. Where k kept vertices share one point (a hole touching the
// outer ring or another hole at a vertex, a self-touching ring), the k boundary visits' angles
// overlap by 2*pi*(k - 1) around that point, so each such extra index removes two triangles:
// expected = n + 2h - 2 - 2m with m = n - (number of distinct kept points); a point inside a
// boundary edge is one more boundary visit there (n and m one more). This is exact as long as
// no ring visits a point twice: a ring's own visits need not have disjoint wedges. Triangles whose
// vertices include one point twice ("collapsed", only with allow_zero_area) carry no area and no
// boundary, so they are left out of the edge and count checks.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <numeric>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "decimal.hpp"
#include "exact_sum.hpp"
#include "geometry/sort.hpp"
#include "pear/predicates.hpp"
#include "pear/validate.hpp"
#include "repairs.hpp"

namespace pear {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

// One use of an undirected edge {lo, hi} (lo < hi, canonical ids): by a triangle or the boundary.
struct EdgeUse {
  std::uint32_t hi;
  std::uint32_t who;   // triangle index, or the raw index of the boundary edge's start vertex
  std::uint8_t flags;  // forward (lo -> hi), boundary, and a triangle's edge slot
};
constexpr std::uint8_t forward_flag = 1;
constexpr std::uint8_t boundary_flag = 2;
constexpr int slot_shift = 2;

// The uses of one undirected edge, summarized.
struct EdgeGroup {
  std::uint32_t lo = 0, hi = 0;
  int boundary_forward = 0, boundary_backward = 0;
  int forward = 0, backward = 0;
  std::uint32_t boundary_start = 0;  // raw index of a boundary use's start vertex
  EdgeUse forward_uses[2]{}, backward_uses[2]{};
};

class Validator {
 public:
  Validator(const PolygonView& polygon, std::span<const Triangle> triangles,
            const ValidateOptions& options)
      : polygon_(polygon), triangles_(triangles), options_(options) {}

  ValidationReport run() {
    report_.triangles = triangles_.size();
    if (!check_structure() || !check_coordinates() || !clean_rings()) return report_;
    canonicalize();
    check_triangles();
    check_edges();
    check_count();
    check_area();
    return report_;
  }

 private:
  // Marks the report invalid; builds the message only while there is room for it (a badly broken
  // triangulation of millions of triangles must not build millions of strings).
  template <class Describe>
  void fail(Describe&& describe) {
    report_.valid = false;
    if (report_.messages.size() < options_.max_messages) report_.messages.push_back(describe());
  }

  // "7 (ring 1, vertex 2)": an index and where the caller's numbering puts it.
  std::string vertex_name(std::uint32_t index) const {
    const auto& starts = polygon_.ring_offsets;
    const auto ring = static_cast<std::size_t>(
        std::upper_bound(starts.begin(), starts.end(), index) - starts.begin() - 1);
    return std::to_string(index) + " (ring " + std::to_string(ring) + ", vertex " +
           std::to_string(index - starts[ring]) + ")";
  }

  std::string triangle_name(std::size_t t) const {
    const Triangle& tri = triangles_[t];
    return "triangle " + std::to_string(t) + " (" + std::to_string(tri[0]) + ", " +
           std::to_string(tri[1]) + ", " + std::to_string(tri[2]) + ")";
  }

  bool check_structure();
  bool check_coordinates();
  bool clean_rings();
  void keep_ring(std::size_t ring, std::vector<std::uint32_t>& kept);
  void canonicalize();
  void check_triangles();
  void check_triangle(std::size_t t);
  void check_edges();
  void fill_edge_uses(std::vector<std::size_t>& offsets, std::vector<EdgeUse>& uses) const;
  void check_edge_group(const EdgeGroup& group);
  void balance_unbalanced();
  void note_self_touching_splits(const std::vector<detail::BoundarySplit>& splits);
  std::size_t ring_of(std::uint32_t index) const;
  void report_bad_edge(const EdgeGroup& group);
  void check_delaunay(const EdgeGroup& group);
  void check_count();
  void check_area();

  const PolygonView polygon_;
  std::span<const Triangle> triangles_;
  const ValidateOptions& options_;
  ValidationReport report_;

  std::vector<std::uint32_t> boundary_;  // kept vertices, interior on the left, ring after ring
  std::vector<std::uint32_t> boundary_starts_;  // kept ring k is [starts[k], starts[k+1])
  std::vector<std::uint32_t> boundary_rings_;   // the caller's ring of kept ring k
  std::size_t holes_ = 0;
  std::vector<std::uint32_t> canonical_;   // index -> smallest index with the same point
  std::vector<std::uint8_t> on_boundary_;  // by canonical id: a kept vertex sits there
  std::size_t distinct_boundary_points_ = 0;
  bool self_touching_ = false;                     // a kept ring passes a point twice
  std::vector<EdgeGroup> unbalanced_;              // edges whose uses do not balance one by one
  std::size_t splits_ = 0;                         // points inside boundary edges (T-junctions)
  std::vector<std::int8_t> orientation_;           // per triangle: +1, 0, -1; 2 = left out
  std::size_t collapsed_triangles_ = 0;            // zero area with a point used twice
  detail::ExactSum polygon_area_, triangle_area_;  // both twice the area
};

constexpr std::int8_t left_out = 2;

bool Validator::check_structure() {
  const auto& starts = polygon_.ring_offsets;
  const std::size_t count = polygon_.points.size();
  if (starts.size() < 2) {
    fail([] { return std::string("the polygon has no rings"); });
    return false;
  }
  if (count >= std::numeric_limits<std::uint32_t>::max()) {
    fail([&] {
      return "the polygon has " + std::to_string(count) +
             " points, more than 32-bit indices number";
    });
    return false;
  }
  if (triangles_.size() >= std::numeric_limits<std::uint32_t>::max()) {
    fail([&] { return std::to_string(triangles_.size()) + " triangles: too many to check"; });
    return false;
  }
  if (starts.front() != 0 || starts.back() != count ||
      !std::is_sorted(starts.begin(), starts.end())) {
    fail([] {
      return std::string("malformed polygon: ring_starts must rise from 0 to the point count");
    });
    return false;
  }
  return true;
}

bool Validator::check_coordinates() {
  bool ok = true;
  for (std::uint32_t i = 0; i < polygon_.points.size(); ++i) {
    for (double c : {polygon_.points[i].x, polygon_.points[i].y}) {
      const double magnitude = std::fabs(c);
      if (!std::isfinite(c)) {
        fail([&] { return "vertex " + vertex_name(i) + ": coordinate is NaN or infinite"; });
        ok = false;
      } else if (magnitude > max_coordinate || (c != 0 && magnitude < min_nonzero_coordinate)) {
        fail([&] { return "vertex " + vertex_name(i) + ": coordinate outside [2^-200, 2^200]"; });
        ok = false;
      }
    }
  }
  return ok;
}

// The cleaned ring's vertices: repeated consecutive points and closing points dropped (the kept
// vertex keeps the index of its first occurrence), then zero-width spikes dissolved.
void Validator::keep_ring(std::size_t ring, std::vector<std::uint32_t>& kept) {
  const auto& points = polygon_.points;
  kept.clear();
  for (std::uint32_t i = polygon_.ring_offsets[ring]; i < polygon_.ring_offsets[ring + 1]; ++i)
    if (kept.empty() || !(points[i] == points[kept.back()])) kept.push_back(i);
  while (kept.size() > 1 && points[kept.back()] == points[kept.front()]) kept.pop_back();
  if (kept.size() >= 3) detail::dissolve_tips(points, kept);
}

bool Validator::clean_rings() {
  const auto& points = polygon_.points;
  std::vector<std::uint32_t> kept;
  boundary_starts_.push_back(0);
  for (std::size_t ring = 0; ring + 1 < polygon_.ring_offsets.size(); ++ring) {
    keep_ring(ring, kept);
    detail::ExactSum area;  // shoelace: twice the signed area
    for (std::size_t k = 0; k < kept.size(); ++k) {
      const Point& a = points[kept[k]];
      const Point& b = points[kept[(k + 1) % kept.size()]];
      area.add_product(a.x, b.y);
      area.add_product(b.x, a.y, true);
    }
    const int sign = kept.size() < 3 ? 0 : area.sign();
    if (sign == 0) {
      if (ring == 0) {
        fail([] {
          return std::string("ring 0 (outer): fewer than 3 distinct points or zero area");
        });
        return false;
      }
      continue;  // dropped hole: not counted, its edges are not boundary
    }
    // Interior on the left: outer ring counterclockwise, holes clockwise.
    if ((ring == 0) != (sign > 0)) std::reverse(kept.begin(), kept.end());
    if ((ring == 0) == (sign > 0))
      polygon_area_.add(area);
    else
      polygon_area_.subtract(area);
    holes_ += ring == 0 ? 0 : 1;
    boundary_.insert(boundary_.end(), kept.begin(), kept.end());
    boundary_starts_.push_back(static_cast<std::uint32_t>(boundary_.size()));
    boundary_rings_.push_back(static_cast<std::uint32_t>(ring));
  }
  return true;
}

// A hash of a point's exact coordinates (-0.0 counted as 0.0, as == does), by the splitmix64
// finalizer: sorting 64-bit hashes is much faster than sorting indices by coordinates.
std::uint64_t point_hash(const Point& p) {
  auto mix = [](std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
  };
  const auto x = std::bit_cast<std::uint64_t>(p.x == 0 ? 0.0 : p.x);
  const auto y = std::bit_cast<std::uint64_t>(p.y == 0 ? 0.0 : p.y);
  return mix(mix(x) + y);
}

// Every index maps to the smallest index with the same coordinates.
void Validator::canonicalize() {
  const auto& points = polygon_.points;
  const auto count = static_cast<std::uint32_t>(points.size());
  std::vector<std::pair<std::uint64_t, std::uint32_t>> hashed(count);
  for (std::uint32_t i = 0; i < count; ++i) hashed[i] = {point_hash(points[i]), i};
  detail::sort(hashed.begin(), hashed.end());
  canonical_.resize(count);
  std::vector<std::uint32_t> run;
  for (std::uint32_t i = 0; i < count;) {
    std::uint32_t j = i + 1;
    while (j < count && hashed[j].first == hashed[i].first) ++j;
    if (j == i + 1) {  // the usual case: a point of its own
      canonical_[hashed[i].second] = hashed[i].second;
      i = j;
      continue;
    }
    // Equal hashes: group by exact coordinates (a collision may mix different points).
    run.clear();
    for (std::uint32_t k = i; k < j; ++k) run.push_back(hashed[k].second);
    detail::sort(run.begin(), run.end(), [&](std::uint32_t a, std::uint32_t b) {
      const Point& p = points[a];
      const Point& q = points[b];
      if (p.x != q.x) return p.x < q.x;
      if (p.y != q.y) return p.y < q.y;
      return a < b;
    });
    for (std::size_t k = 0; k < run.size();) {
      std::size_t l = k;
      while (l < run.size() && points[run[l]] == points[run[k]]) canonical_[run[l++]] = run[k];
      k = l;
    }
    i = j;
  }
  on_boundary_.assign(count, 0);
  for (std::uint32_t v : boundary_) {
    if (on_boundary_[canonical_[v]]) continue;
    on_boundary_[canonical_[v]] = 1;
    ++distinct_boundary_points_;
  }
  std::vector<std::uint32_t> last_ring(count, UINT32_MAX);  // by canonical id
  for (std::size_t k = 0; k + 1 < boundary_starts_.size(); ++k) {
    for (std::uint32_t i = boundary_starts_[k]; i < boundary_starts_[k + 1]; ++i) {
      std::uint32_t& seen = last_ring[canonical_[boundary_[i]]];
      self_touching_ = self_touching_ || seen == k;
      seen = static_cast<std::uint32_t>(k);
    }
  }
}

void Validator::check_triangles() {
  orientation_.assign(triangles_.size(), left_out);
  for (std::size_t t = 0; t < triangles_.size(); ++t) check_triangle(t);
}

void Validator::check_triangle(std::size_t t) {
  const Triangle& tri = triangles_[t];
  const std::size_t count = polygon_.points.size();
  for (std::uint32_t v : tri) {
    if (v < count) continue;
    fail([&] {
      return triangle_name(t) + ": index " + std::to_string(v) +
             " is out of range (the polygon has " + std::to_string(count) + " points)";
    });
    return;
  }
  for (std::uint32_t v : tri) {
    if (!options_.check_count || on_boundary_[canonical_[v]]) continue;
    fail([&] {
      return triangle_name(t) + ": vertex " + vertex_name(v) +
             " is not a vertex of the cleaned polygon (a Steiner point needs check_count=false)";
    });
  }
  const Point& a = polygon_.points[tri[0]];
  const Point& b = polygon_.points[tri[1]];
  const Point& c = polygon_.points[tri[2]];
  const double orientation = orient2d(a, b, c);
  if (orientation == 0) {
    ++report_.zero_area_triangles;
    if (!options_.allow_zero_area)
      fail([&] { return triangle_name(t) + " has zero area (its vertices are collinear)"; });
    const bool collapsed = canonical_[tri[0]] == canonical_[tri[1]] ||
                           canonical_[tri[1]] == canonical_[tri[2]] ||
                           canonical_[tri[2]] == canonical_[tri[0]];
    if (collapsed)
      ++collapsed_triangles_;
    else
      orientation_[t] = 0;
    return;
  }
  const bool clockwise = orientation < 0;
  if (clockwise) {
    ++report_.bad_orientation;
    fail([&] { return triangle_name(t) + " is clockwise"; });
  }
  orientation_[t] = clockwise ? -1 : 1;
  // |twice the area| by the shoelace formula, exactly.
  triangle_area_.add_product(a.x, b.y, clockwise);
  triangle_area_.add_product(b.x, a.y, !clockwise);
  triangle_area_.add_product(b.x, c.y, clockwise);
  triangle_area_.add_product(c.x, b.y, !clockwise);
  triangle_area_.add_product(c.x, a.y, clockwise);
  triangle_area_.add_product(a.x, c.y, !clockwise);
}

// Calls emit(from, to, who, flags) for every directed boundary edge and every edge of a triangle
// that takes part in the edge check, in canonical ids.
template <class Emit>
void for_each_edge(const std::vector<std::uint32_t>& boundary,
                   const std::vector<std::uint32_t>& boundary_starts,
                   const std::vector<std::uint32_t>& canonical, std::span<const Triangle> triangles,
                   const std::vector<std::int8_t>& orientation, Emit&& emit) {
  for (std::size_t ring = 0; ring + 1 < boundary_starts.size(); ++ring) {
    const std::uint32_t begin = boundary_starts[ring], end = boundary_starts[ring + 1];
    for (std::uint32_t k = begin; k < end; ++k) {
      const std::uint32_t next = k + 1 == end ? begin : k + 1;
      emit(canonical[boundary[k]], canonical[boundary[next]], boundary[k], boundary_flag);
    }
  }
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    if (orientation[t] == left_out) continue;
    for (int k = 0; k < 3; ++k)
      emit(canonical[triangles[t][k]], canonical[triangles[t][(k + 1) % 3]],
           static_cast<std::uint32_t>(t), static_cast<std::uint8_t>(k << slot_shift));
  }
}

// Buckets every edge use by its smaller canonical endpoint (a counting sort: linear time).
void Validator::fill_edge_uses(std::vector<std::size_t>& offsets,
                               std::vector<EdgeUse>& uses) const {
  offsets.assign(polygon_.points.size() + 1, 0);
  for_each_edge(boundary_, boundary_starts_, canonical_, triangles_, orientation_,
                [&](std::uint32_t from, std::uint32_t to, std::uint32_t, std::uint8_t) {
                  ++offsets[std::min(from, to) + 1];
                });
  std::partial_sum(offsets.begin(), offsets.end(), offsets.begin());
  uses.resize(offsets.back());
  std::vector<std::size_t> cursor(offsets.begin(), offsets.end() - 1);
  for_each_edge(boundary_, boundary_starts_, canonical_, triangles_, orientation_,
                [&](std::uint32_t from, std::uint32_t to, std::uint32_t who, std::uint8_t flags) {
                  const bool forward = from < to;
                  const auto flag = static_cast<std::uint8_t>(flags | (forward ? forward_flag : 0));
                  uses[cursor[std::min(from, to)]++] = EdgeUse{std::max(from, to), who, flag};
                });
}

void Validator::check_edges() {
  std::vector<std::size_t> offsets;
  std::vector<EdgeUse> uses;
  fill_edge_uses(offsets, uses);
  for (std::size_t lo = 0; lo + 1 < offsets.size(); ++lo) {
    const auto begin = uses.begin() + static_cast<std::ptrdiff_t>(offsets[lo]);
    const auto end = uses.begin() + static_cast<std::ptrdiff_t>(offsets[lo + 1]);
    // Ties by `who` make the messages deterministic.
    detail::sort(begin, end, [](const EdgeUse& a, const EdgeUse& b) {
      return a.hi != b.hi ? a.hi < b.hi : a.who < b.who;
    });
    for (auto use = begin; use != end;) {
      EdgeGroup group;
      group.lo = static_cast<std::uint32_t>(lo);
      group.hi = use->hi;
      for (; use != end && use->hi == group.hi; ++use) {
        const bool forward = use->flags & forward_flag;
        if (use->flags & boundary_flag) {
          ++(forward ? group.boundary_forward : group.boundary_backward);
          group.boundary_start = use->who;
        } else if (forward) {
          if (group.forward < 2) group.forward_uses[group.forward] = *use;
          ++group.forward;
        } else {
          if (group.backward < 2) group.backward_uses[group.backward] = *use;
          ++group.backward;
        }
      }
      check_edge_group(group);
    }
  }
  if (!unbalanced_.empty()) balance_unbalanced();
}

std::size_t Validator::ring_of(std::uint32_t index) const {
  const auto& starts = polygon_.ring_offsets;
  return static_cast<std::size_t>(std::upper_bound(starts.begin(), starts.end(), index) -
                                  starts.begin() - 1);
}

// Edges whose uses do not balance one by one may still balance as segments: a boundary edge
// with a vertex inside it (a T-junction) is matched by the triangles' edges along its parts
// (residue.hpp). Whatever does not cancel is reported, in the order the edges were met.
void Validator::balance_unbalanced() {
  std::vector<detail::Residue> residues;
  for (const EdgeGroup& g : unbalanced_)
    residues.push_back(
        {g.lo, g.hi, g.forward - g.backward, g.boundary_forward - g.boundary_backward});
  const detail::ResidueBalance balance = detail::balance_residue(polygon_.points, residues);
  for (std::size_t r = 0; r < unbalanced_.size(); ++r) {
    if (balance.cancelled[r]) continue;
    ++report_.bad_edges;
    report_bad_edge(unbalanced_[r]);
  }
  splits_ = balance.splits.size();
  note_self_touching_splits(balance.splits);
}

// A split point makes its ring pass that point twice when the ring has a vertex there, or
// another split there.
void Validator::note_self_touching_splits(const std::vector<detail::BoundarySplit>& splits) {
  if (splits.empty() || self_touching_) return;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> at;  // (caller's ring, canonical point)
  std::vector<std::uint8_t> split_point(canonical_.size(), 0);
  for (const detail::BoundarySplit& s : splits) {
    at.emplace_back(ring_of(unbalanced_[s.residue].boundary_start), s.point);
    split_point[s.point] = 1;
  }
  detail::sort(at.begin(), at.end());
  self_touching_ = std::adjacent_find(at.begin(), at.end()) != at.end();
  for (std::size_t k = 0; !self_touching_ && k + 1 < boundary_starts_.size(); ++k)
    for (std::uint32_t i = boundary_starts_[k]; i < boundary_starts_[k + 1]; ++i)
      if (const std::uint32_t c = canonical_[boundary_[i]];
          split_point[c] &&
          std::binary_search(at.begin(), at.end(), std::pair(boundary_rings_[k], c)))
        self_touching_ = true;
}

// The triangles' boundary chain must equal the polygon's on this edge, each direction used at
// most once (more would be an overlap).
void Validator::check_edge_group(const EdgeGroup& group) {
  const int need = group.boundary_forward - group.boundary_backward;
  if (group.forward > 1 || group.backward > 1) {
    ++report_.bad_edges;
    report_bad_edge(group);
    return;
  }
  if (group.forward - group.backward != need) {
    unbalanced_.push_back(group);
    return;
  }
  const bool interior = group.boundary_forward + group.boundary_backward == 0;
  if (options_.check_delaunay && interior && group.forward == 1) check_delaunay(group);
}

std::uint32_t third_vertex(std::span<const Triangle> triangles, const EdgeUse& use) {
  return triangles[use.who][((use.flags >> slot_shift) + 2) % 3];
}

void Validator::report_bad_edge(const EdgeGroup& group) {
  const int need = group.boundary_forward - group.boundary_backward;
  const std::string edge = vertex_name(group.lo) + " - " + vertex_name(group.hi);
  if (group.forward > 1 || group.backward > 1) {
    const EdgeUse* same = group.forward > 1 ? group.forward_uses : group.backward_uses;
    auto vertices = [&](std::uint32_t t) {
      std::array<std::uint32_t, 3> ids;
      for (int k = 0; k < 3; ++k) ids[k] = canonical_[triangles_[t][k]];
      detail::sort(ids.begin(), ids.end());
      return ids;
    };
    if (vertices(same[0].who) == vertices(same[1].who))
      return fail(
          [&] { return triangle_name(same[1].who) + " repeats " + triangle_name(same[0].who); });
    return fail([&] {
      return "edge " + edge + " is used in the same direction by " + triangle_name(same[0].who) +
             " and " + triangle_name(same[1].who) + ": they overlap";
    });
  }
  if (need == 1 || need == -1) {
    const std::string where = "boundary edge from vertex " + vertex_name(group.boundary_start) +
                              " to vertex " + vertex_name(need > 0 ? group.hi : group.lo);
    const int wrong = need > 0 ? group.backward : group.forward;
    const EdgeUse& wrong_use = need > 0 ? group.backward_uses[0] : group.forward_uses[0];
    if (wrong > 0)
      return fail([&] {
        return where + " is used in the wrong direction by " + triangle_name(wrong_use.who) +
               ": the triangle lies outside the polygon";
      });
    return fail([&] { return where + " is not used by any triangle"; });
  }
  if (need != 0)
    return fail([&] {
      return "edge " + edge + " occurs " + std::to_string(std::abs(need)) +
             " times in the same direction in the rings (not a simple polygon)";
    });
  const EdgeUse& use = group.forward > 0 ? group.forward_uses[0] : group.backward_uses[0];
  fail([&] {
    return "edge " + edge + " of " + triangle_name(use.who) +
           " has no triangle across it: the triangulation leaves a gap or overlaps there";
  });
}

// Locally Delaunay: the vertex across the edge is not strictly inside the circumcircle.
void Validator::check_delaunay(const EdgeGroup& group) {
  const EdgeUse& first = group.forward_uses[0];
  const EdgeUse& second = group.backward_uses[0];
  if (orientation_[first.who] != 1 || orientation_[second.who] != 1) return;
  const auto& points = polygon_.points;
  const std::uint32_t across = third_vertex(triangles_, second);
  if (incircle(points[group.lo], points[group.hi], points[third_vertex(triangles_, first)],
               points[across]) <= 0)
    return;
  ++report_.non_delaunay_edges;
  fail([&] {
    return "edge " + vertex_name(group.lo) + " - " + vertex_name(group.hi) + " between " +
           triangle_name(first.who) + " and " + triangle_name(second.who) +
           " is not locally Delaunay: vertex " + vertex_name(across) +
           " lies inside the first triangle's circumcircle";
  });
}

void Validator::check_count() {
  // A point inside a boundary edge splits it: one more boundary vertex, at a repeated point.
  const auto n = static_cast<std::int64_t>(boundary_.size() + splits_);
  const auto h = static_cast<std::int64_t>(holes_);
  const auto m = n - static_cast<std::int64_t>(distinct_boundary_points_);
  const std::int64_t expected = std::max<std::int64_t>(0, n + 2 * h - 2 - 2 * m);
  report_.expected_triangles = static_cast<std::size_t>(expected);
  const std::size_t counted = triangles_.size() - collapsed_triangles_;
  // The formula counts angles: where rings meet at a point, their angles there overlap by a
  // full turn per extra visit (two triangles), which holds whenever no ring passes a point
  // twice. A ring touching itself (lobes touching lobes, as in earcut's shared-points) can
  // differ; there the edge, orientation and area checks alone prove the covering, so the count
  // only informs.
  if (!options_.check_count || counted == report_.expected_triangles || self_touching_) return;
  fail([&] {
    return "wrong triangle count: " + std::to_string(counted) + " (not counting " +
           std::to_string(collapsed_triangles_) +
           " collapsed), expected n + 2h - 2 - 2m = " + std::to_string(expected) +
           " with n = " + std::to_string(n) + " kept vertices (" + std::to_string(splits_) +
           " of them splitting an edge), h = " + std::to_string(h) +
           " holes, m = " + std::to_string(m) + " repeated points";
  });
}

void Validator::check_area() {
  report_.polygon_area = polygon_area_.to_double() * 0.5;
  report_.triangle_area = triangle_area_.to_double() * 0.5;
  detail::ExactSum difference = triangle_area_;
  difference.subtract(polygon_area_);
  const double error = std::fabs(difference.to_double() * 0.5);
  const int sign = difference.sign();
  const double polygon_area = std::fabs(report_.polygon_area);
  report_.area_rel_error = polygon_area > 0 ? error / polygon_area
                           : sign == 0      ? 0
                                            : std::numeric_limits<double>::infinity();
  if (difference.out_of_range())
    return fail([] { return std::string("area sums left the exact accumulator's range"); });
  if (sign == 0) return;
  fail([&] {
    return "total triangle area " + detail::format_g17(report_.triangle_area) +
           " differs from the polygon area " + detail::format_g17(report_.polygon_area) +
           " (relative error " + detail::format_g17(report_.area_rel_error) + ")";
  });
}

}  // namespace

ValidationReport validate(const PolygonView& polygon,
                          std::span<const std::array<std::uint32_t, 3>> triangles,
                          const ValidateOptions& options) {
  return Validator(polygon, triangles, options).run();
}

}  // namespace pear
