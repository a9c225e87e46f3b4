// `pear triangulate FILE...`: read, triangulate, optionally validate, report and write.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "cli.hpp"
#include "inputs.hpp"
#include "json_line.hpp"
#include "output.hpp"
#include "pear/quality.hpp"
#include "pear/scheduler.hpp"
#include "pear/validate.hpp"

namespace pear::cli {
namespace {

struct Settings {
  std::string algorithm_name = "auto";
  Options options;
  bool validate = false;
  bool stats = false;
  io::ReadOptions read;
  std::optional<std::string> output;
  std::optional<OutputFormat> format;
  std::vector<std::string_view> inputs;
};

void print_help() {
  std::string algorithms;
  for (const AlgorithmName& a : algorithm_names())
    algorithms += "      " + std::string(a.name) + std::string(20 - a.name.size(), ' ') +
                  std::string(a.summary) + (a.algorithm ? "" : " [not in this build]") + "\n";
  std::printf(R"(usage: pear triangulate [OPTIONS] FILE...

Triangulates every polygon in the files: GeoJSON (.json, .geojson), WKT (.wkt), Triangle's
.poly, any of them gzipped (.gz); '-' reads stdin. Directories are searched for such files;
quoted globs are expanded.

options:
  --algorithm NAME    which triangulation algorithm (default auto):
%s  --threads N         threads for the parallel algorithms (default: all hardware threads)
  --partitions K      parts the parallel algorithms cut the work into (default: the thread
                      count); the output depends on K, never on the threads
  --heuristic top|fast  ear order: shortest diagonal weighted by shape (top, default), or
                      a walk along the boundary (fast: quickest, thinner triangles)
  --cdt               make the triangulation constrained Delaunay (exact edge flips); with
                      --validate, every interior edge is checked to be locally Delaunay
  --validate          check every result with pear's independent validator
  --stats             print one JSON object per polygon on stdout: file, index, vertices,
                      holes, triangles, status, algorithm, threads, cdt, ms (triangulation
                      only), min_angle_avg_deg, dev60_avg_deg (with --validate also valid,
                      area_rel_error)
  -o OUT              write the triangulations: one file for one input; a directory (an
                      existing one, or a name ending in '/') for one output per input;
                      '-' for stdout
  --format F          obj, geojson, node (.node + .ele) or svg; else guessed from OUT's extension
  --keep-small-rings  accept rings of fewer than 3 points (as earcut's fixtures have); the
                      engine drops such holes
  --help              this text

exit codes: 0 success; 1 bad input (each named on stderr, the other files still processed);
2 usage error; 3 --validate found an invalid triangulation.
)",
              algorithms.c_str());
}

Settings parse(std::span<const std::string_view> arguments) {
  Settings s;
  Args args(arguments);
  while (const auto option = args.next_option()) {
    if (option == "--help" || option == "-h") {
      print_help();
      std::exit(success);
    } else if (option == "--algorithm") {
      s.algorithm_name = args.value();
      s.options.algorithm = parse_algorithm(s.algorithm_name);
    } else if (option == "--threads") {
      s.options.threads = static_cast<unsigned>(args.integer(1, 4096));
    } else if (option == "--partitions") {
      s.options.partitions = static_cast<unsigned>(args.integer(1, 65536));
    } else if (option == "--heuristic") {
      const std::string_view h = args.value();
      if (h != "top" && h != "fast") throw UsageError("--heuristic expects top or fast");
      s.options.heuristic = h == "top" ? EarHeuristic::top : EarHeuristic::fast;
    } else if (option == "--cdt") {
      args.no_value();
      s.options.delaunay = true;
    } else if (option == "--validate" || option == "--stats" || option == "--keep-small-rings") {
      args.no_value();
      (option == "--validate" ? s.validate
       : option == "--stats"  ? s.stats
                              : s.read.keep_small_rings) = true;
    } else if (option == "-o" || option == "--output") {
      s.output = std::string(args.value());
    } else if (option == "--format") {
      s.format = parse_output_format(args.value());
    } else {
      args.unknown();
    }
  }
  s.inputs = args.positionals();
  if (s.inputs.empty()) throw UsageError("triangulate needs at least one FILE (or '-' for stdin)");
  if (s.output == "-" && s.stats) throw UsageError("-o - and --stats would both write to stdout");
  return s;
}

std::size_t thread_count(const Options& options) {
  return options.threads ? options.threads : default_executor().concurrency();
}

struct Totals {
  std::size_t polygons = 0;
  std::size_t failures = 0;
  bool bad_input = false;
  bool invalid = false;
};

// Triangulates one polygon; prints its stats line; records problems.
io::TriangulatedPolygon run_one(const Settings& s, Triangulator& triangulator,
                                const Polygon& polygon, const std::string& file, std::size_t index,
                                Totals& totals, Progress& progress) {
  const auto start = std::chrono::steady_clock::now();
  Triangulation<std::uint32_t> result = triangulator.triangulate(polygon, s.options);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
#ifdef PEAR_CLI_FAULT_INJECTION
  // Only in the test build's pear-fault-injection (tests/cli): no correct engine result is
  // invalid, so exit code 3 is tested by dropping a triangle.
  if (std::getenv("PEAR_TEST_DROP_A_TRIANGLE") != nullptr && !result.triangles.empty())
    result.triangles.pop_back();
#endif
  std::size_t vertices = 0;
  for (const Ring& ring : polygon) vertices += ring.size();
  if (result.status != Status::ok) {
    totals.bad_input = true;
    ++totals.failures;
    std::string why;
    for (const Diagnostic& d : result.diagnostics)
      if (why.empty() || d.is_error()) why = describe(d);
    progress.message(file + ": polygon " + std::to_string(index) + ": " + to_string(result.status) +
                     (why.empty() ? "" : ": " + why));
  }
  if (s.stats || s.validate) {
    const QualityStatistics q = quality(polygon, result.triangles);
    JsonLine line;
    line.add("file", file).add("index", index).add("vertices", vertices);
    line.add("holes", polygon.empty() ? std::size_t{0} : polygon.size() - 1);
    line.add("triangles", result.triangles.size()).add("status", to_string(result.status));
    line.add("algorithm", s.algorithm_name).add("threads", thread_count(s.options));
    line.add("cdt", s.options.delaunay);
    line.add("ms", ms).add("min_angle_avg_deg", q.min_angle_avg_deg);
    line.add("dev60_avg_deg", q.dev60_avg_deg);
    if (s.validate) {
      ValidateOptions check;
      check.check_delaunay = s.options.delaunay;
      const ValidationReport report = pear::validate(polygon, result.triangles, check);
      line.add("valid", report.valid).add("area_rel_error", report.area_rel_error);
      if (!report.valid && result.status == Status::ok) {
        totals.invalid = true;
        progress.message(file + ": polygon " + std::to_string(index) + ": invalid triangulation" +
                         (report.messages.empty() ? "" : ": " + report.messages.front()));
      }
    }
    if (s.stats) std::printf("%s\n", line.str().c_str());
  }
  return {polygon, std::move(result.triangles), {}};
}

}  // namespace

int run_triangulate(std::span<const std::string_view> arguments) {
  const Settings s = parse(arguments);
  const std::vector<std::string> files = expand_inputs(s.inputs);
  const OutputPlan plan = plan_output(s.output, s.format, files.size());
  Progress progress(files.size());
  Totals totals;
  Triangulator triangulator;
  for (const std::string& file : files) {
    try {
      const std::vector<Polygon> polygons = read_input(file, s.read);
      std::vector<io::TriangulatedPolygon> results;
      for (std::size_t i = 0; i < polygons.size(); ++i) {
        results.push_back(run_one(s, triangulator, polygons[i], file, i, totals, progress));
        ++totals.polygons;
      }
      if (plan.format) write_output(plan, file, results);
    } catch (const std::exception& e) {  // a ParseError naming the place, or an unwritable output
      progress.message(e.what());
      totals.bad_input = true;
      ++totals.failures;
    }
    std::fflush(stdout);
    progress.advance();
  }
  progress.summary(totals.polygons, totals.failures);
  if (totals.invalid) return invalid_result;
  return totals.bad_input ? bad_input : success;
}

}  // namespace pear::cli
