// pear_phases: where a run's time goes, phase by phase (issue 18). For one polygon file and each
// configuration (top, fast, the CDT; the parallel variants and the parallel CDT at 2 threads),
// runs pear RUNS times with a RunProfile and prints, per phase, the smallest work (sum of its
// tasks' times) and span (its longest task) over the runs, and the whole run's wall time.
// The smallest of several runs is the one least disturbed on a shared machine.
//
//   pear_phases FILE [RUNS] [CONFIG...]   CONFIG: top fast cdt cdtfast pc2 pc2cdt pc2t1 pc16t1
//   cdt16t1 pc16t4 pc16t8 pc16t16 cdt16t16 mc16t1 dc16t1 auto2t1 auto4t1 auto16t1 auto16t1cdt mc2
//   dc2 auto2 cdt2 cdt2t1
// Each phase also shows its share of the time on k threads by Brent's bound, max(work / k,
// longest task), k the configuration's partitions (else its threads), and the header their sum:
// the phases that bound the work/span projection (docs/scaling.md).
//
// PEAR_PHASES_TASKS=NAME also prints every task's time (ms) of the phases named NAME, in the
// last run: "clip chains" shows how evenly the chains split the work.
//
// Cache misses per phase: run one configuration under cachegrind (bench/profile/README.md).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "corpus.hpp"
#include "pear/io.hpp"
#include "pear/pear.hpp"

namespace {

struct Config {
  const char* name;
  pear::Options options;
};

std::vector<Config> configs() {
  using pear::Algorithm;
  std::vector<Config> all;
  // partitions 0: as many as threads.
  const auto add = [&](const char* name, Algorithm algorithm, unsigned threads, bool cdt,
                       unsigned partitions = 0,
                       pear::EarHeuristic heuristic = pear::EarHeuristic::top) {
    pear::Options o;
    o.algorithm = algorithm;
    o.threads = threads;
    o.partitions = partitions;
    o.delaunay = cdt;
    o.heuristic = heuristic;
    all.push_back({name, o});
  };
  add("top", Algorithm::sequential, 1, false);
  add("fast", Algorithm::sequential, 1, false, 0, pear::EarHeuristic::fast);
  add("cdt", Algorithm::sequential, 1, true);
  add("cdtfast", Algorithm::sequential, 1, true, 0, pear::EarHeuristic::fast);
  add("pc2", Algorithm::partition_and_cut, 2, false);
  add("pc2cdt", Algorithm::partition_and_cut, 2, true);
  add("pc2t1", Algorithm::partition_and_cut, 1, false, 2);  // the same work on one thread
  // 16 partitions on one thread: the work/span bound for 16 cores from task times.
  add("pc16t1", Algorithm::partition_and_cut, 1, false, 16);
  add("cdt16t1", Algorithm::sequential, 1, true, 16);  // the CDT's own phases at 16 partitions
  // 16 partitions on more threads: a task's time against pc16t1's shows what running beside
  // other tasks costs on this machine (shared caches, memory bandwidth, SMT siblings).
  add("pc16t4", Algorithm::partition_and_cut, 4, false, 16);
  add("pc16t8", Algorithm::partition_and_cut, 8, false, 16);
  add("pc16t16", Algorithm::partition_and_cut, 16, false, 16);
  add("cdt16t16", Algorithm::sequential, 16, true, 16);
  add("mc16t1", Algorithm::mark_and_cut, 1, false, 16);
  add("dc16t1", Algorithm::divide_and_conquer, 1, false, 16);
  add("auto2t1", Algorithm::automatic, 1, false, 2);    // what automatic picks at 2 partitions
  add("auto4t1", Algorithm::automatic, 1, false, 4);    // what automatic picks at 4 partitions
  add("auto16t1", Algorithm::automatic, 1, false, 16);  // what automatic picks at 16 partitions
  add("auto16t1cdt", Algorithm::automatic, 1, true, 16);
  add("mc2", Algorithm::mark_and_cut, 2, false);
  add("dc2", Algorithm::divide_and_conquer, 2, false);
  add("auto2", Algorithm::automatic, 2, false);
  add("cdt2", Algorithm::automatic, 2, true);
  add("cdt2t1", Algorithm::automatic, 1, true, 2);  // cdt2's work on one thread
  return all;
}

struct PhaseTimes {
  double work = 1e300, span = 1e300;
};

void profile(const pear::Polygon& polygon, const Config& config, int runs) {
  pear::Triangulator triangulator;
  std::vector<std::string> order;
  std::map<std::string, PhaseTimes> best;
  double wall = 1e300;
  for (int run = 0; run < runs; ++run) {
    pear::RunProfile profile;
    pear::Options options = config.options;
    options.profile = &profile;
    const auto start = std::chrono::steady_clock::now();
    const auto result = triangulator.triangulate(polygon, options);
    wall = std::min(
        wall, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    if (result.status != pear::Status::ok)
      std::fprintf(stderr, "%s: status %s\n", config.name, pear::to_string(result.status));
    if (const char* want = std::getenv("PEAR_PHASES_TASKS"); want && run == runs - 1)
      for (const auto& phase : profile.phases)
        if (phase.name == want) {
          std::printf("  [%s]", want);
          for (double t : phase.task_seconds) std::printf(" %.2f", 1e3 * t);
          std::printf("\n");
        }
    // Phases that repeat (rounds) are summed per name within a run.
    std::map<std::string, PhaseTimes> run_phases;
    for (const auto& phase : profile.phases) {
      double sum = 0, longest = 0;
      for (double t : phase.task_seconds) sum += t, longest = std::max(longest, t);
      auto [it, fresh] = run_phases.try_emplace(phase.name, PhaseTimes{0, 0});
      it->second.work += sum;
      it->second.span += longest;
      if (run == 0 && fresh) order.push_back(phase.name);
    }
    for (const auto& [name, t] : run_phases) {
      PhaseTimes& b = best[name];
      b.work = std::min(b.work, t.work);
      b.span = std::min(b.span, t.span);
    }
  }
  // Each phase's share of the time on k threads (k the partitions, else the threads) by
  // Brent's bound, max(work / k, longest task): the phases that bound RunProfile::projected(k).
  const unsigned k =
      std::max(1u, config.options.partitions ? config.options.partitions : config.options.threads);
  const auto at_k = [&](const PhaseTimes& t) { return std::max(t.work / k, t.span); };
  double total = 0, span = 0, projected = 0;
  for (const auto& name : order) {
    total += best[name].work;
    span += best[name].span;
    projected += at_k(best[name]);
  }
  std::printf("%s: wall %.1f ms, recorded work %.1f ms, span %.1f ms, at %u threads %.1f ms\n",
              config.name, 1e3 * wall, 1e3 * total, 1e3 * span, k, 1e3 * projected);
  for (const auto& name : order)
    std::printf("  %-44s %9.1f ms %5.1f%%  span %9.1f ms  at %2u %7.2f ms\n", name.c_str(),
                1e3 * best[name].work, 100 * best[name].work / total, 1e3 * best[name].span, k,
                1e3 * at_k(best[name]));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: pear_phases FILE [RUNS] [CONFIG...]\n");
    return 2;
  }
  const int runs = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
  const std::vector<std::string> wanted(argv + std::min(argc, 3), argv + argc);
  const auto polygons = pear::io::read_geojson(pear::corpus::read_text(argv[1]), argv[1]);
  if (polygons.size() != 1) {
    std::fprintf(stderr, "%s: expected one polygon\n", argv[1]);
    return 1;
  }
  std::size_t vertices = 0;
  for (const pear::Ring& ring : polygons[0]) vertices += ring.size();
  std::printf("%s: %zu vertices, %zu holes, best of %d runs\n", argv[1], vertices,
              polygons[0].size() - 1, runs);
  for (const Config& config : configs())
    if (wanted.empty() ||
        std::find(wanted.begin(), wanted.end(), std::string(config.name)) != wanted.end())
      profile(polygons[0], config, runs);
}
