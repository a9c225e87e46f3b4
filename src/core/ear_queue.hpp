// The queue of candidate ears: a bucket queue on a quantized key, last in first out within a
// bucket. FIST's heuristics need the best ear roughly, not exactly; buckets make push and pop
// O(1) and cache-friendly where a binary heap of millions of entries was a fifth of the run.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

namespace pear::detail {

class EarQueue {
 public:
  struct Candidate {
    std::uint32_t node;
    std::uint32_t stamp;
  };

  static constexpr int bucket_count = 4096;
  /// Nodes per block (clear's `blocks`): consecutive node numbers, a run of the boundary.
  static constexpr std::uint32_t block_nodes = 32768;
  /// With blocks, keys are ordered in levels of 2^level_shift buckets: a level spans a factor
  /// 2^(1/4) of squared length. (Coarser levels are faster on Eurasia still, but change the
  /// order enough to thin the triangles of long corridors, a 100k spiral's by 28% at 16.)
  static constexpr int level_shift = 2;

  EarQueue() { clear(); }

  /// Empties the queue. With `blocks` > 1 it pops by key level first (2^level_shift buckets),
  /// then by block (the caller's grouping of candidates by memory), then by bucket: on a
  /// boundary larger than the caches, each level then sweeps memory block by block instead of
  /// jumping across it at every pop.
  void clear(std::uint32_t blocks = 1) {
    for (std::size_t word = 0; word < occupied_.size(); ++word)
      for (std::uint64_t bits = occupied_[word]; bits != 0; bits &= bits - 1)
        buckets_[word * 64 + static_cast<std::size_t>(std::countr_zero(bits))].clear();
    blocks_ = std::max<std::uint32_t>(blocks, 1);
    const std::size_t slots = std::size_t{bucket_count} * blocks_;
    if (buckets_.size() < slots) buckets_.resize(slots);
    occupied_.assign(slots / 64 + 1, 0);
    lowest_word_ = occupied_.size();
  }

  /// Bucket 0 is popped first; `block` counts only with blocks (those past the last given to
  /// clear join the last).
  void push(int bucket, Candidate candidate, std::uint32_t block = 0) {
    constexpr int fine = (1 << level_shift) - 1;
    const std::size_t slot =
        ((static_cast<std::size_t>(bucket >> level_shift) * blocks_ + std::min(block, blocks_ - 1))
         << level_shift) +
        static_cast<std::size_t>(bucket & fine);
    buckets_[slot].push_back(candidate);
    occupied_[slot / 64] |= std::uint64_t{1} << (slot % 64);
    lowest_word_ = std::min(lowest_word_, slot / 64);
  }

  bool pop(Candidate& out) {
    for (std::size_t word = lowest_word_; word < occupied_.size(); lowest_word_ = ++word) {
      if (occupied_[word] == 0) continue;
      const std::size_t bucket =
          word * 64 + static_cast<std::size_t>(std::countr_zero(occupied_[word]));
      out = buckets_[bucket].back();
      buckets_[bucket].pop_back();
      rest_ = buckets_[bucket];
      if (buckets_[bucket].empty()) occupied_[word] &= ~(std::uint64_t{1} << (bucket % 64));
      return true;
    }
    return false;
  }

  /// What is left of the bucket the last pop took from, the next candidate last: a caller can
  /// fetch the nodes it will look at soon while it works on this one.
  std::span<const Candidate> bucket_rest() const { return rest_; }

  /// A squared length (or a key of that scale), 16 buckets per power of two; the shortest first.
  static int length_bucket(double squared_length) {
    if (!(squared_length > 0)) return 0;
    if (!(squared_length < INFINITY)) return bucket_count - 1;
    // frexp's exponent and the top four bits of the mantissa, read from the bits (frexp is a
    // library call); subnormals, whose exponent field is 0, take frexp.
    const auto bits = std::bit_cast<std::uint64_t>(squared_length);
    int exponent = static_cast<int>(bits >> 52) - 1022;
    int fine = static_cast<int>(bits >> 48) & 15;
    if ((bits >> 52) == 0) {
      const double mantissa = std::frexp(squared_length, &exponent);  // in [0.5, 1)
      fine = static_cast<int>((mantissa - 0.5) * 32);                 // 0..15
    }
    return std::clamp((exponent + 127) * 16 + fine, 0, bucket_count - 1);
  }

 private:
  std::vector<std::vector<Candidate>> buckets_;
  std::vector<std::uint64_t> occupied_;
  std::uint32_t blocks_ = 1;
  std::size_t lowest_word_ = 0;  ///< no occupied bucket below this word's
  std::span<const Candidate> rest_;
};

}  // namespace pear::detail
