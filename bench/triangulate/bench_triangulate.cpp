// Triangulation time, memory and quality: pear's algorithms against CGAL, GEOS and GLU in one
// binary, on the synthetic families and the shared corpus. See bench/run.sh and bench/report/.
//
// Each benchmark is one input and one triangulator. The input is converted to the
// triangulator's own form untimed. Once per benchmark (not per repetition) an untimed run
// counts peak heap bytes, and its triangles are checked by pear::validate and measured by
// pear::quality. Then the timed runs, in wall-clock time (the parallel variants use several
// threads; every benchmark is timed alike so that ratios compare like with like).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "inputs.hpp"
#include "memory.hpp"
#include "pear/pear.hpp"
#include "pear/quality.hpp"
#include "pear/validate.hpp"
#include "peers.hpp"

namespace bench {
namespace {

/// The polygon of the last input used: benchmarks of one input run one after another, so each
/// input is loaded once without keeping all of them in memory.
struct LoadedInput {
  std::string name;
  pear::Polygon polygon;
  std::vector<pear::Point> points;  ///< ring after ring, as pear numbers them
  std::vector<std::uint32_t> ring_offsets;
  std::size_t holes = 0;
  pear::PolygonView view() const { return {points, ring_offsets}; }
};

const LoadedInput& load(const Input& input) {
  static LoadedInput loaded;
  if (loaded.name != input.name) {
    loaded = {};
    loaded.polygon = input.load();
    loaded.holes = loaded.polygon.empty() ? 0 : loaded.polygon.size() - 1;
    loaded.ring_offsets.push_back(0);
    for (const pear::Ring& ring : loaded.polygon) {
      loaded.points.insert(loaded.points.end(), ring.begin(), ring.end());
      loaded.ring_offsets.push_back(static_cast<std::uint32_t>(loaded.points.size()));
    }
    loaded.name = input.name;
  }
  return loaded;
}

/// What the untimed first run found, kept across repetitions of the same benchmark.
struct FirstRun {
  std::size_t triangles = 0;
  std::size_t peak_bytes = 0;
  double seconds = 0;
  Triangles result;
  std::map<std::string, double> statistics;
};

void set_result_counters(benchmark::State& state, const std::string& label,
                         const LoadedInput& input, const Triangulator& triangulator,
                         std::size_t triangles, const FirstRun& first) {
  const Triangles& result = first.result;
  const auto n = static_cast<double>(input.points.size());
  const pear::QualityStatistics quality = pear::quality(input.points, result);
  pear::ValidateOptions options;
  options.max_messages = 1;
  // The CDT triangulators must also pass the exact empty-circle check.
  options.check_delaunay = triangulator.name.find("cdt") != std::string::npos;
  const pear::ValidationReport report = pear::validate(input.view(), result, options);
  if (!report.valid && !report.messages.empty())
    std::fprintf(stderr, "%s: %s\n", label.c_str(), report.messages[0].c_str());
  using benchmark::Counter;
  state.counters["vertices"] = n;
  state.counters["holes"] = static_cast<double>(input.holes);
  state.counters["triangles"] = static_cast<double>(triangles);
  state.counters["valid"] = report.valid ? 1 : 0;
  state.counters["non_delaunay_edges"] = static_cast<double>(report.non_delaunay_edges);
  state.counters["ns_per_vertex"] =
      Counter(n * 1e-9, Counter::kIsIterationInvariantRate | Counter::kInvert);
  state.counters["peak_bytes_per_vertex"] = static_cast<double>(first.peak_bytes) / n;
  state.counters["min_angle_avg_deg"] = quality.min_angle_avg_deg;
  state.counters["dev60_avg_deg"] = quality.dev60_avg_deg;
  state.counters["threads"] = triangulator.threads;
  state.counters["oversubscribed"] =
      triangulator.threads > std::thread::hardware_concurrency() ? 1 : 0;
  for (const auto& [name, value] : first.statistics) state.counters[name] = value;
}

double env_seconds(const char* name, double fallback) {
  const char* value = std::getenv(name);
  return value != nullptr && *value != '\0' ? std::strtod(value, nullptr) : fallback;
}

/// One untimed run's duration per family and triangulator ("comb/geos_ear"), by size.
using Durations = std::map<std::string, std::vector<std::pair<double, double>>>;

std::string family_of(const Input& input, const std::string& triangulator) {
  return input.family.empty() ? std::string() : input.family + "/" + triangulator;
}

/// The synthetic sizes of a family run small to large. From the two largest done so far we
/// extrapolate one run of this size (growth n^e, e in [1, 2.5]) and skip it when that exceeds
/// PEAR_BENCH_MAX_SECONDS (default 20): GEOS and some ear clippers are quadratic on some
/// families and would run for hours.
std::string too_slow(const std::string& family, double vertices, const Durations& durations) {
  const auto found = durations.find(family);
  if (family.empty() || found == durations.end()) return {};
  const auto& runs = found->second;
  const auto [n1, t1] = runs.back();
  double exponent = 1;
  if (runs.size() >= 2 && runs[runs.size() - 2].second > 1e-3) {
    const auto [n0, t0] = runs[runs.size() - 2];
    exponent = std::clamp(std::log(t1 / t0) / std::log(n1 / n0), 1.0, 2.5);
  }
  const double estimate = t1 * std::pow(vertices / n1, exponent);
  const double limit = env_seconds("PEAR_BENCH_MAX_SECONDS", 20);
  if (estimate <= limit) return {};
  char message[160];
  std::snprintf(message, sizeof message,
                "skipped: one run estimated at %.0f s (n^%.1f from smaller sizes), over "
                "PEAR_BENCH_MAX_SECONDS=%g",
                estimate, exponent, limit);
  return message;
}

void run(benchmark::State& state, const Input& input, const Triangulator& triangulator) {
  static std::map<std::string, FirstRun> first_runs;
  static Durations durations;
  const std::string label = input.name + "/" + triangulator.name;
  try {
    const LoadedInput& loaded = load(input);
    const auto vertices = static_cast<double>(loaded.points.size());
    const std::string family = family_of(input, triangulator.name);
    auto found = first_runs.find(label);
    // The cap is for quadratic peers; pear itself is always measured.
    if (found == first_runs.end() && !triangulator.name.starts_with("pear")) {
      if (std::string why = too_slow(family, vertices, durations); !why.empty())
        throw std::runtime_error(why);
    }
    const std::unique_ptr<PreparedPolygon> prepared = triangulator.prepare(loaded.polygon);
    if (found == first_runs.end()) {
      FirstRun first;
      const auto start = std::chrono::steady_clock::now();
      start_counting_memory();
      try {
        first.triangles = prepared->triangulate();
      } catch (...) {
        stop_counting_memory();
        throw;
      }
      first.peak_bytes = stop_counting_memory();
      first.seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      first.result = prepared->triangles();
      first.statistics = prepared->statistics();
      if (!family.empty()) durations[family].push_back({vertices, first.seconds});
      found = first_runs.emplace(label, std::move(first)).first;
    }
    std::size_t triangles = 0;
    for (auto _ : state) benchmark::DoNotOptimize(triangles = prepared->triangulate());
    set_result_counters(state, label, loaded, triangulator, triangles, found->second);
  } catch (const std::exception& error) {
    state.SkipWithError(error.what());
  }
}

}  // namespace
}  // namespace bench

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  const auto triangulators = bench::triangulators();
  for (const bench::Input& input : bench::inputs()) {
    for (const bench::Triangulator& triangulator : triangulators) {
      benchmark::RegisterBenchmark(("triangulate/" + input.name + "/" + triangulator.name).c_str(),
                                   [input, triangulator](benchmark::State& state) {
                                     bench::run(state, input, triangulator);
                                   })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
