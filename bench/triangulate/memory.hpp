// Peak heap use of one run, counted by this binary's replacement of malloc and free.
#pragma once

#include <cstddef>

namespace bench {

/// Starts counting live heap bytes (as malloc_usable_size reports them: every malloc in the
/// process, operator new and C libraries included) from zero.
void start_counting_memory();
/// Stops counting and returns the peak of live bytes since start_counting_memory().
std::size_t stop_counting_memory();

}  // namespace bench
