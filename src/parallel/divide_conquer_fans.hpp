// Paper §2.1, Fig. 2: the star-shaped ear clipping around a Steiner point, done inside each
// part's task (in parallel) right after its pieces are clipped. A part's clipper often fans
// many triangles out of a Steiner point (the end of a long split segment); all of them would
// have to be removed and redone sequentially by the repair. The fan is star-shaped from its
// Steiner point s, whose angle in the piece is below 180 degrees (the piece lies on one side
// of the line), so every convex vertex of the fan's outer chain is an ear that does not
// contain s: clipping them with a stack leaves s with only the triangles it cannot do without.
#pragma once

#include <vector>

#include "core/boundary.hpp"
#include "core/stage.hpp"
#include "split_pieces.hpp"

namespace pear::detail {

/// Rewrites the triangles `local` (vertex indices of `piece`, whose `count` corners were linked
/// i -> i + 1; the clipper's fallback may have added node copies after them) so that each
/// Steiner point keeps as few triangles as its fan's shape allows. The triangles still
/// triangulate the same cycle; a fan that is not one path around s is left as it is.
class FanReducer {
 public:
  void reduce(const Boundary& piece, const PieceCorner* corners, std::uint32_t count,
              TriangleList& local);

 private:
  bool fan_path(std::uint32_t s, std::uint32_t count, const TriangleList& local);
  void clip_fan(std::uint32_t s, const Boundary& piece, TriangleList& local);
  void add(const std::array<std::uint32_t, 3>& t, TriangleList& local);

  std::vector<std::vector<std::uint32_t>> incident_;            ///< per Steiner slot: triangle ids
  std::vector<std::uint32_t> slot_;                             ///< per node: its Steiner slot
  std::vector<std::uint8_t> dead_;                              ///< per triangle: replaced
  std::vector<std::pair<std::uint32_t, std::uint32_t>> links_;  ///< fan edges a -> b
  std::vector<std::uint32_t> fan_, path_, stack_;
};

}  // namespace pear::detail
