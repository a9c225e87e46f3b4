// Replaces the global operator new and delete (all of them in this process, the peers'
// libraries included). Counting is off except around one untimed run per benchmark, so the
// timed runs pay only a relaxed load. Blocks freed while counting that were allocated before
// only lower the live count: the peak of a run that starts from scratch is exact.
#include "memory.hpp"

#include <malloc.h>

#include <atomic>
#include <cstdlib>
#include <new>

namespace bench {
namespace {

std::atomic<bool> counting{false};
std::atomic<long long> live{0};
std::atomic<long long> peak{0};

void* allocate(std::size_t size) {
  void* p = std::malloc(size == 0 ? 1 : size);
  if (p == nullptr) throw std::bad_alloc();
  if (counting.load(std::memory_order_relaxed)) {
    const long long now =
        live.fetch_add(static_cast<long long>(malloc_usable_size(p)), std::memory_order_relaxed) +
        static_cast<long long>(malloc_usable_size(p));
    long long seen = peak.load(std::memory_order_relaxed);
    while (now > seen && !peak.compare_exchange_weak(seen, now, std::memory_order_relaxed)) {
    }
  }
  return p;
}

void release(void* p) noexcept {
  if (p == nullptr) return;
  if (counting.load(std::memory_order_relaxed))
    live.fetch_sub(static_cast<long long>(malloc_usable_size(p)), std::memory_order_relaxed);
  std::free(p);
}

}  // namespace

void start_counting_memory() {
  live = 0;
  peak = 0;
  counting = true;
}

std::size_t stop_counting_memory() {
  counting = false;
  return static_cast<std::size_t>(peak.load());
}

}  // namespace bench

void* operator new(std::size_t size) {
  return bench::allocate(size);
}
void* operator new[](std::size_t size) {
  return bench::allocate(size);
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return bench::allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  try {
    return bench::allocate(size);
  } catch (...) {
    return nullptr;
  }
}
void operator delete(void* p) noexcept {
  bench::release(p);
}
void operator delete[](void* p) noexcept {
  bench::release(p);
}
void operator delete(void* p, std::size_t) noexcept {
  bench::release(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  bench::release(p);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  bench::release(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  bench::release(p);
}
