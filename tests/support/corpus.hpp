// Helpers for tests that run over ../shared/corpus (when present) and the bundled corpus/:
// listing the files with their MANIFEST validity, reading them, and the validity contract.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "pear/io.hpp"
#include "pear/pear.hpp"
#include "pear/validate.hpp"

namespace pear::testing {

namespace fs = std::filesystem;

struct CorpusFile {
  fs::path path;
  bool valid = true;  ///< the MANIFEST does not call it invalid
  std::string name;
};

inline void PrintTo(const CorpusFile& file, std::ostream* out) {
  *out << file.name;
}

/// Invalid per MANIFEST: GEOS gave a verdict, or the source says NOT SIMPLE.
inline std::map<std::string, bool> manifest_validity(const fs::path& dir) {
  std::map<std::string, bool> valid;
  std::ifstream in(dir / "MANIFEST.tsv");
  std::string line;
  while (std::getline(in, line)) {
    const auto tab = line.find('\t');
    if (tab == std::string::npos) continue;
    valid[line.substr(0, tab)] = line.find("GEOS:") == std::string::npos &&
                                 line.find("NOT SIMPLE") == std::string::npos &&
                                 line.find("DEGENERATE") == std::string::npos;
  }
  return valid;
}

inline std::vector<CorpusFile> list_corpus(const char* env,
                                           std::initializer_list<const char*> folders,
                                           std::size_t every = 1) {
  std::vector<CorpusFile> files;
  const char* root = std::getenv(env);
  if (!root || !fs::is_directory(root)) return files;
  for (const char* folder : folders) {
    const fs::path dir = fs::path(root) / folder;
    if (!fs::is_directory(dir)) continue;
    const auto valid = manifest_validity(dir);
    std::vector<fs::path> paths;
    for (const auto& entry : fs::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      if (name.ends_with(".json") || name.ends_with(".json.gz"))
        if (name != "expected.json") paths.push_back(entry.path());
    }
    std::sort(paths.begin(), paths.end());
    for (std::size_t i = 0; i < paths.size(); i += every) {
      const std::string name = paths[i].filename().string();
      const auto it = valid.find(name);
      files.push_back(
          {paths[i], it == valid.end() || it->second, std::string(folder) + "/" + name});
    }
  }
  return files;
}

inline std::string slurp(const fs::path& path) {
  if (path.extension() == ".gz") {
    std::string command = "gzip -dc '" + path.string() + "'";
    std::string text;
    if (FILE* pipe = popen(command.c_str(), "r")) {
      char buffer[1 << 16];
      std::size_t got;
      while ((got = fread(buffer, 1, sizeof buffer, pipe)) > 0) text.append(buffer, got);
      pclose(pipe);
    }
    return text;
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
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

/// The polygons of a corpus file (GeoJSON, possibly gzipped).
inline std::vector<Polygon> read_corpus_file(const CorpusFile& file) {
  return io::read_text(slurp(file.path), io::Format::geojson, file.path.string(),
                       io::ReadOptions{.keep_small_rings = true});
}

/// A test name made of the file's name.
inline std::string corpus_test_name(const ::testing::TestParamInfo<CorpusFile>& info) {
  std::string name = info.param.name;
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

}  // namespace pear::testing
