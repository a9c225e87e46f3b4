// Helpers shared by the engine's tests: run the engine, then the independent validator.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "pear/pear.hpp"
#include "pear/validate.hpp"

namespace pear::testing {

inline const char* heuristic_name(EarHeuristic h) {
  return h == EarHeuristic::top ? "top" : "fast";
}

/// Triangulates with the given heuristic and asserts status ok plus a valid triangulation.
inline void expect_valid(const Polygon& polygon, EarHeuristic heuristic, const std::string& what) {
  SCOPED_TRACE(what + " (" + heuristic_name(heuristic) + ")");
  const auto result = triangulate(polygon, Options{.heuristic = heuristic});
  ASSERT_EQ(result.status, Status::ok)
      << (result.diagnostics.empty() ? std::string() : describe(result.diagnostics.front()));
  const ValidationReport report = validate(polygon, std::span(result.triangles));
  EXPECT_TRUE(report.valid) << (report.messages.empty() ? std::string() : report.messages.front())
                            << " triangles=" << report.triangles
                            << " expected=" << report.expected_triangles;
  EXPECT_EQ(report.triangles, report.expected_triangles);
  EXPECT_LE(report.area_rel_error, 1e-9);
}

}  // namespace pear::testing
