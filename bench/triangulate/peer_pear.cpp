// pear's algorithms as benchmark entries (sequential, CDT, the parallel variants at several
// thread counts), the list of all triangulators, and the shared point index.
#include <algorithm>
#include <map>
#include <stdexcept>

#include "inputs.hpp"
#include "pear/pear.hpp"
#include "pear/predicates.hpp"
#include "pear/scheduler.hpp"
#include "peers.hpp"

namespace bench {
namespace {

class PearPolygon final : public PreparedPolygon {
 public:
  PearPolygon(const pear::Polygon& polygon, const pear::Options& options)
      : polygon_(polygon), options_(options) {}

  std::size_t triangulate() override {
    result_ = pear::triangulate(polygon_, options_);
    if (result_.status != pear::Status::ok)
      throw std::runtime_error(std::string("pear: ") + pear::to_string(result_.status));
    return result_.triangles.size();
  }
  Triangles triangles() const override { return result_.triangles; }
  std::map<std::string, double> statistics() const override {
    if (!options_.delaunay) return {};
    const pear::DelaunayStatistics& d = result_.delaunay;
    return {{"cdt_edges", static_cast<double>(d.edges)},
            {"cdt_flips", static_cast<double>(d.flips)},
            {"cdt_flips_in_partitions", static_cast<double>(d.flips_in_partitions)},
            {"cdt_flips_on_borders", static_cast<double>(d.flips_on_borders)}};
  }

 private:
  const pear::Polygon& polygon_;
  pear::Options options_;
  pear::Triangulation<std::uint32_t> result_;
};

Triangulator pear_entry(std::string name, pear::Options options) {
  const unsigned threads = std::max(1u, options.threads);
  if (options.algorithm != pear::Algorithm::sequential) options.executor = executor_for(threads);
  return {std::move(name),
          [options](const pear::Polygon& polygon) {
            return std::make_unique<PearPolygon>(polygon, options);
          },
          options.algorithm == pear::Algorithm::sequential ? 1u : threads};
}

}  // namespace

std::vector<Triangulator> pear_triangulators() {
  using pear::Algorithm;
  using pear::EarHeuristic;
  // threads = 1: left at 0, the sequential engine checks and bridges a polygon of 20,000
  // vertices or more in parts on every hardware thread, and would not be the one-thread baseline.
  std::vector<Triangulator> all = {
      pear_entry(
          "pear_top",
          {.algorithm = Algorithm::sequential, .heuristic = EarHeuristic::top, .threads = 1}),
      pear_entry(
          "pear_fast",
          {.algorithm = Algorithm::sequential, .heuristic = EarHeuristic::fast, .threads = 1}),
      pear_entry("pear_cdt", {.algorithm = Algorithm::sequential, .delaunay = true, .threads = 1}),
  };
  const std::pair<const char*, Algorithm> variants[] = {{"pc", Algorithm::partition_and_cut},
                                                        {"mc", Algorithm::mark_and_cut},
                                                        {"dc", Algorithm::divide_and_conquer},
                                                        {"auto", Algorithm::automatic}};
  for (const bool delaunay : {false, true})
    for (const auto& [short_name, algorithm] : variants)
      for (const unsigned threads : {1u, 2u, 4u, 8u, 16u}) {
        std::string name = "pear_" + std::string(short_name) + "_t" + std::to_string(threads);
        if (delaunay) name += "_cdt";
        all.push_back(
            pear_entry(name, {.algorithm = algorithm, .delaunay = delaunay, .threads = threads}));
      }
  return all;
}

std::vector<Triangulator> triangulators() {
  std::vector<Triangulator> all = pear_triangulators();
#ifdef PEAR_WITH_CGAL_ORACLE
  all.push_back({"cgal_cdt", prepare_cgal_cdt});
#endif
#ifdef PEAR_BENCH_WITH_GEOS
  if (std::string why_not; geos_available(why_not)) {
    all.push_back({"geos_ear", prepare_geos_ear});
    all.push_back({"geos_cdt", prepare_geos_cdt});
  }
#endif
#ifdef PEAR_BENCH_WITH_GLU
  all.push_back({"glu", prepare_glu});
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
