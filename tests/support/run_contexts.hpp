// RunContexts on several thread counts for tests of the library's internals (needs
// pear_internal_dep): whatever a stage computes must not depend on which.
#pragma once

#include <memory>
#include <vector>

#include "core/stage.hpp"
#include "pipeline/threading.hpp"

namespace pear::detail {

/// Contexts on 1, 2 and 4 threads (all on the calling thread in a build without threads), with
/// one partition each, or as many as threads when `partitions_as_threads`.
struct ThreadContexts {
  std::vector<std::unique_ptr<Workers>> workers;
  std::vector<RunContext> list;
  explicit ThreadContexts(bool partitions_as_threads = false) {
    for (unsigned threads : {1u, 2u, 4u}) {
      workers.push_back(std::make_unique<Workers>());
      list.push_back(RunContext{.runner = workers.back()->runner(Options{.threads = threads}),
                                .partitions = partitions_as_threads ? threads : 1u});
    }
  }
};

}  // namespace pear::detail
