// The sequential engine on every polygon of ../shared/corpus (when present), the bundled
// corpus/ and the synthetic families: valid polygons must give a valid triangulation with
// status ok; polygons the MANIFEST calls invalid must come back without harm.
#include <gtest/gtest.h>

#include "../support/corpus.hpp"
#include "pear/generate.hpp"

namespace pear {
namespace {

using testing::check_polygon;
using testing::CorpusFile;
using testing::list_corpus;

class Corpus : public ::testing::TestWithParam<CorpusFile> {};

TEST_P(Corpus, TopAndFastAreValid) {
  const CorpusFile& file = GetParam();
  const auto polygons = testing::read_corpus_file(file);
  ASSERT_FALSE(polygons.empty());
  for (const Polygon& polygon : polygons) {
    for (EarHeuristic h : {EarHeuristic::top, EarHeuristic::fast}) {
      SCOPED_TRACE(h == EarHeuristic::top ? "top" : "fast");
      check_polygon(polygon, file.valid, Options{.heuristic = h});
    }
  }
}

constexpr auto test_name = testing::corpus_test_name;

INSTANTIATE_TEST_SUITE_P(Bundled, Corpus,
                         ::testing::ValuesIn(list_corpus("PEAR_CORPUS",
                                                         {"earcut", "countries", "glyphs"})),
                         test_name);
INSTANTIATE_TEST_SUITE_P(Shared, Corpus,
                         ::testing::ValuesIn(list_corpus(
                             "PEAR_SHARED_CORPUS", {"earcut", "countries", "glyphs", "synthetic"})),
                         test_name);
INSTANTIATE_TEST_SUITE_P(SharedCoast, Corpus,
                         ::testing::ValuesIn(list_corpus("PEAR_SHARED_CORPUS", {"coast"})),
                         test_name);
INSTANTIATE_TEST_SUITE_P(SharedCounties, Corpus,
                         ::testing::ValuesIn(list_corpus("PEAR_SHARED_CORPUS", {"counties"})),
                         test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(Corpus);

struct Family {
  std::string kind;
  std::size_t vertices;
};

void PrintTo(const Family& family, std::ostream* out) {
  *out << family.kind << " " << family.vertices;
}

class Synthetic : public ::testing::TestWithParam<Family> {};

TEST_P(Synthetic, TopAndFastAreValid) {
  const Polygon polygon = generate_polygon(GetParam().kind, GetParam().vertices, 7);
  for (EarHeuristic h : {EarHeuristic::top, EarHeuristic::fast})
    check_polygon(polygon, true, Options{.heuristic = h});
}

std::vector<Family> families() {
  std::vector<Family> out;
  for (std::string_view kind : generator_kinds())
    for (std::size_t n : {1000, 20000}) out.push_back({std::string(kind), n});
  if (std::getenv("PEAR_LARGE_TESTS"))
    for (std::string_view kind : generator_kinds()) out.push_back({std::string(kind), 4000000});
  return out;
}

INSTANTIATE_TEST_SUITE_P(Families, Synthetic, ::testing::ValuesIn(families()),
                         [](const auto& info) {
                           std::string name =
                               info.param.kind + "_" + std::to_string(info.param.vertices);
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace pear
