// The held-out style sweep of issue 19: every polygon of ../shared/corpus with every algorithm
// at 1 and 2 threads, with and without the CDT (on the coastlines the CDT with `automatic`
// only). Where the MANIFEST calls a polygon valid (and
// for every county whose edges do not cross, as the audit ran them): status ok, the validator's
// approval (Delaunay with the CDT; the count wherever n + 2h - 2 - 2m is exact) and the exact
// area. Anywhere: ok only with a
// valid triangulation. A summary line per file and for the run says what came back.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <string>

#include "gtest_corpus.hpp"
#include "pear/predicates.hpp"

namespace pear {
namespace {

constexpr Algorithm algorithms[] = {Algorithm::automatic, Algorithm::sequential,
                                    Algorithm::partition_and_cut, Algorithm::mark_and_cut,
                                    Algorithm::divide_and_conquer};

struct Tally {
  std::atomic<std::size_t> files{0}, polygons{0}, runs{0}, ok{0}, not_simple{0},
      not_simple_valid{0}, invalid_ok{0};
};
Tally tally;

class SweepSummary : public ::testing::Environment {
 public:
  void TearDown() override {
    if (tally.files == 0) return;
    std::printf(
        "sweep: %zu files, %zu polygons, %zu runs: %zu ok, %zu not_simple (%zu of them on input "
        "the MANIFEST calls valid), %zu ok but invalid\n",
        tally.files.load(), tally.polygons.load(), tally.runs.load(), tally.ok.load(),
        tally.not_simple.load(), tally.not_simple_valid.load(), tally.invalid_ok.load());
  }
};
const auto* const summary = ::testing::AddGlobalTestEnvironment(new SweepSummary);

/// One polygon, every configuration. Returns how many runs were not ok. `valid`: the polygon
/// must come back ok. Without `every_cdt` the CDT runs with `automatic` only: the coastlines'
/// CDT by every algorithm at 1 and 2 threads is cdt-corpus-coast's, checked against CGAL's
/// (here it took 60 of the large suite's seconds again).
std::size_t sweep(const Polygon& polygon, bool valid, bool every_cdt) {
  std::size_t failed = 0;
  for (Algorithm algorithm : algorithms) {
    for (unsigned threads : {1u, 2u}) {
      for (bool delaunay : {false, true}) {
        if (delaunay && !every_cdt && algorithm != Algorithm::automatic) continue;
        SCOPED_TRACE("algorithm " + std::to_string(static_cast<int>(algorithm)) + ", threads " +
                     std::to_string(threads) + (delaunay ? ", CDT" : ""));
        const auto result = triangulate(
            polygon, {.algorithm = algorithm, .delaunay = delaunay, .threads = threads});
        ++tally.runs;
        if (result.status != Status::ok) {
          ++failed;
          if (result.status == Status::not_simple) ++tally.not_simple;
          if (result.status == Status::not_simple && valid) ++tally.not_simple_valid;
          EXPECT_FALSE(valid) << to_string(result.status) << ": "
                              << (result.diagnostics.empty() ? std::string()
                                                             : describe(result.diagnostics.back()));
          continue;
        }
        ++tally.ok;
        const ValidationReport report =
            validate(polygon, result.triangles, ValidateOptions{.check_delaunay = delaunay});
        if (!report.valid) ++tally.invalid_ok;
        EXPECT_TRUE(report.valid) << "ok but invalid: "
                                  << (report.messages.empty() ? "" : report.messages.front());
        EXPECT_EQ(report.area_rel_error, 0);
      }
    }
  }
  return failed;
}

/// Whether two edges of the rings cross properly (each one's ends strictly on both sides of
/// the other, by exact orient2d): no repair can make such a polygon valid. Brute force, for
/// the counties' small rings.
bool crosses_properly(const Polygon& polygon) {
  std::vector<std::pair<Point, Point>> edges;
  for (const Ring& ring : polygon)
    for (std::size_t i = 0; i < ring.size(); ++i)
      edges.emplace_back(ring[i], ring[(i + 1) % ring.size()]);
  const auto opposite = [](double s, double t) { return (s > 0 && t < 0) || (s < 0 && t > 0); };
  for (std::size_t e = 0; e < edges.size(); ++e) {
    for (std::size_t f = e + 1; f < edges.size(); ++f) {
      const auto& [a, b] = edges[e];
      const auto& [c, d] = edges[f];
      if (opposite(orient2d(a, b, c), orient2d(a, b, d)) &&
          opposite(orient2d(c, d, a), orient2d(c, d, b)))
        return true;
    }
  }
  return false;
}

class Sweep : public testing::CorpusTest {};

TEST_P(Sweep, EveryAlgorithmThreadsAndCdt) {
  const corpus::File& file = GetParam();
  // The audit expected every county back ok, whatever GEOS says of it (spikes, rings touching
  // themselves): all of them are, but those whose edges really cross.
  const auto expect_ok = [&](const Polygon& polygon) {
    return file.valid || (file.folder == "counties" && !crosses_properly(polygon));
  };
  std::size_t polygons = 0, failed = 0;
  const std::size_t runs_before = tally.runs;
  for (const Polygon& polygon : testing::read_polygons(file)) {
    ++polygons;
    failed += sweep(polygon, expect_ok(polygon), file.folder != "coast");
  }
  ++tally.files;
  tally.polygons += polygons;
  if (failed > 0)
    std::printf("%s: %zu of %zu runs not ok\n", file.name().c_str(), failed,
                tally.runs - runs_before);
}

PEAR_INSTANTIATE_CORPUS(Shared, Sweep, corpus::shared_root(),
                        {"earcut", "countries", "glyphs", "synthetic", "counties"});
PEAR_INSTANTIATE_CORPUS(SharedCoast, Sweep, corpus::shared_root(), {"coast"});

}  // namespace
}  // namespace pear
