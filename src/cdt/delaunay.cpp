// Placeholder until the flipping lands: leaves the triangulation as it is.
#include "delaunay.hpp"

namespace pear::detail {

void make_delaunay(std::span<const Point>, const CleanPolygon&, TriangleList&,
                   const ParallelContext&, DelaunayStatistics&) {}

}  // namespace pear::detail
