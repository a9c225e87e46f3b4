// `pear stats FILE...`: the paper's ear prevalence (Fig. 7) of each polygon: how many of its
// vertices, and of its convex vertices, are ears before any clipping.
#include <cstdio>

#include "cli.hpp"
#include "inputs.hpp"
#include "json_line.hpp"

namespace pear::cli {
namespace {

constexpr const char* help = R"(usage: pear stats [OPTIONS] FILE...

For each polygon: vertices of the cleaned, bridged boundary, how many are convex, reflex
(or collinear) and ears, and the fractions of vertices and of convex vertices that are ears.
Inputs as for 'pear triangulate' (files, directories, globs, '-', .gz).

options:
  --json              one JSON object per polygon per line instead of a table
  --keep-small-rings  accept rings of fewer than 3 points
  --gzip-limit SIZE   refuse a .gz that inflates past SIZE bytes (K, M, G; default 1G)
  --help              this text
)";

double fraction(std::size_t part, std::size_t whole) {
  return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
}

}  // namespace

int run_stats(std::span<const std::string_view> arguments) {
  Args args(arguments);
  bool json = false;
  io::ReadOptions read;
  std::size_t gzip_limit = default_gzip_limit;
  while (const auto option = args.next_option()) {
    if (option == "--help" || option == "-h") {
      std::fputs(help, stdout);
      return success;
    } else if (option == "--json" || option == "--keep-small-rings") {
      args.no_value();
      (option == "--json" ? json : read.keep_small_rings) = true;
    } else if (option == "--gzip-limit") {
      gzip_limit = args.byte_size();
    } else {
      args.unknown();
    }
  }
  if (args.positionals().empty()) throw UsageError("stats needs at least one FILE (or '-')");
  const std::vector<Input> inputs = expand_inputs(args.positionals());
  Progress progress(inputs.size());
  Triangulator triangulator;
  std::size_t polygons_total = 0, failures = 0;
  if (!json)
    std::printf("%9s %6s %9s %9s %9s %9s %11s  %s\n", "vertices", "holes", "convex", "reflex",
                "ears", "ears/vert", "ears/convex", "file:polygon");
  for (const Input& input : inputs) {
    const std::string& file = input.name;
    try {
      const gis::Read gis_read = read_input(input, read, gzip_limit);
      const io::ReadResult& result = gis_read.read;
      if (!gis_read.note.empty()) progress.message(gis_read.note);
      for (const std::string& warning : skipped_warnings(file, result, gis_read.source != nullptr))
        progress.message(warning);
      std::vector<Polygon> polygons;
      for (const io::Feature& feature : result.features) polygons.push_back(feature.polygon);
      if (polygons.empty()) throw io::ParseError(file, 0, 0, 0, "no polygon in it");
      for (std::size_t i = 0; i < polygons.size(); ++i, ++polygons_total) {
        const EarStatistics e = triangulator.ear_statistics(polygons[i]);
        const std::size_t holes = polygons[i].empty() ? 0 : polygons[i].size() - 1;
        if (json) {
          JsonLine line;
          line.add("file", file).add("index", i).add("vertices", e.vertices).add("holes", holes);
          line.add("convex", e.convex).add("reflex", e.reflex).add("ears", e.ears);
          line.add("ear_fraction", fraction(e.ears, e.vertices));
          line.add("convex_ear_fraction", fraction(e.ears, e.convex));
          std::printf("%s\n", line.str().c_str());
        } else {
          std::printf("%9zu %6zu %9zu %9zu %9zu %9.3f %11.3f  %s:%zu\n", e.vertices, holes,
                      e.convex, e.reflex, e.ears, fraction(e.ears, e.vertices),
                      fraction(e.ears, e.convex), file.c_str(), i);
        }
      }
    } catch (const io::ParseError& e) {
      progress.message(e.what());
      ++failures;
    } catch (const std::bad_alloc&) {
      progress.message(file + ": out of memory");
      ++failures;
    }
    std::fflush(stdout);
    progress.advance();
  }
  progress.summary(polygons_total, failures);
  return failures > 0 ? bad_input : success;
}

}  // namespace pear::cli
