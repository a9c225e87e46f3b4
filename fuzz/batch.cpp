// Fuzz target "batch" (issue 30): pear::triangulate_batch on offsets from the bytes, in range
// or not: small values, runs, values out of order, the ends of int64 and any 8 bytes. The
// result must have one status per polygon and monotone offsets that end at its arrays' sizes;
// a polygon whose offsets this target finds bad must be invalid_input (invalid_offsets or
// empty_input) without triangles; any other polygon must come out exactly as pear::triangulate
// gives it alone (status, triangles shifted to batch indices, diagnostics).
//
// Bytes: a header (bit 0: two threads, bit 1: delaunay, bit 2: no simplicity check), the
// point count (mod 64) and a byte per point (x = low 4 bits, y = high 4 bits), then the ring
// offsets and the polygon offsets, each a count byte (mod 16, mod 9) and a mode byte per
// entry (read_offset).
#include <algorithm>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "pear/batch.hpp"
#include "pear/pear.hpp"
#include "support.hpp"

namespace {

constexpr std::int64_t int64_min = std::numeric_limits<std::int64_t>::min();
constexpr std::int64_t int64_max = std::numeric_limits<std::int64_t>::max();

/// One offset: mode % 8 picks the kind, mode / 8 the value; `limit` is the count the offset
/// indexes (points for ring offsets, rings for polygon offsets).
std::int64_t read_offset(fuzz::ByteReader& bytes, std::int64_t previous, std::int64_t limit) {
  const std::uint8_t mode = bytes.byte();
  const std::int64_t small = mode >> 3;
  switch (mode % 8) {
    case 4:
      return previous + small % 5;  // a run: mostly in order
    case 5: {
      const std::int64_t ends[8] = {int64_min,     int64_max,     -1,    limit + 1,
                                    int64_min + 1, int64_max - 1, limit, -limit - 1};
      return ends[small % 8];
    }
    case 6: {
      std::uint64_t bits = 0;
      for (int i = 0; i < 8; ++i) bits |= std::uint64_t{bytes.byte()} << (8 * i);
      return static_cast<std::int64_t>(bits);
    }
    case 7:
      return previous - 1 - small % 3;  // out of order
    default:
      return small % (limit + 2);  // mostly in range, sometimes one past
  }
}

std::vector<std::int64_t> read_offsets(fuzz::ByteReader& bytes, std::size_t count,
                                       std::int64_t limit) {
  std::vector<std::int64_t> offsets;
  std::int64_t previous = 0;
  for (std::size_t i = 0; i < count; ++i) {
    // Runs and steps back from the ends of int64 must not overflow in the target itself.
    previous = read_offset(bytes, std::clamp(previous, int64_min + 4, int64_max - 4), limit);
    offsets.push_back(previous);
  }
  return offsets;
}

/// Polygon p's rings and points when its offsets are good, by this target's own reading of
/// pear/batch.hpp's contract; `why` says what is wrong otherwise.
struct Located {
  bool good = false;
  pear::Issue why = pear::Issue::invalid_offsets;
  std::int64_t first_ring = 0, end_ring = 0, first_point = 0, end_point = 0;
};

Located locate(const std::vector<std::int64_t>& rings, const std::vector<std::int64_t>& polygons,
               std::size_t p, std::int64_t points) {
  Located at;
  const auto ring_count = static_cast<std::int64_t>(rings.size()) - 1;
  at.first_ring = polygons[p], at.end_ring = polygons[p + 1];
  if (at.first_ring < 0 || at.end_ring > ring_count || at.end_ring < at.first_ring) return at;
  if (at.first_ring == at.end_ring) {
    at.why = pear::Issue::empty_input;
    return at;
  }
  for (std::int64_t r = at.first_ring; r <= at.end_ring; ++r)
    if (rings[r] < 0 || rings[r] > points || (r > at.first_ring && rings[r] < rings[r - 1]))
      return at;
  at.first_point = rings[at.first_ring], at.end_point = rings[at.end_ring];
  at.good = true;
  return at;
}

/// The result's shape: one status per polygon, offsets from 0, monotone, ending at the sizes.
void check_shape(const pear::BatchTriangulation<>& result, std::size_t polygons) {
  fuzz::require(result.size() == polygons, "not one status per polygon");
  for (const auto* offsets : {&result.triangle_offsets, &result.diagnostic_offsets}) {
    fuzz::require(offsets->size() == polygons + 1 && offsets->front() == 0,
                  "offsets do not start at 0 with one entry per polygon and one more");
    for (std::size_t p = 0; p < polygons; ++p)
      fuzz::require((*offsets)[p] <= (*offsets)[p + 1], "offsets not monotone",
                    "polygon " + std::to_string(p));
  }
  fuzz::require(result.triangle_offsets.back() == std::int64_t(result.triangles.size()),
                "triangle offsets do not end at the triangle count");
  fuzz::require(result.diagnostic_offsets.back() == std::int64_t(result.diagnostics.size()),
                "diagnostic offsets do not end at the diagnostic count");
}

/// Polygon p triangulated alone, as the batch must have done it.
void check_same_as_alone(const pear::BatchTriangulation<>& result, std::size_t p, const Located& at,
                         const std::vector<pear::Point>& points,
                         const std::vector<std::int64_t>& rings, pear::Options options) {
  const std::string where = "polygon " + std::to_string(p);
  const std::vector<pear::Point> own(points.begin() + at.first_point,
                                     points.begin() + at.end_point);
  std::vector<std::uint32_t> offsets;
  for (std::int64_t r = at.first_ring; r <= at.end_ring; ++r)
    offsets.push_back(static_cast<std::uint32_t>(rings[r] - at.first_point));
  options.executor = nullptr;
  options.threads = 1;
  pear::Triangulator triangulator;
  const pear::Triangulation<> alone =
      triangulator.triangulate(pear::PolygonView{own, offsets}, options);
  fuzz::require(result.status[p] == alone.status, "status differs from a call alone", where);
  const std::int64_t t0 = result.triangle_offsets[p], t1 = result.triangle_offsets[p + 1];
  fuzz::require(std::size_t(t1 - t0) == alone.triangles.size(), "triangle count differs", where);
  const auto base = static_cast<std::uint32_t>(at.first_point);
  for (std::int64_t t = t0; t < t1; ++t)
    for (int k = 0; k < 3; ++k)
      fuzz::require(result.triangles[t][k] == alone.triangles[t - t0][k] + base,
                    "triangles differ from a call alone", where);
  const std::int64_t d0 = result.diagnostic_offsets[p], d1 = result.diagnostic_offsets[p + 1];
  fuzz::require(std::size_t(d1 - d0) == alone.diagnostics.size(), "diagnostics differ", where);
  for (std::int64_t d = d0; d < d1; ++d) {
    const pear::Diagnostic &a = result.diagnostics[d], &b = alone.diagnostics[d - d0];
    fuzz::require(a.issue == b.issue && a.ring == b.ring && a.vertex == b.vertex,
                  "a diagnostic differs from a call alone", where);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteReader bytes(data, size);
  const std::uint8_t header = bytes.byte();
  std::vector<pear::Point> points(bytes.byte() % 64);
  std::vector<double> coordinates;
  for (pear::Point& point : points) {
    const std::uint8_t cell = bytes.byte();
    point = {double(cell & 15), double(cell >> 4)};
    coordinates.insert(coordinates.end(), {point.x, point.y});
  }
  const auto point_count = static_cast<std::int64_t>(points.size());
  const std::vector<std::int64_t> rings = read_offsets(bytes, bytes.byte() % 16, point_count);
  const auto ring_count = std::max<std::int64_t>(0, std::int64_t(rings.size()) - 1);
  const std::vector<std::int64_t> polygons = read_offsets(bytes, bytes.byte() % 9, ring_count);

  pear::Options options;
  options.executor = fuzz::shared_executor(header & 1 ? 2 : 1);
  options.delaunay = header & 2;
  options.check_simplicity = !(header & 4);
  const pear::BatchTriangulation<> result =
      pear::triangulate_batch(pear::PolygonBatch{coordinates, rings, polygons}, options);
  const std::size_t count = polygons.empty() ? 0 : polygons.size() - 1;
  check_shape(result, count);
  for (std::size_t p = 0; p < count; ++p) {
    const Located at = locate(rings, polygons, p, point_count);
    if (at.good) {
      check_same_as_alone(result, p, at, points, rings, options);
      continue;
    }
    const std::string where = "polygon " + std::to_string(p);
    fuzz::require(result.status[p] == pear::Status::invalid_input,
                  "bad offsets are not invalid_input", where);
    fuzz::require(result.triangle_offsets[p] == result.triangle_offsets[p + 1],
                  "a polygon with bad offsets has triangles", where);
    fuzz::require(result.diagnostic_offsets[p] < result.diagnostic_offsets[p + 1] &&
                      result.diagnostics[result.diagnostic_offsets[p]].issue == at.why,
                  "bad offsets are not named", where);
  }
  return 0;
}
