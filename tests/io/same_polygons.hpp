// What the io tests compare polygons with: every ring and every coordinate's bits.
#pragma once

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <vector>

#include "pear/geometry.hpp"

namespace pear::testing {

inline bool same_bits(double a, double b) {
  return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

/// The same polygons, rings and points, each coordinate bit for bit (-0 is not 0).
inline void expect_same_polygons(const std::vector<Polygon>& got,
                                 const std::vector<Polygon>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t p = 0; p < want.size(); ++p) {
    ASSERT_EQ(got[p].size(), want[p].size()) << "polygon " << p;
    for (std::size_t r = 0; r < want[p].size(); ++r) {
      ASSERT_EQ(got[p][r].size(), want[p][r].size()) << "polygon " << p << " ring " << r;
      for (std::size_t i = 0; i < want[p][r].size(); ++i) {
        EXPECT_TRUE(same_bits(got[p][r][i].x, want[p][r][i].x)) << got[p][r][i].x;
        EXPECT_TRUE(same_bits(got[p][r][i].y, want[p][r][i].y)) << got[p][r][i].y;
      }
    }
  }
}

}  // namespace pear::testing
