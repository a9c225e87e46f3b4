// Instantiates the public headers' templates with the types a user brings (narrow indices,
// float and int coordinates, a point type of its own), so that the strict warnings of
// check_headers.sh reach the code that a header alone leaves uninstantiated. Compiled only.
#include <pear/config.hpp>
#include <pear/pear.hpp>
#include <pear/quality.hpp>
#include <pear/validate.hpp>
#if PEAR_HAS_THREADS
#include <pear/scheduler.hpp>
#endif

#include <array>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace {

struct UserPoint {
  int x, y;
};

template <class Index, class Rings>
std::size_t use(const Rings& rings) {
  pear::Triangulator triangulator;
  const auto result = triangulator.triangulate<Index>(rings);
  const auto alone = pear::triangulate<Index>(rings);
  const auto report = pear::validate(rings, result.triangles);
  const auto spanned = pear::validate(rings, std::span(alone.triangles));
  const auto angles = pear::quality(rings, result.triangles);
  const auto ears = triangulator.ear_statistics(rings);
  const auto batch = pear::triangulate_batch<Index>(std::vector<Rings>{rings, rings});
  return report.triangles + spanned.triangles + angles.triangles + ears.ears + batch.size();
}

}  // namespace

std::size_t instantiate_public_templates() {
  const std::vector<std::vector<std::array<float, 2>>> floats = {{{0, 0}, {4, 0}, {0, 4}}};
  const std::vector<std::vector<std::pair<int, int>>> pairs = {{{0, 0}, {4, 0}, {0, 4}}};
  const std::vector<std::vector<UserPoint>> users = {{{0, 0}, {4, 0}, {0, 4}}};
  std::size_t sum = use<std::uint16_t>(floats) + use<std::uint8_t>(pairs) +
                    use<std::uint64_t>(users) + use<std::uint32_t>(floats);
#if PEAR_HAS_THREADS
  pear::Executor executor(2);
  std::vector<int> values(100, 1);
  pear::parallel_for(executor, 0, 100, 0, [&](int i) { values[static_cast<std::size_t>(i)] += i; });
  sum += static_cast<std::size_t>(pear::parallel_reduce(
      executor, std::int64_t{0}, std::int64_t{100}, 7, std::int64_t{0},
      [&](std::int64_t i) { return std::int64_t{values[static_cast<std::size_t>(i)]}; },
      [](std::int64_t a, std::int64_t b) { return a + b; }));
  pear::parallel_invoke(
      executor, [&] { ++sum; }, [] {});
  pear::TaskGraph graph;
  auto first = graph.emplace([&] { ++sum; });
  auto second = graph.emplace([](std::stop_token) {});
  first.precede(second);
  executor.run(graph).wait();
#endif
  return sum;
}
