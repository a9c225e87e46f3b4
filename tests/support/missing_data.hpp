// Tests whose data is absent (../shared/corpus on a machine without it) skip with this mark,
// and the tests' main() (main.cpp) exits 77, meson's SKIP, when every test that ran did so.
#pragma once

#include <gtest/gtest.h>

#include <string_view>

namespace pear::testing {

inline constexpr std::string_view missing_data = "missing data: ";

}  // namespace pear::testing

/// Skips the test when `what` (a corpus::Folder or corpus::File) says why it cannot be read.
#define PEAR_SKIP_IF_MISSING(what) \
  if (!(what).missing.empty()) GTEST_SKIP() << ::pear::testing::missing_data << (what).missing
