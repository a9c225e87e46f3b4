// Placeholder until divide-and-conquer lands: the sequential engine does the whole cycle.
#include "variants.hpp"

namespace pear::detail {

bool divide_and_conquer(Boundary& b, std::uint32_t entry, const ParallelContext& ctx,
                        TriangleList& out, std::uint32_t& best_effort_vertex) {
  EarClipper clipper;
  const bool complete = clipper.run(b, entry, ctx.heuristic, out);
  best_effort_vertex = clipper.best_effort_vertex();
  return complete;
}

}  // namespace pear::detail
