// The CDT on every polygon of ../shared/corpus: every algorithm at 1, 2 and 4 threads and 1 to
// 8 partitions must pass the validator's Delaunay check and (with the CGAL oracle) equal CGAL's
// CDT up to cocircular ties. Polygons over 50,000 vertices (the synthetic files and the
// coastlines, up to 1.5M, in the 'large' suite) run a smaller matrix: threads and partitions
// of every kind, not every pair (the full matrix is the countries' and the glyphs'); Eurasia's
// 1.5M the sequential CDT and 2 threads on 8 partitions (20 runs of it took 110 s of CI).
#include <gtest/gtest.h>

#include "gtest_corpus.hpp"
#include "sizes.hpp"
#include "support.hpp"

namespace pear::testing {
namespace {

struct Run {
  unsigned threads, partitions;
};

std::vector<Run> runs_for(std::size_t vertices) {
  std::vector<Run> runs;
  if (vertices > huge_vertices) return {{1, 1}, {2, 8}};
  if (vertices > 50'000) return {{1, 1}, {2, 2}, {4, 4}, {2, 8}, {1, 3}};
  for (unsigned threads : {1u, 2u, 4u})
    for (unsigned partitions = 1; partitions <= 8; ++partitions)
      runs.push_back({threads, partitions});
  return runs;
}

void check_polygon(const Polygon& polygon, const corpus::File& file) {
  const std::size_t vertices = vertex_count(polygon);
  CdtCheck expect_cdt(polygon);
  for (Algorithm algorithm : all_algorithms)
    for (const Run run : runs_for(vertices)) {
      SCOPED_TRACE(std::string(algorithm_name(algorithm)) + " threads " +
                   std::to_string(run.threads) + " partitions " + std::to_string(run.partitions));
      const auto result = constrained_delaunay(polygon, algorithm, run.threads, run.partitions);
      if (!file.valid) {
        if (result.status == Status::ok) expect_delaunay(polygon, result.triangles);
        continue;
      }
      ASSERT_EQ(result.status, Status::ok);
      expect_cdt(result.triangles);
      if (::testing::Test::HasFailure()) return;  // one failing combination says enough
    }
}

class Corpus : public CorpusTest {};

TEST_P(Corpus, IsTheConstrainedDelaunayTriangulation) {
  const corpus::File& file = GetParam();
  const auto polygons = read_polygons(file);
  ASSERT_FALSE(polygons.empty());
  for (const Polygon& polygon : polygons) check_polygon(polygon, file);
}

// Regression: at touching rings the two triangles of a diagonal used different caller indices of
// one point; matched by index only, the diagonal counted as a constraint (not Delaunay), and
// the partitioned flips' relinking paired wrong border edges (overlapping triangles).
TEST(CorpusRegression, DiagonalAtTouchingRingsHasTwoIndices) {
  const corpus::Folder earcut = corpus::read_folder(corpus::shared_root(), "earcut");
  PEAR_SKIP_IF_MISSING(earcut);
  for (const corpus::File& file : earcut.files) {
    if (file.file != "rain.json" && file.file != "hole-touching-outer.json" &&
        file.file != "issue119.json" && file.file != "self-tangent-4.json")
      continue;
    SCOPED_TRACE(file.name());
    for (const Polygon& polygon : read_polygons(file))
      for (unsigned partitions : {1u, 2u}) {
        const auto result = constrained_delaunay(polygon, Algorithm::sequential, 1, partitions);
        ASSERT_EQ(result.status, Status::ok);
        expect_delaunay(polygon, result.triangles);
      }
  }
}

// One instantiation per folder: meson runs them as separate tests (time limits, sanitizers).
PEAR_INSTANTIATE_CORPUS(SharedEarcut, Corpus, corpus::shared_root(), {"earcut"});
PEAR_INSTANTIATE_CORPUS(SharedCountries, Corpus, corpus::shared_root(), {"countries"});
PEAR_INSTANTIATE_CORPUS(SharedGlyphs, Corpus, corpus::shared_root(), {"glyphs"});
PEAR_INSTANTIATE_CORPUS(SharedSynthetic, Corpus, corpus::shared_root(), {"synthetic"});
PEAR_INSTANTIATE_CORPUS(SharedCoast, Corpus, corpus::shared_root(), {"coast"});

}  // namespace
}  // namespace pear::testing
