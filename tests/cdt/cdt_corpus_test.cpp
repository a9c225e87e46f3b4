// The CDT on every polygon of ../shared/corpus: every algorithm at 1, 2 and 4 threads and 1 to
// 8 partitions must pass the validator's Delaunay check and equal CGAL's CDT (up to cocircular
// ties). The coastlines (up to 1.5M vertices) run a smaller matrix in the 'large' suite.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "pear/io.hpp"
#include "support.hpp"

namespace pear::testing {
namespace {

namespace fs = std::filesystem;

struct CorpusFile {
  fs::path path;
  std::string name;  ///< folder/file
  bool valid = true;
};

void PrintTo(const CorpusFile& file, std::ostream* out) {
  *out << file.name;
}

/// Files the folder's MANIFEST.tsv does not call invalid (a GEOS verdict, NOT SIMPLE or
/// DEGENERATE in the line) are valid.
std::vector<CorpusFile> corpus_files(std::initializer_list<const char*> folders) {
  std::vector<CorpusFile> files;
  const char* root = std::getenv("PEAR_SHARED_CORPUS");
  if (root == nullptr) return files;
  for (const char* folder : folders) {
    std::ifstream manifest(fs::path(root) / folder / "MANIFEST.tsv");
    std::string line;
    std::getline(manifest, line);  // the header
    while (std::getline(manifest, line)) {
      const std::string name = line.substr(0, line.find('\t'));
      const bool valid = line.find("GEOS:") == std::string::npos &&
                         line.find("NOT SIMPLE") == std::string::npos &&
                         line.find("DEGENERATE") == std::string::npos;
      files.push_back({fs::path(root) / folder / name, std::string(folder) + "/" + name, valid});
    }
  }
  return files;
}

std::string read_all(const fs::path& path) {
  std::string text;
  const bool gzip = path.extension() == ".gz";
  FILE* in = gzip ? popen(("gzip -dc '" + path.string() + "'").c_str(), "r")
                  : std::fopen(path.c_str(), "rb");
  if (in == nullptr) return text;
  char buffer[1 << 16];
  for (std::size_t got; (got = std::fread(buffer, 1, sizeof buffer, in)) > 0;)
    text.append(buffer, got);
  gzip ? pclose(in) : std::fclose(in);
  return text;
}

struct Run {
  unsigned threads, partitions;
};

std::vector<Run> runs_for(std::size_t vertices) {
  std::vector<Run> runs;
  if (vertices > 300'000) return {{1, 1}, {2, 2}, {4, 4}, {2, 8}, {1, 3}};
  for (unsigned threads : {1u, 2u, 4u})
    for (unsigned partitions = 1; partitions <= 8; ++partitions)
      runs.push_back({threads, partitions});
  return runs;
}

void check_polygon(const Polygon& polygon, const CorpusFile& file) {
  std::size_t vertices = 0;
  for (const Ring& ring : polygon) vertices += ring.size();
  std::unique_ptr<CgalReference> cgal;
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
      expect_delaunay(polygon, result.triangles);
      if (!cgal) cgal = std::make_unique<CgalReference>(polygon);
      expect_equal_to_cgal(*cgal, result.triangles);
      if (::testing::Test::HasFailure()) return;  // one failing combination says enough
    }
}

class Corpus : public ::testing::TestWithParam<CorpusFile> {};

TEST_P(Corpus, DelaunayAndEqualToCgal) {
  const CorpusFile& file = GetParam();
  const auto polygons = io::read_text(read_all(file.path), io::Format::geojson, file.name,
                                      io::ReadOptions{.keep_small_rings = true});
  ASSERT_FALSE(polygons.empty());
  for (const Polygon& polygon : polygons) check_polygon(polygon, file);
}

// Regression: at touching rings the two triangles of a diagonal used different caller indices of
// one point; matched by index only, the diagonal counted as a constraint (not Delaunay), and
// the partitioned flips' relinking paired wrong border edges (overlapping triangles).
TEST(CorpusRegression, DiagonalAtTouchingRingsHasTwoIndices) {
  for (const CorpusFile& file : corpus_files({"earcut"})) {
    if (!file.name.ends_with("rain.json") && !file.name.ends_with("hole-touching-outer.json") &&
        !file.name.ends_with("issue119.json") && !file.name.ends_with("self-tangent-4.json"))
      continue;
    SCOPED_TRACE(file.name);
    for (const Polygon& polygon : io::read_text(read_all(file.path), io::Format::geojson, file.name,
                                                {.keep_small_rings = true}))
      for (unsigned partitions : {1u, 2u}) {
        const auto result = constrained_delaunay(polygon, Algorithm::sequential, 1, partitions);
        ASSERT_EQ(result.status, Status::ok);
        expect_delaunay(polygon, result.triangles);
      }
  }
}

std::string test_name(const ::testing::TestParamInfo<CorpusFile>& info) {
  std::string name = info.param.name;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

// One instantiation per folder: meson runs them as separate tests (time limits, sanitizers).
INSTANTIATE_TEST_SUITE_P(SharedEarcut, Corpus, ::testing::ValuesIn(corpus_files({"earcut"})),
                         test_name);
INSTANTIATE_TEST_SUITE_P(SharedCountries, Corpus, ::testing::ValuesIn(corpus_files({"countries"})),
                         test_name);
INSTANTIATE_TEST_SUITE_P(SharedGlyphs, Corpus, ::testing::ValuesIn(corpus_files({"glyphs"})),
                         test_name);
INSTANTIATE_TEST_SUITE_P(SharedSynthetic, Corpus, ::testing::ValuesIn(corpus_files({"synthetic"})),
                         test_name);
INSTANTIATE_TEST_SUITE_P(SharedCoast, Corpus, ::testing::ValuesIn(corpus_files({"coast"})),
                         test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(Corpus);

}  // namespace
}  // namespace pear::testing
