// pear's sequential ear clipper as a benchmark entry, and the shared point index.
#include <algorithm>
#include <stdexcept>

#include "pear/pear.hpp"
#include "pear/predicates.hpp"
#include "peers.hpp"

namespace bench {
namespace {

class PearPolygon final : public PreparedPolygon {
 public:
  PearPolygon(const pear::Polygon& polygon, pear::EarHeuristic heuristic)
      : polygon_(polygon), options_{.heuristic = heuristic} {}

  std::size_t triangulate() override {
    result_ = pear::triangulate(polygon_, options_);
    if (result_.status != pear::Status::ok)
      throw std::runtime_error(std::string("pear: ") + pear::to_string(result_.status));
    return result_.triangles.size();
  }
  Triangles triangles() const override { return result_.triangles; }

 private:
  const pear::Polygon& polygon_;
  pear::Options options_;
  pear::Triangulation<std::uint32_t> result_;
};

}  // namespace

std::unique_ptr<PreparedPolygon> prepare_pear_fast(const pear::Polygon& polygon) {
  return std::make_unique<PearPolygon>(polygon, pear::EarHeuristic::fast);
}
std::unique_ptr<PreparedPolygon> prepare_pear_top(const pear::Polygon& polygon) {
  return std::make_unique<PearPolygon>(polygon, pear::EarHeuristic::top);
}

std::vector<Triangulator> triangulators() {
  std::vector<Triangulator> all = {{"pear_fast", prepare_pear_fast},
                                   {"pear_top", prepare_pear_top}};
#ifdef PEAR_BENCH_WITH_CGAL
  all.push_back({"cgal_cdt", prepare_cgal_cdt});
#endif
#ifdef PEAR_BENCH_WITH_GEOS
  if (std::string why_not; geos_available(why_not)) {
    all.push_back({"geos_ear", prepare_geos_ear});
    all.push_back({"geos_cdt", prepare_geos_cdt});
  }
#endif
  return all;
}

namespace {
bool before(const pear::Point& a, const pear::Point& b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}
}  // namespace

PointIndex::PointIndex(const pear::Polygon& polygon) {
  std::uint32_t index = 0;
  for (const auto& ring : polygon)
    for (const auto& p : ring) sorted_.push_back({p, index++});
  std::stable_sort(sorted_.begin(), sorted_.end(),
                   [](const auto& a, const auto& b) { return before(a.first, b.first); });
}

std::uint32_t PointIndex::at(const pear::Point& p) const {
  const auto it = std::lower_bound(
      sorted_.begin(), sorted_.end(), p,
      [](const auto& entry, const pear::Point& q) { return before(entry.first, q); });
  if (it == sorted_.end() || it->first != p)
    throw std::runtime_error("triangle corner is not an input point (a Steiner point)");
  return it->second;
}

std::array<std::uint32_t, 3> PointIndex::triangle(const pear::Point& a, const pear::Point& b,
                                                  const pear::Point& c) const {
  if (pear::orient2d(a, b, c) < 0) return {at(a), at(c), at(b)};
  return {at(a), at(b), at(c)};
}

}  // namespace bench
