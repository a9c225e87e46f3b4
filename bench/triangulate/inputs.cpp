#include "inputs.hpp"

#if PEAR_BENCH_WITH_ZLIB
#include <zlib.h>
#endif

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "pear/generate.hpp"
#include "pear/io.hpp"

namespace bench {
namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& path) {
  std::string text;
  if (path.extension() == ".gz") {
#if PEAR_BENCH_WITH_ZLIB
    gzFile file = gzopen(path.c_str(), "rb");
    if (file == nullptr) throw std::runtime_error("cannot open " + path.string());
    char chunk[1 << 16];
    int n = 0;
    while ((n = gzread(file, chunk, sizeof chunk)) > 0)
      text.append(chunk, static_cast<std::size_t>(n));
    gzclose(file);
    if (n < 0) throw std::runtime_error("cannot decompress " + path.string());
#else
    throw std::runtime_error("built without zlib: cannot read " + path.string());
#endif
  } else {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path.string());
    std::ostringstream buffer;
    buffer << in.rdbuf();
    text = buffer.str();
  }
  return text;
}

pear::Polygon load_corpus_file(const fs::path& path) {
  auto polygons = pear::io::read_geojson(read_text(path), path.string());
  if (polygons.size() != 1) throw std::runtime_error(path.string() + ": expected one polygon");
  return std::move(polygons[0]);
}

std::string size_label(std::size_t n) {
  if (n % 1'000'000 == 0) return std::to_string(n / 1'000'000) + "M";
  return std::to_string(n / 1000) + "k";
}

std::size_t env_size(const char* name, std::size_t fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? std::strtoull(value, nullptr, 10) : fallback;
}

/// The corpus's MANIFEST.tsv: file name and vertex count of each file.
std::vector<std::pair<std::string, std::size_t>> manifest(const fs::path& dir) {
  std::ifstream in(dir / "MANIFEST.tsv");
  std::vector<std::pair<std::string, std::size_t>> files;
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    std::istringstream fields(line);
    std::string file;
    std::string vertices;
    if (std::getline(fields, file, '\t') && std::getline(fields, vertices, '\t'))
      files.push_back({file, std::strtoull(vertices.c_str(), nullptr, 10)});
  }
  return files;
}

fs::path corpus_dir() {
  const char* dir = std::getenv("PEAR_BENCH_CORPUS");
  return dir != nullptr && *dir != '\0' ? fs::path(dir) : fs::path(PEAR_BENCH_DEFAULT_CORPUS);
}

}  // namespace

std::vector<Input> inputs() {
  const std::size_t max_vertices = env_size("PEAR_BENCH_MAX_VERTICES", SIZE_MAX);
  std::vector<std::size_t> sizes = {1000, 10'000, 100'000, 1'000'000};
  if (env_size("PEAR_BENCH_LARGE", 0) != 0) sizes.push_back(4'000'000);
  std::vector<Input> all;
  for (std::string_view kind : pear::generator_kinds()) {
    for (std::size_t n : sizes) {
      if (n > max_vertices) continue;
      const std::string k(kind);
      all.push_back({k + "-" + size_label(n), n, [k, n] { return pear::generate_polygon(k, n); }});
    }
  }
  const fs::path corpus = corpus_dir();
  if (!fs::exists(corpus)) {
    std::fprintf(stderr, "corpus %s is absent (set PEAR_BENCH_CORPUS): only synthetic inputs\n",
                 corpus.c_str());
    return all;
  }
  for (const char* folder : {"synthetic", "coast"}) {
    for (const auto& [file, vertices] : manifest(corpus / folder)) {
      if (vertices > max_vertices) continue;
#if !PEAR_BENCH_WITH_ZLIB
      if (file.ends_with(".gz")) {
        std::fprintf(stderr, "built without zlib: skipping %s\n", file.c_str());
        continue;
      }
#endif
      std::string stem = file.substr(0, file.find('.'));
      if (std::string_view(folder) == "coast") stem = stem.substr(0, stem.find("_gshhg"));
      const fs::path path = corpus / folder / file;
      all.push_back(
          {std::string(folder) + "/" + stem, vertices, [path] { return load_corpus_file(path); }});
    }
  }
  return all;
}

}  // namespace bench
