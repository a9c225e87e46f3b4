// The simplicity checker must reject what is not simple, or the generator tests prove nothing.
#include <utility>

#include <gtest/gtest.h>

#include "pear/generate.hpp"
#include "simple_polygon.hpp"

namespace {

using pear::Polygon;
using pear::testing::ring_orientation;
using pear::testing::simplicity_problem;

const pear::Ring square = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};

TEST(SimplicityChecker, AcceptsSquareWithHoles) {
  EXPECT_EQ(simplicity_problem(
                {square, {{1, 1}, {1, 2}, {2, 2}, {2, 1}}, {{5, 5}, {5, 8}, {8, 8}, {8, 5}}}),
            "");
}

TEST(SimplicityChecker, RejectsBowTie) {
  EXPECT_NE(simplicity_problem({{{0, 0}, {10, 10}, {10, 0}, {0, 10}}}), "");
}

TEST(SimplicityChecker, RejectsVertexTouchingAnEdge) {
  EXPECT_NE(simplicity_problem({{{0, 0}, {10, 0}, {10, 10}, {5, 0.0}, {0, 10}}}), "");
  EXPECT_NE(simplicity_problem({square, {{5, 0}, {6, 1}, {4, 1}}}), "");
}

TEST(SimplicityChecker, RejectsOverlappingAndFoldingEdges) {
  EXPECT_NE(simplicity_problem({{{0, 0}, {10, 0}, {5, 0}, {5, 5}}}), "");  // folds back
  EXPECT_NE(simplicity_problem({{{0, 0}, {4, 0}, {4, 4}, {2, 0}, {1, 0}, {0, 4}}}), "");
  EXPECT_NE(simplicity_problem({{{0, 0}, {1, 0}, {2, 0}}}), "");  // zero-area triangle
}

TEST(SimplicityChecker, RejectsRepeatedAndTooFewPoints) {
  EXPECT_NE(simplicity_problem({{{0, 0}, {1, 0}, {1, 0}, {0, 1}}}), "");
  EXPECT_NE(simplicity_problem({{{0, 0}, {1, 0}, {0, 1}, {0, 0}}}), "");  // closing point
  EXPECT_NE(simplicity_problem({{{0, 0}, {1, 0}}}), "");
}

TEST(SimplicityChecker, RejectsBadNesting) {
  EXPECT_NE(simplicity_problem({square, {{20, 20}, {20, 21}, {21, 21}}}), "");  // outside
  EXPECT_NE(simplicity_problem(
                {square, {{1, 1}, {1, 9}, {9, 9}, {9, 1}}, {{4, 4}, {4, 5}, {5, 5}, {5, 4}}}),
            "");                                                           // hole in hole
  EXPECT_NE(simplicity_problem({square, {{-1, 5}, {5, 6}, {5, 4}}}), "");  // crosses outer
}

TEST(SimplicityChecker, RejectsOneCrossingInALargeComb) {
  // Vertices 2 and 3 are the top of the rightmost tooth; pulling vertex 3 left over the next
  // tooth makes edges 2 and 3 cross that tooth's sides properly.
  Polygon comb = pear::generate_polygon("comb", 20'000);
  ASSERT_EQ(simplicity_problem(comb), "");
  const double right = comb[0][2].x;
  comb[0][3] = {right - 3, 10.5};
  EXPECT_NE(simplicity_problem(comb), "");
}

TEST(SimplicityChecker, RejectsOverlappingHolesInALargePolygon) {
  Polygon holes = pear::generate_polygon("holes", 40'004);
  ASSERT_EQ(simplicity_problem(holes), "");
  for (auto& p : holes[5000]) p.x += 2.5;  // onto its neighbour's column
  EXPECT_NE(simplicity_problem(holes), "");
  for (auto& p : holes[5000]) p.x -= 2.5;
  holes[5000][0].x = holes[5000][1].x + 0.5;  // vertex 0 now on the hole's own edge 1 line
  holes[5000][0].y = holes[5000][1].y;
  EXPECT_NE(simplicity_problem(holes), "");
}

TEST(SimplicityChecker, RejectsHoleTouchingOuterAtAVertex) {
  EXPECT_NE(simplicity_problem({square, {{0, 0}, {1, 2}, {2, 1}}}), "");
}

TEST(SimplicityChecker, OrientationIsExact) {
  EXPECT_EQ(ring_orientation(square), 1);
  EXPECT_EQ(ring_orientation({{0, 0}, {0, 1}, {1e-300, 0}}), -1);
}

}  // namespace
