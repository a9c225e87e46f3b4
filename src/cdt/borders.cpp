#include "borders.hpp"

#include <algorithm>
#include <span>

#include "geometry/sort.hpp"
#include "pear/config.hpp"

namespace pear::detail {
namespace {

/// Below this many suspects a round's tasks cost more than they save: it runs on this thread.
constexpr std::size_t min_round_suspects = 512;
/// Suspects per task in a round.
constexpr std::size_t round_chunk = 256;
/// A round that flips fewer than one in this many of its suspects: the flips wait on one
/// another in long chains (a thin ellipse's diagonals flip one after the other across the
/// polygon), and every round tests all that wait again. Lawson's loop on one thread then
/// finishes the rest, as it does below min_round_suspects: a round costs its set-up however
/// few it flips, and the ellipse's cascade after partition-and-cut took 3.7 million rounds
/// of two flips (26 s, against 57 ms now).
constexpr std::size_t thin_round = 16;

/// Which triangles this round's picked flips use (own) or update a twin in (touched).
struct RoundMarks {
  /// Round numbers, per triangle (own, touched) and per half-edge (listed): BorderFlipMarks'.
  std::uint32_t *own = nullptr, *touched = nullptr, *listed = nullptr;
  std::uint32_t round = 0;
  std::vector<std::uint8_t> needs;             ///< per suspect: must be flipped
  std::vector<std::uint32_t> picked, waiting;  ///< flipped this round, and left for the next
};

std::uint32_t outer_neighbour(const Mesh& mesh, std::uint32_t h) {
  const std::uint32_t twin = mesh.twin[h];
  return twin == no_twin ? no_twin : twin / 3;
}

/// A flip of h writes its two triangles and one twin in each of the up to four neighbours. It
/// may run beside the flips picked before it when no triangle it writes is one they own, and no
/// triangle it owns is one they write.
bool pick(const Mesh& mesh, std::uint32_t h, RoundMarks& marks) {
  const std::uint32_t g = mesh.twin[h];
  const std::uint32_t own[2] = {h / 3, g / 3};
  const std::uint32_t outer[4] = {outer_neighbour(mesh, next_half_edge(h)),
                                  outer_neighbour(mesh, next_half_edge(next_half_edge(h))),
                                  outer_neighbour(mesh, next_half_edge(g)),
                                  outer_neighbour(mesh, next_half_edge(next_half_edge(g)))};
  for (std::uint32_t t : own)
    if (marks.own[t] == marks.round || marks.touched[t] == marks.round) return false;
  for (std::uint32_t t : outer)
    if (t != no_twin && marks.own[t] == marks.round) return false;
  for (std::uint32_t t : own) marks.own[t] = marks.round;
  for (std::uint32_t t : outer)
    if (t != no_twin) marks.touched[t] = marks.round;
  return true;
}

/// Appends the edge of h to `list` unless already listed this round.
void list_once(const Mesh& mesh, std::uint32_t h, RoundMarks& marks,
               std::vector<std::uint32_t>& list) {
  const std::uint32_t g = mesh.twin[h];
  if (g == no_twin) return;
  const std::uint32_t first = std::min(h, g);
  if (marks.listed[first] == marks.round) return;
  marks.listed[first] = marks.round;
  list.push_back(h);
}

/// A round's serial step: recorded as a phase when the round is large (its tasks are), else run
/// as part of the small rounds' one phase.
template <class Step>
void serial_step(const RunContext& ctx, bool parallel, const char* phase, Step&& step) {
  if (parallel)
    ctx.run_serial(phase, step);
  else
    step();
}

/// Runs body(begin, end) over [0, count) in chunks: as parallel tasks when the round is large,
/// else right here (the result is the same either way).
template <class Body>
void for_chunks(const RunContext& ctx, bool parallel, const char* phase, std::size_t count,
                Body&& body) {
  if (!parallel) return body(std::size_t{0}, count);
  ctx.run_tasks(phase, (count + round_chunk - 1) / round_chunk, [&](std::size_t c) {
    body(c * round_chunk, std::min(count, (c + 1) * round_chunk));
  });
}

/// One round; returns the flips done (at most `budget`) and leaves the next suspects in
/// `suspects`.
std::size_t flip_round(Mesh& mesh, std::vector<std::uint32_t>& suspects, RoundMarks& marks,
                       const RunContext& ctx, std::size_t budget) {
  const bool parallel = suspects.size() >= min_round_suspects;
  std::vector<std::uint8_t>& needs = marks.needs;
  needs.assign(suspects.size(), 0);
  for_chunks(ctx, parallel, "cdt border round: test", suspects.size(),
             [&](std::size_t begin, std::size_t end) {
               for (std::size_t i = begin; i < end; ++i)
                 needs[i] = mesh.twin[suspects[i]] != no_twin && must_flip(mesh, suspects[i]);
             });
  ++marks.round;
  std::vector<std::uint32_t>&picked = marks.picked, &waiting = marks.waiting;
  picked.clear();
  waiting.clear();
  serial_step(ctx, parallel, "cdt border round: pick", [&] {
    for (std::size_t i = 0; i < suspects.size(); ++i) {
      if (!needs[i]) continue;
      const bool independent = picked.size() < budget && pick(mesh, suspects[i], marks);
      (independent ? picked : waiting).push_back(suspects[i]);
    }
  });
  for_chunks(ctx, parallel, "cdt border round: flip", picked.size(),
             [&](std::size_t begin, std::size_t end) {
               for (std::size_t i = begin; i < end; ++i) flip(mesh, picked[i], FlipScope{});
             });
  suspects.clear();
  if (picked.empty()) return 0;  // nothing to flip (or no budget left): done
  serial_step(ctx, parallel, "cdt border round: list", [&] {
    for (std::uint32_t h : waiting) list_once(mesh, h, marks, suspects);
    for (std::uint32_t h : picked) {
      const std::uint32_t g = mesh.twin[h];
      for (std::uint32_t e : {next_half_edge(h), next_half_edge(next_half_edge(h)),
                              next_half_edge(g), next_half_edge(next_half_edge(g))})
        list_once(mesh, e, marks, suspects);
    }
  });
  return picked.size();
}

}  // namespace

void collect_borders(const Mesh& mesh, const TrianglePartition& partition, std::uint32_t s,
                     std::vector<std::uint32_t>& borders) {
  for (std::size_t i = partition.begin[s]; i < partition.begin[s + 1]; ++i) {
    const std::uint32_t t = partition.order[i];
    for (std::uint32_t h = 3 * t; h < 3 * t + 3; ++h)
      if (mesh.twin[h] != no_twin && partition.part[mesh.twin[h] / 3] != s) borders.push_back(h);
  }
}

namespace {

/// A border half-edge with its edge's ends, so that sorting compares stored keys instead of
/// reading triangles and points at every comparison.
struct KeyedBorder {
  Point low, high;  ///< EdgeEnds'
  std::uint32_t h = 0;
  /// By ends alone: the two half-edges of an edge are equal.
  friend bool ends_before(const KeyedBorder& a, const KeyedBorder& b) {
    return a.low != b.low ? lexicographic_less(a.low, b.low) : lexicographic_less(a.high, b.high);
  }
  friend bool operator<(const KeyedBorder& a, const KeyedBorder& b) {
    if (a.low != b.low || a.high != b.high) return ends_before(a, b);
    return a.h < b.h;
  }
};

/// The fewest border half-edges a range task pairs: a range of a few hundred is sorted in
/// microseconds. (At 1,024 a range, Borneo's 2,500 borders at 16 partitions were two tasks, the
/// longest of them 0.08 ms of the CDT's 2.2 ms projected at 16 threads.)
constexpr std::size_t borders_per_range = 128;

/// The sets' border half-edges with their ends as keys, scattered into ranges of their sorted
/// order: cut at keys sampled every k-th border (in set order, so the cuts depend on the
/// partitions only) and compared by ends alone, so the two half-edges of an edge share a range.
/// The ranges, each sorted, one after another are the order one sort of them all gives.
class BorderRanges {
 public:
  BorderRanges(const Mesh& mesh, const std::vector<std::vector<std::uint32_t>>& sets)
      : mesh_(mesh), sets_(sets), offset_(1, 0) {
    for (const auto& borders : sets) offset_.push_back(offset_.back() + borders.size());
  }

  std::size_t total() const { return offset_.back(); }
  std::size_t ranges() const { return cuts_.size() + 1; }
  std::span<KeyedBorder> range(std::size_t r) {
    return std::span(all_).subspan(start_[r], start_[r + 1] - start_[r]);
  }

  void cut(std::size_t ranges) {
    cuts_.clear();
    for (std::size_t k = 1; k < ranges; ++k) {
      const std::size_t i = k * total() / ranges;
      const auto s = static_cast<std::size_t>(std::upper_bound(offset_.begin(), offset_.end(), i) -
                                              offset_.begin() - 1);
      cuts_.push_back(keyed(sets_[s][i - offset_[s]]));
    }
    detail::sort(cuts_.begin(), cuts_.end());
  }

  /// Each set's borders counted per range, then (after the counts are summed into places,
  /// range by range, set by set) scattered by the set's own task.
  void scatter(const RunContext& ctx) {
    const std::size_t sets = sets_.size(), ranges = this->ranges();
    std::vector<std::size_t> place(sets * ranges, 0);
    std::vector<std::uint32_t> range_of_border(total());
    ctx.run_tasks("cdt relink borders: keys", sets, [&](std::size_t s) {
      for (std::size_t i = 0; i < sets_[s].size(); ++i) {
        const std::size_t r = range_of(keyed(sets_[s][i]));
        range_of_border[offset_[s] + i] = static_cast<std::uint32_t>(r);
        ++place[s * ranges + r];
      }
    });
    start_.assign(ranges + 1, total());
    for (std::size_t r = 0, at = 0; r < ranges; ++r) {
      start_[r] = at;
      for (std::size_t s = 0; s < sets; ++s) {
        const std::size_t count = place[s * ranges + r];
        place[s * ranges + r] = at;
        at += count;
      }
    }
    all_.resize(total());
    ctx.run_tasks("cdt relink borders: scatter", sets, [&](std::size_t s) {
      for (std::size_t i = 0; i < sets_[s].size(); ++i)
        all_[place[s * ranges + range_of_border[offset_[s] + i]]++] = keyed(sets_[s][i]);
    });
  }

 private:
  // By position, not caller index: see pair_by_position in mesh.cpp.
  KeyedBorder keyed(std::uint32_t h) const {
    const EdgeEnds ends(mesh_.points[mesh_.origin(h)], mesh_.points[mesh_.destination(h)]);
    return {ends.low, ends.high, h};
  }
  std::size_t range_of(const KeyedBorder& b) const {
    const auto after = std::upper_bound(
        cuts_.begin(), cuts_.end(), b,
        [](const KeyedBorder& x, const KeyedBorder& y) { return ends_before(x, y); });
    return static_cast<std::size_t>(after - cuts_.begin());
  }

  const Mesh& mesh_;
  const std::vector<std::vector<std::uint32_t>>& sets_;
  std::vector<std::size_t> offset_;  ///< set s's borders are [offset_[s], offset_[s + 1])
  std::vector<KeyedBorder> cuts_, all_;
  std::vector<std::size_t> start_;  ///< range r is all_[start_[r], start_[r + 1])
};

}  // namespace

std::vector<std::uint32_t> relink_borders(Mesh& mesh,
                                          const std::vector<std::vector<std::uint32_t>>& sets,
                                          const RunContext& ctx) {
  BorderRanges borders(mesh, sets);
  borders.cut(PEAR_HAS_THREADS ? ctx.tasks_for(borders.total(), borders_per_range) : 1);
  borders.scatter(ctx);
  std::vector<std::vector<std::uint32_t>> firsts(borders.ranges());
  ctx.run_tasks("cdt relink borders: pair", borders.ranges(), [&](std::size_t r) {
    const std::span<KeyedBorder> range = borders.range(r);
    detail::sort(range.begin(), range.end());
    for (std::size_t i = 0; i + 1 < range.size(); i += 2) {
      mesh.twin[range[i].h] = range[i + 1].h;
      mesh.twin[range[i + 1].h] = range[i].h;
      firsts[r].push_back(range[i].h);
    }
  });
  std::vector<std::uint32_t> first_of_pair;
  for (const auto& f : firsts) first_of_pair.insert(first_of_pair.end(), f.begin(), f.end());
  return first_of_pair;
}

namespace {

/// Lawson's loop over the suspects left by a thin round, on this thread; `queued` all clear
/// (zeroing a fresh one here was 1.2-1.4 ms of Eurasia's 10 ms tail at 16 sets), and so left.
std::size_t flip_rest_sequentially(Mesh& mesh, std::vector<std::uint32_t>& suspects,
                                   std::span<std::uint8_t> queued, const RunContext& ctx,
                                   std::size_t budget) {
  std::size_t flips = 0;
  ctx.run_serial("cdt border rounds: Lawson", [&] {
    std::vector<std::uint32_t> stack;
    for (std::uint32_t h : suspects) {
      const std::uint32_t g = mesh.twin[h];
      if (g == no_twin || queued[h] || queued[g]) continue;
      queued[h] = 1;
      stack.push_back(h);
    }
    flips = flip_until_delaunay(mesh, stack, queued, FlipScope{}, budget);
  });
  suspects.clear();
  return flips;
}

}  // namespace

std::size_t flip_borders(Mesh& mesh, std::vector<std::uint32_t> suspects,
                         std::span<std::uint8_t> queued, BorderFlipMarks& kept,
                         const RunContext& ctx, std::size_t budget) {
  RoundMarks marks;
  const std::size_t triangles = mesh.triangles->size(), halves = mesh.twin.size();
  // The tasks below write every entry.
  marks.own = regrow_unfilled(kept.own, triangles);
  marks.touched = regrow_unfilled(kept.touched, triangles);
  marks.listed = regrow_unfilled(kept.listed, halves);
  const std::size_t tasks = std::max<std::size_t>(1, halves >> 16);
  ctx.run_tasks("cdt border rounds: marks", tasks, [&](std::size_t t) {
    const auto clear = [&](std::uint32_t* marks_of, std::size_t n) {
      std::fill(marks_of + part_begin(n, tasks, t), marks_of + part_begin(n, tasks, t + 1), 0u);
    };
    clear(marks.own, triangles);
    clear(marks.touched, triangles);
    clear(marks.listed, halves);
  });
  std::size_t flips = 0;
  while (!suspects.empty()) {
    const std::size_t tested = suspects.size();
    if (tested < min_round_suspects) {
      flips += flip_rest_sequentially(mesh, suspects, queued, ctx, budget - flips);
      break;
    }
    const std::size_t picked = flip_round(mesh, suspects, marks, ctx, budget - flips);
    flips += picked;
    if (picked * thin_round < tested && !suspects.empty())
      flips += flip_rest_sequentially(mesh, suspects, queued, ctx, budget - flips);
  }
  return flips;
}

}  // namespace pear::detail
