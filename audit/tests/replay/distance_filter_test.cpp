// SPDX-License-Identifier: GPL-3.0-or-later
// The replay's filter before an exact distance (audit/src/replay/distance_filter.h):
// "surely farther than the tolerance" only when the exact distance is, read from the
// candidate's interval approximation with outward rounding; a wide interval that
// straddles the tolerance leaves the answer to the exact distance.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "../../src/replay/distance_filter.h"

namespace {

using lepp::Point;
using lepp::audit::replay_detail::CPoint;
using lepp::audit::replay_detail::FT;
using lepp::audit::replay_detail::ApproxBox;
using lepp::audit::replay_detail::surely_farther;

// The replay's distance (Replayer::distance): each exact difference through CGAL's to_double.
double replay_distance(const Point& p, const CPoint& q) {
  return std::max(std::abs(CGAL::to_double(FT(p.x) - q.x())), std::abs(CGAL::to_double(FT(p.y) - q.y())));
}

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

// A box's lower bound against every point made of its points with non-negative
// weights (midpoints, centroids), for points outside, inside and on its edges.
TEST(ApproxBox, NeverAboveTheReplaysDistanceToAPointInTheBox) {
  const CPoint a(0.1, 0.2), b(0.7, -0.3), c(0.4, 0.9);
  ApproxBox box;
  for (const CPoint& v : {a, b, c}) box.add(v);
  const std::vector<CPoint> inside = {a, b, c, CGAL::midpoint(a, b), CGAL::midpoint(b, c), CGAL::centroid(a, b, c),
                                      CPoint((a.x() + b.x() * 2) / 3, (a.y() + b.y() * 2) / 3)};
  int outside = 0;
  for (double x : {-3.0, -0.1, 0.1, 0.3, 0.7, 0.70000000000000007, 2.0, 1e300})
    for (double y : {-1e-300, -0.3, 0.0, 0.9, 0.90000000000000013, 5.0}) {
      const Point p{x, y};
      const double lb = box.lower_bound(p);
      EXPECT_GE(lb, 0);
      outside += lb > 0;
      for (const CPoint& q : inside) EXPECT_LE(lb, replay_distance(p, q)) << x << " " << y;
    }
  EXPECT_GT(outside, 20);  // the bound says something outside the box
  EXPECT_EQ(box.lower_bound({0.4, 0.1}), 0);  // inside: nothing
  EXPECT_NEAR(box.lower_bound({2, 0}), 2 - 0.7, 2e-3);
  EXPECT_NEAR(box.lower_bound({0.4, -3}), 3 - 0.3, 3e-3);
}

// to_double of a lazy difference may be the midpoint of an interval a little below
// the exact value: 1.5 - (1/3)(3/1) is exactly 0.5, but reads 0.49999999999999994.
// The bound stays under it (by its margin), though the exact gap to the box is 0.5.
TEST(ApproxBox, StaysBelowADifferenceThatToDoubleReadsLow) {
  const CPoint q((FT(1) / FT(3)) * (FT(3) / FT(1)), FT(0));  // exactly (1, 0)
  const Point p{1.5, 0};
  ASSERT_LT(replay_distance(p, q), 0.5);  // CGAL's to_double reads it low
  ApproxBox box;
  box.add(CPoint(1, 0));
  box.add(CPoint(0, 1));
  EXPECT_LE(box.lower_bound(p), replay_distance(p, q));
  EXPECT_GT(box.lower_bound(p), 0.49);
}

TEST(ApproxBox, SaysNothingForAPointOffTheDoublesOrAnEmptyBox) {
  ApproxBox box;
  EXPECT_EQ(box.lower_bound({1, 2}), 0);
  box.add(CPoint(0, 0));
  EXPECT_EQ(box.lower_bound({std::numeric_limits<double>::infinity(), 0}), 0);
  EXPECT_EQ(box.lower_bound({0, std::numeric_limits<double>::quiet_NaN()}), 0);
  EXPECT_GT(box.lower_bound({0, -1}), 0.99);
}

}  // namespace
