// A vector whose resize() leaves new elements of trivial types uninitialised, for the large
// arrays that parallel tasks fill in full: std::vector would zero them first, on one thread,
// and that thread would take every page fault of fresh memory (on a first call with Eurasia,
// a tenth of the run at two threads). Filled in the tasks, the pages fault where they are
// written, in parallel.
#pragma once

#include <memory>
#include <new>
#include <type_traits>
#include <vector>

#include "pear/config.hpp"

namespace pear::detail {

template <class T>
struct NoZeroAllocator : std::allocator<T> {
  template <class U>
  struct rebind {
    using other = NoZeroAllocator<U>;
  };
  NoZeroAllocator() = default;
  template <class U>
  NoZeroAllocator(const NoZeroAllocator<U>&) noexcept {}

  /// Default-initialises: nothing for a trivial type, the default constructor otherwise.
  /// (Construction from values is std::allocator_traits' own, std::construct_at.)
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
};

#if PEAR_HAS_THREADS
/// resize(n) grows without writing; assign(n, value) and resize(n, value) still fill.
template <class T>
using FillVector = std::vector<T, NoZeroAllocator<T>>;
#else
/// Without threads nothing fills these in tasks, and the allocator's element-wise copies
/// cost code size (the .wasm grew 8.6 KB past its 300 KB budget): a plain vector.
template <class T>
using FillVector = std::vector<T>;
#endif

/// `v` made `count` long without keeping what it held: emptied first, a FillVector grows
/// without copying or filling (for arrays whose every entry the tasks then write), and within
/// its capacity it does not allocate. Returns its data.
template <class T>
T* regrow_unfilled(FillVector<T>& v, std::size_t count) {
  v.clear();
  v.resize(count);
  return v.data();
}

}  // namespace pear::detail
