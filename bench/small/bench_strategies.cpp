// bench_strategies: the crossover of the ear clipper's two strategies, which decides
// BitsetClipper::max_nodes. One ring of n vertices of a synthetic family (random, star, koch),
// cleaned and made a boundary once, clipped many times over by the bit sets and by the queue
// (EarClipper::run_queue), n from 16 to 4096 (the bit sets up to their limit of 1,024). Each
// iteration copies the boundary first (clipping works in place): the same cost for both.
//
//   bench_strategies [--benchmark_filter=...]
//
// Counter: ns_per_vertex; quote ratios of benchmarks of one run.
#include <benchmark/benchmark.h>

#include <string>

#include "clean/clean.hpp"
#include "earclip/bitset_clipper.hpp"
#include "earclip/ear_clipper.hpp"
#include "pear/generate.hpp"

namespace {

using namespace pear::detail;

Boundary ring_boundary(const std::string& kind, std::size_t n) {
  const pear::Polygon polygon = pear::generate_polygon(kind, n, 7);
  FlatPolygon flat;
  flatten(polygon, flat);
  CleanPolygon clean;
  std::vector<pear::Diagnostic> ignored;
  clean_polygon(pear::PolygonView{flat.points, flat.ring_starts}, clean, ignored);
  Boundary b;
  for (std::uint32_t i = 0; i < clean.points.size(); ++i) b.add(clean.points[i], clean.original[i]);
  for (std::uint32_t i = 0; i < b.size(); ++i) b.link(i, i + 1 == b.size() ? 0 : i + 1);
  return b;
}

void strategy(benchmark::State& state, std::string kind, std::size_t n, bool queue) {
  const Boundary original = ring_boundary(kind, n);
  Boundary b;
  EarClipper clipper;
  TriangleList out;
  for (auto _ : state) {
    b = original;
    out.clear();
    const bool done = queue ? clipper.run_queue(b, 0, pear::EarHeuristic::top, out, {nullptr, true})
                            : clipper.run(b, 0, pear::EarHeuristic::top, out, {nullptr, true});
    benchmark::DoNotOptimize(done);
  }
  state.counters["ns_per_vertex"] =
      benchmark::Counter(static_cast<double>(state.iterations() * original.size()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

}  // namespace

int main(int argc, char** argv) {
  for (const char* kind : {"random", "star", "koch"})
    for (std::size_t n :
         {16u, 32u, 64u, 128u, 256u, 384u, 512u, 768u, 1024u, 1280u, 1536u, 2048u, 4096u})
      for (bool queue : {false, true}) {
        try {
          pear::generate_polygon(kind, n, 7);
        } catch (const std::invalid_argument&) {
          continue;
        }
        if (!queue && n > BitsetClipper::max_nodes) continue;
        benchmark::RegisterBenchmark(("crossover/" + std::string(kind) + "/" + std::to_string(n) +
                                      (queue ? "/queue" : "/bitset"))
                                         .c_str(),
                                     strategy, std::string(kind), n, queue);
      }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
