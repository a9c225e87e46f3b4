// The sequential engine as the parallel variants see it: something that clips one cycle of a
// boundary down to nothing. The pipeline hands them earclip's clipper through this, so that
// the parallel variants and the sequential engine stand side by side (docs/architecture.md).
#pragma once

#include <cstdint>
#include <memory>

#include "core/boundary.hpp"
#include "core/pinches.hpp"
#include "core/stage.hpp"

namespace pear::detail {

class CycleClipper {
 public:
  virtual ~CycleClipper() = default;
  /// Clips the cycle through `entry`, appending its triangles (the caller's vertex indices,
  /// counterclockwise) to `out`. Returns false when a best-effort fallback had to act: the
  /// cycle was not weakly simple, and the result may overlap. `shared`: the nodes at repeated
  /// positions when the caller knows them (else the clipper hashes every position).
  virtual bool clip(Boundary& b, std::uint32_t entry, EarHeuristic heuristic, TriangleList& out,
                    SharedPositions shared) = 0;
  /// The caller's index of the vertex where the last clip's first fallback acted.
  virtual std::uint32_t best_effort_vertex() const = 0;
};

/// Makes a clipper for one task: every task that clips in parallel has its own.
using MakeClipper = std::unique_ptr<CycleClipper> (*)();

}  // namespace pear::detail
