// pear's C ABI for JavaScript (js/pear.js): the WebAssembly module's exports.
//
// JavaScript cannot hand wasm a pointer to its own arrays, so every input goes through
// buffers that live here and are reused: the loader asks for room (pear_points, ...), writes
// into wasm memory, calls, and reads the results where the returned Results says they are.
// Buffers only grow, and a call of the same size as an earlier one allocates nothing, so
// repeated calls leave memory.buffer the same size. One polygon's results stay valid until the
// next call of the same kind. Built only for wasm32 (js/meson.build), on the public API only.
#include <cstdint>
#include <string>
#include <vector>

#include "pear/pear.hpp"
#include "pear/validate.hpp"

#define PEAR_WASM_EXPORT(name) extern "C" __attribute__((export_name(#name))) auto name

namespace {

/// Where a call's results are: the loader reads this struct out of wasm memory (uint32 fields).
struct Results {
  std::uint32_t status = 0;
  std::uint32_t triangles = 0;  ///< address of 3 x count uint32 indices
  std::uint32_t triangle_count = 0;
  std::uint32_t diagnostics = 0;  ///< address of (issue, ring, vertex) uint32 triples
  std::uint32_t diagnostic_count = 0;
  std::uint32_t flips = 0;  ///< CDT flips
};

/// Where pear_polygon made room: the points' and the ring offsets' addresses.
struct Room {
  std::uint32_t points = 0, ring_offsets = 0;
};

/// A batch's extra results: per polygon offsets and statuses (see pear::BatchTriangulation).
struct BatchResults {
  std::uint32_t triangle_offsets = 0;    ///< polygons + 1 uint32
  std::uint32_t diagnostic_offsets = 0;  ///< polygons + 1 uint32
  std::uint32_t status = 0;              ///< polygons uint8
};

/// The validator's report as uint32 fields plus the area error (a double, 8-aligned).
struct Report {
  std::uint32_t valid = 0, triangles = 0, expected_triangles = 0, zero_area_triangles = 0;
  std::uint32_t bad_orientation = 0, bad_edges = 0, non_delaunay_edges = 0, messages = 0;
  double area_rel_error = 0;
};

template <class T>
std::uint32_t address(const T* pointer) {
  return static_cast<std::uint32_t>(reinterpret_cast<std::uintptr_t>(pointer));
}

/// Everything the module keeps between calls.
struct Session {
  std::vector<pear::Point> points;
  std::vector<std::uint32_t> ring_offsets;
  std::vector<std::array<std::uint32_t, 3>> triangles_in;  ///< for the validator
  pear::Triangulator triangulator;
  pear::Triangulation<std::uint32_t> result;
  std::vector<std::uint32_t> diagnostics;
  Results results;
  Room room;
  // The batch: offsets come as uint32 and are widened to the int64 of pear::PolygonBatch.
  std::vector<std::uint32_t> batch_offsets_in;
  std::vector<std::int64_t> batch_ring_offsets, batch_polygon_offsets;
  pear::BatchTriangulation<std::uint32_t> batch;
  std::vector<std::uint32_t> batch_triangle_offsets, batch_diagnostic_offsets;
  BatchResults batch_results;
  pear::ValidationReport validation;
  Report report;
  std::string text;
};

Session& session() {
  static Session instance;
  return instance;
}

/// Options from the loader's bits: algorithm (bits 0-2), heuristic fast (3), delaunay (4),
/// no simplicity check (5). Always on the calling thread, as the build has no threads.
pear::Options options_from(std::uint32_t bits) {
  pear::Options options;
  options.algorithm = static_cast<pear::Algorithm>(bits & 7u);
  options.heuristic = (bits & 8u) ? pear::EarHeuristic::fast : pear::EarHeuristic::top;
  options.delaunay = (bits & 16u) != 0;
  options.check_simplicity = (bits & 32u) == 0;
  options.threads = 1;
  return options;
}

void copy_diagnostics(std::span<const pear::Diagnostic> from, std::vector<std::uint32_t>& to) {
  for (const pear::Diagnostic& d : from) {
    to.push_back(static_cast<std::uint32_t>(d.issue));
    to.push_back(static_cast<std::uint32_t>(d.ring));
    to.push_back(static_cast<std::uint32_t>(d.vertex));
  }
}

}  // namespace

/// Makes `v` at least `count` long: it never shrinks, so that room made for a polygon stays
/// where it is for every smaller one, and the loader asks again only when one is larger.
template <class T>
void grow_to(std::vector<T>& v, std::uint32_t count) {
  if (v.size() < count) v.resize(count);
}

/// Room for `count` points (x, y interleaved doubles); returns its address.
PEAR_WASM_EXPORT(pear_points)(std::uint32_t count)->double* {
  Session& s = session();
  grow_to(s.points, count);
  return &s.points.data()->x;
}

/// Room for a polygon's `points` points (x, y interleaved doubles) and `offsets` ring offsets
/// (uint32), in one call. Returns where; the room stays there until a call of pear_polygon or
/// pear_points asks for more.
PEAR_WASM_EXPORT(pear_polygon)(std::uint32_t points, std::uint32_t offsets)->const Room* {
  Session& s = session();
  grow_to(s.points, points);
  grow_to(s.ring_offsets, offsets);
  s.room = {address(s.points.data()), address(s.ring_offsets.data())};
  return &s.room;
}

/// Triangulates the first `points` points in rings given by the first `offsets` ring offsets.
PEAR_WASM_EXPORT(pear_triangulate)
(std::uint32_t points, std::uint32_t offsets, std::uint32_t option_bits)->const Results* {
  Session& s = session();
  const pear::PolygonView polygon{std::span(s.points).first(points),
                                  std::span(s.ring_offsets).first(offsets)};
  s.triangulator.triangulate_into(polygon, options_from(option_bits), s.result);
  s.diagnostics.clear();
  copy_diagnostics(s.result.diagnostics, s.diagnostics);
  s.results = {static_cast<std::uint32_t>(s.result.status),
               address(s.result.triangles.data()),
               static_cast<std::uint32_t>(s.result.triangles.size()),
               address(s.diagnostics.data()),
               static_cast<std::uint32_t>(s.result.diagnostics.size()),
               static_cast<std::uint32_t>(s.result.delaunay.flips)};
  return &s.results;
}

/// Room for `count` uint32 offsets of a batch (rings + 1 ring offsets, then polygons + 1
/// polygon offsets); returns its address.
PEAR_WASM_EXPORT(pear_batch_offsets)(std::uint32_t count)->std::uint32_t* {
  Session& s = session();
  s.batch_offsets_in.resize(count);
  return s.batch_offsets_in.data();
}

/// Triangulates a batch: the first `points` points, `rings` + 1 ring offsets and `polygons` + 1
/// polygon offsets (pear_batch_offsets). Fills `Results` (triangles index the batch's points)
/// and returns the per-polygon arrays.
PEAR_WASM_EXPORT(pear_triangulate_batch)
(std::uint32_t points, std::uint32_t rings, std::uint32_t polygons, std::uint32_t option_bits)
    ->const BatchResults* {
  Session& s = session();
  const std::span<const std::uint32_t> in(s.batch_offsets_in);
  s.batch_ring_offsets.assign(in.begin(), in.begin() + rings + 1);
  s.batch_polygon_offsets.assign(in.begin() + rings + 1, in.begin() + rings + polygons + 2);
  const pear::PolygonBatch batch{
      std::span<const double>(&s.points.data()->x, 2 * std::size_t{points}), s.batch_ring_offsets,
      s.batch_polygon_offsets};
  s.batch = pear::triangulate_batch(batch, options_from(option_bits));
  s.batch_triangle_offsets.assign(s.batch.triangle_offsets.begin(), s.batch.triangle_offsets.end());
  s.batch_diagnostic_offsets.assign(s.batch.diagnostic_offsets.begin(),
                                    s.batch.diagnostic_offsets.end());
  s.diagnostics.clear();
  copy_diagnostics(s.batch.diagnostics, s.diagnostics);
  s.results = {0,
               address(s.batch.triangles.data()),
               static_cast<std::uint32_t>(s.batch.triangles.size()),
               address(s.diagnostics.data()),
               static_cast<std::uint32_t>(s.batch.diagnostics.size()),
               static_cast<std::uint32_t>(s.batch.delaunay_flips)};
  s.batch_results = {address(s.batch_triangle_offsets.data()),
                     address(s.batch_diagnostic_offsets.data()), address(s.batch.status.data())};
  return &s.batch_results;
}

/// The results of the last call (pear_triangulate or pear_triangulate_batch).
PEAR_WASM_EXPORT(pear_results)()->const Results* {
  return &session().results;
}

/// Room for `count` triangles (3 uint32 each) for the validator; returns its address.
PEAR_WASM_EXPORT(pear_triangle_input)(std::uint32_t count)->std::uint32_t* {
  Session& s = session();
  s.triangles_in.resize(count);
  return s.triangles_in.data()->data();
}

/// Validates the first `triangles` triangles against the polygon pear_polygon made room for
/// (pear::validate); `check_delaunay` also asks for a CDT.
PEAR_WASM_EXPORT(pear_validate)
(std::uint32_t points, std::uint32_t offsets, std::uint32_t triangles, std::uint32_t check_delaunay)
    ->const Report* {
  Session& s = session();
  const pear::PolygonView polygon{std::span(s.points).first(points),
                                  std::span(s.ring_offsets).first(offsets)};
  pear::ValidateOptions options;
  options.check_delaunay = check_delaunay != 0;
  options.max_messages = 8;
  s.validation = pear::validate(polygon, std::span(s.triangles_in).first(triangles), options);
  const pear::ValidationReport& v = s.validation;
  s.report = {v.valid,
              static_cast<std::uint32_t>(v.triangles),
              static_cast<std::uint32_t>(v.expected_triangles),
              static_cast<std::uint32_t>(v.zero_area_triangles),
              static_cast<std::uint32_t>(v.bad_orientation),
              static_cast<std::uint32_t>(v.bad_edges),
              static_cast<std::uint32_t>(v.non_delaunay_edges),
              static_cast<std::uint32_t>(v.messages.size()),
              v.area_rel_error};
  return &s.report;
}

/// The validator's message `index` (UTF-8, ending in a zero byte).
PEAR_WASM_EXPORT(pear_validation_message)(std::uint32_t index)->const char* {
  Session& s = session();
  s.text = index < s.validation.messages.size() ? s.validation.messages[index] : "";
  return s.text.c_str();
}

/// A sentence for people about diagnostic `issue` at (ring, vertex), pear::describe's (UTF-8,
/// ending in a zero byte).
PEAR_WASM_EXPORT(pear_describe)
(std::uint32_t issue, std::uint32_t ring, std::uint32_t vertex)->const char* {
  Session& s = session();
  s.text = pear::describe({static_cast<pear::Issue>(issue), ring, vertex});
  return s.text.c_str();
}

/// The short name of an issue ("t_junction_split"), pear::to_string's.
PEAR_WASM_EXPORT(pear_issue_name)(std::uint32_t issue)->const char* {
  return pear::to_string(static_cast<pear::Issue>(issue));
}
