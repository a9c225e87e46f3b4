// bench_small: many small polygons (issue 16). Per folder of the shared corpus (counties,
// glyphs, countries): pear one call per polygon (a reused Triangulator with the default options;
// with `fast` and no check; the free function pear::triangulate), pear::triangulate_batch at 1
// and 2 threads, and CGAL's CDT in the same binary as a stable yardstick. The ear clipper's
// crossover of its two strategies is bench_strategies (bench_strategies.cpp).
//
//   bench_small [--benchmark_filter=...]      PEAR_BENCH_CORPUS: the corpus (default ../shared)
//
// Counters: polygons_per_s (and vertices_per_s); quote ratios of benchmarks of one run.
#include <benchmark/benchmark.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "corpus.hpp"
#include "pear/generate.hpp"
#include "pear/io.hpp"
#include "pear/pear.hpp"
#ifdef PEAR_WITH_CGAL_ORACLE
#include "cgal_cdt.hpp"
#endif

namespace {

namespace fs = std::filesystem;

struct Folder {
  std::string name;
  std::vector<pear::Polygon> polygons;
  std::size_t vertices = 0;
  // The same polygons as one batch.
  std::vector<double> coordinates;
  std::vector<std::int64_t> ring_offsets{0}, polygon_offsets{0};
};

Folder load_folder(const std::string& name) {
  Folder folder{name, {}, 0, {}, {}, {}};
  const fs::path root = [] {
    const char* dir = std::getenv("PEAR_BENCH_CORPUS");
    return dir && *dir ? fs::path(dir) : pear::corpus::shared_root();
  }();
  const pear::corpus::Folder manifest = pear::corpus::read_folder(root, name);
  for (const pear::corpus::File& file : manifest.files) {
    if (!file.missing.empty()) continue;
    for (pear::Polygon& polygon :
         pear::io::read_geojson(pear::corpus::read_text(file.path), file.name())) {
      for (const pear::Ring& ring : polygon) {
        for (const pear::Point& p : ring)
          folder.coordinates.insert(folder.coordinates.end(), {p.x, p.y});
        folder.ring_offsets.push_back(static_cast<std::int64_t>(folder.coordinates.size() / 2));
        folder.vertices += ring.size();
      }
      folder.polygon_offsets.push_back(static_cast<std::int64_t>(folder.ring_offsets.size() - 1));
      folder.polygons.push_back(std::move(polygon));
    }
  }
  return folder;
}

void set_rates(benchmark::State& state, const Folder& folder) {
  const auto runs = static_cast<double>(state.iterations());
  state.counters["polygons_per_s"] = benchmark::Counter(
      runs * static_cast<double>(folder.polygons.size()), benchmark::Counter::kIsRate);
  state.counters["vertices_per_s"] =
      benchmark::Counter(runs * static_cast<double>(folder.vertices), benchmark::Counter::kIsRate);
}

void per_polygon(benchmark::State& state, const Folder* folder, pear::Options options) {
  pear::Triangulator triangulator;
  for (auto _ : state)
    for (const pear::Polygon& polygon : folder->polygons)
      benchmark::DoNotOptimize(triangulator.triangulate(polygon, options).triangles.data());
  set_rates(state, *folder);
}

void free_function(benchmark::State& state, const Folder* folder) {
  for (auto _ : state)
    for (const pear::Polygon& polygon : folder->polygons)
      benchmark::DoNotOptimize(pear::triangulate(polygon).triangles.data());
  set_rates(state, *folder);
}

void batch(benchmark::State& state, const Folder* folder, unsigned threads) {
  pear::Options options;
  options.threads = threads;
  const pear::PolygonBatch view{folder->coordinates, folder->ring_offsets, folder->polygon_offsets};
  for (auto _ : state) benchmark::DoNotOptimize(pear::triangulate_batch(view, options).size());
  set_rates(state, *folder);
}

#ifdef PEAR_WITH_CGAL_ORACLE
/// CGAL's CDT over the polygons it accepts (it refuses those whose rings cross); the rates
/// count only those, and `polygons` says how many they are.
void cgal(benchmark::State& state, const Folder* folder) {
  std::vector<pear::testing::CgalCdt> prepared;
  Folder accepted;
  for (const pear::Polygon& polygon : folder->polygons) {
    pear::testing::CgalCdt cdt(polygon);
    try {
      cdt.triangulate();
    } catch (const std::exception&) {
      continue;
    }
    prepared.push_back(std::move(cdt));
    accepted.polygons.push_back(polygon);
    for (const pear::Ring& ring : polygon) accepted.vertices += ring.size();
  }
  for (auto _ : state)
    for (pear::testing::CgalCdt& cdt : prepared) benchmark::DoNotOptimize(cdt.triangulate());
  set_rates(state, accepted);
  state.counters["polygons"] = static_cast<double>(prepared.size());
}
#endif

void register_benchmarks(std::vector<std::unique_ptr<Folder>>& folders) {
  for (const char* name : {"counties", "glyphs", "countries"}) {
    auto folder = std::make_unique<Folder>(load_folder(name));
    if (folder->polygons.empty()) {
      std::fprintf(stderr, "bench_small: no %s folder in the corpus: left out\n", name);
      continue;
    }
    const std::string prefix = std::string("small/") + name + "/";
    pear::Options top;
    top.threads = 1;
    pear::Options fast = top;
    fast.heuristic = pear::EarHeuristic::fast;
    fast.check_simplicity = false;
    benchmark::RegisterBenchmark((prefix + "pear_top").c_str(), per_polygon, folder.get(), top);
    benchmark::RegisterBenchmark((prefix + "pear_fast_nocheck").c_str(), per_polygon, folder.get(),
                                 fast);
    benchmark::RegisterBenchmark((prefix + "pear_free_function").c_str(), free_function,
                                 folder.get());
    for (unsigned threads : {1u, 2u})
      benchmark::RegisterBenchmark((prefix + "pear_batch_t" + std::to_string(threads)).c_str(),
                                   batch, folder.get(), threads)
          ->UseRealTime();
#ifdef PEAR_WITH_CGAL_ORACLE
    benchmark::RegisterBenchmark((prefix + "cgal_cdt").c_str(), cgal, folder.get());
#endif
    folders.push_back(std::move(folder));
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::unique_ptr<Folder>> folders;
  register_benchmarks(folders);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
