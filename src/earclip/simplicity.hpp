// An exact check that the cleaned rings form a valid polygon boundary: no two edges cross,
// overlap, or meet where one of them does not end (a vertex inside another edge). Rings may
// touch at shared vertices, which the engine handles.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "clean.hpp"
#include "uniform_grid.hpp"

namespace pear::detail {

class SimplicityCheck {
 public:
  /// The index (into polygon.points) of a vertex of the first offending edge found, if any.
  std::optional<std::uint32_t> find_violation(const CleanPolygon& polygon);

 private:
  bool edges_conflict(std::uint32_t e, std::uint32_t f) const;

  const CleanPolygon* polygon_ = nullptr;
  std::vector<std::uint32_t> next_;  ///< the next vertex in its ring
  GridFrame frame_;
  std::vector<std::uint32_t> cell_start_, items_, fill_;
};

}  // namespace pear::detail
