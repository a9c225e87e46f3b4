// The sequential engine: clean -> boundary with bridges -> ear clipping.
#pragma once

#include <vector>

#include "bridge.hpp"
#include "clean.hpp"
#include "ear_clipper.hpp"
#include "simplicity.hpp"

namespace pear::detail {

class Engine {
 public:
  Status triangulate(const FlatPolygon& input, const Options& options, TriangleList& out,
                     std::vector<Diagnostic>& diagnostics);
  EarStatistics statistics(const FlatPolygon& input);

 private:
  /// Cleans and bridges; returns false when nothing can be triangulated.
  bool prepare(const FlatPolygon& input, bool check_simplicity,
               std::vector<Diagnostic>& diagnostics, Status& status);
  Diagnostic locate(const FlatPolygon& input, Issue issue, std::uint32_t caller_index) const;

  CleanPolygon clean_;
  Boundary boundary_;
  SimplicityCheck simplicity_;
  HoleBridger bridger_;
  EarClipper clipper_;
};

}  // namespace pear::detail
