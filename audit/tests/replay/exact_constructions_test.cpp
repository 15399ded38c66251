// SPDX-License-Identifier: GPL-3.0-or-later
// The guarded exact constructions of the conformance replay and its deviation
// catalogue (audit/src/replay/exact_constructions.h, issue 30): on degenerate input each has
// a defined answer. Without the guards these cases are a GMP division by zero
// or an infinity made into a rational: SIGFPE, which ends this test program.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <limits>

#include "../../src/replay/exact_constructions.h"

namespace {

using lepp::audit::replay_detail::CPoint;
using lepp::audit::replay_detail::FT;
using lepp::audit::replay_detail::guarded_area_centroid;
using lepp::audit::replay_detail::guarded_circumcenter;
using lepp::audit::replay_detail::round_nearest;

TEST(ReplayGuards, CircumcenterOfCollinearOrRepeatedPointsIsNone) {
  EXPECT_FALSE(guarded_circumcenter(CPoint(0, 0), CPoint(1, 1), CPoint(2, 2)));
  EXPECT_FALSE(guarded_circumcenter(CPoint(1, 1), CPoint(1, 1), CPoint(3, 0)));  // a zero-length edge
  EXPECT_FALSE(guarded_circumcenter(CPoint(5, 5), CPoint(5, 5), CPoint(5, 5)));
  // Collinear at subnormal and at huge coordinates too (exact, no tolerance).
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_FALSE(guarded_circumcenter(CPoint(0, 0), CPoint(tiny, tiny), CPoint(2 * tiny, 2 * tiny)));
  EXPECT_FALSE(guarded_circumcenter(CPoint(-1e300, 0), CPoint(0, 0), CPoint(1e300, 0)));
  // A proper triangle keeps its exact circumcenter.
  const auto c = guarded_circumcenter(CPoint(0, 0), CPoint(2, 0), CPoint(0, 2));
  ASSERT_TRUE(c);
  EXPECT_EQ(*c, CPoint(1, 1));
}

TEST(ReplayGuards, AreaCentroidOfAFlatQuadIsNone) {
  // Terminal edge ab, apexes c and d both on its line: no area, no centre of mass.
  EXPECT_FALSE(guarded_area_centroid(CPoint(0, 0), CPoint(4, 0), CPoint(1, 0), CPoint(3, 0)));
  EXPECT_FALSE(guarded_area_centroid(CPoint(0, 0), CPoint(0, 0), CPoint(1, 2), CPoint(3, 4)));  // a = b
  // One flat triangle is fine: the other's centroid.
  const auto one = guarded_area_centroid(CPoint(0, 0), CPoint(3, 0), CPoint(0, 3), CPoint(1, 0));
  ASSERT_TRUE(one);
  EXPECT_EQ(*one, CPoint(1, 1));
  const auto square = guarded_area_centroid(CPoint(0, 0), CPoint(2, 2), CPoint(2, 0), CPoint(0, 2));
  ASSERT_TRUE(square);
  EXPECT_EQ(*square, CPoint(1, 1));
}

TEST(ReplayGuards, RoundNearestBeyondTheLargestDouble) {
  const double max = DBL_MAX;
  const FT half_ulp = FT(std::ldexp(1.0, 970));  // half the spacing of the doubles at DBL_MAX
  EXPECT_EQ(round_nearest(FT(max) * 2), std::numeric_limits<double>::infinity());
  EXPECT_EQ(round_nearest(-FT(max) * 2), -std::numeric_limits<double>::infinity());
  // Below DBL_MAX plus half its ulp: DBL_MAX; at it, the tie goes to the even side (the infinity).
  EXPECT_EQ(round_nearest(FT(max) + half_ulp / 2), max);
  EXPECT_EQ(round_nearest(-FT(max) - half_ulp / 2), -max);
  EXPECT_EQ(round_nearest(FT(max) + half_ulp), std::numeric_limits<double>::infinity());
  // In range, unchanged: the nearest double, ties to even.
  EXPECT_EQ(round_nearest(FT(1) / 3), 1.0 / 3);
  EXPECT_EQ(round_nearest(FT(1) + FT(DBL_EPSILON) / 2), 1.0);
  EXPECT_EQ(round_nearest(FT(max)), max);
}

}  // namespace
