// Replaces malloc, free and their relatives for the whole process (glibc allows a program to do
// so; see the glibc manual, "Replacing malloc"), passing every call on to glibc's own allocator.
// So the heap of every triangulator is counted, C libraries (GLU) and C++ ones (operator new
// calls malloc) alike. Counting is off except around one untimed run per benchmark, so the
// timed runs pay only a relaxed load. Blocks freed while counting that were allocated before
// only lower the live count: the peak of a run that starts from scratch is exact.
#include "memory.hpp"

#include <malloc.h>

#include <atomic>
#include <cerrno>
#include <cstddef>

extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);
void __libc_free(void* p);
}

namespace bench {
namespace {

std::atomic<bool> counting{false};
std::atomic<long long> live{0};
std::atomic<long long> peak{0};

void add_live(long long bytes) {
  const long long now = live.fetch_add(bytes, std::memory_order_relaxed) + bytes;
  long long seen = peak.load(std::memory_order_relaxed);
  while (now > seen && !peak.compare_exchange_weak(seen, now, std::memory_order_relaxed)) {
  }
}

long long usable(void* p) {
  return p == nullptr ? 0 : static_cast<long long>(malloc_usable_size(p));
}

void* counted(void* p) {
  if (p != nullptr && counting.load(std::memory_order_relaxed)) add_live(usable(p));
  return p;
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

extern "C" {

void* malloc(std::size_t size) {
  return bench::counted(__libc_malloc(size));
}

void* calloc(std::size_t count, std::size_t size) {
  return bench::counted(__libc_calloc(count, size));
}

void free(void* p) {
  if (p != nullptr && bench::counting.load(std::memory_order_relaxed))
    bench::live.fetch_sub(bench::usable(p), std::memory_order_relaxed);
  __libc_free(p);
}

void* realloc(void* p, std::size_t size) {
  const bool counting = bench::counting.load(std::memory_order_relaxed);
  const long long before = counting ? bench::usable(p) : 0;
  void* q = __libc_realloc(p, size);
  // Null with size > 0: the old block is untouched. Null with size 0: it was freed.
  if (counting && (q != nullptr || size == 0)) bench::add_live(bench::usable(q) - before);
  return q;
}

void* memalign(std::size_t alignment, std::size_t size) {
  return bench::counted(__libc_memalign(alignment, size));
}

void* aligned_alloc(std::size_t alignment, std::size_t size) {
  return bench::counted(__libc_memalign(alignment, size));
}

int posix_memalign(void** out, std::size_t alignment, std::size_t size) {
  if (alignment % sizeof(void*) != 0 || (alignment & (alignment - 1)) != 0) return EINVAL;
  void* p = bench::counted(__libc_memalign(alignment, size));
  if (p == nullptr) return ENOMEM;
  *out = p;
  return 0;
}

}  // extern "C"
