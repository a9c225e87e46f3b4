// pear: a growable Chase–Lev work-stealing deque.
//
// One owner thread pushes and pops at the bottom (LIFO, good locality); any number of thieves
// steal at the top (FIFO, the oldest and usually largest work). The algorithm is Chase and Lev,
// "Dynamic Circular Work-Stealing Deque" (SPAA 2005); the memory orders are those of Lê, Pop,
// Cohen and Zappa Nardelli, "Correct and Efficient Work-Stealing for Weak Memory Models"
// (PPoPP 2013, Fig. 1), each one commented where it is used.
//
//   pear::WorkStealingDeque<Job*> deque;
//   deque.push(job);                        // owner only
//   if (auto job = deque.pop()) run(*job);  // owner only
//   if (auto job = deque.steal()) ...;      // any thread
//
// T must be trivially copyable (a pointer or an index, typically): slots are std::atomic<T>.
// Buffers are never freed while the deque lives, because a thief may still read a slot of an
// old buffer after the owner grew it (the paper leaves reclamation out for the same reason).
//
// ThreadSanitizer does not model std::atomic_thread_fence, so under TSan every operation is
// sequentially consistent instead (the original Chase–Lev setting, also correct) and the fences
// are left out; TSan then checks everything around the deque with a sound happens-before.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <type_traits>
#include <vector>

#if defined(__SANITIZE_THREAD__)
#define PEAR_THREAD_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define PEAR_THREAD_SANITIZER 1
#endif
#endif

namespace pear {

namespace detail {
#if defined(PEAR_THREAD_SANITIZER)
inline constexpr bool thread_sanitizer = true;
#else
inline constexpr bool thread_sanitizer = false;
#endif

/// The paper's order, or seq_cst under ThreadSanitizer (see the file comment).
constexpr std::memory_order order(std::memory_order paper) {
  return thread_sanitizer ? std::memory_order_seq_cst : paper;
}

inline void fence(std::memory_order paper) {
  if constexpr (!thread_sanitizer) std::atomic_thread_fence(paper);
}
}  // namespace detail

template <class T>
class WorkStealingDeque {
  static_assert(std::is_trivially_copyable_v<T>, "slots are std::atomic<T>");

 public:
  explicit WorkStealingDeque(std::size_t initial_capacity = 64) {
    std::size_t capacity = 2;
    while (capacity < initial_capacity) capacity *= 2;
    buffers_.push_back(std::make_unique<Buffer>(capacity));
    buffer_.store(buffers_.back().get(), std::memory_order_relaxed);
  }
  WorkStealingDeque(const WorkStealingDeque&) = delete;
  WorkStealingDeque& operator=(const WorkStealingDeque&) = delete;

  /// Owner only. Grows the buffer when full; never fails (except std::bad_alloc).
  void push(T item) {
    using std::memory_order_acquire, std::memory_order_relaxed, std::memory_order_release;
    const std::int64_t b = bottom_.load(detail::order(memory_order_relaxed));  // only we write it
    // acquire: pairs with a thief's CAS on top, so a slot it stole is not overwritten too early.
    const std::int64_t t = top_.load(detail::order(memory_order_acquire));
    Buffer* buffer = buffer_.load(detail::order(memory_order_relaxed));  // only we write it
    if (b - t > static_cast<std::int64_t>(buffer->mask)) buffer = grow(buffer, t, b);
    buffer->put(b, item);
    // release fence: the item (and what it points to) is visible before the new bottom is.
    detail::fence(memory_order_release);
    bottom_.store(b + 1, detail::order(memory_order_relaxed));
  }

  /// Owner only. The most recently pushed item not yet taken, or nothing when empty.
  std::optional<T> pop() {
    using std::memory_order_relaxed, std::memory_order_seq_cst;
    const std::int64_t b = bottom_.load(detail::order(memory_order_relaxed)) - 1;
    Buffer* buffer = buffer_.load(detail::order(memory_order_relaxed));
    bottom_.store(b, detail::order(memory_order_relaxed));
    // seq_cst fence: our store to bottom and a thief's load of it are ordered against our load
    // of top and its CAS, so at most one of us takes the last item (the paper's key fence).
    detail::fence(memory_order_seq_cst);
    std::int64_t t = top_.load(detail::order(memory_order_relaxed));
    if (t > b) {  // already empty: restore bottom
      bottom_.store(b + 1, detail::order(memory_order_relaxed));
      return std::nullopt;
    }
    std::optional<T> item = buffer->get(b);
    if (t == b) {
      // The last item: race the thieves for it with a CAS on top (seq_cst on success as in the
      // paper; relaxed on failure, we only give up).
      if (!top_.compare_exchange_strong(t, t + 1, memory_order_seq_cst,
                                        detail::order(memory_order_relaxed))) {
        item.reset();
      }
      bottom_.store(b + 1, detail::order(memory_order_relaxed));
    }
    return item;
  }

  /// Any thread. The oldest item, or nothing when empty or when another thread won the race.
  std::optional<T> steal() {
    using std::memory_order_acquire, std::memory_order_relaxed, std::memory_order_seq_cst;
    // acquire: pairs with other thieves' CAS on top.
    std::int64_t t = top_.load(detail::order(memory_order_acquire));
    // seq_cst fence: pairs with the fence in pop(), see there.
    detail::fence(memory_order_seq_cst);
    // acquire: pairs with push()'s release fence, so the item we read is complete.
    const std::int64_t b = bottom_.load(detail::order(memory_order_acquire));
    if (t >= b) return std::nullopt;
    // The paper's consume, strengthened to acquire: pairs with the release store in grow().
    Buffer* buffer = buffer_.load(detail::order(memory_order_acquire));
    const T item = buffer->get(t);
    // seq_cst CAS claims the item; on failure another thief or the owner took it first.
    if (!top_.compare_exchange_strong(t, t + 1, memory_order_seq_cst,
                                      detail::order(memory_order_relaxed))) {
      return std::nullopt;
    }
    return item;
  }

  /// Any thread; a snapshot that may be stale by the time it returns.
  bool empty() const { return size() == 0; }
  std::size_t size() const {
    const std::int64_t b = bottom_.load(std::memory_order_seq_cst);
    const std::int64_t t = top_.load(std::memory_order_seq_cst);
    return b > t ? static_cast<std::size_t>(b - t) : 0;
  }
  /// Owner only.
  std::size_t capacity() const { return buffer_.load(std::memory_order_relaxed)->mask + 1; }

 private:
  struct Buffer {
    explicit Buffer(std::size_t capacity) : mask(capacity - 1), slots(new Slot[capacity]) {}
    // Slots are atomics accessed relaxed, as in the paper: a thief may read a slot whose item
    // another thread has already taken; its CAS on top then fails and the value is discarded.
    using Slot = std::atomic<T>;
    void put(std::int64_t i, T item) {
      slots[static_cast<std::size_t>(i) & mask].store(item,
                                                      detail::order(std::memory_order_relaxed));
    }
    T get(std::int64_t i) const {
      return slots[static_cast<std::size_t>(i) & mask].load(
          detail::order(std::memory_order_relaxed));
    }
    std::size_t mask;
    std::unique_ptr<Slot[]> slots;
  };

  Buffer* grow(Buffer* old, std::int64_t t, std::int64_t b) {
    auto bigger = std::make_unique<Buffer>(2 * (old->mask + 1));
    for (std::int64_t i = t; i < b; ++i) bigger->put(i, old->get(i));
    Buffer* raw = bigger.get();
    buffers_.push_back(std::move(bigger));  // the old one stays alive for late thieves
    // release: a thief that sees the new buffer sees the copied slots.
    buffer_.store(raw, detail::order(std::memory_order_release));
    return raw;
  }

  // top and bottom on separate cache lines: thieves hammer top, the owner bottom.
  alignas(64) std::atomic<std::int64_t> top_{0};
  alignas(64) std::atomic<std::int64_t> bottom_{0};
  alignas(64) std::atomic<Buffer*> buffer_{nullptr};
  std::vector<std::unique_ptr<Buffer>> buffers_;  // owner only: every buffer ever used
};

}  // namespace pear
