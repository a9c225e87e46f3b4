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

std::vector<double> split_positions(const Boundary& b, const FillVector<PieceCorner>& cycle,
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
                          const Pieces& in, const RunContext* ctx) {
  SplitLine& split_line = lines[line];
  const auto smallest_after = [&](std::size_t from, std::size_t to) {
    double next = std::numeric_limits<double>::infinity();
    for (std::size_t i = from; i < to; ++i) {
      const double x = corner_pos(b, lines, in.corners[i]).x;
      if (x > split_line.after && x < next) next = x;
    }
    return next;
  };
  double next = std::numeric_limits<double>::infinity();
  if (!PEAR_HAS_THREADS || ctx == nullptr) {
    next = smallest_after(0, in.corners.size());
  } else {
    const std::size_t n = in.corners.size(), tasks = ctx->tasks_for(n, 4096);
    std::vector<double> nexts(tasks);
    ctx->run_tasks("split: place", tasks, [&](std::size_t t) {
      nexts[t] = smallest_after(part_begin(n, tasks, t), part_begin(n, tasks, t + 1));
    });
    next = *std::min_element(nexts.begin(), nexts.end());
  }
  if (std::isinf(next)) return false;
  // Never through a vertex (paper §2.1): strictly between two consecutive corner x values.
  double x = split_line.after * 0.5 + next * 0.5;
  if (!(split_line.after < x && x < next)) x = std::nextafter(split_line.after, next);
  if (!(split_line.after < x && x < next)) return false;
  split_line.x = x;
  return true;
}

/// The crossing of the piece edge corners[i] -> corners[i + 1] (whose ends lie on the two sides
/// of the line at x, corners[i] on the left where `u_left`) and its Steiner point; false where
/// the input edge does not reach across the line.
bool PieceSplitter::crossing_at(const Boundary& b, const std::vector<SplitLine>& lines,
                                const PieceCorner* corners, std::uint32_t count, std::uint32_t i,
                                bool u_left, double x, Crossing& c, SteinerPoint& s) const {
  const PieceCorner u = corners[i], v = corners[i + 1 == count ? 0 : i + 1];
  // Only sub-segments of input edges cross: split segments are vertical on other lines.
  const std::uint32_t from =
      is_steiner(u) ? lines[corner_line(u)].steiner[corner_index(u)].from : corner_index(u);
  const std::uint32_t to =
      is_steiner(v) ? lines[corner_line(v)].steiner[corner_index(v)].to : corner_index(v);
  const Point& a = b.pos[from];
  const Point& e = b.pos[to];
  const Point low = a.x < e.x ? a : e, high = a.x < e.x ? e : a;
  if (!(low.x < x && x < high.x)) return false;
  s = {from, to, {x, rounded_y(low, high, x)}};
  c = {i, 0, low, high, u_left, 0};
  return true;
}

bool PieceSplitter::find_crossings(const Boundary& b, std::vector<SplitLine>& lines,
                                   std::uint32_t line, const PieceCorner* corners,
                                   std::uint32_t count, const RunContext* ctx) {
  const double x = lines[line].x;
  const std::size_t tasks = !PEAR_HAS_THREADS || ctx == nullptr ? 1 : ctx->tasks_for(count, 4096);
  found_.resize(std::max(found_.size(), tasks));
  std::vector<std::uint8_t> ok(tasks, 1);
  // Each task's edges in order, each corner's side computed once (the first's twice).
  const auto find = [&](std::size_t t) {
    auto& mine = found_[t];
    mine.clear();
    const auto first = static_cast<std::uint32_t>(part_begin(count, tasks, t));
    const auto end = static_cast<std::uint32_t>(part_begin(count, tasks, t + 1));
    bool v_left = first < end && corner_pos(b, lines, corners[first]).x < x;
    for (std::uint32_t i = first; i < end; ++i) {
      const bool u_left = v_left;
      v_left = corner_pos(b, lines, corners[i + 1 == count ? 0 : i + 1]).x < x;
      if (u_left == v_left) continue;
      auto& [c, s] = mine.emplace_back();
      if (!crossing_at(b, lines, corners, count, i, u_left, x, c, s)) {
        ok[t] = 0;
        return;
      }
    }
  };
  if (!PEAR_HAS_THREADS || ctx == nullptr)
    find(0);
  else
    ctx->run_tasks("split: crossings", tasks, find);
  if (std::find(ok.begin(), ok.end(), 0) != ok.end()) return false;
  // The Steiner points numbered in cycle order, as one pass would.
  crossings_.clear();
  std::vector<SteinerPoint>& steiner = lines[line].steiner;
  for (std::size_t t = 0; t < tasks; ++t)
    for (auto& [c, s] : found_[t]) {
      c.steiner = steiner_corner(line, static_cast<std::uint32_t>(steiner.size()));
      steiner.push_back(s);
      crossings_.push_back(c);
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
/// The walk plans the runs and where each goes; their corners are then copied (in tasks of ctx,
/// by equal shares of the output: one run may be most of the cycle).
bool PieceSplitter::emit(const PieceCorner* corners, std::uint32_t count, bool left_side,
                         Pieces& out, const RunContext* ctx) {
  const std::uint32_t total = static_cast<std::uint32_t>(crossings_.size());
  used_.assign(total, 0);
  runs_.clear();
  piece_ends_.clear();
  planned_ = 0;
  for (std::uint32_t first = 0; first < total; ++first) {
    // The chain after a rightward crossing lies right of the line.
    if (crossings_[first].rightward == left_side || used_[first]) continue;
    std::uint32_t k = first;
    do {
      used_[k] = 1;
      const std::uint32_t end = k + 1 == total ? 0 : k + 1;
      const std::uint32_t at = crossings_[k].at, to = crossings_[end].at;
      runs_.push_back({k, end, planned_});
      planned_ += 2 + (to > at ? to - at : to + count - at);  // the corners after at, to `to`
      k = crossings_[end].partner;
    } while (!used_[k]);
    if (k != first) return false;
    piece_ends_.push_back(planned_);
  }
  const std::size_t base = out.corners.size();
  out.corners.resize(base + planned_);
  PieceCorner* written = out.corners.data() + base;
  if (!PEAR_HAS_THREADS || ctx == nullptr) {
    fill_runs(corners, count, written, 0, planned_);
  } else {
    const std::size_t tasks = ctx->tasks_for(planned_, 4096);
    ctx->run_tasks("split: pieces", tasks, [&](std::size_t t) {
      fill_runs(corners, count, written, part_begin(planned_, tasks, t),
                part_begin(planned_, tasks, t + 1));
    });
  }
  for (const std::size_t end : piece_ends_)
    out.starts.push_back(static_cast<std::uint32_t>(base + end));
  return true;
}

/// Writes output positions [from, to) of the planned runs.
void PieceSplitter::fill_runs(const PieceCorner* corners, std::uint32_t count, PieceCorner* out,
                              std::size_t from, std::size_t to) const {
  std::size_t r = static_cast<std::size_t>(
      std::upper_bound(runs_.begin(), runs_.end(), from,
                       [](std::size_t o, const Run& run) { return o < run.out; }) -
      runs_.begin() - 1);
  for (std::size_t o = from; o < to; ++r) {
    const Run& run = runs_[r];
    const std::size_t last = (r + 1 < runs_.size() ? runs_[r + 1].out : planned_) - 1;
    if (o == run.out) out[o++] = crossings_[run.crossing].steiner;
    std::uint32_t i = crossings_[run.crossing].at + static_cast<std::uint32_t>(o - run.out);
    for (; o < std::min(to, last); ++o, ++i) out[o] = corners[i >= count ? i - count : i];
    if (o == last && o < to) out[o++] = crossings_[run.end].steiner;
  }
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

bool PieceSplitter::split_in_parts(const Boundary& b, std::vector<SplitLine>& lines,
                                   std::uint32_t line, const Pieces& in, Pieces& left,
                                   Pieces& right, const RunContext& ctx) {
  // A build without threads keeps one path (the .wasm's size).
  if (!PEAR_HAS_THREADS || in.count() != 1) return split(b, lines, line, in, left, right);
  const PieceCorner* corners = in.corners.data();
  const auto count = static_cast<std::uint32_t>(in.corners.size());
  if (!place(b, lines, line, in, &ctx)) {
    append_piece(corners, count, left);
    return true;
  }
  if (!find_crossings(b, lines, line, corners, count, &ctx)) return false;
  if (crossings_.empty()) {
    append_piece(corners, count, corner_pos(b, lines, corners[0]).x < lines[line].x ? left : right);
    return true;
  }
  bool paired = false;
  ctx.run_serial("split: pair", [&] { paired = pair_crossings(lines, line); });
  return paired && emit(corners, count, true, left, &ctx) &&
         emit(corners, count, false, right, &ctx);
}

}  // namespace pear::detail
