// The queue of candidate ears: a bucket queue on a quantized key, last in first out within a
// bucket. FIST's heuristics need the best ear roughly, not exactly; buckets make push and pop
// O(1) and cache-friendly where a binary heap of millions of entries was a fifth of the run.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

namespace pear::detail {

class EarQueue {
 public:
  struct Candidate {
    std::uint32_t node;
    std::uint32_t stamp;
  };

  static constexpr int bucket_count = 4096;

  void clear() {
    for (int word = 0; word < word_count; ++word) {
      for (std::uint64_t bits = occupied_[word]; bits != 0; bits &= bits - 1)
        buckets_[word * 64 + std::countr_zero(bits)].clear();
      occupied_[word] = 0;
    }
    lowest_word_ = word_count;
  }

  /// Bucket 0 is popped first.
  void push(int bucket, Candidate candidate) {
    buckets_[bucket].push_back(candidate);
    occupied_[bucket / 64] |= std::uint64_t{1} << (bucket % 64);
    lowest_word_ = std::min(lowest_word_, bucket / 64);
  }

  bool pop(Candidate& out) {
    for (int word = lowest_word_; word < word_count; lowest_word_ = ++word) {
      if (occupied_[word] == 0) continue;
      const int bucket = word * 64 + std::countr_zero(occupied_[word]);
      out = buckets_[bucket].back();
      buckets_[bucket].pop_back();
      if (buckets_[bucket].empty()) occupied_[word] &= ~(std::uint64_t{1} << (bucket % 64));
      return true;
    }
    return false;
  }

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
  static constexpr int word_count = bucket_count / 64;
  std::vector<Candidate> buckets_[bucket_count];
  std::uint64_t occupied_[word_count] = {};
  int lowest_word_ = word_count;  ///< no occupied bucket below this word's
};

}  // namespace pear::detail
