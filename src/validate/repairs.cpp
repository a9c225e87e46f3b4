// The validator's repairs (repairs.hpp). Why cancelling T-junction residues line by line is
// the right test: two chains of segments are equal as point sets with multiplicity (the
// covering argument of validate.cpp needs no more) exactly when, on every line, the signed
// coverage of each point of the line is the same. Residue edges that are collinear and share
// an end form a run; runs on one line share no point, and a run's coverage changes only at its
// own points, so two runs can only cancel each other if each cancels alone.
#include "repairs.hpp"

#include <algorithm>
#include <cstdlib>
#include <numeric>
#include <utility>

#include "geometry/sort.hpp"
#include "pear/predicates.hpp"

namespace pear::detail {
namespace {

// Whether a ring going a -> b -> c turns straight back at b: collinear, and b not strictly
// between a and c. Distinct points on a line differ in x unless the line is vertical.
bool turns_back(const Point& a, const Point& b, const Point& c) {
  if (orient2d(a, b, c) != 0) return false;
  const auto between = [](double p, double q, double r) {
    return (p < q && q < r) || (r < q && q < p);
  };
  return !between(a.x, b.x, c.x) && !between(a.y, b.y, c.y);
}

bool lexicographic_less(const Point& a, const Point& b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

class Runs {
 public:
  explicit Runs(std::size_t count) : parent_(count) {
    std::iota(parent_.begin(), parent_.end(), 0u);
  }
  std::uint32_t find(std::uint32_t r) {
    while (parent_[r] != r) r = parent_[r] = parent_[parent_[r]];
    return r;
  }
  void join(std::uint32_t a, std::uint32_t b) { parent_[find(a)] = find(b); }

 private:
  std::vector<std::uint32_t> parent_;
};

/// Joins the residues meeting at point p that go the same or the opposite way from it: sorted
/// by direction folded into the half-plane [0, 180) degrees, exactly (the fold flips the sign
/// of orient2d when exactly one of the two directions is folded).
void join_collinear_at(std::span<const Point> points, std::span<const Residue> residues,
                       std::uint32_t p, std::vector<std::uint32_t>& meeting, Runs& runs) {
  const Point& at = points[p];
  const auto other = [&](std::uint32_t r) -> const Point& {
    return points[residues[r].lo == p ? residues[r].hi : residues[r].lo];
  };
  const auto upper = [&](const Point& q) { return q.y > at.y || (q.y == at.y && q.x > at.x); };
  const auto turn = [&](std::uint32_t r, std::uint32_t s) {
    const Point &q = other(r), &u = other(s);
    const double side = orient2d(at, q, u);
    return upper(q) == upper(u) ? side : -side;
  };
  detail::sort(meeting.begin(), meeting.end(),
               [&](std::uint32_t r, std::uint32_t s) { return turn(r, s) > 0; });
  for (std::size_t i = 1; i < meeting.size(); ++i)
    if (turn(meeting[i - 1], meeting[i]) == 0) runs.join(meeting[i - 1], meeting[i]);
}

/// One run: its points in order along the line, the coverage between consecutive points.
void check_run(std::span<const Point> points, std::span<const Residue> residues,
               std::span<const std::uint32_t> run, std::vector<std::uint32_t>& line,
               ResidueBalance& balance) {
  line.clear();
  for (std::uint32_t r : run) line.insert(line.end(), {residues[r].lo, residues[r].hi});
  // Distinct canonical indices are distinct points; on a line, x then y orders them along it.
  detail::sort(line.begin(), line.end(), [&](std::uint32_t a, std::uint32_t b) {
    return lexicographic_less(points[a], points[b]);
  });
  line.erase(std::unique(line.begin(), line.end()), line.end());
  const auto place = [&](std::uint32_t p) {
    return static_cast<std::size_t>(std::lower_bound(line.begin(), line.end(), p,
                                                     [&](std::uint32_t a, std::uint32_t b) {
                                                       return lexicographic_less(points[a],
                                                                                 points[b]);
                                                     }) -
                                    line.begin());
  };
  // Per stretch between consecutive points: the signed coverage (must be 0) and how many
  // boundary edges cover it (at most 1: boundary edges that overlap, a slit of zero width or
  // worse, are not made valid by triangles that fill it).
  std::vector<long long> change(line.size() + 1, 0), boundary(line.size() + 1, 0);
  bool conforming = true;
  for (std::uint32_t r : run) {
    const Residue& e = residues[r];
    const std::size_t from = place(e.lo), to = place(e.hi);
    const std::size_t low = std::min(from, to), high = std::max(from, to);
    const long long uses = e.triangle_uses - e.boundary_uses;
    change[low] += from < to ? uses : -uses;
    change[high] -= from < to ? uses : -uses;
    boundary[low] += std::abs(e.boundary_uses);
    boundary[high] -= std::abs(e.boundary_uses);
    if (e.triangle_uses != 0 && high - low != 1) conforming = false;
  }
  long long coverage = 0, boundary_edges = 0;
  for (std::size_t k = 0; k < change.size(); ++k) {
    coverage += change[k];
    boundary_edges += boundary[k];
    if (coverage != 0 || boundary_edges > 1) return;
  }
  if (!conforming) return;
  for (std::uint32_t r : run) {
    balance.cancelled[r] = 1;
    if (residues[r].boundary_uses == 0) continue;
    const std::size_t from = place(residues[r].lo), to = place(residues[r].hi);
    for (std::size_t k = std::min(from, to) + 1; k < std::max(from, to); ++k)
      balance.splits.push_back({r, line[k]});
  }
}

}  // namespace

// Zero-width spikes leave the ring in rounds: every vertex where the ring turns straight back
// (its two edges cancel in the boundary chain) goes at once, then a point that comes to follow
// an equal one goes, until no such vertex is left. Rounds, because the order of two adjacent
// tips could decide whether a point between them stays (pear's cleaning does the same). Only
// the neighbours of what left are looked at again.
void dissolve_tips(std::span<const Point> points, std::vector<std::uint32_t>& kept) {
  const std::size_t k = kept.size();
  std::vector<std::size_t> before(k), after(k), suspects(k), round;
  std::vector<std::uint8_t> gone(k, 0);
  for (std::size_t i = 0; i < k; ++i) {
    before[i] = i == 0 ? k - 1 : i - 1;
    after[i] = i + 1 == k ? 0 : i + 1;
    suspects[i] = i;
  }
  std::size_t left = k;
  const auto at = [&](std::size_t i) -> const Point& { return points[kept[i]]; };
  const auto leave = [&](std::size_t i) {
    gone[i] = 1;
    --left;
    after[before[i]] = after[i];
    before[after[i]] = before[i];
    suspects.push_back(before[i]);
    suspects.push_back(after[i]);
  };
  while (left >= 3 && !suspects.empty()) {
    round.clear();
    for (std::size_t i : suspects)
      if (!gone[i] && turns_back(at(before[i]), at(i), at(after[i]))) round.push_back(i);
    detail::sort(round.begin(), round.end());
    round.erase(std::unique(round.begin(), round.end()), round.end());
    suspects.clear();
    for (std::size_t i : round) leave(i);
    for (std::size_t s = 0; s < suspects.size() && left >= 2; ++s)
      if (const std::size_t i = suspects[s]; !gone[i] && at(after[i]) == at(i)) leave(after[i]);
  }
  std::size_t w = 0;
  for (std::size_t i = 0; i < k; ++i)
    if (!gone[i]) kept[w++] = kept[i];
  kept.resize(w);
}

ResidueBalance balance_residue(std::span<const Point> points, std::span<const Residue> residues) {
  const auto count = static_cast<std::uint32_t>(residues.size());
  ResidueBalance balance;
  balance.cancelled.assign(count, 0);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> ends;  // (point, residue)
  for (std::uint32_t r = 0; r < count; ++r) {
    ends.emplace_back(residues[r].lo, r);
    ends.emplace_back(residues[r].hi, r);
  }
  detail::sort(ends.begin(), ends.end());
  Runs runs(count);
  std::vector<std::uint32_t> scratch;
  for (std::size_t i = 0; i < ends.size();) {
    std::size_t j = i;
    scratch.clear();
    for (; j < ends.size() && ends[j].first == ends[i].first; ++j)
      scratch.push_back(ends[j].second);
    if (scratch.size() > 1) join_collinear_at(points, residues, ends[i].first, scratch, runs);
    i = j;
  }
  std::vector<std::pair<std::uint32_t, std::uint32_t>> by_run;  // (run, residue)
  for (std::uint32_t r = 0; r < count; ++r) by_run.emplace_back(runs.find(r), r);
  detail::sort(by_run.begin(), by_run.end());
  std::vector<std::uint32_t> run, line;
  for (std::size_t i = 0; i < by_run.size();) {
    run.clear();
    std::size_t j = i;
    for (; j < by_run.size() && by_run[j].first == by_run[i].first; ++j)
      run.push_back(by_run[j].second);
    check_run(points, residues, run, line, balance);
    i = j;
  }
  return balance;
}

}  // namespace pear::detail
