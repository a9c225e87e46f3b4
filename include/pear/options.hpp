// pear: how to triangulate. Options, the algorithms and heuristics, and the per-task profile;
// no threads are needed to include it (an Executor is only named, in pear/scheduler.hpp).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pear/export.hpp"

namespace pear {

/// The most threads Options::threads may ask for.
inline constexpr unsigned max_threads = 4096;
/// Options::partitions above this count as this many (no variant uses more parts than the
/// boundary has room for: partition-and-cut's chains are at least 256 nodes long).
inline constexpr unsigned max_partitions = 4096;

class Executor;  // pear/scheduler.hpp

/// Which triangulation algorithm to run. Every algorithm gives a valid triangulation of the same
/// polygon; they differ in speed, in the triangles' shapes, and in how they use threads.
enum class Algorithm : std::uint8_t {
  automatic,           ///< pear picks by size and partitions (see README "Which algorithm")
  sequential,          ///< the sequential FIST-style ear clipper
  partition_and_cut,   ///< paper §2.2: chains clipped in parallel, each with its own queue
  mark_and_cut,        ///< paper §2.3: rounds of clipping every second ear in parallel
  divide_and_conquer,  ///< paper §2.1: vertical split lines, sub-polygons in parallel, Steiner
                       ///< points removed again
};

/// How the sequential engine chooses the next ear.
enum class EarHeuristic : std::uint8_t {
  top,   ///< shortest diagonal weighted by shape first: near-CDT angles (see README)
  fast,  ///< walk the boundary clipping ears as met (no queue): fastest, earcut-like angles
};

struct Options {
  Algorithm algorithm = Algorithm::automatic;
  EarHeuristic heuristic = EarHeuristic::top;
  /// Check exactly, before clipping, that no two edges cross or overlap; a vertex lying inside
  /// another edge splits that edge (Issue::t_junction_split, a warning), a crossing or overlap
  /// gives Status::not_simple and names the place. Without the check no edge is split, and
  /// such input may come back as Status::ok with a triangulation that is not valid.
  bool check_simplicity = true;
  /// Turn the triangulation into the constrained Delaunay triangulation of the polygon by exact
  /// edge flips (paper §2.4); in parallel when the algorithm is a parallel one.
  bool delaunay = false;
  /// Threads for the parallel algorithms: 0 = the executor's concurrency (pear's default
  /// executor: all hardware threads), 1 = run everything on the calling thread. An executor
  /// pear makes for this count runs at most max(16, 4 x hardware threads) workers: more only
  /// add context switches (the count still decides `partitions` when that is 0).
  unsigned threads = 0;
  /// How many parts the parallel algorithms cut the work into: 0 = the thread count; above
  /// max_partitions (4096) counts as 4096. Divide-and-conquer halves it until its split lines
  /// make at most n/16 + 64 Steiner points (docs/parallel.md), so that no count costs more than
  /// a small multiple of the sequential run. The output depends on the algorithm, the options and
  /// this number, never on the threads or their timing: fix it to get bit-identical results
  /// on any machine.
  unsigned partitions = 0;
  /// Where parallel work runs; nullptr = pear's default executor (or a private one with
  /// `threads` threads when that differs from the default's concurrency).
  Executor* executor = nullptr;
  /// When set, filled with the time of every task of every phase (see RunProfile).
  struct RunProfile* profile = nullptr;
};

/// Per-phase task times of one run, for work/span analysis: a phase's tasks run in parallel,
/// phases run one after another. Sequential phases have one task.
struct PEAR_API RunProfile {
  struct Phase {
    std::string name;
    std::vector<double> task_seconds;
    /// The phase's elapsed time as it ran: on several threads, set beside the projection
    /// max(sum / threads, longest task), what scheduling and memory cost on the machine.
    double wall_seconds = 0;
  };
  std::vector<Phase> phases;
  /// Total work: the time on one thread.
  double work() const;
  /// Critical path: the sum over phases of each phase's longest task.
  double span() const;
  /// The time on `threads` threads by Brent's bound per phase, max(sum/threads, longest task)
  /// summed over phases (greedy scheduling does at most 2x worse, usually close to this).
  double projected(unsigned threads) const;
};

}  // namespace pear
