// A CMake user's program: triangulates a square with a hole (pear::pear) and the polygons of a
// WKT string (pear::io), and checks the triangle counts that n + 2h - 2 gives (n vertices, h
// holes). Exits 1, saying what differs, when any check fails.
#include <pear/io.hpp>
#include <pear/pear.hpp>
#include <pear/validate.hpp>

#include <cstdio>
#include <string_view>

namespace {

bool triangulates(const pear::Polygon& polygon, std::size_t expected, std::string_view what) {
  const auto result = pear::triangulate(polygon);
  const auto report = pear::validate(polygon, result.triangles);
  if (result.status == pear::Status::ok && result.triangles.size() == expected && report.valid)
    return true;
  std::fprintf(stderr, "cmake_consumer: %.*s: status %s, %zu triangles (expected %zu), %s\n",
               static_cast<int>(what.size()), what.data(), pear::to_string(result.status),
               result.triangles.size(), expected, report.valid ? "valid" : "not valid");
  return false;
}

}  // namespace

int main() {
  const pear::Polygon square_with_hole = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                                          {{4, 4}, {4, 6}, {6, 6}, {6, 4}}};
  bool ok = triangulates(square_with_hole, 8, "square with a hole");

  // The same square with its hole and a triangle, closed rings as WKT writes them.
  const auto polygons = pear::io::read_wkt(
      "MULTIPOLYGON(((0 0,10 0,10 10,0 10,0 0),(4 4,4 6,6 6,6 4,4 4)),((20 0,24 0,22 3,20 0)))");
  if (polygons.size() != 2) {
    std::fprintf(stderr, "cmake_consumer: WKT gave %zu polygons, expected 2\n", polygons.size());
    return 1;
  }
  ok = triangulates(polygons[0], 8, "WKT square with a hole") && ok;
  ok = triangulates(polygons[1], 1, "WKT triangle") && ok;
  if (ok) std::puts("cmake_consumer: ok");
  return ok ? 0 : 1;
}
