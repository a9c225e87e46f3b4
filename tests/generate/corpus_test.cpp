// The deterministic families against the shared corpus's synthetic inputs (made by another
// program), and the random star's distribution against the corpus's star.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "corpus.hpp"
#include "missing_data.hpp"
#include "pear/generate.hpp"
#include "simple_polygon.hpp"

namespace {

using pear::Polygon;

/// Reads the corpus's one-line GeoJSON Polygon: the arrays three deep are points. Drops each
/// ring's closing point.
Polygon read_corpus_polygon(const pear::corpus::fs::path& path) {
  const std::string text = pear::corpus::read_text(path);
  Polygon polygon;
  int depth = 0;
  for (std::size_t i = text.find("\"coordinates\""); i < text.size(); ++i) {
    const char c = text[i];
    if (c == '[') {
      ++depth;
      if (depth == 2) polygon.emplace_back();
      if (depth == 3) {
        char* end = nullptr;
        const double x = std::strtod(text.c_str() + i + 1, &end);
        const double y = std::strtod(end + 1, &end);  // skips the comma
        polygon.back().push_back({x, y});
        i = static_cast<std::size_t>(end - text.c_str()) - 1;
      }
    } else if (c == ']') {
      if (--depth == 0) break;
    }
  }
  for (auto& ring : polygon)
    if (ring.size() > 1 && ring.front() == ring.back()) ring.pop_back();
  return polygon;
}

class CorpusSynthetic : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto folder = pear::corpus::read_folder(pear::corpus::shared_root(), "synthetic");
    PEAR_SKIP_IF_MISSING(folder);
    synthetic_ = folder.dir;
  }
  Polygon corpus(const char* file) const { return read_corpus_polygon(synthetic_ / file); }

  pear::corpus::fs::path synthetic_;
};

/// Same rings, same vertex order, coordinates within `tolerance`.
void expect_same(const Polygon& ours, const Polygon& theirs, double tolerance) {
  ASSERT_EQ(ours.size(), theirs.size());
  for (std::size_t r = 0; r < ours.size(); ++r) {
    ASSERT_EQ(ours[r].size(), theirs[r].size()) << "ring " << r;
    for (std::size_t i = 0; i < ours[r].size(); ++i) {
      ASSERT_NEAR(ours[r][i].x, theirs[r][i].x, tolerance) << "ring " << r << " vertex " << i;
      ASSERT_NEAR(ours[r][i].y, theirs[r][i].y, tolerance) << "ring " << r << " vertex " << i;
    }
  }
}

TEST_F(CorpusSynthetic, CombMatchesExactly) {
  expect_same(pear::generate_polygon("comb", 100'000), corpus("comb-100000.json"), 0);
}

TEST_F(CorpusSynthetic, HolesMatchExactly) {
  expect_same(pear::generate_polygon("holes", 40'004), corpus("holes-100x100.json"), 0);
}

TEST_F(CorpusSynthetic, KochMatches) {
  expect_same(pear::generate_polygon("koch", 196'608), corpus("koch-8.json"), 1e-13);
}

TEST_F(CorpusSynthetic, SpiralMatches) {
  expect_same(pear::generate_polygon("spiral", 100'000), corpus("spiral-100000.json"), 1e-11);
}

TEST_F(CorpusSynthetic, StarHasTheSameDistribution) {
  // Different random numbers, same law: radii uniform in [0.5, 1] at sorted angles. The area
  // is a sum of 100,000 small independent terms, so both are within 1% of each other.
  const Polygon ours = pear::generate_polygon("star", 100'000, 11);
  const Polygon theirs = corpus("star-100000.json");
  ASSERT_EQ(ours[0].size(), theirs[0].size());
  auto mean_radius = [](const Polygon& p) {
    double sum = 0;
    for (const auto& v : p[0]) sum += std::hypot(v.x, v.y);
    return sum / static_cast<double>(p[0].size());
  };
  EXPECT_NEAR(mean_radius(ours), mean_radius(theirs), 0.005);
  EXPECT_NEAR(mean_radius(ours), 0.75, 0.005);
  const long double ours_area = pear::testing::twice_signed_area(ours[0]) / 2;
  const long double theirs_area = pear::testing::twice_signed_area(theirs[0]) / 2;
  EXPECT_NEAR(static_cast<double>(ours_area / theirs_area), 1.0, 0.01);
  EXPECT_EQ(pear::testing::simplicity_problem(theirs), "") << "the checker on the corpus star";
}

TEST_F(CorpusSynthetic, CheckerAcceptsEveryCorpusFile) {
  for (const char* file : {"comb-100000.json", "holes-100x100.json", "koch-8.json",
                           "spiral-100000.json", "star-100000.json"})
    EXPECT_EQ(pear::testing::simplicity_problem(corpus(file)), "") << file;
}

}  // namespace
