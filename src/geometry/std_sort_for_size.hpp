// Force-included (-include) into every libpear translation unit of the WebAssembly build
// (src/meson.build): the standard algorithms that are not inlined, std::sort's introsort and
// its helpers above all, are compiled for size there. Each comparator instantiates its own
// (3-6 KB of wasm at -O2); in code compiled for speed they are most of what is not hot.
// Inlined algorithms (std::min, std::lower_bound) take their caller's optimization.
#pragma once

#pragma clang attribute push(__attribute__((minsize)), apply_to = function)
#include <algorithm>
#pragma clang attribute pop
