#include "split_pieces.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/sort_in_parts.hpp"
#include "geometry/sort.hpp"
#include "pear/config.hpp"

namespace pear::detail {
namespace {

/// Sign of (y of c) - (y of d) where both edges meet the vertical line between their endpoints'
/// x; exact for edges that do not cross (the sweep-line order of Bentley–Ottmann): the edge
/// that starts further right is placed by its start against the other edge's supporting line,
/// by its end when its start lies on that line.
template <class Crossing>
int compare_along_line(const Crossing& c, const Crossing& d) {
  if (c.low.x >= d.low.x) {
    double o = orient2d(d.low, d.high, c.low);
    if (o == 0) o = orient2d(d.low, d.high, c.high);
    return (o > 0) - (o < 0);
  }
  double o = orient2d(c.low, c.high, d.low);
  if (o == 0) o = orient2d(c.low, c.high, d.high);
  return (o < 0) - (o > 0);
}

/// The rounded point where the edge low-high meets x. The same for both directions of a bridge
/// (the edge is always taken from its left end), and never outside the edge's y range.
double rounded_y(const Point& low, const Point& high, double x) {
  const double t = (x - low.x) / (high.x - low.x);
  const double y = low.y + t * (high.y - low.y);
  if (std::isnan(y)) return low.y;
  return std::clamp(y, std::min(low.y, high.y), std::max(low.y, high.y));
}

void append_piece(const PieceCorner* corners, std::uint32_t count, Pieces& out) {
  out.corners.insert(out.corners.end(), corners, corners + count);
  out.close_piece();
}

/// Up to this many split lines, ranks are selected and crossings counted in linear passes (a
/// sort of Borneo's sample was most of dividing it in two); past it, sorted.
constexpr std::size_t few_lines = 16;

/// Quantiles of the sample: the ceil(i * n / (parts - 1 + last_share))-th smallest x, without
/// repeats (the last part a `last_share` of the others'). Reorders xs unless `sorted` says it
/// is: for a few lines each rank is selected above the last (nth_element), else xs is sorted.
std::vector<double> quantile_positions(std::vector<double>& xs, unsigned parts, bool sorted,
                                       double last_share) {
  std::vector<double> after;
  if (xs.empty()) return after;
  const bool select = !sorted && parts - 1 <= few_lines;
  if (!select && !sorted) detail::sort(xs.begin(), xs.end());
  const double largest = sorted ? xs.back() : *std::max_element(xs.begin(), xs.end());
  std::size_t selected = 0;  // xs[0, selected) hold the smallest values, in no order
  for (std::size_t i = 1; i < parts; ++i) {
    // The paper's m_i = ceil(i n / k) where last_share is 1.
    const auto m = static_cast<std::size_t>(
        std::ceil(static_cast<double>(i * xs.size()) / (parts - 1 + last_share)));
    if (select && m > selected) {
      std::nth_element(xs.begin() + static_cast<std::ptrdiff_t>(selected),
                       xs.begin() + static_cast<std::ptrdiff_t>(m - 1), xs.end());
      selected = m;
    }
    const double v = xs[m - 1];
    if (v < largest && (after.empty() || after.back() < v)) after.push_back(v);
  }
  return after;
}

/// Every stride-th corner's x, and the x range of the edge from it.
struct CycleSample {
  std::vector<double> xs, low, high;
  std::size_t stride = 1;
};

/// The crossings of the sample's edges with lines placed right after each x of `after`
/// (increasing), times the stride: an edge crosses such a line when its x range holds the x and
/// reaches past it. Counted in `tasks` tasks of ctx: up to few_lines lines line by line, past
/// that by two binary searches an edge (a serial sort of the ranges was 1.5 ms of
/// random-holes-100k at 32 parts, its longest phase).
std::size_t estimated_crossings(const CycleSample& sample, const std::vector<double>& after,
                                std::size_t tasks, const RunContext& ctx) {
  const std::vector<double>&low = sample.low, &high = sample.high;
  std::vector<std::size_t> counts(tasks, 0);
  ctx.run_tasks_if_threads("split lines: crossings", tasks, [&](std::size_t t) {
    std::size_t crossings = 0;
    const std::size_t end = low.size() * (t + 1) / tasks;
    for (std::size_t e = low.size() * t / tasks; e < end; ++e) {
      if (after.size() <= few_lines) {
        for (double v : after)  // bitwise, without a branch (clang warns of & on bools)
          crossings +=
              static_cast<std::size_t>(low[e] <= v) & static_cast<std::size_t>(v < high[e]);
      } else {  // the lines at or right of low[e] and left of high[e]
        crossings +=
            static_cast<std::size_t>(std::lower_bound(after.begin(), after.end(), high[e]) -
                                     std::lower_bound(after.begin(), after.end(), low[e]));
      }
    }
    counts[t] = crossings;
  });
  return std::accumulate(counts.begin(), counts.end(), std::size_t{0}) * sample.stride;
}

}  // namespace

std::vector<double> split_positions(const Boundary& b, const std::vector<PieceCorner>& cycle,
                                    unsigned parts, const RunContext& ctx, double last_share) {
  // Quantiles of a sample of at most 2^14 x values: balanced enough, and O(n) to take.
  constexpr std::size_t sample_limit = std::size_t{1} << 14;
  CycleSample sample;
  sample.stride = std::max<std::size_t>(1, cycle.size() / sample_limit);
  const std::size_t count = (cycle.size() + sample.stride - 1) / sample.stride;
  const std::size_t tasks =
      PEAR_HAS_THREADS ? std::clamp<std::size_t>(count / 1024, 1, ctx.partitions) : 1;
  ctx.run_serial_if_threads("split lines: allocate", [&] {
    sample.xs.resize(count);
    sample.low.resize(count);
    sample.high.resize(count);
  });
  ctx.run_tasks_if_threads("split lines: sample", tasks, [&](std::size_t t) {
    const std::size_t end = count * (t + 1) / tasks;
    for (std::size_t k = count * t / tasks; k < end; ++k) {
      const std::size_t i = k * sample.stride;
      const double x0 = b.pos[corner_index(cycle[i])].x;
      const double x1 = b.pos[corner_index(cycle[i + 1 == cycle.size() ? 0 : i + 1])].x;
      sample.xs[k] = x0;
      sample.low[k] = std::min(x0, x1);
      sample.high[k] = std::max(x0, x1);
    }
  });
  // In tasks, one sort gives every quantile for less than selecting them on one thread.
  const bool sorted = tasks >= 4;
  if (sorted)
    sort_in_parts(ctx, "split lines: sort", "split lines: merge", sample.xs, std::less<>{});
  const std::size_t budget = max_steiner_points(cycle.size());
  for (; parts >= 2; parts /= 2) {
    std::vector<double> after;
    ctx.run_serial_if_threads("split lines: quantiles", [&] {
      after = quantile_positions(sample.xs, parts, sorted, last_share);
    });
    if (estimated_crossings(sample, after, tasks, ctx) <= budget) return after;
  }
  return {};
}

bool PieceSplitter::place(const Boundary& b, std::vector<SplitLine>& lines, std::uint32_t line,
                          const Pieces& in) {
  SplitLine& split_line = lines[line];
  double next = std::numeric_limits<double>::infinity();
  for (PieceCorner c : in.corners) {
    const double x = corner_pos(b, lines, c).x;
    if (x > split_line.after && x < next) next = x;
  }
  if (std::isinf(next)) return false;
  // Never through a vertex (paper §2.1): strictly between two consecutive corner x values.
  double x = split_line.after * 0.5 + next * 0.5;
  if (!(split_line.after < x && x < next)) x = std::nextafter(split_line.after, next);
  if (!(split_line.after < x && x < next)) return false;
  split_line.x = x;
  return true;
}

bool PieceSplitter::find_crossings(const Boundary& b, std::vector<SplitLine>& lines,
                                   std::uint32_t line, const PieceCorner* corners,
                                   std::uint32_t count) {
  crossings_.clear();
  const double x = lines[line].x;
  const bool first_left = corner_pos(b, lines, corners[0]).x < x;
  bool v_left = first_left;  // each corner's side is computed once
  for (std::uint32_t i = 0; i < count; ++i) {
    const PieceCorner u = corners[i], v = corners[i + 1 == count ? 0 : i + 1];
    const bool u_left = v_left;
    v_left = i + 1 == count ? first_left : corner_pos(b, lines, v).x < x;
    if (u_left == v_left) continue;
    // Only sub-segments of input edges cross: split segments are vertical on other lines.
    const std::uint32_t from =
        is_steiner(u) ? lines[corner_line(u)].steiner[corner_index(u)].from : corner_index(u);
    const std::uint32_t to =
        is_steiner(v) ? lines[corner_line(v)].steiner[corner_index(v)].to : corner_index(v);
    const Point& a = b.pos[from];
    const Point& c = b.pos[to];
    const Point low = a.x < c.x ? a : c, high = a.x < c.x ? c : a;
    if (!(low.x < x && x < high.x)) return false;
    std::vector<SteinerPoint>& steiner = lines[line].steiner;
    const PieceCorner corner = steiner_corner(line, static_cast<std::uint32_t>(steiner.size()));
    steiner.push_back({from, to, {x, rounded_y(low, high, x)}});
    crossings_.push_back({i, corner, low, high, u_left, 0});
  }
  return true;
}

/// Sorts the crossings bottom to top and pairs them: going up, a rightward edge starts an
/// interior segment and a leftward one ends it. At one point (the two sides of a bridge) the
/// leftward comes first, as the interior lies on both sides of a bridge.
bool PieceSplitter::pair_crossings(const std::vector<SplitLine>& lines, std::uint32_t line) {
  const std::size_t count = crossings_.size();
  if (count % 2 != 0) return false;
  const auto& steiner = lines[line].steiner;
  const auto y = [&](std::uint32_t k) {
    return steiner[corner_index(crossings_[k].steiner)].pos.y;
  };
  order_.resize(count);
  std::iota(order_.begin(), order_.end(), 0u);
  detail::sort(order_.begin(), order_.end(), [&](std::uint32_t i, std::uint32_t j) {
    if (y(i) != y(j)) return y(i) < y(j);
    if (crossings_[i].rightward != crossings_[j].rightward) return !crossings_[i].rightward;
    return i < j;
  });
  // The rounded order is nearly right; insertion sort with the exact order repairs it (and,
  // unlike std::sort, stays harmless if crossing input edges make the order inconsistent).
  const auto before = [&](std::uint32_t i, std::uint32_t j) {
    const int order = compare_along_line(crossings_[i], crossings_[j]);
    return order < 0 || (order == 0 && !crossings_[i].rightward && crossings_[j].rightward);
  };
  // A budget on the swaps: many crossings within an ulp of each other (contrived input) would
  // make this quadratic; the split fails instead and the sequential engine takes over.
  std::size_t budget = 64 * count + 4096;
  for (std::size_t i = 1; i < count; ++i)
    for (std::size_t j = i; j > 0 && before(order_[j], order_[j - 1]); --j) {
      if (budget-- == 0) return false;
      std::swap(order_[j], order_[j - 1]);
    }
  for (std::size_t k = 0; k < count; k += 2) {
    const std::uint32_t bottom = order_[k], top = order_[k + 1];
    if (!crossings_[bottom].rightward || crossings_[top].rightward) return false;
    crossings_[bottom].partner = top;
    crossings_[top].partner = bottom;
  }
  return true;
}

/// Walks the pieces on one side: a chain of the cycle on that side, then along the line to the
/// partner crossing (upward on the left side, downward on the right), the next chain, and so on.
bool PieceSplitter::emit(const PieceCorner* corners, std::uint32_t count, bool left_side,
                         Pieces& out) {
  const std::uint32_t total = static_cast<std::uint32_t>(crossings_.size());
  used_.assign(total, 0);
  for (std::uint32_t first = 0; first < total; ++first) {
    // The chain after a rightward crossing lies right of the line.
    if (crossings_[first].rightward == left_side || used_[first]) continue;
    std::uint32_t k = first;
    do {
      used_[k] = 1;
      out.corners.push_back(crossings_[k].steiner);
      const std::uint32_t end = k + 1 == total ? 0 : k + 1;
      for (std::uint32_t i = crossings_[k].at;;) {
        i = i + 1 == count ? 0 : i + 1;
        out.corners.push_back(corners[i]);
        if (i == crossings_[end].at) break;
      }
      out.corners.push_back(crossings_[end].steiner);
      k = crossings_[end].partner;
    } while (!used_[k]);
    if (k != first) return false;
    out.close_piece();
  }
  return true;
}

bool PieceSplitter::split(const Boundary& b, std::vector<SplitLine>& lines, std::uint32_t line,
                          const Pieces& in, Pieces& left, Pieces& right) {
  if (!place(b, lines, line, in)) {  // no corner x beyond the line's place: nothing to cut
    for (std::size_t p = 0; p < in.count(); ++p)
      append_piece(&in.corners[in.starts[p]], in.starts[p + 1] - in.starts[p], left);
    return true;
  }
  const double x = lines[line].x;
  for (std::size_t p = 0; p < in.count(); ++p) {
    const PieceCorner* corners = &in.corners[in.starts[p]];
    const std::uint32_t count = in.starts[p + 1] - in.starts[p];
    if (!find_crossings(b, lines, line, corners, count)) return false;
    if (crossings_.empty()) {
      append_piece(corners, count, corner_pos(b, lines, corners[0]).x < x ? left : right);
      continue;
    }
    if (!pair_crossings(lines, line) || !emit(corners, count, true, left) ||
        !emit(corners, count, false, right))
      return false;
  }
  return true;
}

}  // namespace pear::detail
