// The ear queue: its length key read from a double's bits must equal the frexp definition
// (16 buckets per power of two, subnormals and the ends included), and pops must come in
// bucket order, last in first out within a bucket, however pushes and pops interleave.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <tuple>
#include <vector>

#include "core/ear_queue.hpp"

namespace pear::detail {
namespace {

int bucket_by_frexp(double squared_length) {
  if (!(squared_length > 0)) return 0;
  if (!(squared_length < INFINITY)) return EarQueue::bucket_count - 1;
  int exponent;
  const double mantissa = std::frexp(squared_length, &exponent);
  const int fine = static_cast<int>((mantissa - 0.5) * 32);
  return std::clamp((exponent + 127) * 16 + fine, 0, EarQueue::bucket_count - 1);
}

TEST(EarQueue, LengthBucketEqualsTheFrexpDefinition) {
  std::vector<double> values = {0.0,
                                -0.0,
                                -1.0,
                                std::numeric_limits<double>::denorm_min(),
                                std::numeric_limits<double>::min(),
                                std::nextafter(std::numeric_limits<double>::min(), 0.0),
                                std::numeric_limits<double>::max(),
                                INFINITY,
                                NAN,
                                1.0,
                                0.5,
                                std::nextafter(1.0, 0.0),
                                std::nextafter(1.0, 2.0),
                                0x1p-127,
                                0x1p-128,
                                0x1p128,
                                0x1p129};
  std::mt19937_64 random(5);
  for (int i = 0; i < 200000; ++i) {
    // Random bit patterns: every exponent (subnormals too) and mantissa.
    const double d = std::bit_cast<double>(random() & 0x7fffffffffffffffull);
    if (!std::isnan(d)) values.push_back(d);
  }
  for (int e = -1074; e <= 1023; ++e)
    for (int k = 0; k < 16; ++k) values.push_back(std::ldexp(1.0 + k / 16.0, e));
  for (const double d : values)
    ASSERT_EQ(EarQueue::length_bucket(d), bucket_by_frexp(d)) << std::hexfloat << d;
}

TEST(EarQueue, PopsInBucketOrderAndLastInFirstOutWithinABucket) {
  EarQueue queue;
  std::vector<std::vector<std::uint32_t>> reference(EarQueue::bucket_count);
  std::mt19937 random(9);
  std::uniform_int_distribution<int> bucket(0, EarQueue::bucket_count - 1), coin(0, 2);
  std::uint32_t next_node = 0;
  for (int round = 0; round < 3; ++round) {
    for (int step = 0; step < 20000; ++step) {
      if (coin(random) != 0) {
        // Clustered buckets too, so that words fill and empty while pops go on.
        const int b = step % 3 == 0 ? bucket(random) : bucket(random) % 200;
        queue.push(b, {next_node, 0});
        reference[b].push_back(next_node++);
        continue;
      }
      EarQueue::Candidate got;
      const auto lowest = std::find_if(reference.begin(), reference.end(),
                                       [](const auto& list) { return !list.empty(); });
      ASSERT_EQ(queue.pop(got), lowest != reference.end());
      if (lowest == reference.end()) continue;
      ASSERT_EQ(got.node, lowest->back());
      lowest->pop_back();
    }
    if (round == 1) {
      queue.clear();
      for (auto& list : reference) list.clear();
      EarQueue::Candidate got;
      ASSERT_FALSE(queue.pop(got));
    }
  }
}

// With blocks: by key level (2^level_shift buckets), then block, then bucket, last in first
// out; blocks past the last count as the last.
TEST(EarQueue, WithBlocksPopsByLevelThenBlockThenBucket) {
  constexpr std::uint32_t blocks = 5;
  EarQueue queue;
  queue.clear(blocks);
  const auto key = [](int bucket, std::uint32_t block) {
    return std::tuple(bucket >> EarQueue::level_shift, std::min(block, blocks - 1),
                      bucket & ((1 << EarQueue::level_shift) - 1));
  };
  std::map<std::tuple<int, std::uint32_t, int>, std::vector<std::uint32_t>> reference;
  std::mt19937 random(13);
  std::uniform_int_distribution<int> bucket(0, 300), coin(0, 2);
  std::uniform_int_distribution<std::uint32_t> block(0, blocks + 1);
  std::uint32_t next_node = 0;
  for (int step = 0; step < 30000; ++step) {
    if (coin(random) != 0) {
      const int b = bucket(random);
      const std::uint32_t k = block(random);
      queue.push(b, {next_node, 0}, k);
      reference[key(b, k)].push_back(next_node++);
      continue;
    }
    EarQueue::Candidate got;
    ASSERT_EQ(queue.pop(got), !reference.empty());
    if (reference.empty()) continue;
    const auto lowest = reference.begin();
    ASSERT_EQ(got.node, lowest->second.back());
    lowest->second.pop_back();
    if (lowest->second.empty()) reference.erase(lowest);
  }
  // Back to one block: plain bucket order again.
  queue.clear();
  queue.push(7, {1, 0}, 3);
  queue.push(5, {2, 0}, 0);
  EarQueue::Candidate got;
  ASSERT_TRUE(queue.pop(got));
  EXPECT_EQ(got.node, 2u);
}

}  // namespace
}  // namespace pear::detail
