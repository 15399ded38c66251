// SPDX-License-Identifier: GPL-3.0-or-later
// The replay's filter before an exact distance (audit/src/replay/distance_filter.h):
// "surely farther than the tolerance" only when the exact distance is, read from the
// candidate's interval approximation with outward rounding; a wide interval that
// straddles the tolerance leaves the answer to the exact distance.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "../../src/replay/distance_filter.h"

namespace {

using lepp::Point;
using lepp::audit::replay_detail::CPoint;
using lepp::audit::replay_detail::FT;
using lepp::audit::replay_detail::surely_farther;

// The exact max(|p.x - q.x|, |p.y - q.y|) > tol.
bool exactly_farther(const Point& p, const CPoint& q, double tol) {
  return CGAL::abs(FT(p.x) - q.x()) > FT(tol) || CGAL::abs(FT(p.y) - q.y()) > FT(tol);
}

// Exact x 1, interval x about [0, 2]: 1e16 + 1 rounds within [1e16, 1e16 + 2].
CPoint wide_one() {
  const FT big(1e16);
  return CPoint((big + FT(1)) - big, FT(0));
}

TEST(DistanceFilter, AWideIntervalAroundTheProgramsPointIsNotFarther) {
  const CPoint q = wide_one();
  ASSERT_LT(CGAL::approx(q).x().inf(), 1.0);  // the interval really is wide
  ASSERT_GT(CGAL::approx(q).x().sup(), 1.5);
  EXPECT_FALSE(exactly_farther({1, 0}, q, 0.5));
  EXPECT_FALSE(surely_farther({1, 0}, q, 0.5));
  EXPECT_FALSE(surely_farther({1, 0}, q, 0.0));
  EXPECT_FALSE(surely_farther({1.25, 0}, q, 0.5));
}

TEST(DistanceFilter, FarOnEitherSideOfEitherAxisIsFarther) {
  const CPoint q(FT(1) / FT(3), FT(2) / FT(3));
  for (const Point p : {Point{10, 2.0 / 3}, Point{-10, 2.0 / 3}, Point{1.0 / 3, 10}, Point{1.0 / 3, -10}}) {
    EXPECT_TRUE(surely_farther(p, q, 1.0)) << p.x << " " << p.y;
    EXPECT_TRUE(exactly_farther(p, q, 1.0));
  }
}

// Never farther where the exact distance is not: ties at the tolerance, a point an ulp
// off, a tolerance of 0 and of an ulp, an infinite one.
TEST(DistanceFilter, NeverFartherWhereTheExactDistanceIsNot) {
  for (const CPoint& q : {CPoint(FT(1) / FT(3), FT(0)), CPoint(FT(1) / FT(2), FT(-1) / FT(7)), wide_one()})
    for (double tol : {0.0, 1e-17, 0x1p-54, 0x1p-53, 1e-3, 0.5, 2.0 / 3, 1.0, std::numeric_limits<double>::infinity()})
      for (double x : {1.0 / 3, std::nextafter(1.0 / 3, 1.0), 0.0, 0.5, 1.0, 2.0 / 3, -1.0})
        for (double y : {0.0, -1.0 / 7, 0.5}) {
          const Point p{x, y};
          if (surely_farther(p, q, tol)) EXPECT_TRUE(exactly_farther(p, q, tol)) << x << " " << y << " " << tol;
        }
  // A distance of exactly the tolerance: 1 - 1/2 against 1/2.
  EXPECT_FALSE(surely_farther({1, 0}, CPoint(FT(1) / FT(2), FT(0)), 0.5));
}

TEST(DistanceFilter, APointOffTheDoublesIsLeftToTheExactDistance) {
  const CPoint q(0, 0);
  EXPECT_FALSE(surely_farther({std::numeric_limits<double>::infinity(), 0}, q, 1.0));
  EXPECT_FALSE(surely_farther({std::numeric_limits<double>::quiet_NaN(), 0}, q, 1.0));
}

}  // namespace
