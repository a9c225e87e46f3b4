// GoogleTest over the corpora (corpus.hpp): one parameter per file, a fixture that skips a file
// whose data is missing, the polygons of a file, and the validity contract the engines share.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "corpus.hpp"
#include "missing_data.hpp"
#include "pear/io.hpp"
#include "pear/pear.hpp"
#include "pear/validate.hpp"

namespace pear::testing {

/// Every `every`-th file of the folders under `root`. A folder that cannot be read gives one
/// stand-in file that says why, so that its tests skip (and are counted) instead of vanishing.
inline std::vector<corpus::File> corpus_cases(const corpus::fs::path& root,
                                              std::initializer_list<const char*> folders,
                                              std::size_t every = 1) {
  std::vector<corpus::File> files;
  for (const char* name : folders) {
    corpus::Folder folder = corpus::read_folder(root, name);
    if (!folder.missing.empty()) {
      corpus::File& stand_in = files.emplace_back();
      stand_in.folder = folder.name;
      stand_in.file = "missing";
      stand_in.missing = folder.missing;
    }
    for (std::size_t i = 0; i < folder.files.size(); i += every)
      files.push_back(std::move(folder.files[i]));
  }
  return files;
}

/// A test over one corpus file; skipped when the file's data is missing.
class CorpusTest : public ::testing::TestWithParam<corpus::File> {
 protected:
  void SetUp() override { PEAR_SKIP_IF_MISSING(GetParam()); }
};

/// A test name made of the file's folder and name.
inline std::string corpus_test_name(const ::testing::TestParamInfo<corpus::File>& info) {
  std::string name = info.param.name();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

/// Instantiates the CorpusTest `suite` with `prefix` over corpus_cases(root, folders[, every]).
#define PEAR_INSTANTIATE_CORPUS(prefix, suite, ...)                                         \
  INSTANTIATE_TEST_SUITE_P(prefix, suite,                                                   \
                           ::testing::ValuesIn(::pear::testing::corpus_cases(__VA_ARGS__)), \
                           ::pear::testing::corpus_test_name)

/// The polygons of a corpus file (GeoJSON, possibly gzipped), small rings kept.
inline std::vector<Polygon> read_polygons(const corpus::File& file) {
  return io::read_text(corpus::read_text(file.path), io::Format::geojson, file.path.string(),
                       io::ReadOptions{.keep_small_rings = true});
}

/// Triangulates with `options`: valid input must give status ok and a valid triangulation with
/// n + 2h - 2 triangles and exact area; invalid input may give any status, but ok only with a
/// valid triangulation. Returns the triangles.
inline std::vector<std::array<std::uint32_t, 3>> check_polygon(const Polygon& polygon,
                                                               bool expect_valid,
                                                               const Options& options) {
  auto result = triangulate(polygon, options);
  if (expect_valid) {
    EXPECT_NE(result.status, Status::invalid_input)
        << (result.diagnostics.empty() ? "" : describe(result.diagnostics[0]));
  }
  std::size_t n = 0;
  for (const Ring& ring : polygon) n += ring.size();
  for (const auto& t : result.triangles)
    for (auto i : t) EXPECT_LT(i, n);
  if (!expect_valid) {
    // Invalid input may give any status but ok with a wrong triangulation: never silently wrong.
    if (result.status == Status::ok) {
      const ValidationReport report = validate(polygon, result.triangles);
      EXPECT_TRUE(report.valid) << "status ok on invalid input, but: "
                                << (report.messages.empty() ? "" : report.messages.front());
    }
    return std::move(result.triangles);
  }
  EXPECT_EQ(result.status, Status::ok)
      << (result.diagnostics.empty() ? "" : describe(result.diagnostics.back()));
  const ValidationReport report = validate(polygon, result.triangles);
  EXPECT_TRUE(report.valid) << (report.messages.empty() ? "" : report.messages.front());
  EXPECT_EQ(report.triangles, report.expected_triangles);
  EXPECT_LE(report.area_rel_error, 1e-9);
  return std::move(result.triangles);
}

}  // namespace pear::testing
