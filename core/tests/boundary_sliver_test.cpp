// SPDX-License-Identifier: GPL-3.0-or-later
// The sliver clause's geometry (lepp/boundary_sliver.h) at its boundaries: closed
// segments that share exactly one point, and the closed sliver a, p, b touched
// only along one side. Small integer coordinates, so the double orientation below
// is exact. Each case names the edit of the header it fails under.
#include <gtest/gtest.h>

#include "lepp/boundary_sliver.h"

namespace lepp {
namespace {

int orient(const Point& a, const Point& b, const Point& c) {
  const double d = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  return (d > 0) - (d < 0);
}
bool meet(Point p1, Point p2, Point q1, Point q2) { return closed_segments_meet(p1, p2, q1, q2, orient); }

// A vertical segment touching another at its lowest point, and a horizontal one at
// its leftmost: the shared point is on the boundary of each box (fails if the box
// test is made half-open at its minimum x or y).
TEST(BoundarySliver, ClosedSegmentsMeetAtTheEndOfABox) {
  EXPECT_TRUE(meet({6, -1}, {6, 2}, {0, 0}, {6, 0}));   // (6, 0): an end of one, inside the other; x at the vertical's box
  EXPECT_TRUE(meet({0, 0}, {6, 0}, {6, -1}, {6, 2}));   // the same pair, the other way round
  EXPECT_TRUE(meet({-1, 3}, {2, 3}, {-1, 0}, {-1, 5}));  // T at the horizontal's leftmost point
  EXPECT_TRUE(meet({3, 0}, {3, 4}, {0, 0}, {5, 0}));    // T at the vertical's lowest point
  EXPECT_FALSE(meet({6, 1}, {6, 2}, {0, 0}, {6, 0}));   // collinear with neither, one unit off
  EXPECT_FALSE(meet({7, 0}, {9, 0}, {0, 0}, {6, 0}));   // collinear, disjoint
  EXPECT_TRUE(meet({6, 0}, {9, 0}, {0, 0}, {6, 0}));    // collinear, sharing an end
}

// Two segments whose lines each cut the other, but one only beyond the other's end:
// they do not meet (fails if one straddle is taken for a crossing).
TEST(BoundarySliver, StraddlingOneLineIsNoCrossing) {
  EXPECT_FALSE(meet({0, 0}, {4, 0}, {6, -1}, {6, 1}));
  EXPECT_TRUE(meet({0, 0}, {8, 0}, {6, -1}, {6, 1}));
}

// The sliver a = (0, 0), p = (6, 0), b = (12, 1) (p right of a -> b), touched along
// side pb only.
TEST(BoundarySliver, SliverIsClosedAlongSidePb) {
  const Point a{0, 0}, p{6, 0}, b{12, 1};
  auto blocked = [&](OutsideInput o) { return sliver_blocked(o, a, b, p, orient); };
  // From b back along bp, through p and beyond (fails if an edge at b must be strictly inside the angle).
  EXPECT_TRUE(blocked({{}, {{b, Point{0, -1}}}}));
  // From b, just below bp: outside the sliver.
  EXPECT_FALSE(blocked({{}, {{b, Point{0, -2}}}}));
  // Across pb and ab with both ends outside (fails if only side ap is tested for crossings).
  EXPECT_TRUE(blocked({{}, {{Point{9, -1}, Point{9, 2}}}}));
  // Across ap and ab with both ends outside.
  EXPECT_TRUE(blocked({{}, {{Point{3, -1}, Point{3, 2}}}}));
  // A vertex on pb, and one just below it.
  EXPECT_TRUE(blocked({{{9, 0.5}}, {}}));
  EXPECT_FALSE(blocked({{{9, 0.25}}, {}}));
}

}  // namespace
}  // namespace lepp
