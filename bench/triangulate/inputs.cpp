#include "inputs.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "corpus.hpp"
#include "pear/generate.hpp"
#include "pear/io.hpp"

namespace bench {
namespace {

namespace fs = std::filesystem;

std::string size_label(std::size_t n) {
  if (n % 1'000'000 == 0) return std::to_string(n / 1'000'000) + "M";
  return std::to_string(n / 1000) + "k";
}

std::size_t env_size(const char* name, std::size_t fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? std::strtoull(value, nullptr, 10) : fallback;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::istringstream in(text);
  for (std::string part; std::getline(in, part, separator);)
    if (!part.empty()) parts.push_back(part);
  return parts;
}

std::string env_text(const char* name, const char* fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? value : fallback;
}

std::vector<std::size_t> sizes() {
  std::vector<std::size_t> all;
  for (const std::string& size :
       split(env_text("PEAR_BENCH_SIZES", "1000,10000,100000,1000000,4000000"), ','))
    all.push_back(std::strtoull(size.c_str(), nullptr, 10));
  return all;
}

/// Whether the comma-separated list in the environment variable (all when unset) names `name`.
bool listed(const char* variable, std::string_view name) {
  const std::string list = env_text(variable, "");
  if (list.empty()) return true;
  for (const std::string& item : split(list, ','))
    if (item == name) return true;
  return false;
}

/// The synthetic/ files were made by the same families as pear::generate_polygon.
std::string family_of_file(const std::string& stem) {
  return stem.substr(0, stem.find('-'));
}

bool readable(const fs::path& path) {
  if (pear::corpus::readable(path)) return true;
  std::fprintf(stderr, "built without zlib: skipping %s\n", path.c_str());
  return false;
}

constexpr const char* default_real_paths =
    "earcut/rain.json:glyphs/dejavusans_u2741_0.json:countries/united_kingdom_001.json:"
    "countries/antarctica_000.json";

}  // namespace

pear::Polygon load_polygon_file(const fs::path& path) {
  auto polygons = pear::io::read_geojson(pear::corpus::read_text(path), path.string());
  if (polygons.size() != 1) throw std::runtime_error(path.string() + ": expected one polygon");
  return std::move(polygons[0]);
}

std::vector<pear::corpus::File> manifest(const fs::path& dir) {
  return pear::corpus::read_folder(dir.parent_path(), dir.filename().string()).files;
}

pear::Executor* executor_for(unsigned threads) {
  static std::map<unsigned, std::unique_ptr<pear::Executor>> executors;
  if (threads <= 1) return nullptr;
  auto& executor = executors[threads];
  if (!executor) executor = std::make_unique<pear::Executor>(threads);
  return executor.get();
}

fs::path corpus_dir() {
  const char* value = std::getenv("PEAR_BENCH_CORPUS");
  return value != nullptr && *value != '\0' ? fs::path(value) : pear::corpus::shared_root();
}

std::vector<Input> inputs() {
  const std::size_t max_vertices = env_size("PEAR_BENCH_MAX_VERTICES", SIZE_MAX);
  std::vector<Input> all;
  for (std::string_view kind : pear::generator_kinds()) {
    if (!listed("PEAR_BENCH_FAMILIES", kind)) continue;
    for (std::size_t n : sizes()) {
      if (n > max_vertices) continue;
      const std::string k(kind);
      all.push_back(
          {k + "-" + size_label(n), k, n, [k, n] { return pear::generate_polygon(k, n); }});
    }
  }
  const fs::path corpus = corpus_dir();
  if (!fs::exists(corpus)) {
    std::fprintf(stderr, "corpus %s is absent (set PEAR_BENCH_CORPUS): only synthetic inputs\n",
                 corpus.c_str());
    return all;
  }
  const auto add = [&](const std::string& name, const std::string& family, std::size_t vertices,
                       const fs::path& path) {
    if (vertices <= max_vertices)
      all.push_back({name, family, vertices, [path] { return load_polygon_file(path); }});
  };
  for (const pear::corpus::File& file : manifest(corpus / "synthetic")) {
    const std::string stem = file.file.substr(0, file.file.find('.'));
    if (readable(file.path))
      add("synthetic/" + stem, family_of_file(stem), file.vertices, file.path);
  }
  std::vector<std::pair<std::string, std::size_t>> real;
  for (const std::string& relative : split(env_text("PEAR_BENCH_PATHS", default_real_paths), ':')) {
    const fs::path path = corpus / relative;
    std::size_t vertices = 0;
    for (const pear::corpus::File& file : manifest(path.parent_path()))
      if (file.file == path.filename().string()) vertices = file.vertices;
    if (readable(path)) real.push_back({relative, vertices});
  }
  std::stable_sort(real.begin(), real.end(),
                   [](const auto& a, const auto& b) { return a.second < b.second; });
  for (const auto& [relative, vertices] : real) {
    const fs::path path = corpus / relative;
    add("real/" + (path.parent_path().filename() / path.stem()).string(), "real", vertices, path);
  }
  auto coasts = manifest(corpus / "coast");
  std::sort(coasts.begin(), coasts.end(),
            [](const auto& a, const auto& b) { return a.vertices < b.vertices; });
  for (const pear::corpus::File& file : coasts) {
    const std::string name = file.file.substr(0, file.file.find("_gshhg"));
    if (readable(file.path) && listed("PEAR_BENCH_COASTS", name))
      add("coast/" + name, "coast", file.vertices, file.path);
  }
  return all;
}

}  // namespace bench
