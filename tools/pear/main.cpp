// pear: triangulate polygons from GeoJSON, WKT, WKB and .poly files; see `pear --help`.
#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#include "cli.hpp"

namespace {

constexpr const char* help = R"(pear: polygon triangulation by parallel ear clipping

usage: pear COMMAND [OPTIONS] [ARGS]

commands:
  triangulate FILE...   triangulate every polygon in the files (GeoJSON, WKT, WKB, .poly, .gz)
  stats FILE...         vertex, convex, reflex and ear counts of each polygon
  generate KIND N       write a synthetic polygon as GeoJSON

Each command has --help. Exit codes: 0 success; 1 bad input (each problem named on stderr,
other files still processed); 2 usage error; 3 --validate found an invalid triangulation.
)";

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string_view> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
    std::fputs(help, args.empty() ? stderr : stdout);
    return args.empty() ? pear::cli::usage : pear::cli::success;
  }
  if (args[0] == "--version") {
    std::puts("pear 0.1.0");
    return pear::cli::success;
  }
  const std::string_view command = args[0];
  const std::span<const std::string_view> rest(args.data() + 1, args.size() - 1);
  try {
    if (command == "triangulate") return pear::cli::run_triangulate(rest);
    if (command == "stats") return pear::cli::run_stats(rest);
    if (command == "generate") return pear::cli::run_generate(rest);
    throw pear::cli::UsageError("unknown command '" + std::string(command) + "'");
  } catch (const pear::cli::UsageError& e) {
    std::fprintf(stderr, "pear: %s\n(see 'pear --help')\n", e.what());
    return pear::cli::usage;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "pear: out of memory\n");
    return pear::cli::bad_input;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "pear: %s\n", e.what());
    return pear::cli::bad_input;
  }
}
