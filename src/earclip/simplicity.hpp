// An exact check that the cleaned rings form a valid polygon boundary: no two edges cross,
// overlap, or meet where one of them does not end (a vertex inside another edge). Rings may
// touch at shared vertices, which the engine handles. A grid of edges decides where edges are
// short against their spacing; a Shamos-Hoey sweep (O(n log n)) everywhere else.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "clean.hpp"
#include "uniform_grid.hpp"

namespace pear::detail {

class SimplicityCheck {
 public:
  enum class Method : std::uint8_t { automatic, grid_only, sweep_only };

  /// The index (into polygon.points) of a vertex of an offending edge, if any. `grid_only` and
  /// `sweep_only` are for tests that compare the two (grid_only may give no verdict: nullopt
  /// then means "gave up", never "simple", so tests must use small inputs).
  std::optional<std::uint32_t> find_violation(const CleanPolygon& polygon,
                                              Method method = Method::automatic);

 private:
  bool edges_conflict(std::uint32_t e, std::uint32_t f) const;
  bool pair_conflicts(std::uint32_t e, std::uint32_t f) const;
  struct GridVerdict {
    bool decided = false;  ///< false: the grid would be too costly for this polygon
    std::optional<std::uint32_t> violation;
  };
  GridVerdict check_on_grid();
  std::optional<std::uint32_t> sweep();

  const CleanPolygon* polygon_ = nullptr;
  std::vector<std::uint32_t> next_;  ///< the next vertex in its ring
  GridFrame frame_;
  std::vector<std::uint32_t> cell_start_, items_, fill_;
};

}  // namespace pear::detail
