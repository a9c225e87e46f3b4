// `pear triangulate FILE...`: read, triangulate, optionally validate, report and write.
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <span>

#include "cli.hpp"
#include "inputs.hpp"
#include "json_line.hpp"
#include "output.hpp"
#include "pear/config.hpp"
#include "pear/quality.hpp"
#if PEAR_HAS_THREADS
#include "pear/scheduler.hpp"
#endif
#include "pear/validate.hpp"

namespace pear::cli {
namespace {

struct Settings {
  std::string algorithm_name = "auto";
  Options options;
  bool validate = false;
  bool stats = false;
  bool profile = false;
  io::ReadOptions read;
  std::size_t gzip_limit = default_gzip_limit;
  std::optional<std::string> output;
  std::optional<FormatChoice> format;
  gis::LayerChoice layer;
  std::vector<std::string_view> inputs;
};

void print_help() {
  std::string algorithms;
  for (const AlgorithmName& a : algorithm_names())
    algorithms += "      " + std::string(a.name) + std::string(20 - a.name.size(), ' ') +
                  std::string(a.summary) + (a.algorithm ? "" : " [not in this build]") + "\n";
  std::printf(R"(usage: pear triangulate [OPTIONS] FILE...

Triangulates every polygon in the files: GeoJSON (.json, .geojson), WKT or EWKT (.wkt),
Triangle's .poly, WKB or EWKB (.wkb: one value; .hexwkb, .wkb.hex: hex, a value a line), any
of them gzipped (.gz); '-' reads stdin. Directories are searched for such files; quoted globs
are expanded. Points and lines among the polygons are skipped, each named on stderr. GeoJSON
output keeps each feature's properties (pear's own under "pear") and the SRID; GeoJSON and
OBJ keep z (docs/cli.md). Built with GDAL, pear also reads any OGR vector file (GeoPackage,
Shapefile, FlatGeobuf, ...: every file whose extension is not pear's own that GDAL opens) and
writes a layer with one feature per input feature, its attributes, FID and CRS.

options:
  --algorithm NAME    which triangulation algorithm (default auto):
%s  --threads N         threads for the parallel algorithms (default: all hardware threads)
  --partitions K      parts the parallel algorithms cut the work into, 1 to 4096 (default:
                      the thread count); the output depends on K, never on the threads
  --heuristic top|fast  ear order: shortest diagonal weighted by shape (top, default), or
                      a walk along the boundary (fast: quickest, thinner triangles)
  --cdt               make the triangulation constrained Delaunay (exact edge flips); with
                      --validate, every interior edge is checked to be locally Delaunay
  --validate          check every result with pear's independent validator
  --stats             print one JSON object per polygon on stdout: file, index, vertices,
                      holes, triangles, status, algorithm, threads, cdt, ms (triangulation
                      only), min_angle_avg_deg, dev60_avg_deg (with --validate also valid,
                      area_rel_error)
  --profile           with --stats: each polygon's run alone, its lines adding work_ms and
                      span_ms (all tasks; the longest path through the phases) and
                      projected_speedup, the bound work / time on 2, 4, 8 and 16 threads
                      for the run's --partitions (docs/cli.md)
  -o OUT              write the triangulations: one file for one input; a directory (an
                      existing one, or a name ending in '/') for one output per input, named
                      after it; '-' for stdout. Two inputs that would write the same file, or
                      an output that would overwrite an input, are a usage error
  --format F          obj, geojson, node (.node + .ele) or svg, or (built with GDAL) a GDAL
                      vector driver: GPKG, "ESRI Shapefile", FlatGeobuf, ...; else guessed from
                      OUT's extension (.gpkg, .shp, .fgb and any a GDAL driver claims)
  --layer NAME        the layer of a GDAL input (default: its first)
  --where SQL         an OGR attribute filter on a GDAL input's features
  --keep-small-rings  accept rings of fewer than 3 points (as earcut's fixtures have); the
                      engine drops such holes
  --gzip-limit SIZE   a .gz that inflates past SIZE bytes (K, M, G: KiB, MiB, GiB) is refused
                      as a likely decompression bomb, whatever its own size (default 1G)
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
      s.options.partitions = static_cast<unsigned>(args.integer(1, max_partitions));
    } else if (option == "--heuristic") {
      const std::string_view h = args.value();
      if (h != "top" && h != "fast") throw UsageError("--heuristic expects top or fast");
      s.options.heuristic = h == "top" ? EarHeuristic::top : EarHeuristic::fast;
    } else if (option == "--cdt") {
      args.no_value();
      s.options.delaunay = true;
    } else if (option == "--validate" || option == "--stats" || option == "--profile" ||
               option == "--keep-small-rings") {
      args.no_value();
      (option == "--validate"  ? s.validate
       : option == "--stats"   ? s.stats
       : option == "--profile" ? s.profile
                               : s.read.keep_small_rings) = true;
    } else if (option == "-o" || option == "--output") {
      s.output = std::string(args.value());
    } else if (option == "--format") {
      s.format = parse_output_format(args.value());
    } else if (option == "--gzip-limit") {
      s.gzip_limit = args.byte_size();
    } else if (option == "--layer" || option == "--where") {
      if (!gis::available())
        throw UsageError(std::string(*option) + " needs a pear built with GDAL");
      (option == "--layer" ? s.layer.layer : s.layer.where) = std::string(args.value());
    } else {
      args.unknown();
    }
  }
  s.inputs = args.positionals();
  if (s.inputs.empty()) throw UsageError("triangulate needs at least one FILE (or '-' for stdin)");
  if (s.output == "-" && s.stats) throw UsageError("-o - and --stats would both write to stdout");
  if (s.profile && !s.stats) throw UsageError("--profile adds to the lines of --stats: give both");
  return s;
}

std::size_t thread_count(const Options& options) {
#if PEAR_HAS_THREADS
  return options.threads ? options.threads : default_executor().concurrency();
#else
  return options.threads ? options.threads : 1;  // no threads: all on this one
#endif
}

struct Totals {
  std::size_t polygons = 0;
  std::size_t failures = 0;
  bool bad_input = false;
  bool invalid = false;
};

/// How messages name an input.
std::string display_name(const Input& input) {
  return input.name == "-" ? "<stdin>" : input.name;
}

/// What the batch gave for one polygon, with indices into the polygon's own points.
struct PolygonResult {
  std::vector<std::array<std::uint32_t, 3>> triangles;
  Status status = Status::ok;
  std::vector<Diagnostic> diagnostics;
  double ms = 0;
  std::optional<RunProfile> profile;  ///< with --profile: this polygon's run alone
};

/// The diagnostic that says why the status is not ok (warnings about what was repaired, such as
/// a dropped hole, may come before it); the first when none matches.
const Diagnostic* explaining(Status status, std::span<const Diagnostic> diagnostics) {
  for (const Diagnostic& d : diagnostics)
    if (status == Status::not_simple ? d.is_not_simple() : d.is_error()) return &d;
  return diagnostics.empty() ? nullptr : &diagnostics.front();
}

/// --profile's fields: the run's work and span, and its speedup bound on 2 to 16 threads (work
/// over RunProfile::projected, Brent's bound per phase for the run's partitions).
void add_profile(JsonLine& line, const RunProfile& profile) {
  const double work = profile.work();
  line.add("work_ms", 1000 * work).add("span_ms", 1000 * profile.span());
  JsonLine speedups;
  for (const unsigned threads : {2u, 4u, 8u, 16u}) {
    const double projected = profile.projected(threads);
    // projected >= work / threads but for rounding: the bound is kept within [1, threads].
    const double bound = projected > 0 ? std::min(work / projected, double(threads)) : 1.0;
    speedups.add(std::to_string(threads), bound);
  }
  line.add("projected_speedup", speedups);
}

// Reports one polygon's result: its stats line, its problems (and the test build's fault).
// The feature's polygon, z, m and properties move into what is written.
io::TriangulatedPolygon report_one(const Settings& s, io::Feature& feature, PolygonResult result,
                                   const std::string& file, std::size_t index, Totals& totals,
                                   Progress& progress) {
  const Polygon& polygon = feature.polygon;
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
    const Diagnostic* cause = explaining(result.status, result.diagnostics);
    const std::string why = cause ? describe(*cause) : "";
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
    line.add("ms", result.ms).add("min_angle_avg_deg", q.min_angle_avg_deg);
    line.add("dev60_avg_deg", q.dev60_avg_deg);
    if (result.profile) add_profile(line, *result.profile);
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
  return {.polygon = std::move(feature.polygon),
          .triangles = std::move(result.triangles),
          .z = std::move(feature.z),
          .m = std::move(feature.m),
          .properties = std::move(feature.properties),
          .feature_index = feature.feature_index,
          .status = result.status};
}

/// Files read but not yet triangulated: they go to pear::triangulate_batch together, so that
/// many small polygons (a directory of parcels, a file of countries) run in parallel.
class Group {
 public:
  /// Vertices past which the group is triangulated before more files are read.
  static constexpr std::size_t vertex_budget = std::size_t{1} << 20;

  void add(std::string file, gis::Read read) {
    for (const io::Feature& feature : read.read.features)
      for (const Ring& ring : feature.polygon) vertices_ += ring.size();
    files_.push_back({std::move(file), std::move(read)});
  }
  bool full() const { return vertices_ >= vertex_budget; }

  /// Triangulates every polygon of the group as one batch (with --profile, one at a time),
  /// then reports and writes file by file, in the order the files came.
  void flush(const Settings& s, const OutputPlan& plan, Totals& totals, Progress& progress) {
    if (files_.empty()) return;
    std::optional<Batch> together;
    if (!s.profile) {
      try {
        together = triangulate_together(s.options);
      } catch (const std::bad_alloc&) {
        flush_one_by_one(s, plan, totals, progress);
        return;
      }
    }
    std::size_t p = 0;
    for (File& f : files_) {
      // What the read skipped, said here to stay in the order of the files.
      if (!f.read.note.empty()) progress.message(f.read.note);
      for (const std::string& warning : skipped_warnings(f.name == "-" ? "<stdin>" : f.name,
                                                         f.read.read, f.read.source != nullptr))
        progress.message(warning);
      try {
        std::vector<io::TriangulatedPolygon> results;
        for (std::size_t i = 0; i < f.read.read.features.size(); ++i, ++p) {
          io::Feature& feature = f.read.read.features[i];
          PolygonResult result =
              together ? together->take(p) : triangulate_alone(feature.polygon, s.options);
          results.push_back(report_one(s, feature, std::move(result), f.name, i, totals, progress));
          ++totals.polygons;
        }
        if (plan.format)
          for (const std::string& note : write_output(plan, f.name, results, f.read.read.srid,
                                                      f.read.source.get(), f.read.layer))
            progress.message(note);
      } catch (const std::bad_alloc&) {
        fail(f.name + ": out of memory while triangulating, reporting or writing it", totals,
             progress);
      } catch (const std::exception& e) {  // an unwritable output, named with the reason
        fail(e.what(), totals, progress);
      }
      std::fflush(stdout);
      progress.advance();
    }
    clear();
  }

 private:
  struct File {
    std::string name;
    gis::Read read;
  };

  /// The group's polygons as one batch, with the offsets that locate each polygon in it.
  struct Batch {
    BatchTriangulation<> triangles;
    RunProfile profile;  // one phase: each polygon's time
    std::vector<std::int64_t> ring_offsets{0}, polygon_offsets{0};

    /// Polygon p's result, its indices made local to the polygon again.
    PolygonResult take(std::size_t p) const {
      PolygonResult r;
      const auto base = static_cast<std::uint32_t>(ring_offsets[polygon_offsets[p]]);
      for (auto t = triangles.triangle_offsets[p]; t < triangles.triangle_offsets[p + 1]; ++t) {
        const auto& triangle = triangles.triangles[t];
        r.triangles.push_back({triangle[0] - base, triangle[1] - base, triangle[2] - base});
      }
      r.status = triangles.status[p];
      r.diagnostics.assign(triangles.diagnostics.begin() + triangles.diagnostic_offsets[p],
                           triangles.diagnostics.begin() + triangles.diagnostic_offsets[p + 1]);
      r.ms = 1000 * profile.phases.front().task_seconds[p];
      return r;
    }
  };

  Batch triangulate_together(const Options& options) const {
    Batch b;
    std::vector<double> coordinates;
    coordinates.reserve(2 * vertices_);
    for (const File& f : files_) {
      for (const io::Feature& feature : f.read.read.features) {
        for (const Ring& ring : feature.polygon) {
          for (const Point& p : ring) coordinates.insert(coordinates.end(), {p.x, p.y});
          b.ring_offsets.push_back(static_cast<std::int64_t>(coordinates.size() / 2));
        }
        b.polygon_offsets.push_back(static_cast<std::int64_t>(b.ring_offsets.size() - 1));
      }
    }
    Options with_times = options;
    with_times.profile = &b.profile;  // each polygon's time, for --stats
    b.triangles =
        triangulate_batch(PolygonBatch{coordinates, b.ring_offsets, b.polygon_offsets}, with_times);
    return b;
  }

  /// One polygon in a run of its own, profiled: --profile's figures are that run's.
  PolygonResult triangulate_alone(const Polygon& polygon, const Options& options) {
    PolygonResult r;
    r.profile.emplace();
    Options profiled = options;
    profiled.profile = &*r.profile;
    const auto start = std::chrono::steady_clock::now();
    Triangulation<> t = triangulator_.triangulate(polygon, profiled);
    r.ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    r.triangles = std::move(t.triangles);
    r.status = t.status;
    r.diagnostics = std::move(t.diagnostics);
    return r;
  }

  /// The files together did not fit: each alone may, and one that does not is named.
  void flush_one_by_one(const Settings& s, const OutputPlan& plan, Totals& totals,
                        Progress& progress) {
    std::vector<File> files = std::move(files_);
    clear();
    for (File& f : files) {
      if (files.size() == 1) {
        fail(f.name + ": out of memory while triangulating it", totals, progress);
        progress.advance();
        continue;
      }
      add(std::move(f.name), std::move(f.read));
      flush(s, plan, totals, progress);
    }
  }

  static void fail(const std::string& message, Totals& totals, Progress& progress) {
    progress.message(message);
    totals.bad_input = true;
    ++totals.failures;
  }

  void clear() {
    files_.clear();
    vertices_ = 0;
  }

  Triangulator triangulator_;  // --profile's runs, one polygon at a time
  std::vector<File> files_;
  std::size_t vertices_ = 0;
};

}  // namespace

int run_triangulate(std::span<const std::string_view> arguments) {
  const Settings s = parse(arguments);
  const std::vector<Input> inputs = expand_inputs(s.inputs);
  const OutputPlan plan = plan_output(s.output, s.format, inputs);
  Progress progress(inputs.size());
  Totals totals;
  Group group;
  for (const Input& input : inputs) {
    std::string problem;
    gis::Read read;
    try {
      read = read_input(input, s.read, s.gzip_limit, s.layer);
      if (read.read.features.empty()) problem = display_name(input) + ": no polygon in it";
    } catch (const io::ParseError& e) {  // naming the place
      problem = e.what();
    } catch (const std::bad_alloc&) {
      problem = display_name(input) + ": out of memory while reading it";
    } catch (const std::exception& e) {
      problem = display_name(input) + ": " + e.what();
    }
    if (!problem.empty()) {
      group.flush(s, plan, totals, progress);  // the messages stay in the order of the files
      progress.message(problem);
      totals.bad_input = true;
      ++totals.failures;
      progress.advance();
      continue;
    }
    group.add(input.name, std::move(read));
    if (group.full()) group.flush(s, plan, totals, progress);
  }
  group.flush(s, plan, totals, progress);
  progress.summary(totals.polygons, totals.failures);
  if (totals.invalid) return invalid_result;
  return totals.bad_input ? bad_input : success;
}

}  // namespace pear::cli
