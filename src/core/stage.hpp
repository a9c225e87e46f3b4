// The types that cross the pipeline's stages (docs/architecture.md): the cleaned polygon that
// the checks, the bridges and the CDT read, the triangle list every algorithm appends to, and
// where a stage's tasks run. The algorithm folders share these and nothing else.
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <span>
#include <vector>

#include "core/fill_vector.hpp"
#include "core/tasks.hpp"
#include "pear/config.hpp"
#include "pear/geometry.hpp"
#include "pear/pear.hpp"

namespace pear::detail {

/// The caller's polygon as the pipeline reads it, where it is: its points, its interleaved
/// coordinates (pear::CoordinateView), or its rings' own arrays (pear::Polygon: never copied
/// into one array first). Ring r is points [ring_offsets[r], ring_offsets[r + 1]), read
/// through ring(r).
struct InputPolygon {
  const Point* points = nullptr;                  ///< or
  const double* xy = nullptr;                     ///< x0, y0, x1, y1, ... or
  const std::span<const Point>* rings = nullptr;  ///< each ring's points
  std::size_t count = 0;
  std::span<const std::uint32_t> ring_offsets;

  InputPolygon(const PolygonView& view)  // NOLINT(google-explicit-constructor): a view of a view
      : points(view.points.data()), count(view.points.size()), ring_offsets(view.ring_offsets) {}
  InputPolygon(const CoordinateView& view)  // NOLINT(google-explicit-constructor)
      : xy(view.xy.data()), count(view.xy.size() / 2), ring_offsets(view.ring_offsets) {}
  InputPolygon(const RingSpans& view)  // NOLINT(google-explicit-constructor)
      : rings(view.rings.data()),
        count(view.ring_offsets.empty() ? 0 : view.ring_offsets.back()),
        ring_offsets(view.ring_offsets) {}

  std::size_t size() const { return count; }

  /// The points of one ring, indexed from the ring's first: one well-predicted branch a point,
  /// whichever the layout.
  struct Ring {
    const Point* points;
    const double* xy;
    Point operator[](std::size_t k) const {
      return xy != nullptr ? Point{xy[2 * k], xy[2 * k + 1]} : points[k];
    }
  };
  Ring ring(std::size_t r) const {
    if (xy != nullptr) return {nullptr, xy + 2 * std::size_t{ring_offsets[r]}};
    return {rings != nullptr ? rings[r].data() : points + ring_offsets[r], nullptr};
  }
  /// The ring point i lies in: the last one starting at or before it (an empty ring starts
  /// where the next one does).
  std::size_t ring_of(std::size_t i) const {
    return static_cast<std::size_t>(std::upper_bound(ring_offsets.begin(), ring_offsets.end(), i) -
                                    ring_offsets.begin()) -
           1;
  }
  /// Point i of ring r (i numbered among all the points).
  Point at(std::size_t r, std::size_t i) const { return ring(r)[i - ring_offsets[r]]; }
};

/// Triangles as counterclockwise triples of the caller's vertex indices.
using TriangleList = std::vector<std::array<std::uint32_t, 3>>;

/// The polygon after cleaning: repeated consecutive points and closing points dropped, outer ring
/// counterclockwise, holes clockwise, degenerate holes removed.
struct CleanPolygon {
  FillVector<Point> points;                ///< kept vertices, ring after ring
  FillVector<std::uint32_t> original;      ///< the caller's index of each kept vertex
  std::vector<std::uint32_t> ring_starts;  ///< kept ring r is [ring_starts[r], ring_starts[r+1])
  std::vector<std::uint32_t> ring_source;  ///< the caller's ring number of each kept ring
  std::size_t ring_count() const { return ring_starts.empty() ? 0 : ring_starts.size() - 1; }
  /// The ring of point (or edge) i.
  std::size_t ring_of(std::size_t i) const {
    return static_cast<std::size_t>(std::upper_bound(ring_starts.begin(), ring_starts.end(), i) -
                                    ring_starts.begin()) -
           1;
  }
  void clear() {
    points.clear();
    original.clear();
    ring_starts.clear();
    ring_source.clear();
  }
};

/// A vertex lying strictly inside an edge (exact orient2d == 0, strictly between its ends): the
/// simplicity check finds them, cleaning splits the edges there.
struct TJunction {
  std::uint32_t edge;    ///< the edge from vertex `edge` to its successor in the ring
  std::uint32_t vertex;  ///< the vertex inside it
};

/// Where a stage's tasks run, into how many parts the work is cut, and the profile that records
/// every task's time for the work/span analysis. How to clip (the heuristic) is not here: the
/// stages that clip take it as an argument.
struct RunContext {
  const TaskRunner* runner = nullptr;  ///< nullptr: tasks run one after another on this thread
  std::uint32_t partitions = 1;        ///< decides the output; the thread count never does
  RunProfile* profile = nullptr;

  bool parallel() const { return runner != nullptr && runner->concurrency() > 1; }
  /// Tasks for a pass over `items` in parts: four a partition (more tasks than threads even
  /// out the uneven ones), but each of at least `min_items` and at most 512 in all (a pass
  /// that keeps a count per task and band, the bridges' grid, must not grow square with 4,096
  /// partitions). Never 0.
  std::size_t tasks_for(std::size_t items, std::size_t min_items) const {
    const std::size_t most =
        std::min<std::size_t>(512, std::max<std::size_t>(1, items / min_items));
    return std::clamp<std::size_t>(std::size_t{partitions} * 4, 1, most);
  }

  /// Runs task(i) for i in [0, count) in parallel and waits; records the phase when profiling.
  template <class Task>
  void run_tasks(const char* phase, std::size_t count, Task&& task) const {
    // Inlined only where the tasks run here, unprofiled, in a build with threads (the
    // per-polygon path); everything else is dispatched out of line.
    if (PEAR_HAS_THREADS && !profile && !(parallel() && count > 1)) {
      for (std::size_t i = 0; i < count; ++i) task(i);
      return;
    }
    run_out_of_line(phase, count, TaskFunction(task));
  }

  /// run_tasks with every task's time and the phase's elapsed time recorded. Out of line: inlined
  /// at each of the pipeline's phases it made the WebAssembly module 8 KB larger.
  void run_profiled(const char* phase, std::size_t count, TaskFunction task) const;
  /// run_tasks where its tasks run in parallel, are profiled, or the build has no threads: each
  /// task's body one function, called through a pointer (without threads, not also inlined into
  /// a loop at every call: pear.wasm 10.3 KB smaller, as fast in node; docs/javascript.md).
  void run_out_of_line(const char* phase, std::size_t count, TaskFunction task) const;

  /// Runs a sequential step, recorded as a phase of one task when profiling.
  template <class Step>
  void run_serial(const char* phase, Step&& step) const {
    run_tasks(phase, 1, [&](std::size_t) { step(); });
  }

  /// run_tasks for the steps that only a build with threads cuts into phases of their own;
  /// without threads the tasks are plain calls, timed with whatever phase encloses them (the
  /// .wasm keeps no wrapper per step).
  template <class Task>
  void run_tasks_if_threads(const char* phase, std::size_t count, Task&& task) const {
    if constexpr (PEAR_HAS_THREADS)
      run_tasks(phase, count, task);
    else
      for (std::size_t i = 0; i < count; ++i) task(i);
  }
  /// run_serial the same way.
  template <class Step>
  void run_serial_if_threads(const char* phase, Step&& step) const {
    run_tasks_if_threads(phase, 1, [&](std::size_t) { step(); });
  }
};

/// Splits [0, count) into `parts` ranges of nearly equal size: part i is
/// [count * i / parts, count * (i + 1) / parts), the product in 64 bits (size_t has 32 on
/// wasm32).
inline std::size_t part_begin(std::size_t count, std::size_t parts, std::size_t i) {
  return static_cast<std::size_t>(std::uint64_t{count} * i / parts);
}

}  // namespace pear::detail
