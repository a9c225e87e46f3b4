// Shared by the fuzz targets: reading the fuzzer's bytes, failing loudly, exact areas, and the
// checks every triangulation must pass whatever its input.
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "pear/pear.hpp"
#include "pear/validate.hpp"

namespace pear {
class Executor;
}

namespace fuzz {

/// Takes values off the front of the fuzzer's bytes. Past the end every value is zero, so any
/// input decodes to something and a short input to a small polygon.
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  bool empty() const { return position_ >= size_; }
  std::uint8_t byte() { return empty() ? 0 : data_[position_++]; }
  std::uint16_t u16() { return static_cast<std::uint16_t>(byte() | (byte() << 8)); }
  /// Eight bytes, little endian, as the bits of a double (any value, NaN included).
  double f64();
  /// What is left, as text.
  std::string_view rest();

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t position_ = 0;
};

/// Prints what failed and aborts: libFuzzer saves the input as a crash, a replay test fails.
[[noreturn]] void fail(std::string_view what, const std::string& detail = {});
inline void require(bool condition, std::string_view what, const std::string& detail = {}) {
  if (!condition) fail(what, detail);
}

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

/// Twice the signed area of triangle abc, exactly (doubles convert to rationals exactly).
mpq_class twice_area(const pear::Point& a, const pear::Point& b, const pear::Point& c);
/// Twice the signed area of a ring (shoelace), exactly.
mpq_class twice_ring_area(const pear::Ring& ring);
/// All points ring after ring: what pear's triangle indices number.
std::vector<pear::Point> flat_points(const pear::Polygon& polygon);
/// Twice the area the triangles cover, exactly (each counted with its sign).
mpq_class twice_triangles_area(const std::vector<pear::Point>& points, const Triangles& triangles);

/// The promises that hold for any input: indices in range, no triangles after invalid_input,
/// and Status::ok only with a triangulation pear::validate accepts. Returns the validation
/// report (valid stays true when the status is not ok and nothing was validated).
pear::ValidationReport check_any_result(const pear::Polygon& polygon,
                                        const pear::Triangulation<>& result,
                                        bool check_delaunay = false);

/// Twice the area of a valid polygon (outer ring minus holes, either orientation), exactly.
mpq_class twice_polygon_area(const pear::Polygon& polygon);

/// For a polygon known to be valid: Status::ok, the expected triangle count, and triangles that
/// cover exactly the polygon's area (on top of check_any_result's validation).
void check_exact_triangulation(const pear::Polygon& polygon, const pear::Triangulation<>& result,
                               std::size_t expected_triangles, const mpq_class& twice_area);

/// One executor for each thread count 1 to 3, made on first use and kept: starting threads for
/// every input would cost more than the triangulations.
pear::Executor* shared_executor(unsigned threads);

/// A short text of the polygon for failure messages (first points of each ring).
std::string describe(const pear::Polygon& polygon);

}  // namespace fuzz
