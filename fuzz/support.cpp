#include "support.hpp"

#include "pear/config.hpp"
#if PEAR_HAS_THREADS
#include "pear/scheduler.hpp"
#endif

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <sstream>

namespace fuzz {

double ByteReader::f64() {
  std::uint64_t bits = 0;
  for (int i = 0; i < 8; ++i) bits |= static_cast<std::uint64_t>(byte()) << (8 * i);
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

std::string_view ByteReader::rest() {
  if (empty()) return {};
  const std::string_view text(reinterpret_cast<const char*>(data_ + position_), size_ - position_);
  position_ = size_;
  return text;
}

void fail(std::string_view what, const std::string& detail) {
  std::fprintf(stderr, "fuzz check failed: %.*s\n%s\n", static_cast<int>(what.size()), what.data(),
               detail.c_str());
  std::fflush(stderr);
  std::abort();
}

mpq_class twice_area(const pear::Point& a, const pear::Point& b, const pear::Point& c) {
  const mpq_class ax(a.x), ay(a.y), bx(b.x), by(b.y), cx(c.x), cy(c.y);
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

mpq_class twice_ring_area(const pear::Ring& ring) {
  mpq_class sum = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const pear::Point& p = ring[i];
    const pear::Point& q = ring[(i + 1) % ring.size()];
    sum += mpq_class(p.x) * mpq_class(q.y) - mpq_class(q.x) * mpq_class(p.y);
  }
  return sum;
}

std::vector<pear::Point> flat_points(const pear::Polygon& polygon) {
  std::vector<pear::Point> points;
  for (const pear::Ring& ring : polygon) points.insert(points.end(), ring.begin(), ring.end());
  return points;
}

mpq_class twice_triangles_area(const std::vector<pear::Point>& points, const Triangles& triangles) {
  mpq_class sum = 0;
  for (const auto& [a, b, c] : triangles) sum += twice_area(points[a], points[b], points[c]);
  return sum;
}

pear::ValidationReport check_any_result(const pear::Polygon& polygon,
                                        const pear::Triangulation<>& result, bool check_delaunay) {
  const std::size_t point_count = flat_points(polygon).size();
  for (const auto& triangle : result.triangles)
    for (std::uint32_t index : triangle)
      require(index < point_count, "triangle index out of range", describe(polygon));
  if (result.status == pear::Status::invalid_input)
    require(result.triangles.empty(), "triangles returned with invalid_input", describe(polygon));
  if (result.status != pear::Status::ok) return {};
  pear::ValidateOptions options;
  options.check_delaunay = check_delaunay;
  pear::ValidationReport report = pear::validate(polygon, result.triangles, options);
  if (!report.valid) {
    std::string detail = describe(polygon);
    for (const std::string& message : report.messages) detail += "\n  " + message;
    fail("Status::ok but pear::validate rejects the triangulation", detail);
  }
  return report;
}

mpq_class twice_polygon_area(const pear::Polygon& polygon) {
  mpq_class area = 0;
  for (std::size_t r = 0; r < polygon.size(); ++r) {
    const mpq_class ring_area = abs(twice_ring_area(polygon[r]));
    area += r == 0 ? ring_area : -ring_area;
  }
  return area;
}

void check_exact_triangulation(const pear::Polygon& polygon, const pear::Triangulation<>& result,
                               std::size_t expected_triangles, const mpq_class& twice_area) {
  require(result.status == pear::Status::ok, "a valid polygon was not triangulated",
          describe(polygon) + "\nstatus: " + pear::to_string(result.status));
  require(result.triangles.size() == expected_triangles, "wrong triangle count",
          describe(polygon) + "\nexpected " + std::to_string(expected_triangles) + ", got " +
              std::to_string(result.triangles.size()));
  require(twice_triangles_area(flat_points(polygon), result.triangles) == twice_area,
          "the triangles do not cover the polygon's exact area", describe(polygon));
}

pear::Executor* shared_executor([[maybe_unused]] unsigned threads) {
#if PEAR_HAS_THREADS
  static std::array<std::unique_ptr<pear::Executor>, 3> executors;
  std::unique_ptr<pear::Executor>& slot = executors.at(threads - 1);
  if (!slot) slot = std::make_unique<pear::Executor>(threads);
  return slot.get();
#else
  return nullptr;
#endif
}

std::string describe(const pear::Polygon& polygon) {
  std::ostringstream out;
  out.precision(17);
  out << "polygon with " << polygon.size() << " rings:";
  for (const pear::Ring& ring : polygon) {
    out << "\n  [";
    for (const pear::Point& p : ring) out << " (" << p.x << ", " << p.y << ")";
    out << " ]";
  }
  return out.str();
}

}  // namespace fuzz
