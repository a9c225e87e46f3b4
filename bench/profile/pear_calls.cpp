// pear_calls: one pear call per polygon of a folder, for counting instructions per stage under
// callgrind (bench/profile/stages.py runs it). Only run_calls is measured (callgrind's
// --toggle-collect), not the reading of the files.
//
//   pear_calls FOLDER MODE [ROUNDS]   MODE: top fast fastnocheck
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "pear/io.hpp"
#include "pear/pear.hpp"

namespace {

struct Flat {
  std::vector<pear::Point> points;
  std::vector<std::uint32_t> ring_ends{0};
};

std::vector<Flat> read_folder(const std::filesystem::path& folder, std::size_t& vertices) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(folder))
    if (entry.path().extension() == ".json" || entry.path().extension() == ".geojson")
      files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  std::vector<Flat> polygons;
  for (const auto& file : files)
    for (const pear::Polygon& polygon : pear::io::read_file(file)) {
      Flat& flat = polygons.emplace_back();
      for (const pear::Ring& ring : polygon) {
        flat.points.insert(flat.points.end(), ring.begin(), ring.end());
        flat.ring_ends.push_back(static_cast<std::uint32_t>(flat.points.size()));
      }
      vertices += flat.points.size();
    }
  return polygons;
}

}  // namespace

/// Every polygon once per round with one reused Triangulator, as a caller with many would.
__attribute__((noinline)) std::size_t run_calls(const std::vector<Flat>& polygons,
                                                const pear::Options& options, int rounds) {
  pear::Triangulator triangulator;
  pear::Triangulation<> result;
  std::size_t triangles = 0;
  for (int round = 0; round < rounds; ++round)
    for (const Flat& flat : polygons) {
      triangulator.triangulate_into(pear::PolygonView{flat.points, flat.ring_ends}, options,
                                    result);
      triangles += result.triangles.size();
    }
  return triangles;
}

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: pear_calls FOLDER top|fast|fastnocheck [ROUNDS]\n");
    return 2;
  }
  const std::string mode = argv[2];
  pear::Options options;
  options.threads = 1;
  if (mode != "top") options.heuristic = pear::EarHeuristic::fast;
  if (mode == "fastnocheck") options.check_simplicity = false;
  std::size_t vertices = 0;
  const std::vector<Flat> polygons = read_folder(argv[1], vertices);
  const std::size_t triangles = run_calls(polygons, options, argc > 3 ? std::atoi(argv[3]) : 1);
  std::printf("polygons %zu vertices %zu triangles %zu\n", polygons.size(), vertices, triangles);
}
