// `pear generate KIND N`: a synthetic polygon as GeoJSON, deterministic in --seed.
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>

#include "cli.hpp"
#include "pear/generate.hpp"
#include "pear/io.hpp"

namespace pear::cli {
namespace {

void print_help() {
  std::string kinds;
  for (const std::string_view kind : generator_kinds()) {
    kinds += ' ';
    kinds += kind;
  }
  std::printf(R"(usage: pear generate [OPTIONS] KIND N

Writes a valid polygon of about N vertices (at most 100000000) of the family KIND as GeoJSON,
the same for the same --seed. Kinds:%s

options:
  --seed S   the random seed (default 1)
  -o OUT     write to OUT instead of stdout
  --help     this text
)",
              kinds.c_str());
}

/// Above this the polygon (16 bytes a vertex, and its text) would not fit a machine's memory
/// anyway: a usage error, not an allocation failure.
constexpr std::size_t max_generated_vertices = 100'000'000;

}  // namespace

int run_generate(std::span<const std::string_view> arguments) {
  Args args(arguments);
  std::uint64_t seed = 1;
  std::optional<std::string> output;
  while (const auto option = args.next_option()) {
    if (option == "--help" || option == "-h") {
      print_help();
      return success;
    } else if (option == "--seed") {
      seed = args.integer(0, UINT64_MAX);
    } else if (option == "-o" || option == "--output") {
      output = std::string(args.value());
    } else {
      args.unknown();
    }
  }
  const auto& positionals = args.positionals();
  if (positionals.size() != 2) throw UsageError("generate needs KIND and N");
  const std::string_view kind = positionals[0];
  bool known = false;
  for (const std::string_view k : generator_kinds()) known = known || k == kind;
  if (!known)
    throw UsageError("unknown kind '" + std::string(kind) + "' (see pear generate --help)");
  const std::string_view count_text = positionals[1];
  std::size_t count = 0;
  const auto [ptr, ec] =
      std::from_chars(count_text.data(), count_text.data() + count_text.size(), count);
  if (ec != std::errc() || ptr != count_text.data() + count_text.size() || count == 0 ||
      count > max_generated_vertices)
    throw UsageError("N must be a positive integer up to " +
                     std::to_string(max_generated_vertices) + ", not '" + std::string(count_text) +
                     "'");
  Polygon polygon;
  try {
    polygon = generate_polygon(kind, count, seed);
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  const Polygon polygons[] = {std::move(polygon)};
  if (!output || *output == "-") {
    io::write_geojson_polygons(std::cout, polygons);
    std::cout.flush();
    return success;
  }
  errno = 0;
  std::ofstream out(*output, std::ios::binary);
  if (out) io::write_geojson_polygons(out, polygons);
  if (!out.flush())
    throw std::runtime_error("cannot write " + *output + ": " + std::strerror(errno));
  return success;
}

}  // namespace pear::cli
