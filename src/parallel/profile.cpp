#include <algorithm>
#include <numeric>

#include "pear/pear.hpp"

namespace pear {

double RunProfile::work() const {
  double total = 0;
  for (const Phase& phase : phases)
    total += std::accumulate(phase.task_seconds.begin(), phase.task_seconds.end(), 0.0);
  return total;
}

double RunProfile::span() const {
  double total = 0;
  for (const Phase& phase : phases)
    if (!phase.task_seconds.empty())
      total += *std::max_element(phase.task_seconds.begin(), phase.task_seconds.end());
  return total;
}

double RunProfile::projected(unsigned threads) const {
  double total = 0;
  for (const Phase& phase : phases) {
    if (phase.task_seconds.empty()) continue;
    const double sum = std::accumulate(phase.task_seconds.begin(), phase.task_seconds.end(), 0.0);
    const double longest = *std::max_element(phase.task_seconds.begin(), phase.task_seconds.end());
    total += std::max(sum / std::max(1u, threads), longest);
  }
  return total;
}

}  // namespace pear
