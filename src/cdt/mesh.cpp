#include "mesh.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <utility>

#include "geometry/sort.hpp"
#include "pear/predicates.hpp"

namespace pear::detail {
namespace {

/// The edges to match, as (low, high) caller indices: every half-edge e < half_edges (3t + k),
/// then every ring edge (half_edges + its first clean vertex). In the mesh's build arrays, which
/// the tasks fill (filled on one thread they were 25 ms of Eurasia's 6M edges).
struct EdgeKeys {
  std::uint32_t *low = nullptr, *high = nullptr;
  std::size_t half_edges = 0;
};

/// Edges are cut into `parts` chunks (each a range of triangles and one of ring vertices) and
/// put into `parts` buckets by their low vertex (VertexBuckets), so that equal edges meet in one
/// bucket and the buckets are matched in parallel.
struct EdgeBuckets {
  VertexBuckets vertices;
  std::size_t parts = 1;
  std::vector<std::size_t> counts;    ///< [chunk * parts + bucket]: then where the chunk writes
  std::vector<std::size_t> begin;     ///< bucket b is edges[begin[b], begin[b + 1])
  std::uint32_t* edges = nullptr;     ///< bucket after bucket (as EdgeKeys, in the build arrays)
  std::vector<std::uint8_t> bad_end;  ///< per chunk: an edge ends past the points
};

/// Chunk c of [0, count) cut into `parts`.
std::pair<std::size_t, std::size_t> chunk_of(std::size_t count, std::size_t parts, std::size_t c) {
  return {c * count / parts, (c + 1) * count / parts};
}

/// Calls visit(e) for every edge of chunk c: its triangles' half-edges, then its ring edges.
template <class Visit>
void for_chunk_edges(const EdgeKeys& keys, std::size_t ring_edges, std::size_t parts, std::size_t c,
                     Visit&& visit) {
  const auto [t0, t1] = chunk_of(keys.half_edges / 3, parts, c);
  for (std::size_t e = 3 * t0; e < 3 * t1; ++e) visit(e);
  const auto [v0, v1] = chunk_of(ring_edges, parts, c);
  for (std::size_t v = v0; v < v1; ++v) visit(keys.half_edges + v);
}

/// Writes chunk c's keys and counts its edges per bucket.
void collect_chunk(const CleanPolygon& polygon, const TriangleList& triangles, std::size_t vertices,
                   EdgeKeys& keys, EdgeBuckets& buckets, std::size_t c) {
  // Four rows of counters, one per edge of a triangle and one for the ring edges: consecutive
  // edges mostly fall in one bucket, and one counter would make each increment wait for the last.
  std::array<std::array<std::uint32_t, max_mesh_parts>, 4> counts{};
  std::uint32_t highest = 0;
  const auto put = [&](std::size_t e, std::uint32_t u, std::uint32_t v, std::size_t row) {
    const std::uint32_t low = std::min(u, v), high = std::max(u, v);
    keys.low[e] = low;
    keys.high[e] = high;
    highest = std::max(highest, high);
    if (buckets.parts > 1) ++counts[row][buckets.vertices.bucket(low)];
  };
  const auto [t0, t1] = chunk_of(triangles.size(), buckets.parts, c);
  for (std::size_t t = t0; t < t1; ++t)
    for (std::size_t k = 0; k < 3; ++k)
      put(3 * t + k, triangles[t][k], triangles[t][(k + 1) % 3], k);
  const auto [v0, v1] = chunk_of(polygon.points.size(), buckets.parts, c);
  // The ring of v0, then walked along: ring r is [ring_starts[r], ring_starts[r + 1]).
  std::size_t r = static_cast<std::size_t>(
      std::upper_bound(polygon.ring_starts.begin(), polygon.ring_starts.end(), v0) -
      polygon.ring_starts.begin() - 1);
  for (std::size_t v = v0; v < v1; ++v) {
    while (v >= polygon.ring_starts[r + 1]) ++r;
    const std::uint32_t next = v + 1 < polygon.ring_starts[r + 1] ? v + 1 : polygon.ring_starts[r];
    put(keys.half_edges + v, polygon.original[v], polygon.original[next], 3);
  }
  // An end past the points makes the buckets meaningless: build_mesh stops before using them.
  if (t0 < t1 || v0 < v1) buckets.bad_end[c] = highest >= vertices;
  std::size_t* count = &buckets.counts[c * buckets.parts];
  for (std::size_t b = 0; b < buckets.parts; ++b)
    count[b] = counts[0][b] + counts[1][b] + counts[2][b] + counts[3][b];
}

/// Where each chunk writes in each bucket: buckets one after another, chunks in order inside.
void place_chunks(EdgeBuckets& buckets, FillVector<std::uint32_t>& edges) {
  const std::size_t parts = buckets.parts;
  buckets.begin.assign(parts + 1, 0);
  std::size_t at = 0;
  for (std::size_t b = 0; b < parts; ++b) {
    buckets.begin[b] = at;
    for (std::size_t c = 0; c < parts; ++c) at += std::exchange(buckets.counts[c * parts + b], at);
  }
  buckets.begin[parts] = at;
  buckets.edges = regrow_unfilled(edges, at);
}

/// Makes h and g twins, counted in `pairs` (a bucket's own count: buckets run in parallel).
bool pair(Mesh& mesh, std::uint32_t h, std::uint32_t g, std::size_t& pairs) {
  // The same direction: the two triangles overlap.
  if (mesh.points[mesh.origin(h)] == mesh.points[mesh.origin(g)]) return false;
  mesh.twin[h] = g;
  mesh.twin[g] = h;
  ++pairs;
  return true;
}

/// What matching found: its twins are written into the mesh.
struct BucketMatch {
  std::size_t pairs = 0;
  std::vector<std::uint32_t> loose;  ///< matched to nothing by index: see pair_by_position
  bool triangulation = true;         ///< false: an edge with more than two triangles
};

/// One bucket (or, in one part, every edge): its edges counted by low over the bucket's
/// vertex slots (slot(low) < width), each low's few edges sorted by high by insertion (a fan's
/// by sort_by_high), as high << 32 | edge (integers compared, no key looked up), then equal
/// edges paired from those values alone. A ring edge makes its triangle's edge a constraint.
/// Every twin depends on neither the chunks nor the parts. The bucket's edges are
/// list[0, count), or 0 to count - 1 where list is null (one part): one function for both, as a
/// second copy cost the WebAssembly module its size budget.
BucketMatch match_bucket(Mesh& mesh, const EdgeKeys& keys, const std::uint32_t* list,
                         std::size_t count, const VertexBuckets& slots, std::size_t width) {
  std::vector<std::uint32_t> start(width + 1, 0);
  std::vector<std::uint64_t> sorted(count), scratch;
  // The test out of the loops; with one part a vertex's slot is the vertex.
  const auto for_each_edge = [&](auto visit) {
    if (list != nullptr) {
      for (std::size_t i = 0; i < count; ++i) visit(list[i], slots.slot(keys.low[list[i]]));
    } else {
      for (std::uint32_t e = 0; e < count; ++e) visit(e, keys.low[e]);
    }
  };
  for_each_edge([&](std::uint32_t, std::uint32_t slot) { ++start[slot + 1]; });
  for (std::size_t v = 0; v < width; ++v) start[v + 1] += start[v];
  for_each_edge([&](std::uint32_t e, std::uint32_t slot) {
    sorted[start[slot]++] = std::uint64_t{keys.high[e]} << 32 | e;
  });
  BucketMatch m;
  for (std::size_t v = 0, from = 0; v < width; from = start[v++]) {
    const auto first = sorted.begin() + static_cast<std::ptrdiff_t>(from);
    const auto last = sorted.begin() + start[v];
    if (last - first > 1024) {
      sort_by_high(&*first, &*last, scratch);  // a fan (the comb's base: 100,000 edges)
    } else if (last - first > 16) {
      detail::sort(first, last);
    } else {
      for (auto it = first; it != last; ++it)
        for (auto at = it; at != first && *(at - 1) > *at; --at) std::iter_swap(at - 1, at);
    }
    for (auto i = first; i != last;) {
      auto j = i;
      std::size_t rings = 0;
      for (; j != last && (*j >> 32) == (*i >> 32); ++j)
        rings += static_cast<std::uint32_t>(*j) >= keys.half_edges ? 1 : 0;
      const auto uses = static_cast<std::size_t>(j - i) - rings;
      const auto edge = static_cast<std::uint32_t>(*i);
      if (uses > 2 || (uses == 2 && rings == 0 &&
                       !pair(mesh, edge, static_cast<std::uint32_t>(*(i + 1)), m.pairs))) {
        m.triangulation = false;
        return m;
      }
      if (uses + rings == 1) m.loose.push_back(edge);
      i = j;
    }
  }
  return m;
}

/// Where rings touch, two caller indices share a point, and the triangles on the two sides of a
/// diagonal there, or a ring edge and its triangle, may use different ones. The edges the index
/// matching left alone are few: they are matched again by their endpoints' positions with a
/// plain sort. A ring edge among them keeps its triangle's edge a constraint.
bool pair_by_position(Mesh& mesh, const EdgeKeys& keys, std::vector<std::uint32_t>& loose) {
  const auto ends = [&](std::uint32_t e) {
    return EdgeEnds(mesh.points[keys.low[e]], mesh.points[keys.high[e]]);
  };
  detail::sort(loose.begin(), loose.end(), [&](std::uint32_t h, std::uint32_t g) {
    const EdgeEnds e = ends(h), f = ends(g);
    return e != f ? e < f : h < g;
  });
  for (std::size_t i = 0, j = 0; i < loose.size(); i = j) {
    std::size_t rings = 0;
    for (j = i; j < loose.size() && ends(loose[j]) == ends(loose[i]); ++j)
      rings += loose[j] >= keys.half_edges ? 1 : 0;
    if (j - i - rings > 2) return false;
    if (j - i == 2 && rings == 0 && !pair(mesh, loose[i], loose[i + 1], mesh.interior_edges))
      return false;
  }
  return true;
}

}  // namespace

VertexBuckets::VertexBuckets(std::size_t vertices, std::size_t parts) : parts_(parts) {
  while ((std::size_t{1} << parts_shift_) < parts) ++parts_shift_;
  block_shift_ = 6;
  while ((vertices >> block_shift_) > 4 * parts) ++block_shift_;
  width_ = ((vertices >> (block_shift_ + parts_shift_)) + 1) << block_shift_;
}

std::size_t mesh_parts(std::size_t edges, std::uint32_t partitions) {
  const std::size_t most = std::clamp<std::size_t>(partitions, 1, max_mesh_parts);
  return std::min(std::bit_ceil(most),
                  std::bit_floor(std::max<std::size_t>(edges / mesh_edges_per_task, 1)));
}

void sort_by_high(std::uint64_t* first, std::uint64_t* last, std::vector<std::uint64_t>& scratch) {
  constexpr unsigned digit_bits = 11;
  const auto n = static_cast<std::size_t>(last - first);
  std::uint64_t highest = 0;
  for (const std::uint64_t* it = first; it != last; ++it) highest = std::max(highest, *it);
  scratch.resize(n);
  std::uint64_t* from = first;
  std::uint64_t* to = scratch.data();
  for (unsigned shift = 32; shift < 64 && (highest >> shift) != 0; shift += digit_bits) {
    std::array<std::uint32_t, std::size_t{1} << digit_bits> place{};
    const auto digit = [&](std::uint64_t x) { return (x >> shift) & ((1u << digit_bits) - 1); };
    for (std::size_t i = 0; i < n; ++i) ++place[digit(from[i])];
    std::uint32_t at = 0;
    for (std::uint32_t& p : place) at += std::exchange(p, at);
    for (std::size_t i = 0; i < n; ++i) to[place[digit(from[i])]++] = from[i];
    std::swap(from, to);
  }
  if (from != first) std::copy(from, from + n, first);
}

EdgeEnds::EdgeEnds(const Point& p, const Point& q) : low(p), high(q) {
  if (lexicographic_less(q, p)) std::swap(low, high);
}

bool build_mesh(std::span<const Point> points, const CleanPolygon& polygon, TriangleList& triangles,
                Mesh& mesh, const RunContext& ctx) {
  const std::size_t edges = 3 * triangles.size() + polygon.points.size();
  EdgeKeys keys;
  EdgeBuckets buckets;
  buckets.parts = mesh_parts(edges, ctx.partitions);
  buckets.vertices = VertexBuckets(points.size(), buckets.parts);
  ctx.run_serial("cdt adjacency: allocate", [&] {
    mesh.points = points;
    mesh.triangles = &triangles;
    mesh.interior_edges = 0;
    regrow_unfilled(mesh.twin, 3 * triangles.size());  // no_twin written by the tasks below
    keys.half_edges = 3 * triangles.size();
    keys.low = regrow_unfilled(mesh.build.low, edges);
    keys.high = regrow_unfilled(mesh.build.high, edges);
    buckets.counts.assign(buckets.parts * buckets.parts, 0);
    buckets.bad_end.assign(buckets.parts, 0);
  });
  ctx.run_tasks("cdt adjacency: edges", buckets.parts, [&](std::size_t c) {
    const std::size_t halves = mesh.twin.size();
    std::fill(mesh.twin.begin() + static_cast<std::ptrdiff_t>(halves * c / buckets.parts),
              mesh.twin.begin() + static_cast<std::ptrdiff_t>(halves * (c + 1) / buckets.parts),
              no_twin);
    collect_chunk(polygon, triangles, points.size(), keys, buckets, c);
  });
  if (std::find(buckets.bad_end.begin(), buckets.bad_end.end(), 1) != buckets.bad_end.end())
    return false;
  std::vector<BucketMatch> matches(buckets.parts);
  if (buckets.parts == 1) {
    ctx.run_serial("cdt adjacency: match", [&] {
      // One part: slot(v) is v.
      matches[0] = match_bucket(mesh, keys, nullptr, edges, buckets.vertices, points.size());
    });
  } else {
    ctx.run_serial("cdt adjacency: place", [&] { place_chunks(buckets, mesh.build.edges); });
    ctx.run_tasks("cdt adjacency: scatter", buckets.parts, [&](std::size_t c) {
      std::size_t* at = &buckets.counts[c * buckets.parts];
      for_chunk_edges(keys, polygon.points.size(), buckets.parts, c, [&](std::size_t e) {
        buckets.edges[at[buckets.vertices.bucket(keys.low[e])]++] = static_cast<std::uint32_t>(e);
      });
    });
    ctx.run_tasks("cdt adjacency: match", buckets.parts, [&](std::size_t b) {
      matches[b] = match_bucket(mesh, keys, buckets.edges + buckets.begin[b],
                                buckets.begin[b + 1] - buckets.begin[b], buckets.vertices,
                                buckets.vertices.width());
    });
  }
  bool built = true;
  ctx.run_serial("cdt adjacency: by position", [&] {
    std::vector<std::uint32_t> loose;
    for (const BucketMatch& m : matches) {
      built = built && m.triangulation;
      mesh.interior_edges += m.pairs;
      loose.insert(loose.end(), m.loose.begin(), m.loose.end());
    }
    built = built && pair_by_position(mesh, keys, loose);
  });
  return built;
}

bool must_flip(const Mesh& mesh, std::uint32_t h) {
  const std::uint32_t g = mesh.twin[h];
  const Point& a = mesh.points[mesh.corner(h, 0)];
  const Point& b = mesh.points[mesh.corner(h, 1)];
  const Point& c = mesh.points[mesh.corner(h, 2)];
  const Point& d = mesh.points[mesh.corner(g, 2)];
  // The new triangles (a, d, c) and (d, b, c) must both be counterclockwise.
  const auto flippable = [&] { return orient2d(a, d, c) > 0 && orient2d(d, b, c) > 0; };
  const double first = orient2d(a, b, c), second = orient2d(b, a, d);
  if (first < 0 || second < 0) return false;  // not a triangulation: leave it
  if (first == 0 || second == 0) return flippable();
  return incircle(a, b, c, d) > 0 && flippable();
}

void flip(Mesh& mesh, std::uint32_t h, FlipScope scope) {
  const std::uint32_t g = mesh.twin[h];
  auto& triangles = *mesh.triangles;
  const std::uint32_t t = h / 3, u = g / 3, i = h % 3, j = g % 3;
  const std::uint32_t a = triangles[t][i], b = triangles[t][(i + 1) % 3];
  const std::uint32_t c = triangles[t][(i + 2) % 3], d = triangles[u][(j + 2) % 3];
  const std::uint32_t h1 = 3 * t + (i + 1) % 3, h2 = 3 * t + (i + 2) % 3;
  const std::uint32_t g1 = 3 * u + (j + 1) % 3, g2 = 3 * u + (j + 2) % 3;
  const std::uint32_t bc = mesh.twin[h1], ca = mesh.twin[h2];
  const std::uint32_t ad = mesh.twin[g1], db = mesh.twin[g2];
  // t becomes (d, c, a) and u becomes (c, d, b), each starting at slot i resp. j: slot i and
  // slot j hold the new diagonal, the outer edges move one slot on or over to the other side.
  triangles[t][i] = d;
  triangles[t][(i + 1) % 3] = c;
  triangles[t][(i + 2) % 3] = a;
  triangles[u][j] = c;
  triangles[u][(j + 1) % 3] = d;
  triangles[u][(j + 2) % 3] = b;
  const auto link = [&](std::uint32_t slot, std::uint32_t outer) {
    mesh.twin[slot] = outer;
    if (outer != no_twin && scope.contains(outer)) mesh.twin[outer] = slot;
  };
  link(h1, ca);
  link(h2, ad);
  link(g1, db);
  link(g2, bc);
}

std::size_t flip_until_delaunay(Mesh& mesh, std::vector<std::uint32_t>& stack,
                                std::span<std::uint8_t> queued, FlipScope scope,
                                std::size_t budget) {
  std::size_t flips = 0;
  const auto push = [&](std::uint32_t h) {
    const std::uint32_t g = mesh.twin[h];
    if (g == no_twin || !scope.contains(g) || queued[h] || queued[g]) return;
    queued[h] = 1;
    stack.push_back(h);
  };
  while (!stack.empty()) {
    const std::uint32_t h = stack.back();
    stack.pop_back();
    queued[h] = 0;
    const std::uint32_t g = mesh.twin[h];
    if (g == no_twin || !scope.contains(g) || flips == budget || !must_flip(mesh, h)) continue;
    flip(mesh, h, scope);
    ++flips;
    push(next_half_edge(h));
    push(next_half_edge(next_half_edge(h)));
    push(next_half_edge(g));
    push(next_half_edge(next_half_edge(g)));
  }
  return flips;
}

}  // namespace pear::detail
