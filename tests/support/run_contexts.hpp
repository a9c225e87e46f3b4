// RunContexts on several thread counts for tests of the library's internals (needs
// pear_internal_dep): whatever a stage computes must not depend on which.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <memory>
#include <string>
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

/// Calls check(ctx, profile) for every thread count and partition count given, each pair in a
/// SCOPED_TRACE that names it, with a fresh RunProfile that the context records the phases in.
template <class Check>
void for_each_context(std::initializer_list<unsigned> thread_counts,
                      std::initializer_list<std::uint32_t> partition_counts, Check&& check) {
  for (unsigned threads : thread_counts) {
    Workers workers;
    for (std::uint32_t partitions : partition_counts) {
      SCOPED_TRACE("threads " + std::to_string(threads) + " partitions " +
                   std::to_string(partitions));
      RunProfile profile;
      const RunContext ctx{.runner = workers.runner(Options{.threads = threads}),
                           .partitions = partitions,
                           .profile = &profile};
      check(ctx, profile);
    }
  }
}

}  // namespace pear::detail
