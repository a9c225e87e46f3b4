// The benchmark's inputs: synthetic families at several sizes and the shared corpus's files.
#pragma once

#include <cstddef>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "corpus.hpp"
#include "pear/geometry.hpp"
#include "pear/scheduler.hpp"

namespace bench {

struct Input {
  std::string name;      ///< "koch-100k", "coast/eurasia", "real/countries/russia_000", ...
  std::string family;    ///< "koch", "coast", ...: sizes of one family grow alike (too_slow)
  std::size_t vertices;  ///< about how many, to choose before loading
  std::function<pear::Polygon()> load;
};

/// In this order: the generator families (PEAR_BENCH_FAMILIES, comma-separated, default all)
/// at PEAR_BENCH_SIZES (default 1000,10000,100000,1000000,4000000); the corpus's synthetic/
/// files; the real polygons of PEAR_BENCH_PATHS (colon-separated, relative to the corpus,
/// default the largest of earcut/, glyphs/, countries/), small to large; the coast/ files
/// (PEAR_BENCH_COASTS, comma-separated names such as "eurasia", default all), small to large.
/// The corpus is PEAR_BENCH_CORPUS, else the shared corpus (tests/support/corpus.hpp); inputs above
/// PEAR_BENCH_MAX_VERTICES are left out. Messages about what is left out go to stderr.
std::vector<Input> inputs();

/// One executor per thread count, made once for the program: a user running many
/// triangulations would share one too, so thread start-up is not part of any time. threads <= 1
/// needs none (nullptr).
pear::Executor* executor_for(unsigned threads);

/// The corpus directory (PEAR_BENCH_CORPUS, else pear::corpus::shared_root()).
std::filesystem::path corpus_dir();
/// One polygon from a GeoJSON file (.json, or .json.gz when built with zlib).
pear::Polygon load_polygon_file(const std::filesystem::path& path);
/// The corpus folder's MANIFEST.tsv rows (none when it cannot be read).
std::vector<pear::corpus::File> manifest(const std::filesystem::path& dir);

}  // namespace bench
