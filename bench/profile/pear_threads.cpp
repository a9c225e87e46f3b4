// pear_threads: wall time of pear's parallel variants at several thread counts on the machine it
// runs on (issue 27), each against the sequential engine, the sequential CDT and CGAL's CDT in
// the same run. A shared or virtual machine drifts by tens of per cent over seconds, so the
// configurations of one input run in interleaved rounds (each round in its own shuffled order,
// after one untimed round) and each keeps the median of its rounds: ratios compare the same
// moments. Shuffled, not rotated: a rotation keeps each configuration after the same one, and
// on a 16-core VM `top` ran up to 1.34x slower than `auto_t1`. (`auto_t1` is the sequential
// engine below 300,000 vertices; from there on it clips in divide-and-conquer's parts, faster.)
//
//   pear_threads [--threads 1,2,4,8,16] [--rounds 7] [--phases] [--configs NAME,...] INPUT...
//   (--rounds 0 with --phases: the profiled runs only; --configs keeps the configurations
//   named, e.g. top,pc_t16,auto_t16, for an A/B of two builds of the library in turn)
//   INPUT: a GeoJSON polygon file (.json, or .json.gz with zlib) or FAMILY:N (generate_polygon)
//
// Writes a JSON array to stdout (bench/report/threads.py makes the table): the machine, then per
// input and configuration the median and fastest time in ms and the triangle count. --phases
// adds, per input at the largest thread count, `automatic` and its CDT profiled: each phase's
// elapsed time beside its work / threads and its longest task, what keeps a phase from scaling.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <numeric>
#include <random>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "inputs.hpp"
#include "json.hpp"
#include "pear/generate.hpp"
#include "pear/pear.hpp"
#include "pear/scheduler.hpp"
#ifdef PEAR_WITH_CGAL_ORACLE
#include "cgal_cdt.hpp"
#endif

namespace {

struct Config {
  std::string name;      ///< top, cdt, cgal_cdt, pc_t4, auto_t16_cdt, ...
  unsigned threads = 1;  ///< the thread count (the peers and the sequential engine: 1)
  pear::Options options;
  bool cgal = false;
};

std::vector<Config> configs(const std::vector<unsigned>& thread_counts) {
  using pear::Algorithm;
  // threads = 1: left at 0, the sequential engine still checks and bridges a large polygon in
  // parts on every hardware thread.
  std::vector<Config> all = {
      {"top", 1, {.algorithm = Algorithm::sequential, .threads = 1}},
      {"cdt", 1, {.algorithm = Algorithm::sequential, .delaunay = true, .threads = 1}},
  };
#ifdef PEAR_WITH_CGAL_ORACLE
  all.push_back({"cgal_cdt", 1, {}, true});
#endif
  const std::pair<const char*, Algorithm> variants[] = {{"pc", Algorithm::partition_and_cut},
                                                        {"mc", Algorithm::mark_and_cut},
                                                        {"dc", Algorithm::divide_and_conquer},
                                                        {"auto", Algorithm::automatic}};
  for (const unsigned t : thread_counts) {
    const std::string suffix = "_t" + std::to_string(t);
    for (const auto& [name, algorithm] : variants)
      all.push_back({name + suffix,
                     t,
                     {.algorithm = algorithm, .threads = t, .executor = bench::executor_for(t)}});
    all.push_back({"auto" + suffix + "_cdt",
                   t,
                   {.algorithm = Algorithm::automatic,
                    .delaunay = true,
                    .threads = t,
                    .executor = bench::executor_for(t)}});
  }
  return all;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// One timed run; the triangle count, or 0 when pear's status is not ok.
std::size_t run_once(const pear::Polygon& polygon, const Config& config, double& seconds) {
#ifdef PEAR_WITH_CGAL_ORACLE
  if (config.cgal) {
    pear::testing::CgalCdt cdt(polygon);  // the conversion is not timed
    const auto start = std::chrono::steady_clock::now();
    const std::size_t triangles = cdt.triangulate();
    seconds = seconds_since(start);
    return triangles;
  }
#endif
  const auto start = std::chrono::steady_clock::now();
  const auto result = pear::triangulate(polygon, config.options);
  seconds = seconds_since(start);
  return result.status == pear::Status::ok ? result.triangles.size() : 0;
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

struct Input {
  std::string name;
  pear::Polygon polygon;
  std::size_t vertices = 0;
};

Input load(const std::string& spec) {
  Input input{spec, {}, 0};
  const auto colon = spec.find(':');
  if (colon != std::string::npos && spec.find('/') == std::string::npos)
    input.polygon = pear::generate_polygon(spec.substr(0, colon),
                                           std::strtoull(spec.c_str() + colon + 1, nullptr, 10));
  else {
    input.polygon = bench::load_polygon_file(spec);
    // "australia" for .../australia_gshhg_full.json.gz, "koch-8" for .../koch-8.json
    std::string stem = std::filesystem::path(spec).filename().string();
    stem = stem.substr(0, stem.find('.'));
    input.name = stem.substr(0, stem.find("_gshhg"));
  }
  for (const pear::Ring& ring : input.polygon) input.vertices += ring.size();
  return input;
}

void time_rounds(bench::Json& out, const Input& input, const std::vector<Config>& all, int rounds) {
  std::vector<std::vector<double>> times(all.size());
  std::vector<std::size_t> triangles(all.size(), 0);
  std::vector<std::size_t> order(all.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::mt19937 shuffle(2026);                      // the same orders in every run
  for (int round = -1; round < rounds; ++round) {  // round -1: untimed, warms memory and caches
    std::shuffle(order.begin(), order.end(), shuffle);
    for (const std::size_t c : order) {
      double seconds = 0;
      triangles[c] = run_once(input.polygon, all[c], seconds);
      if (round >= 0) times[c].push_back(seconds);
    }
  }
  for (std::size_t c = 0; c < all.size(); ++c) {
    out.begin_object()
        .field("input", input.name)
        .field("vertices", input.vertices)
        .field("holes", input.polygon.size() - 1)
        .field("config", all[c].name)
        .field("threads", all[c].threads)
        .field("median_ms", 1e3 * median(times[c]))
        .field("min_ms", 1e3 * *std::min_element(times[c].begin(), times[c].end()))
        .field("rounds", times[c].size())
        .field("triangles", triangles[c])
        .end_object();
    std::fflush(stdout);
  }
}

/// The fastest of three profiled runs of `config`: each phase's elapsed time against its work.
void print_phases(bench::Json& out, const Input& input, const Config& config) {
  pear::RunProfile best;
  double best_seconds = 1e300;
  for (int run = 0; run < 3; ++run) {
    pear::RunProfile profile;
    pear::Options options = config.options;
    options.profile = &profile;
    const auto start = std::chrono::steady_clock::now();
    pear::triangulate(input.polygon, options);
    if (const double s = seconds_since(start); s < best_seconds) best_seconds = s, best = profile;
  }
  out.begin_object()
      .field("input", input.name)
      .field("config", config.name)
      .field("threads", config.threads)
      .field("wall_ms", 1e3 * best_seconds)
      .field("work_ms", 1e3 * best.work())
      .field("projected_ms", 1e3 * best.projected(config.threads))
      .key("phases")
      .begin_array();
  for (const auto& phase : best.phases) {
    double work = 0, longest = 0;
    for (const double t : phase.task_seconds) work += t, longest = std::max(longest, t);
    out.begin_object()
        .field("name", phase.name)
        .field("tasks", phase.task_seconds.size())
        .field("wall_ms", 1e3 * phase.wall_seconds)
        .field("work_ms", 1e3 * work)
        .field("longest_ms", 1e3 * longest)
        .end_object();
  }
  out.end_array().end_object();
  std::fflush(stdout);
}

std::vector<unsigned> parse_threads(const char* text) {
  std::vector<unsigned> counts;
  for (const char* p = text; *p;) {
    char* end = nullptr;
    const unsigned long t = std::strtoul(p, &end, 10);
    if (end == p || t == 0 || t > 4096) return {};
    counts.push_back(static_cast<unsigned>(t));
    p = *end == ',' ? end + 1 : end;
    if (*end != ',' && *end != '\0') return {};
  }
  return counts;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<unsigned> thread_counts = {1, 2, 4, 8, 16};
  int rounds = 7;
  bool phases = false;
  std::vector<std::string> specs, only;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--threads" && i + 1 < argc) {
      thread_counts = parse_threads(argv[++i]);
    } else if (arg == "--rounds" && i + 1 < argc) {
      rounds = std::atoi(argv[++i]);
    } else if (arg == "--phases") {
      phases = true;
    } else if (arg == "--configs" && i + 1 < argc) {
      for (std::string_view list = argv[++i]; !list.empty();) {
        const std::size_t comma = std::min(list.find(','), list.size());
        only.emplace_back(list.substr(0, comma));
        list.remove_prefix(std::min(comma + 1, list.size()));
      }
    } else if (!arg.starts_with("--")) {
      specs.push_back(arg);
    } else {
      specs.clear();
      break;
    }
  }
  if (specs.empty() || thread_counts.empty() || rounds < 0 || (rounds == 0 && !phases)) {
    std::fprintf(stderr,
                 "usage: pear_threads [--threads 1,2,4,8,16] [--rounds 7] [--phases]"
                 " [--configs NAME,...] INPUT...\n"
                 "INPUT: a GeoJSON polygon file or FAMILY:N\n");
    return 2;
  }
  bench::Json out;
  out.begin_array();
  out.begin_object()
      .field("hardware_threads", std::thread::hardware_concurrency())
      .field("rounds", rounds)
      .end_object();
  std::vector<Config> all = configs(thread_counts);
  if (!only.empty())
    std::erase_if(all, [&](const Config& c) {
      return std::find(only.begin(), only.end(), c.name) == only.end();
    });
  if (all.empty()) {
    std::fprintf(stderr, "pear_threads: no configuration left by --configs\n");
    return 2;
  }
  for (const std::string& spec : specs) {
    try {
      const Input input = load(spec);
      if (rounds > 0) time_rounds(out, input, all, rounds);
      if (phases) {
        const unsigned most = *std::max_element(thread_counts.begin(), thread_counts.end());
        for (const Config& c : all)
          if (c.threads == most && c.name.starts_with("auto")) print_phases(out, input, c);
      }
    } catch (const std::exception& error) {
      std::fprintf(stderr, "%s: %s\n", spec.c_str(), error.what());
      out.end_array();
      return 1;
    }
  }
  out.end_array();
  std::printf("\n");
  return 0;
}
