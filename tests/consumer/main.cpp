// Triangulates a square with a square hole through pear's public API: 8 vertices and 1 hole
// need n + 2h - 2 = 8 triangles. Exits 0 iff pear says ok, gives 8 triangles, and its own
// validator accepts them.
#include <pear/pear.hpp>
#include <pear/validate.hpp>

#include <cstdio>

int main() {
  const pear::Polygon polygon = {{{0, 0}, {10, 0}, {10, 10}, {0, 10}},
                                 {{3, 3}, {3, 7}, {7, 7}, {7, 3}}};
  const auto result = pear::triangulate(polygon);
  if (result.status != pear::Status::ok) {
    std::fprintf(stderr, "consumer: status %s\n", pear::to_string(result.status));
    return 1;
  }
  if (result.triangles.size() != 8) {
    std::fprintf(stderr, "consumer: %zu triangles, expected 8\n", result.triangles.size());
    return 1;
  }
  const auto report = pear::validate(polygon, std::span(result.triangles));
  for (const auto& message : report.messages)
    std::fprintf(stderr, "consumer: %s\n", message.c_str());
  return report.valid ? 0 : 1;
}
