// The paper's experiments that are not timings (§3): ear prevalence (Fig. 7), the work/span
// profile of the parallel variants (the projection behind Fig. 9 for more cores than this
// machine has), angle quality per algorithm (Table 1) and the CDT's flips per edge. Writes one
// JSON document to stdout; bench/report/ turns it into figures and tables.
//
//   paper_experiments ears|profile|quality [max_vertices]
//
// Inputs: ears and quality walk the corpus folders (PEAR_BENCH_CORPUS) and the generator
// families at 10k vertices; profile uses the benchmark's inputs (PEAR_BENCH_SIZES, ...) of
// 10k vertices and more, each run PEAR_BENCH_PROFILE_RUNS times (default 3, 1 above 1M).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "inputs.hpp"
#include "json.hpp"
#include "pear/generate.hpp"
#include "pear/pear.hpp"
#include "pear/quality.hpp"
#include "pear/validate.hpp"

namespace bench {
namespace {

namespace fs = std::filesystem;

struct Named {
  std::string folder;  ///< "countries", "synthetic-10k", ...
  std::string name;
  std::function<pear::Polygon()> load;
};

/// The corpus's files (all folders, coastlines included up to max_vertices) and the generator
/// families at 10,000 vertices.
std::vector<Named> corpus(std::size_t max_vertices) {
  std::vector<Named> all;
  for (std::string_view kind : pear::generator_kinds()) {
    const std::string k(kind);
    all.push_back({"families-10k", k, [k] { return pear::generate_polygon(k, 10'000); }});
  }
  const fs::path root = corpus_dir();
  for (const char* folder : {"earcut", "glyphs", "countries", "counties", "synthetic", "coast"}) {
    if (!fs::exists(root / folder)) continue;
    for (const pear::corpus::File& file : manifest(root / folder)) {
      if (file.vertices > max_vertices) continue;
      const fs::path path = file.path;
      all.push_back({folder, file.file, [path] { return load_polygon_file(path); }});
    }
  }
  return all;
}

void ears(std::size_t max_vertices) {
  Json out;
  out.begin_array();
  pear::Triangulator triangulator;
  for (const Named& input : corpus(max_vertices)) {
    pear::EarStatistics s;
    std::fprintf(stderr, "ears %s/%s\n", input.folder.c_str(), input.name.c_str());
    try {
      const pear::Polygon polygon = input.load();
      // Only polygons pear triangulates: ear_statistics can loop on degenerate input (reported).
      const auto result = triangulator.triangulate(polygon);
      if (result.status != pear::Status::ok)
        throw std::runtime_error(std::string("not counted: ") + pear::to_string(result.status));
      s = triangulator.ear_statistics(polygon);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "%s: %s\n", input.name.c_str(), error.what());
      continue;
    }
    out.begin_object();
    out.field("folder", input.folder).field("name", input.name);
    out.field("vertices", s.vertices).field("convex", s.convex).field("reflex", s.reflex);
    out.field("ears", s.ears);
    out.end_object();
  }
  out.end_array();
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// The fastest of `runs` runs on the calling thread (threads = 1): on a loaded machine the
/// minimum is the run least disturbed. Its profile is kept in `profile` when given.
double best_run(const pear::Polygon& polygon, pear::Options options, int runs,
                pear::RunProfile* profile) {
  double best = 1e300;
  options.threads = 1;
  for (int r = 0; r < runs; ++r) {
    pear::RunProfile current;
    options.profile = profile != nullptr ? &current : nullptr;
    const auto start = std::chrono::steady_clock::now();
    const auto result = pear::triangulate(polygon, options);
    const double wall = seconds_since(start);
    if (result.status != pear::Status::ok)
      throw std::runtime_error(std::string("pear: ") + pear::to_string(result.status));
    if (wall < best) {
      best = wall;
      if (profile != nullptr) *profile = std::move(current);
    }
  }
  return best;
}

struct Variant {
  const char* name;
  pear::Algorithm algorithm;
  bool delaunay;
};
/// Every variant at k partitions: the sequential clipper too (its simplicity check and the
/// CDT's flips are cut into k parts), the CDT after the sequential and the parallel clip, and
/// automatic (the default: whichever it picks at k).
constexpr Variant parallel_variants[] = {
    {"seq", pear::Algorithm::sequential, false},
    {"mc", pear::Algorithm::mark_and_cut, false},
    {"pc", pear::Algorithm::partition_and_cut, false},
    {"dc", pear::Algorithm::divide_and_conquer, false},
    {"auto", pear::Algorithm::automatic, false},
    {"seq_cdt", pear::Algorithm::sequential, true},
    {"pc_cdt", pear::Algorithm::partition_and_cut, true},
    {"auto_cdt", pear::Algorithm::automatic, true},
};

void write_profile(Json& out, const pear::RunProfile& profile, double wall) {
  // Time outside the recorded phases (cleaning, bridging, ...) counts as one serial task.
  const double unrecorded = std::max(0.0, wall - profile.work());
  out.field("wall", wall).field("work", profile.work() + unrecorded);
  out.field("span", profile.span() + unrecorded).field("unrecorded", unrecorded);
  out.key("projected").begin_object();
  for (const unsigned t : {1u, 2u, 4u, 8u, 16u})
    out.field(std::to_string(t).c_str(), profile.projected(t) + unrecorded);
  out.end_object();
  out.key("phases").begin_array();
  for (const auto& phase : profile.phases) {
    double sum = 0, longest = 0;
    for (const double s : phase.task_seconds) sum += s, longest = std::max(longest, s);
    out.begin_object().field("name", phase.name).field("tasks", phase.task_seconds.size());
    out.field("work", sum).field("longest", longest).end_object();
  }
  out.end_array();
}

/// One configuration of the profile and its least disturbed run so far.
struct Profiled {
  const char* variant;  ///< "sequential", "sequential_cdt" (the bases) or a Variant's name
  unsigned partitions;
  pear::Options options;
  double wall = 1e300;
  pear::RunProfile profile{};
  /// The least projection at `partitions` threads over the runs: the bound's denominator.
  double projected = 1e300;
};

/// The bases at one partition, then every variant at 2, 4, 8 and 16.
std::vector<Profiled> profile_configs() {
  using pear::Algorithm;
  std::vector<Profiled> all = {
      {"sequential", 1, {.algorithm = Algorithm::sequential}},
      {"sequential_cdt", 1, {.algorithm = Algorithm::sequential, .delaunay = true}}};
  for (const Variant& variant : parallel_variants)
    for (const unsigned k : {2u, 4u, 8u, 16u})
      all.push_back(
          {variant.name,
           k,
           {.algorithm = variant.algorithm, .delaunay = variant.delaunay, .partitions = k}});
  return all;
}

void profile_input(Json& out, const Input& input) {
  const pear::Polygon polygon = input.load();
  const char* runs_text = std::getenv("PEAR_BENCH_PROFILE_RUNS");
  const int runs = runs_text != nullptr         ? std::max(1, std::atoi(runs_text))
                   : input.vertices > 1'000'000 ? 1
                                                : 3;
  std::size_t vertices = 0;
  for (const auto& ring : polygon) vertices += ring.size();
  // Round after round over all configurations: on a shared machine a busy minute then spoils
  // one run of each, not every run of one. The bases run again before every few variants: the
  // bounds divide by their fastest run, and runs of a base once a round could all fall in slow
  // spells (a coast's base 40% slower than in the table before, each of its bounds with it);
  // a ratio of runs paired in time favoured the variants (time lost in a spell counts in full
  // in a sequential run, in about a k-th part in a projection).
  std::vector<Profiled> configs = profile_configs();
  const auto run = [&](Profiled& c) {
    pear::RunProfile profile;
    const double wall = best_run(polygon, c.options, 1, &profile);
    const double unrecorded = std::max(0.0, wall - profile.work());
    c.projected = std::min(c.projected, profile.projected(c.partitions) + unrecorded);
    if (wall < c.wall) c.wall = wall, c.profile = std::move(profile);
  };
  constexpr std::size_t variants_per_base_run = 4;
  for (int r = 0; r < runs; ++r)
    for (std::size_t i = 2; i < configs.size(); ++i) {
      if ((i - 2) % variants_per_base_run == 0) run(configs[0]), run(configs[1]);
      run(configs[i]);
    }
  out.begin_object().field("input", input.name).field("vertices", vertices);
  out.field("sequential", configs[0].wall).field("sequential_cdt", configs[1].wall);
  out.key("variants").begin_array();
  for (std::size_t i = 2; i < configs.size(); ++i) {
    out.begin_object().field("variant", configs[i].variant);
    out.field("partitions", configs[i].partitions);
    write_profile(out, configs[i].profile, configs[i].wall);
    out.field("least_projected", configs[i].projected);
    out.end_object();
  }
  out.end_array().end_object();
}

void profile(std::size_t max_vertices) {
  Json out;
  out.begin_array();
  for (const Input& input : inputs()) {
    if (input.vertices > max_vertices || input.vertices < 10'000) continue;
    std::fprintf(stderr, "profile %s\n", input.name.c_str());
    try {
      profile_input(out, input);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "%s: %s\n", input.name.c_str(), error.what());
    }
  }
  out.end_array();
}

struct QualityConfig {
  const char* name;
  pear::Options options;
};

std::vector<QualityConfig> quality_configs() {
  using pear::Algorithm;
  // The paper's Table 1 ran the parallel variants on 8 cores: 8 partitions here (the output
  // depends on the partition count only, so one thread gives the same triangles).
  return {
      {"top", {.algorithm = Algorithm::sequential}},
      {"fast", {.algorithm = Algorithm::sequential, .heuristic = pear::EarHeuristic::fast}},
      {"dc", {.algorithm = Algorithm::divide_and_conquer, .partitions = 8}},
      {"pc", {.algorithm = Algorithm::partition_and_cut, .partitions = 8}},
      {"mc", {.algorithm = Algorithm::mark_and_cut, .partitions = 8}},
      {"cdt", {.algorithm = Algorithm::sequential, .delaunay = true}},
      {"pc_cdt_2", {.algorithm = Algorithm::partition_and_cut, .delaunay = true, .partitions = 2}},
      {"pc_cdt_4", {.algorithm = Algorithm::partition_and_cut, .delaunay = true, .partitions = 4}},
      {"pc_cdt_8", {.algorithm = Algorithm::partition_and_cut, .delaunay = true, .partitions = 8}}};
}

void quality_of(Json& out, const pear::Polygon& polygon, const QualityConfig& config) {
  pear::Options options = config.options;
  options.threads = 1;
  const auto result = pear::triangulate(polygon, options);
  out.begin_object().field("config", config.name).field("status", pear::to_string(result.status));
  if (result.status == pear::Status::ok) {
    const pear::QualityStatistics q = pear::quality(polygon, result.triangles);
    pear::ValidateOptions check;
    check.check_delaunay = options.delaunay;
    check.max_messages = 0;
    out.field("valid", pear::validate(polygon, result.triangles, check).valid);
    out.field("triangles", q.triangles).field("dev60", q.dev60_avg_deg);
    out.field("min_angle", q.min_angle_avg_deg);
    const pear::DelaunayStatistics& d = result.delaunay;
    if (options.delaunay)
      out.field("edges", d.edges)
          .field("flips", d.flips)
          .field("flips_in", d.flips_in_partitions)
          .field("flips_border", d.flips_on_borders);
  }
  out.end_object();
}

void quality(std::size_t max_vertices) {
  Json out;
  out.begin_array();
  const auto configs = quality_configs();
  for (const Named& input : corpus(max_vertices)) {
    try {
      const pear::Polygon polygon = input.load();
      out.begin_object().field("folder", input.folder).field("name", input.name);
      out.key("results").begin_array();
      for (const QualityConfig& config : configs) quality_of(out, polygon, config);
      out.end_array().end_object();
    } catch (const std::exception& error) {
      std::fprintf(stderr, "%s: %s\n", input.name.c_str(), error.what());
    }
  }
  out.end_array();
}

}  // namespace
}  // namespace bench

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  const std::size_t max_vertices = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : SIZE_MAX;
  try {
    if (mode == "ears")
      bench::ears(max_vertices);
    else if (mode == "profile")
      bench::profile(max_vertices);
    else if (mode == "quality")
      bench::quality(max_vertices);
    else {
      std::fprintf(stderr, "usage: %s ears|profile|quality [max_vertices]\n", argv[0]);
      return 2;
    }
  } catch (const std::exception& error) {
    std::fprintf(stderr, "error: %s\n", error.what());
    return 1;
  }
  std::printf("\n");
  return 0;
}
