// The constrained Delaunay triangulation: pear (ear clipping, then exact flips; sequential and at
// 2 threads) against CGAL's CDT and GEOS's ConstrainedDelaunayTriangulator, in one binary, on the
// corpus's synthetic/ files and (PEAR_BENCH_LARGE=1) the Australia and Eurasia coastlines.
// Inputs and peers come from bench/triangulate. Wall-clock time (pear at 2 threads runs in
// parallel); ratios only within one run. See run.sh and docs/cdt.md.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

#include "inputs.hpp"
#include "pear/pear.hpp"
#include "pear/scheduler.hpp"
#include "pear/validate.hpp"
#include "peers.hpp"

namespace {

/// pear with Options::delaunay (or without: the ear clipping alone); threads > 1 runs parallel
/// clipping (automatic choice) and the partitioned flips on one executor made once.
class PearCdt final : public bench::PreparedPolygon {
 public:
  PearCdt(const pear::Polygon& polygon, unsigned threads, bool delaunay,
          pear::EarHeuristic heuristic)
      : polygon_(polygon) {
    options_.delaunay = delaunay;
    options_.heuristic = heuristic;
    options_.threads = threads;
    options_.algorithm = threads > 1 ? pear::Algorithm::automatic : pear::Algorithm::sequential;
    options_.executor = bench::executor_for(threads);
  }
  std::size_t triangulate() override {
    result_ = pear::triangulate(polygon_, options_);
    if (result_.status != pear::Status::ok)
      throw std::runtime_error(std::string("pear: ") + pear::to_string(result_.status));
    return result_.triangles.size();
  }
  bench::Triangles triangles() const override { return result_.triangles; }
  const pear::DelaunayStatistics& flip_statistics() const { return result_.delaunay; }

 private:
  const pear::Polygon& polygon_;
  pear::Options options_;
  pear::Triangulation<std::uint32_t> result_;
};

struct Entry {
  std::string name;
  std::function<std::unique_ptr<bench::PreparedPolygon>(const pear::Polygon&)> prepare;
};

std::vector<Entry> entries() {
  const auto pear_entry = [](unsigned threads, bool delaunay,
                             pear::EarHeuristic heuristic = pear::EarHeuristic::top) {
    return [=](const pear::Polygon& p) {
      return std::make_unique<PearCdt>(p, threads, delaunay, heuristic);
    };
  };
  // The CDT does not depend on the ears' shapes: "fast" clips sooner and may need fewer flips.
  std::vector<Entry> all = {{"pear_ear_t1", pear_entry(1, false)},
                            {"pear_cdt_t1", pear_entry(1, true)},
                            {"pear_cdt_fast_t1", pear_entry(1, true, pear::EarHeuristic::fast)},
                            {"pear_cdt_t2", pear_entry(2, true)},
                            {"pear_cdt_fast_t2", pear_entry(2, true, pear::EarHeuristic::fast)}};
  all.push_back({"cgal_cdt", bench::prepare_cgal_cdt});
  if (std::string why_not; bench::geos_available(why_not))
    all.push_back({"geos_cdt", bench::prepare_geos_cdt});
  return all;
}

/// GEOS's CDT grows about quadratically (13 s on the 40k-vertex holes grid): above
/// PEAR_BENCH_GEOS_MAX_VERTICES (default 50,000) it is left out.
bool too_large_for(const Entry& entry, const bench::Input& input) {
  const char* limit = std::getenv("PEAR_BENCH_GEOS_MAX_VERTICES");
  const std::size_t max = limit != nullptr ? std::strtoull(limit, nullptr, 10) : 50'000;
  return entry.name == "geos_cdt" && input.vertices > max;
}

bool wanted(const bench::Input& input) {
  const char* large = std::getenv("PEAR_BENCH_LARGE");
  const bool with_coasts = large != nullptr && std::string(large) == "1";
  return input.name.starts_with("synthetic/") ||
         (with_coasts && (input.name == "coast/australia" || input.name == "coast/eurasia"));
}

/// Untimed: the result must pass the validator's Delaunay check (pear and peers alike).
void check_once(benchmark::State& state, const pear::Polygon& polygon,
                const bench::PreparedPolygon& prepared) {
  const pear::ValidationReport report =
      pear::validate(polygon, prepared.triangles(), pear::ValidateOptions{.check_delaunay = true});
  state.counters["delaunay_valid"] = report.valid ? 1 : 0;
  const auto* pear_cdt = dynamic_cast<const PearCdt*>(&prepared);
  if (pear_cdt == nullptr || pear_cdt->flip_statistics().edges == 0) return;
  const pear::DelaunayStatistics& d = pear_cdt->flip_statistics();
  const auto edges = static_cast<double>(d.edges);
  state.counters["flips_per_edge"] = static_cast<double>(d.flips) / edges;
  state.counters["in_partitions_per_edge"] = static_cast<double>(d.flips_in_partitions) / edges;
  state.counters["on_borders_per_edge"] = static_cast<double>(d.flips_on_borders) / edges;
}

void run(benchmark::State& state, const bench::Input& input, const Entry& entry) {
  static std::string loaded_name;
  static pear::Polygon polygon;
  try {
    if (loaded_name != input.name) {
      polygon = input.load();
      loaded_name = input.name;
    }
    const auto prepared = entry.prepare(polygon);
    prepared->triangulate();
    check_once(state, polygon, *prepared);
    for (auto _ : state) benchmark::DoNotOptimize(prepared->triangulate());
  } catch (const std::exception& error) {
    state.SkipWithError(error.what());
  }
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  const std::vector<Entry> all = entries();
  for (const bench::Input& input : bench::inputs()) {
    if (!wanted(input)) continue;
    for (const Entry& entry : all)
      if (!too_large_for(entry, input))
        benchmark::RegisterBenchmark(
            ("cdt/" + input.name + "/" + entry.name).c_str(),
            [input, entry](benchmark::State& state) { run(state, input, entry); })
            ->Unit(benchmark::kMillisecond)
            ->UseRealTime();
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
