// pear::triangulate_batch: polygons cut into chunks of about equal vertex counts, each chunk
// triangulated by one pooled engine on pear's scheduler, its triangles written straight into
// room saved for it in the result, whose gaps are then closed in polygon order.
#include <algorithm>
#include <chrono>
#include <iterator>
#include <limits>
#include <optional>
#include <span>

#include "engine_pool.hpp"
#include "pear/batch.hpp"

namespace pear {
namespace detail {
namespace {

/// Where polygon p's rings and points are, once its offsets were checked.
struct PolygonSpan {
  std::int64_t first_ring = 0, end_ring = 0;
  std::int64_t first_point = 0, end_point = 0;
};

/// Polygon p's span, or the diagnostic that says what is wrong with its offsets.
std::optional<Diagnostic> locate_polygon(const PolygonBatch& batch, std::size_t p,
                                         std::uint64_t max_index, PolygonSpan& span) {
  const auto rings = static_cast<std::int64_t>(batch.ring_offsets.size()) - 1;
  const auto points = static_cast<std::int64_t>(batch.coordinates.size() / 2);
  span.first_ring = batch.polygon_offsets[p];
  span.end_ring = batch.polygon_offsets[p + 1];
  if (span.first_ring < 0 || span.end_ring < span.first_ring || span.end_ring > rings)
    return Diagnostic{Issue::invalid_offsets, 0, 0};
  if (span.first_ring == span.end_ring) return Diagnostic{Issue::empty_input, 0, 0};
  for (std::int64_t r = span.first_ring; r <= span.end_ring; ++r) {
    const std::int64_t offset = batch.ring_offsets[static_cast<std::size_t>(r)];
    const bool in_order = r == span.first_ring || batch.ring_offsets[r - 1] <= offset;
    if (offset < 0 || offset > points || !in_order)
      return Diagnostic{Issue::invalid_offsets, static_cast<std::size_t>(r - span.first_ring), 0};
  }
  span.first_point = batch.ring_offsets[static_cast<std::size_t>(span.first_ring)];
  span.end_point = batch.ring_offsets[static_cast<std::size_t>(span.end_ring)];
  if (span.end_point > 0 && static_cast<std::uint64_t>(span.end_point - 1) > max_index)
    return Diagnostic{Issue::index_overflow, 0, 0};
  return std::nullopt;
}

/// One chunk's results. Its triangles go straight into the result's array, in the room
/// saved for the chunk (triangle_room); those that do not fit there, and every one after
/// them, are spilled, in order. Diagnostics are few: a vector per chunk.
struct ChunkResult {
  std::span<std::array<std::uint32_t, 3>> room;
  std::size_t written = 0;  // triangles in room
  TriangleList spilled;
  std::vector<Diagnostic> diagnostics;
  std::size_t flips = 0;

  /// A polygon's triangles (polygon indices), shifted by `base` to batch indices.
  void add(const TriangleList& triangles, std::uint32_t base) {
    const auto shifted = [base](const std::array<std::uint32_t, 3>& t) {
      return std::array<std::uint32_t, 3>{t[0] + base, t[1] + base, t[2] + base};
    };
    if (spilled.empty() && triangles.size() <= room.size() - written) {
      std::transform(triangles.begin(), triangles.end(), room.begin() + written, shifted);
      written += triangles.size();
    } else {
      std::transform(triangles.begin(), triangles.end(), std::back_inserter(spilled), shifted);
    }
  }
  std::size_t size() const { return written + spilled.size(); }
};

/// Polygon `span` of the batch by the one run, its points read where they are (only its ring
/// offsets are made relative); its triangles (batch indices) and diagnostics added to `chunk`.
Status triangulate_one(const PolygonBatch& batch, const PolygonSpan& span, const Options& options,
                       Engine& engine, ChunkResult& chunk) {
  Engine::Buffers& w = engine.buffers();
  w.input.ring_starts.clear();
  for (std::int64_t r = span.first_ring; r <= span.end_ring; ++r)
    w.input.ring_starts.push_back(
        static_cast<std::uint32_t>(batch.ring_offsets[r] - span.first_point));
  const std::span<const double> xy =
      batch.coordinates.subspan(static_cast<std::size_t>(2 * span.first_point),
                                static_cast<std::size_t>(2 * (span.end_point - span.first_point)));
  w.diagnostics.clear();
  DelaunayStatistics flips;
  const Status status = engine.run(CoordinateView{xy, w.input.ring_starts}, options, w.triangles,
                                   w.diagnostics, flips);
  chunk.add(w.triangles, static_cast<std::uint32_t>(span.first_point));
  chunk.diagnostics.insert(chunk.diagnostics.end(), w.diagnostics.begin(), w.diagnostics.end());
  chunk.flips += flips.flips;
  return status;
}

/// Room for polygon p's triangles: a simple polygon of n vertices and h holes has n + 2h - 2,
/// that is points + 2 * rings - 4 without closing points (fewer with them, or with repeated
/// points cleaned away); a repair that adds nodes may need more: those spill. Offsets out of
/// range or order get none (such a polygon has no triangles).
std::size_t triangle_room(const PolygonBatch& batch, std::size_t p) {
  const auto rings = static_cast<std::int64_t>(batch.ring_offsets.size()) - 1;
  const auto points = static_cast<std::int64_t>(batch.coordinates.size() / 2);
  const std::int64_t r0 = batch.polygon_offsets[p], r1 = batch.polygon_offsets[p + 1];
  if (r0 < 0 || r1 < r0 || r1 > rings) return 0;
  const std::int64_t first = batch.ring_offsets[r0], end = batch.ring_offsets[r1];
  if (first < 0 || end < first || end > points) return 0;
  return static_cast<std::size_t>(std::max<std::int64_t>(end - first + 2 * (r1 - r0) - 4, 0));
}

/// Chunk boundaries (polygon indices): about 16 chunks per thread of about equal vertex counts,
/// none below a few thousand vertices (a task's overhead is a few microseconds). The offsets
/// are not checked yet: a polygon whose outer offsets are out of range or order weighs as one
/// without points, and the sums saturate, so that no offset can overflow the arithmetic.
std::vector<std::size_t> chunk_bounds(const PolygonBatch& batch, std::size_t polygons,
                                      std::size_t concurrency) {
  const auto rings = static_cast<std::int64_t>(batch.ring_offsets.size()) - 1;
  const auto points = static_cast<std::int64_t>(batch.coordinates.size() / 2);
  const auto weight = [&](std::size_t p) -> std::uint64_t {
    const std::int64_t r0 = batch.polygon_offsets[p], r1 = batch.polygon_offsets[p + 1];
    if (r0 < 0 || r1 < r0 || r1 > rings) return 8;
    const std::int64_t first = batch.ring_offsets[r0], end = batch.ring_offsets[r1];
    if (first < 0 || end < first || end > points) return 8;
    return static_cast<std::uint64_t>(end - first) + 8;  // both in [0, points]
  };
  constexpr std::uint64_t most = std::numeric_limits<std::uint64_t>::max();
  const auto add = [](std::uint64_t a, std::uint64_t b) { return a > most - b ? most : a + b; };
  std::uint64_t total = 0;
  for (std::size_t p = 0; p < polygons; ++p) total = add(total, weight(p));
  const std::uint64_t target = std::max<std::uint64_t>(4096, total / (16 * concurrency));
  std::vector<std::size_t> bounds{0};
  std::uint64_t filled = 0;
  for (std::size_t p = 0; p < polygons; ++p) {
    filled = add(filled, weight(p));
    if (filled >= target && p + 1 < polygons) bounds.push_back(p + 1), filled = 0;
  }
  bounds.push_back(polygons);
  return bounds;
}

/// Gives each chunk its room in `triangles`, the sum of its polygons' rooms, all within a
/// budget of points + 2 * rings (polygons that share points would otherwise size it by their
/// sum): a chunk past the budget spills. Written in place, the triangles are not copied from
/// a vector per chunk, which cost fresh pages (page faults) at every call.
void give_rooms(const PolygonBatch& batch, std::span<const std::size_t> bounds,
                std::vector<ChunkResult>& parts, TriangleList& triangles) {
  const std::size_t budget = batch.coordinates.size() / 2 + 2 * batch.ring_offsets.size();
  std::vector<std::size_t> rooms(parts.size());
  std::size_t total = 0;
  for (std::size_t c = 0; c < parts.size(); ++c) {
    std::size_t room = 0;  // each polygon's room is within the budget: no overflow
    for (std::size_t p = bounds[c]; p < bounds[c + 1]; ++p)
      room = std::min(room + triangle_room(batch, p), budget);
    rooms[c] = std::min(room, budget - total);
    total += rooms[c];
  }
  triangles.resize(total);
  std::size_t start = 0;
  for (std::size_t c = 0; c < parts.size(); ++c) {
    parts[c].room = std::span(triangles).subspan(start, rooms[c]);
    start += rooms[c];
  }
}

/// Closes the gaps between the chunks' rooms, front to back in place, when nothing spilled;
/// else gathers the rooms and spills into a new array.
void gather_triangles(const std::vector<ChunkResult>& parts, TriangleList& triangles) {
  const bool spilled = std::any_of(parts.begin(), parts.end(),
                                   [](const ChunkResult& part) { return !part.spilled.empty(); });
  if (!spilled) {
    std::size_t end = 0;
    for (const ChunkResult& part : parts) {
      const auto from = static_cast<std::size_t>(part.room.data() - triangles.data());
      const auto source = triangles.begin() + static_cast<std::ptrdiff_t>(from);
      if (from != end)  // from > end: a forward copy is safe
        std::copy(source, source + static_cast<std::ptrdiff_t>(part.written),
                  triangles.begin() + static_cast<std::ptrdiff_t>(end));
      end += part.written;
    }
    triangles.resize(end);
    return;
  }
  TriangleList gathered;
  std::size_t total = 0;
  for (const ChunkResult& part : parts) total += part.size();
  gathered.reserve(total);
  for (const ChunkResult& part : parts) {
    gathered.insert(gathered.end(), part.room.begin(), part.room.begin() + part.written);
    gathered.insert(gathered.end(), part.spilled.begin(), part.spilled.end());
  }
  triangles = std::move(gathered);
}

BatchTriangulation<std::uint32_t> triangulate_chunks(const PolygonBatch& batch,
                                                     const Options& options,
                                                     std::uint64_t max_index) {
  BatchTriangulation<std::uint32_t> result;
  const std::size_t polygons = batch.polygon_offsets.empty() ? 0 : batch.polygon_offsets.size() - 1;
  result.status.assign(polygons, Status::ok);
  result.triangle_offsets.assign(polygons + 1, 0);
  result.diagnostic_offsets.assign(polygons + 1, 0);
  if (polygons == 0) return result;
  Workers workers;
  const bool valid_options = options.threads <= max_threads;
  const TaskRunner* runner = valid_options ? workers.runner(options) : nullptr;
  // Inside a polygon, work goes to the same executor (nested tasks), never to a new one; the
  // partitions are the batch's (0: its thread count), whatever thread a polygon runs on.
  Options per_polygon = options;
  per_polygon.executor = valid_options ? workers.executor(options) : nullptr;
  per_polygon.threads = per_polygon.executor ? 0 : 1;
  per_polygon.partitions = options.partitions ? options.partitions : Workers::concurrency(options);
  per_polygon.profile = nullptr;

  const std::vector<std::size_t> bounds =
      chunk_bounds(batch, polygons, runner ? runner->concurrency() : 1);
  const std::size_t chunks = bounds.size() - 1;
  std::vector<ChunkResult> parts(chunks);
  give_rooms(batch, bounds, parts, result.triangles);
  std::vector<std::int64_t> triangle_counts(polygons), diagnostic_counts(polygons);
  // With a profile: one phase whose tasks are the polygons (they run in parallel).
  std::vector<double> seconds(options.profile ? polygons : 0);
  const auto run_chunk = [&](std::size_t c) {
    PooledEngine engine;
    for (std::size_t p = bounds[c]; p < bounds[c + 1]; ++p) {
      const std::size_t triangles_before = parts[c].size();
      const std::size_t diagnostics_before = parts[c].diagnostics.size();
      PolygonSpan span;
      // The clock only for a profile: in WebAssembly each reading is a call out to JavaScript.
      const auto start = options.profile ? std::chrono::steady_clock::now()
                                         : std::chrono::steady_clock::time_point{};
      if (options.threads > max_threads) {
        parts[c].diagnostics.push_back({Issue::invalid_options, 0, 0});
        result.status[p] = Status::invalid_input;
      } else if (const std::optional<Diagnostic> bad = locate_polygon(batch, p, max_index, span)) {
        parts[c].diagnostics.push_back(*bad);
        result.status[p] =
            bad->issue == Issue::index_overflow ? Status::index_overflow : Status::invalid_input;
      } else {
        result.status[p] = triangulate_one(batch, span, per_polygon, *engine, parts[c]);
      }
      if (options.profile)
        seconds[p] =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      triangle_counts[p] = static_cast<std::int64_t>(parts[c].size() - triangles_before);
      diagnostic_counts[p] =
          static_cast<std::int64_t>(parts[c].diagnostics.size() - diagnostics_before);
    }
  };
  if (runner && chunks > 1)
    runner->run(chunks, run_chunk);
  else
    for (std::size_t c = 0; c < chunks; ++c) run_chunk(c);

  for (std::size_t p = 0; p < polygons; ++p) {
    result.triangle_offsets[p + 1] = result.triangle_offsets[p] + triangle_counts[p];
    result.diagnostic_offsets[p + 1] = result.diagnostic_offsets[p] + diagnostic_counts[p];
  }
  gather_triangles(parts, result.triangles);
  for (const ChunkResult& part : parts) {
    result.diagnostics.insert(result.diagnostics.end(), part.diagnostics.begin(),
                              part.diagnostics.end());
    result.delaunay_flips += part.flips;
  }
  if (options.profile) options.profile->phases = {{"triangulate polygons", std::move(seconds)}};
  return result;
}

}  // namespace
}  // namespace detail

BatchTriangulation<std::uint32_t> triangulate_batch(const PolygonBatch& batch,
                                                    const Options& options,
                                                    std::uint64_t max_index) {
  return detail::triangulate_chunks(batch, options, max_index);
}

}  // namespace pear
