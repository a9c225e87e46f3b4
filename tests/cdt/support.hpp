// Helpers for the CDT tests: run pear with Options::delaunay under any algorithm, thread count
// and partition count; check the CDT property with the validator; where the build has the CGAL
// oracle (tests/support/cgal_cdt.hpp, PEAR_WITH_CGAL_ORACLE), compare with CGAL's CDT.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "pear/config.hpp"
#include "pear/pear.hpp"
#include "pear/predicates.hpp"
#if PEAR_HAS_THREADS
#include "pear/scheduler.hpp"
#endif
#include "pear/validate.hpp"
#ifdef PEAR_WITH_CGAL_ORACLE
#include "cgal_cdt.hpp"
#endif

namespace pear::testing {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

inline constexpr Algorithm all_algorithms[] = {Algorithm::sequential, Algorithm::partition_and_cut,
                                               Algorithm::mark_and_cut,
                                               Algorithm::divide_and_conquer};

inline const char* algorithm_name(Algorithm a) {
  switch (a) {
    case Algorithm::sequential:
      return "sequential";
    case Algorithm::partition_and_cut:
      return "partition_and_cut";
    case Algorithm::mark_and_cut:
      return "mark_and_cut";
    case Algorithm::divide_and_conquer:
      return "divide_and_conquer";
    default:
      return "automatic";
  }
}

/// One executor per thread count for the whole test program (threads 1, or a build without
/// threads: none).
inline Executor* executor_for([[maybe_unused]] unsigned threads) {
#if PEAR_HAS_THREADS
  static std::map<unsigned, std::unique_ptr<Executor>> executors;
  if (threads <= 1) return nullptr;
  auto& executor = executors[threads];
  if (!executor) executor = std::make_unique<Executor>(threads);
  return executor.get();
#else
  return nullptr;
#endif
}

inline Triangulation<> constrained_delaunay(const Polygon& polygon, Algorithm algorithm,
                                            unsigned threads, unsigned partitions,
                                            RunProfile* profile = nullptr) {
  Options options{.algorithm = algorithm, .delaunay = true};
  options.threads = threads;
  options.partitions = partitions;
  options.executor = executor_for(threads);
  options.profile = profile;
  return triangulate(polygon, options);
}

/// The tasks the profile recorded for phase `name`; none when it has no such phase.
inline std::size_t tasks_of(const RunProfile& profile, std::string_view name) {
  for (const auto& phase : profile.phases)
    if (phase.name == name) return phase.task_seconds.size();
  return 0;
}

/// Valid triangulation with n + 2h - 2 - 2m triangles, exact area, every edge locally Delaunay.
inline void expect_delaunay(const Polygon& polygon, const Triangles& triangles) {
  const ValidationReport report =
      validate(polygon, triangles, ValidateOptions{.check_delaunay = true});
  EXPECT_TRUE(report.valid) << (report.messages.empty() ? std::string() : report.messages[0])
                            << " (" << report.non_delaunay_edges << " edges not Delaunay)";
  EXPECT_EQ(report.zero_area_triangles, 0u);
  EXPECT_EQ(report.area_rel_error, 0.0);
}

#ifdef PEAR_WITH_CGAL_ORACLE

/// The first index of every point's position: touching rings repeat a point under two indices,
/// and CGAL keeps only one vertex there.
inline std::vector<std::uint32_t> canonical_indices(const Polygon& polygon) {
  std::map<std::pair<double, double>, std::uint32_t> first;
  std::vector<std::uint32_t> canonical;
  for (const Ring& ring : polygon)
    for (const Point& p : ring) {
      const auto [it, added] =
          first.emplace(std::pair{p.x, p.y}, static_cast<std::uint32_t>(canonical.size()));
      canonical.push_back(it->second);
    }
  return canonical;
}

/// Triangles by canonical index, each rotated to start at its smallest corner, sorted.
inline Triangles canonical_triangles(const Triangles& triangles,
                                     const std::vector<std::uint32_t>& canonical) {
  Triangles out;
  out.reserve(triangles.size());
  for (const auto& t : triangles) {
    std::array<std::uint32_t, 3> c = {canonical[t[0]], canonical[t[1]], canonical[t[2]]};
    std::rotate(c.begin(), std::min_element(c.begin(), c.end()), c.end());
    out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// CGAL's exact CDT restricted to the polygon, canonical and sorted.
struct CgalReference {
  std::vector<std::uint32_t> canonical;
  std::vector<Point> points;
  Triangles triangles;
  explicit CgalReference(const Polygon& polygon) : canonical(canonical_indices(polygon)) {
    for (const Ring& ring : polygon) points.insert(points.end(), ring.begin(), ring.end());
    CgalCdt cgal(polygon);
    cgal.triangulate();
    triangles = canonical_triangles(cgal.triangles(), canonical);
  }
};

/// True when some edge of `t` is shared with another of `sorted` whose apex lies exactly on t's
/// circumcircle: the only place where two CDTs of one polygon may differ.
inline bool has_cocircular_neighbour(const std::array<std::uint32_t, 3>& t, const Triangles& sorted,
                                     const std::vector<Point>& points) {
  for (const auto& other : sorted)
    for (int k = 0; k < 3; ++k)
      for (int m = 0; m < 3; ++m)
        if (other[m] == t[(k + 1) % 3] && other[(m + 1) % 3] == t[k] &&
            incircle(points[t[0]], points[t[1]], points[t[2]], points[other[(m + 2) % 3]]) == 0)
          return true;
  return false;
}

/// The same triangles as CGAL, except where four or more points are cocircular; there the counts
/// must agree and each of our differing triangles must have a cocircular neighbour (and
/// expect_delaunay must hold, checked separately).
inline void expect_equal_to_cgal(const CgalReference& cgal, const Triangles& ours) {
  const Triangles mine = canonical_triangles(ours, cgal.canonical);
  ASSERT_EQ(mine.size(), cgal.triangles.size()) << "pear and CGAL differ in the triangle count";
  if (mine == cgal.triangles) return;
  std::size_t differing = 0, unexplained = 0;
  for (const auto& t : mine) {
    if (std::binary_search(cgal.triangles.begin(), cgal.triangles.end(), t)) continue;
    ++differing;
    // The neighbour search is quadratic: only a few differing triangles are looked at.
    if (differing <= 50 && !has_cocircular_neighbour(t, mine, cgal.points)) ++unexplained;
  }
  EXPECT_EQ(unexplained, 0u) << "of " << differing
                             << " triangles not in CGAL's CDT, some have no cocircular neighbour";
}

#endif  // PEAR_WITH_CGAL_ORACLE

/// Checks CDTs of one polygon that came with status ok: the validator's Delaunay check, and with
/// the CGAL oracle the same triangles as CGAL's CDT (computed once, on the first check).
class CdtCheck {
 public:
  explicit CdtCheck(const Polygon& polygon) : polygon_(polygon) {}
  void operator()(const Triangles& triangles) {
    expect_delaunay(polygon_, triangles);
#ifdef PEAR_WITH_CGAL_ORACLE
    if (!cgal_) cgal_ = std::make_unique<CgalReference>(polygon_);
    expect_equal_to_cgal(*cgal_, triangles);
#endif
  }

 private:
  const Polygon& polygon_;
#ifdef PEAR_WITH_CGAL_ORACLE
  std::unique_ptr<CgalReference> cgal_;
#endif
};

}  // namespace pear::testing
