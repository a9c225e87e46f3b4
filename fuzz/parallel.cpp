// Fuzz target "parallel": one polygon through every algorithm on 1, 2 and 3 threads with the
// partition count from the bytes. Every result passes check_any_result (and is exact when the
// polygon is known valid), and for one algorithm and partition count the output must be
// identical whatever the thread count (README: output depends on the partitions, never on the
// threads or their timing).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>

#include "known_polygon.hpp"

namespace {

constexpr std::array algorithms = {pear::Algorithm::sequential, pear::Algorithm::partition_and_cut,
                                   pear::Algorithm::mark_and_cut,
                                   pear::Algorithm::divide_and_conquer};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  fuzz::ByteReader bytes(data, size);
  const std::uint8_t header = bytes.byte();
  pear::Options options;
  options.heuristic = header & 2 ? pear::EarHeuristic::fast : pear::EarHeuristic::top;
  options.partitions = 1 + bytes.byte() % 8;
  const auto known = fuzz::decode_known_polygon(bytes, header & 1);
  if (!known) return 0;
  for (const pear::Algorithm algorithm : algorithms) {
    options.algorithm = algorithm;
    std::array<pear::Triangulation<>, 3> results;
    for (unsigned threads = 1; threads <= 3; ++threads) {
      options.threads = threads;
      options.executor = fuzz::shared_executor(threads);
      results[threads - 1] = pear::triangulate(known->polygon, options);
    }
    // Determinism first: a result that is also invalid then reports the rarer finding.
    for (unsigned threads = 2; threads <= 3; ++threads)
      fuzz::require(results[threads - 1].status == results[0].status &&
                        results[threads - 1].triangles == results[0].triangles,
                    "output depends on the thread count",
                    fuzz::describe(known->polygon) + "\nalgorithm " +
                        std::to_string(static_cast<int>(algorithm)) + ", partitions " +
                        std::to_string(options.partitions) + ", threads " +
                        std::to_string(threads));
    for (const pear::Triangulation<>& result : results) fuzz::check_known(*known, result);
  }
  return 0;
}
