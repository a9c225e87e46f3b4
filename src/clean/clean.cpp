#include "clean.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <numeric>
#include <span>

#include "geometry/segments.hpp"
#include "geometry/sort.hpp"
#include "pear/config.hpp"
#include "pear/predicates.hpp"
#include "predicates/expansion.hpp"
#include "predicates/long_accumulator.hpp"

namespace pear::detail {
namespace {

bool coordinate_in_range(double c) {
  // Doubles without their sign order as their bits: one unsigned compare for the range (a bit
  // pattern below the lowest wraps round to above it); NaN and the infinities lie above.
  constexpr auto low = std::bit_cast<std::uint64_t>(min_nonzero_coordinate);
  constexpr auto high = std::bit_cast<std::uint64_t>(max_coordinate);
  const std::uint64_t m = std::bit_cast<std::uint64_t>(c) & ~(std::uint64_t{1} << 63);
  return (m == 0) | (m - low <= high - low);
}

/// Names the first coordinate, from ring `from` on, that is not finite or out of range;
/// returns whether there is one.
bool name_coordinate_error(const InputPolygon& in, std::size_t from,
                           std::vector<Diagnostic>& diagnostics) {
  for (std::size_t r = from; r + 1 < in.ring_offsets.size(); ++r) {
    const InputPolygon::Ring ring = in.ring(r);
    for (std::uint32_t i = in.ring_offsets[r]; i < in.ring_offsets[r + 1]; ++i) {
      const std::size_t vertex = i - in.ring_offsets[r];
      const Point p = ring[vertex];
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
        diagnostics.push_back({Issue::non_finite_coordinate, r, vertex});
        return true;
      }
      if (!coordinate_in_range(p.x) || !coordinate_in_range(p.y)) {
        diagnostics.push_back({Issue::coordinate_out_of_range, r, vertex});
        return true;
      }
    }
  }
  return false;
}

/// Whether p is below q, or level with it and to its left.
bool lower_left(const Point& p, const Point& q) {
  return p.y < q.y || (p.y == q.y && p.x < q.x);
}

/// The lowest point, leftmost among equals: a convex corner of any simple ring.
std::size_t lowest_leftmost(const Point* p, std::size_t n) {
  std::size_t lowest = 0;
  for (std::size_t i = 1; i < n; ++i)
    if (lower_left(p[i], p[lowest])) lowest = i;
  return lowest;
}

/// +1 counterclockwise, -1 clockwise, 0 when every point is collinear (zero area).
/// Decided exactly at the lowest-leftmost vertex, which is convex for a simple ring;
/// for non-simple rings whose extreme corner is flat, the exact sign of the shoelace sum
/// (each term's two products exactly, summed without rounding: the same answer on every
/// platform, where a long double was 80 bits on x86 and soft floats of 128 in WebAssembly).
int ring_orientation(const Point* p, std::size_t n, std::size_t lowest) {
  const double turn = orient2d(p[(lowest + n - 1) % n], p[lowest], p[(lowest + 1) % n]);
  if (turn != 0) return turn > 0 ? 1 : -1;
  LongAccumulator area;
  bool collinear = true;
  for (std::size_t i = 0; i < n; ++i) {
    const Point& a = p[i];
    const Point& b = p[(i + 1) % n];
    area.add(exact_cross(a.x, b.y, b.x, a.y).view());
    if (collinear && orient2d(p[0], p[lowest == 0 ? 1 : lowest], a) != 0) collinear = false;
  }
  if (collinear) return 0;
  return area.sign() >= 0 ? 1 : -1;
}

/// Whether a ring going a -> b -> c (a != b != c) turns straight back at b: collinear, b not
/// strictly between a and c. The edges a-b and b-c then overlap: b is the tip of a zero-width
/// spike. Most corners need no orientation test: the two edges' vectors are then antiparallel,
/// so both terms of their dot product are at most 0, and rounding keeps each difference's and
/// each product's sign; a positive computed dot product proves a corner is no tip.
bool folds_back(const Point& a, const Point& b, const Point& c) {
  if ((b.x - a.x) * (c.x - b.x) + (b.y - a.y) * (c.y - b.y) > 0) return false;
  return orient2d(a, b, c) == 0 && !on_open_segment(b, a, c);
}

/// Appends ring `ring` of the input without repeated consecutive points (the first occurrence
/// stays) nor a repeated closing point. Each point is written, and kept by a count, not a branch;
/// returns whether every coordinate is in range, tested without a branch too (NaN and
/// infinities fail the range test).
bool append_deduplicated(const InputPolygon& in, std::size_t ring, CleanPolygon& out) {
  const std::size_t first = out.points.size();
  const std::uint32_t begin = in.ring_offsets[ring], end = in.ring_offsets[ring + 1];
  out.points.resize(first + (end - begin));
  out.original.resize(first + (end - begin));
  std::size_t kept = first;
  Point last = {std::numeric_limits<double>::quiet_NaN(), 0};  // equal to no point
  bool in_range = true;
  const InputPolygon::Ring points = in.ring(ring);
  for (std::uint32_t i = begin; i < end; ++i) {
    const Point p = points[i - begin];
    in_range &= coordinate_in_range(p.x);
    in_range &= coordinate_in_range(p.y);
    out.points[kept] = p;
    out.original[kept] = i;
    kept += (p.x != last.x) | (p.y != last.y);
    last = p;
  }
  while (kept > first + 1 && out.points[kept - 1] == out.points[first]) --kept;
  out.points.resize(kept);
  out.original.resize(kept);
  return in_range;
}

/// What a pass over the corners [from, to) of the ring p[0, n) finds: whether any may fold back
/// (a tip), and the lowest-leftmost of them (the first such).
struct CornerScan {
  bool maybe = false;
  std::size_t lowest = 0;
};

/// Every corner without a branch: a positive dot product (see folds_back) or an orientation
/// the filter of orient2d finds clearly nonzero rules a tip out. Real rings turn sharply at a
/// quarter of their corners, but tips are rare: the exact test then runs for almost none. The
/// lowest-leftmost point is found in the same pass, also without a branch.
[[gnu::noinline]] CornerScan scan_corners(const Point* p, std::size_t n, std::size_t from,
                                          std::size_t to) {
  CornerScan scan{false, from};
  // The lowest point so far as the bits of its coordinates, chosen by masks: GCC 12 made the
  // selects of doubles branches (and kept `low` in memory), a misprediction at every new low.
  std::uint64_t low_x = std::bit_cast<std::uint64_t>(p[from].x);
  std::uint64_t low_y = std::bit_cast<std::uint64_t>(p[from].y);
  // The corner's edges as vectors u = b - a and w = c - b, w becoming the next corner's u: the
  // orientation is u x w, whose filter bound is orient2d's (any four rounded differences).
  const Point& first_before = p[(from == 0 ? n : from) - 1];
  double ux = p[from].x - first_before.x, uy = p[from].y - first_before.y;
  for (std::size_t k = from; k < to; ++k) {
    const Point &b = p[k], &c = p[k + 1 == n ? 0 : k + 1];
    const double lx = std::bit_cast<double>(low_x), ly = std::bit_cast<double>(low_y);
    const bool lower = (b.y < ly) | ((b.y == ly) & (b.x < lx));
    const std::uint64_t keep = std::uint64_t{0} - lower;
    low_x = (std::bit_cast<std::uint64_t>(b.x) & keep) | (low_x & ~keep);
    low_y = (std::bit_cast<std::uint64_t>(b.y) & keep) | (low_y & ~keep);
    scan.lowest = (k & keep) | (scan.lowest & ~keep);
    const double wx = c.x - b.x, wy = c.y - b.y;
    const double left = ux * wy, right = uy * wx;
    const bool turns =
        std::fabs(left - right) > 2 * orient2d_filter_bound * (std::fabs(left) + std::fabs(right));
    scan.maybe |= !(ux * wx + uy * wy > 0) & !turns;
    ux = wx, uy = wy;
  }
  return scan;
}

/// Whether any corner of the ring p[0, n) folds back, by the exact test.
bool folds_anywhere(const Point* p, std::size_t n) {
  for (std::size_t k = 0, before = n - 1; k < n; before = k++)
    if (folds_back(p[before], p[k], p[k + 1 == n ? 0 : k + 1])) return true;
  return false;
}

/// Whether any corner of the ring from `first` on folds back (a tip), and its lowest-leftmost
/// point (`lowest`, relative to `first`).
bool has_tip(std::span<const Point> pts, std::size_t first, std::size_t& lowest) {
  const std::size_t n = pts.size() - first;
  lowest = 0;
  if (n < 3) return false;
  const CornerScan scan = scan_corners(pts.data() + first, n, 0, n);
  lowest = scan.lowest;
  return scan.maybe && folds_anywhere(pts.data() + first, n);
}

/// Dissolves the zero-width spikes and antennas of the ring [first, end) of `out` (no repeated
/// consecutive points), in rounds: every tip of the ring as it is leaves at once (adjacent tips
/// lie on one line, so the boundary as a chain of segments is unchanged, and so is the area),
/// then points that come to follow their equal merge (the earlier stays), and the ring is looked
/// at again where it changed, until no tip is left. Rounds, not one tip after another: which tip
/// goes first could decide whether a point between them stays, and the validator must find the
/// same vertices. Each tip is named in a warning, by round, in ring order.
void dissolve_spikes(CleanPolygon& out, std::size_t first, std::size_t ring, const InputPolygon& in,
                     std::vector<Diagnostic>& diagnostics) {
  const auto n = static_cast<std::uint32_t>(out.points.size() - first);
  const auto at = [&](std::uint32_t k) -> const Point& { return out.points[first + k]; };
  std::vector<std::uint32_t> prev(n), next(n), look(n), tips;
  std::vector<std::uint8_t> alive(n, 1);
  for (std::uint32_t k = 0; k < n; ++k)
    prev[k] = (k + n - 1) % n, next[k] = (k + 1) % n, look[k] = k;
  std::uint32_t left = n;
  const auto drop = [&](std::uint32_t k) {
    alive[k] = 0;
    --left;
    next[prev[k]] = next[k];
    prev[next[k]] = prev[k];
    look.insert(look.end(), {prev[k], next[k]});
  };
  // The first round looks at every point, already in order: only later rounds sort.
  for (bool first_round = true; left >= 3 && !look.empty(); first_round = false) {
    if (!first_round) {
      detail::sort(look.begin(), look.end());
      look.erase(std::unique(look.begin(), look.end()), look.end());
    }
    tips.clear();
    for (std::uint32_t k : look)
      if (alive[k] && folds_back(at(prev[k]), at(k), at(next[k]))) tips.push_back(k);
    look.clear();
    for (std::uint32_t k : tips) {
      diagnostics.push_back(
          {Issue::spike_dissolved, ring, out.original[first + k] - in.ring_offsets[ring]});
      drop(k);
    }
    for (std::size_t i = 0; i < look.size() && left >= 2; ++i) {
      const std::uint32_t k = look[i];
      if (alive[k] && at(next[k]) == at(k)) drop(std::max(k, next[k]));
    }
  }
  std::uint32_t kept = 0;
  for (std::uint32_t k = 0; k < n; ++k) {
    if (!alive[k]) continue;
    out.points[first + kept] = out.points[first + k];
    out.original[first + kept++] = out.original[first + k];
  }
  out.points.resize(first + kept);
  out.original.resize(first + kept);
}

bool fewer_than_3_points(const InputPolygon& in, std::size_t ring) {
  Point seen[2];
  std::size_t distinct = 0;
  const InputPolygon::Ring points = in.ring(ring);
  for (std::uint32_t k = 0; k < in.ring_offsets[ring + 1] - in.ring_offsets[ring]; ++k) {
    const Point p = points[k];
    if ((distinct > 0 && seen[0] == p) || (distinct > 1 && seen[1] == p)) continue;
    if (distinct == 2) return false;
    seen[distinct++] = p;
  }
  return true;
}

void reverse_ring(CleanPolygon& out, std::size_t first) {
  std::reverse(out.points.begin() + first, out.points.end());
  std::reverse(out.original.begin() + first, out.original.end());
}

void drop_ring(CleanPolygon& out, std::size_t first) {
  out.points.resize(first);
  out.original.resize(first);
}

/// The offsets in order, the last at the input's end, the outer ring not empty.
Status check_offsets(const InputPolygon& in, std::vector<Diagnostic>& diagnostics) {
  const std::size_t rings = in.ring_offsets.empty() ? 0 : in.ring_offsets.size() - 1;
  if (rings == 0) {
    diagnostics.push_back({Issue::empty_input, 0, 0});
    return Status::invalid_input;
  }
  for (std::size_t r = 0; r <= rings; ++r) {
    const std::uint32_t offset = in.ring_offsets[r];
    const bool in_order = r == 0 ? offset == 0 : in.ring_offsets[r - 1] <= offset;
    if (!in_order || (r == rings && offset != in.size())) {
      diagnostics.push_back({Issue::invalid_offsets, r, 0});
      return Status::invalid_input;
    }
  }
  if (in.ring_offsets[1] == 0) {
    diagnostics.push_back({Issue::empty_input, 0, 0});
    return Status::invalid_input;
  }
  return Status::ok;
}

Status clean_serially(const InputPolygon& in, CleanPolygon& out,
                      std::vector<Diagnostic>& diagnostics) {
  out.clear();
  const std::size_t rings = in.ring_offsets.size() - 1;
  const std::size_t earlier = diagnostics.size();
  for (std::size_t r = 0; r < rings; ++r) {
    const std::size_t first = out.points.size();
    const std::size_t warnings = diagnostics.size();
    if (!append_deduplicated(in, r, out)) {
      // Bad coordinates make the whole input invalid: the earlier rings' warnings go.
      diagnostics.resize(earlier);
      name_coordinate_error(in, r, diagnostics);
      return Status::invalid_input;
    }
    std::size_t lowest = 0;
    if (has_tip(out.points, first, lowest)) {
      dissolve_spikes(out, first, r, in, diagnostics);
      lowest = lowest_leftmost(&out.points[first], out.points.size() - first);
    }
    const std::size_t count = out.points.size() - first;
    const int orientation = count >= 3 ? ring_orientation(&out.points[first], count, lowest) : 0;
    if (count < 3 || orientation == 0) {
      // A ring that is all spike (any collinear ring is) goes as a whole, named once.
      diagnostics.resize(warnings);
      const Issue issue = r == 0 ? Issue::outer_ring_too_small
                                 : (fewer_than_3_points(in, r) ? Issue::hole_dropped_too_small
                                                               : Issue::hole_dropped_zero_area);
      if (r == 0) {
        // The input is invalid either way; a bad coordinate further on is named first.
        if (!name_coordinate_error(in, 1, diagnostics)) diagnostics.push_back({issue, r, 0});
        return Status::invalid_input;
      }
      diagnostics.push_back({issue, r, 0});
      drop_ring(out, first);
      continue;
    }
    if ((r == 0) != (orientation > 0)) reverse_ring(out, first);
    out.ring_starts.push_back(static_cast<std::uint32_t>(first));
    out.ring_source.push_back(static_cast<std::uint32_t>(r));
  }
  out.ring_starts.push_back(static_cast<std::uint32_t>(out.points.size()));
  return Status::ok;
}

/// Pieces of at most clean_chunk items cut from consecutive ranges of `lengths` items, and the
/// tasks that take them: runs of pieces of about clean_chunk items together, so that a
/// country's thousand small holes are not a thousand tasks.
struct Pieces {
  struct Piece {
    std::uint32_t range;
    std::size_t from, to;
  };
  std::vector<Piece> list;
  std::vector<std::size_t> task_start{0};
  std::vector<std::size_t> range_first;  ///< range r's pieces start at list[range_first[r]]

  explicit Pieces(const std::vector<std::size_t>& lengths) {
    std::size_t load = 0;
    range_first.resize(lengths.size() + 1);
    list.reserve(lengths.size());  // a piece a ring but for long ones (random holes: 12,500)
    for (std::uint32_t r = 0; r < lengths.size(); ++r) {
      range_first[r] = list.size();
      for (std::size_t k = 0; k < lengths[r]; k += clean_chunk) {
        list.push_back({r, k, std::min(lengths[r], k + clean_chunk)});
        load += list.back().to - k;
        if (load >= clean_chunk) {
          task_start.push_back(list.size());
          load = 0;
        }
      }
    }
    if (task_start.back() != list.size()) task_start.push_back(list.size());
    range_first.back() = list.size();
  }
  std::size_t tasks() const { return task_start.size() - 1; }
  template <class Visit>
  void visit_task(std::size_t task, Visit&& visit) const {
    for (std::size_t j = task_start[task]; j < task_start[task + 1]; ++j) visit(j, list[j]);
  }
};

/// The input's points of chunk c in order, each with whether cleaning keeps it (the first of a
/// run of equal points, unless it repeats its ring's first point at the ring's end); entering a
/// ring calls enter(r) before its first point.
template <class Enter, class Visit>
void walk_chunk(const InputPolygon& in, std::span<const std::uint32_t> closing, std::size_t c,
                Enter&& enter, Visit&& visit) {
  const auto& offsets = in.ring_offsets;
  const std::size_t rings = offsets.size() - 1, begin = c * clean_chunk,
                    end = std::min(in.size(), begin + clean_chunk);
  auto next = static_cast<std::size_t>(
      std::lower_bound(offsets.begin(), offsets.begin() + static_cast<std::ptrdiff_t>(rings),
                       begin) -
      offsets.begin());
  Point last = begin > 0 ? in.at(in.ring_of(begin - 1), begin - 1) : Point{};
  // Until a ring is entered, point begin lies in the ring before `next` (begin is inside it).
  InputPolygon::Ring ring = in.ring(next > 0 ? next - 1 : 0);
  std::size_t ring_start = offsets[next > 0 ? next - 1 : 0];
  for (std::size_t i = begin; i < end; ++i) {
    bool starts = false;
    for (; next < rings && offsets[next] == i; ++next) enter(next), starts = true;
    if (starts) ring = in.ring(next - 1), ring_start = offsets[next - 1];
    const Point p = ring[i - ring_start];
    visit(i, p, (starts || p != last) && i != closing[next - 1]);
    last = p;
  }
}

/// Each ring's tips and lowest point by a pass over its corners in parallel pieces, its
/// orientation, then the rings that need it reversed in parallel pieces. False where a ring
/// has a tip or no area (out half done).
bool orient_in_parts(CleanPolygon& out, const std::vector<std::uint32_t>& first,
                     const std::vector<std::size_t>& length, const RunContext& ctx) {
  const std::size_t rings = length.size();
  const Pieces corners(length);
  std::vector<CornerScan> scans(corners.list.size());
  ctx.run_tasks("clean: corners", corners.tasks(), [&](std::size_t task) {
    corners.visit_task(task, [&](std::size_t j, const Pieces::Piece& q) {
      scans[j] = scan_corners(out.points.data() + first[q.range], length[q.range], q.from, q.to);
    });
  });
  // Each ring's scans merged and its orientation found, in tasks of rings (a grid of 10,000
  // holes: 0.05 ms on one thread).
  std::vector<std::size_t> half(rings, 0);
  const std::size_t tasks = ctx.tasks_for(rings, 256);
  std::vector<std::uint8_t> simple(tasks, 1);
  ctx.run_tasks("clean: orient", tasks, [&](std::size_t task) {
    const std::size_t end = part_begin(rings, tasks, task + 1);
    for (std::size_t r = part_begin(rings, tasks, task); r < end && simple[task]; ++r) {
      const Point* p = out.points.data() + first[r];
      std::size_t j = corners.range_first[r];
      CornerScan ring = scans[j];  // every ring has a piece: at least 3 points
      for (++j; j < corners.range_first[r + 1]; ++j) {
        ring.maybe |= scans[j].maybe;
        if (lower_left(p[scans[j].lowest], p[ring.lowest])) ring.lowest = scans[j].lowest;
      }
      const int orientation = ring.maybe && folds_anywhere(p, length[r])
                                  ? 0
                                  : ring_orientation(p, length[r], ring.lowest);
      simple[task] = orientation != 0;
      if ((r == 0) != (orientation > 0)) half[r] = length[r] / 2;
    }
  });
  const bool simple_corners = std::find(simple.begin(), simple.end(), 0) == simple.end();
  if (!simple_corners) return false;
  const Pieces swaps(half);
  ctx.run_tasks("clean: reverse", swaps.tasks(), [&](std::size_t task) {
    swaps.visit_task(task, [&](std::size_t, const Pieces::Piece& q) {
      const std::size_t from = first[q.range], last = from + length[q.range] - 1;
      for (std::size_t k = q.from; k < q.to; ++k) {
        std::swap(out.points[from + k], out.points[last - k]);
        std::swap(out.original[from + k], out.original[last - k]);
      }
    });
  });
  out.ring_starts.assign(first.begin(), first.end());
  out.ring_source.resize(rings);
  std::iota(out.ring_source.begin(), out.ring_source.end(), 0u);
  return true;
}

/// The common case of a large input in parallel passes: every coordinate in range, no tip,
/// every ring kept. Returns false (out half filled) for anything else.
bool clean_in_parts(const InputPolygon& in, CleanPolygon& out, const RunContext& ctx) {
  const auto& offsets = in.ring_offsets;
  const std::size_t rings = offsets.size() - 1, n = in.size();
  const std::size_t chunks = (n + clean_chunk - 1) / clean_chunk;
  // Where a ring's last run of equal points repeats its first point: that run goes.
  std::vector<std::uint32_t> closing(rings, UINT32_MAX);
  const std::size_t ring_tasks = ctx.tasks_for(rings, 256);
  ctx.run_tasks("clean: ring ends", ring_tasks, [&](std::size_t task) {
    const std::size_t end = part_begin(rings, ring_tasks, task + 1);
    for (std::size_t r = part_begin(rings, ring_tasks, task); r < end; ++r) {
      const std::uint32_t first = offsets[r], end = offsets[r + 1];
      if (end - first < 2) continue;
      std::uint32_t run = end - 1;
      const InputPolygon::Ring ring = in.ring(r);
      while (run > first && ring[run - 1 - first] == ring[run - first]) --run;
      if (run > first && ring[run - first] == ring[0]) closing[r] = run;
    }
  });
  std::vector<std::uint32_t> start(chunks + 1, 0);
  std::vector<std::uint8_t> in_range(chunks, 1);
  ctx.run_tasks("clean: count", chunks, [&](std::size_t c) {
    std::uint32_t kept = 0;
    bool all_in_range = true;
    walk_chunk(
        in, closing, c, [](std::size_t) {},
        [&](std::size_t, const Point& p, bool keep) {
          all_in_range &= static_cast<unsigned>(coordinate_in_range(p.x)) &
                          static_cast<unsigned>(coordinate_in_range(p.y));
          kept += keep;
        });
    start[c + 1] = kept;
    in_range[c] = all_in_range;
  });
  if (std::find(in_range.begin(), in_range.end(), 0) != in_range.end()) return false;
  for (std::size_t c = 0; c < chunks; ++c) start[c + 1] += start[c];
  const std::uint32_t total = start[chunks];
  out.points.resize(total);
  out.original.resize(total);
  std::vector<std::uint32_t> first(rings + 1, total);
  ctx.run_tasks("clean: copy", chunks, [&](std::size_t c) {
    std::uint32_t at = start[c];
    walk_chunk(
        in, closing, c, [&](std::size_t r) { first[r] = at; },
        [&](std::size_t i, const Point& p, bool keep) {
          if (!keep) return;
          out.points[at] = p;
          out.original[at++] = static_cast<std::uint32_t>(i);
        });
  });
  std::vector<std::size_t> length(rings);
  for (std::size_t r = 0; r < rings; ++r) {
    length[r] = first[r + 1] - first[r];
    if (length[r] < 3) return false;
  }
  return orient_in_parts(out, first, length, ctx);
}

}  // namespace

Status clean_polygon(const InputPolygon& in, CleanPolygon& out,
                     std::vector<Diagnostic>& diagnostics, const RunContext& ctx,
                     std::size_t in_parts_from) {
  out.clear();
  if (check_offsets(in, diagnostics) != Status::ok) return Status::invalid_input;
  // In parts only where they may run in parallel: on one thread they cost 1.2x the serial
  // pass (Eurasia 14 against 11.5 ms). The same result either way, so a build without threads
  // never takes them and leaves their code out (the WebAssembly module: 8 KB).
  const bool in_parts =
      PEAR_HAS_THREADS && in.size() >= in_parts_from && (ctx.parallel() || ctx.partitions > 1);
  if (in_parts && clean_in_parts(in, out, ctx)) return Status::ok;
  Status status = Status::ok;
  ctx.run_serial("clean", [&] { status = clean_serially(in, out, diagnostics); });
  return status;
}

void split_at_t_junctions(const CleanPolygon& in, std::span<const TJunction> junctions,
                          CleanPolygon& out) {
  out.clear();
  out.points.reserve(in.points.size() + junctions.size());
  out.original.reserve(in.points.size() + junctions.size());
  out.ring_source = in.ring_source;
  std::size_t next = 0;  // the first junction not yet placed
  for (std::size_t r = 0; r < in.ring_count(); ++r) {
    out.ring_starts.push_back(static_cast<std::uint32_t>(out.points.size()));
    for (std::uint32_t i = in.ring_starts[r]; i < in.ring_starts[r + 1]; ++i) {
      out.points.push_back(in.points[i]);
      out.original.push_back(in.original[i]);
      for (; next < junctions.size() && junctions[next].edge == i; ++next) {
        out.points.push_back(in.points[junctions[next].vertex]);
        out.original.push_back(in.original[junctions[next].vertex]);
      }
    }
  }
  out.ring_starts.push_back(static_cast<std::uint32_t>(out.points.size()));
}

}  // namespace pear::detail
