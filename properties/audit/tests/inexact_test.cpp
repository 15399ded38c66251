// SPDX-License-Identifier: GPL-3.0-or-later
// inexact-threshold and inexact-incircle (lepp/audit/inexact.h) at the exact
// ends of their bounds, and a row named only when every violation is within
// rounding. The boundary points were found with exact rationals: sin^2 of the
// smallest angle of (0,0) (1,0) (x,0.5) is 0.25/(x^2+0.25), and
// sin2_bracket(30) = [0.25 - DBL_EPSILON/4, 0.25 + DBL_EPSILON/4].
#include <gtest/gtest.h>

#include "lepp/audit/inexact.h"

namespace {

using lepp::Point;
using lepp::audit::angle_within_rounding_below;
using lepp::audit::incircle_within_rounding;

TEST(InexactBounds, ThresholdJustInsideAndJustOutsideSixteenEpsilon) {
  // sin^2 is 15.89 DBL_EPSILON below the bracket's lower end: within.
  EXPECT_TRUE(angle_within_rounding_below({0, 0}, {1, 0}, {0.8660254037844469, 0.5}, 30));
  // One ulp further: 16.11 below, outside.
  EXPECT_FALSE(angle_within_rounding_below({0, 0}, {1, 0}, {0.866025403784447, 0.5}, 30));
  // The order of the vertices does not choose the angle: the one opposite the shortest edge does.
  EXPECT_TRUE(angle_within_rounding_below({0.8660254037844469, 0.5}, {0, 0}, {1, 0}, 30));
  EXPECT_FALSE(angle_within_rounding_below({1, 0}, {0.866025403784447, 0.5}, {0, 0}, 30));
  // Scale does not matter (sin^2 is scale-free): the same triangle times 2^20.
  EXPECT_TRUE(angle_within_rounding_below({0, 0}, {1048576, 0}, {0.8660254037844469 * 1048576, 524288}, 30));
  // A broken input for the name: 29 degrees is a wrong threshold, not rounding.
  EXPECT_FALSE(angle_within_rounding_below({0, 0}, {1, 0}, {0.8746197071393957, 0.48480962024633706}, 30));
}

TEST(InexactBounds, IncircleJustInsideAndJustOutsideSixteenEpsilonOfThePermanent) {
  // (0,0) (1,0) (1,y) (0,1): |det| / permanent is 15.75 DBL_EPSILON at the
  // first y, 16.0000000000000002 one ulp up.
  EXPECT_TRUE(incircle_within_rounding({0, 0}, {1, 0}, {1, 1.000000000000014}, {0, 1}));
  EXPECT_FALSE(incircle_within_rounding({0, 0}, {1, 0}, {1, 1.0000000000000142}, {0, 1}));
  EXPECT_TRUE(incircle_within_rounding({0, 0}, {1, 0}, {1, 1}, {0, 1}));  // exactly cocircular
  // The sign does not matter: the quad the other way round.
  EXPECT_TRUE(incircle_within_rounding({1, 0}, {0, 0}, {1, 1.000000000000014}, {0, 1}));
  // A broken input: a quad far from cocircular.
  EXPECT_FALSE(incircle_within_rounding({0, 0}, {1, 0}, {1, 1}, {0, 0.9}));
}

lepp::certify::Violation violation(lepp::certify::Reason reason, std::vector<Point> points) {
  lepp::certify::Violation v;
  v.reason = reason;
  v.points = std::move(points);
  return v;
}

lepp::certify::Report report_of(const std::vector<lepp::certify::Violation>& listed, std::size_t extra = 0) {
  lepp::certify::Report r;
  r.count_by_reason.assign(static_cast<std::size_t>(lepp::certify::Reason::AreaAboveBound) + 1, 0);
  for (const auto& v : listed) ++r.count_by_reason[static_cast<std::size_t>(v.reason)];
  if (!listed.empty()) r.count_by_reason[static_cast<std::size_t>(listed.front().reason)] += extra;
  r.violations = listed;
  return r;
}

TEST(InexactBounds, RowNamedOnlyWhenEveryViolationIsWithinRounding) {
  using lepp::certify::Reason;
  const auto near = violation(Reason::NotLocallyDelaunay, {{0, 0}, {1, 0}, {1, 1.000000000000014}, {0, 1}});
  const auto far = violation(Reason::NotLocallyDelaunay, {{0, 0}, {1, 0}, {1, 1}, {0, 0.9}});
  EXPECT_EQ(lepp::audit::inexact_incircle_edges(report_of({near})), 1u);
  EXPECT_EQ(lepp::audit::inexact_incircle_edges(report_of({near, near})), 2u);
  EXPECT_EQ(lepp::audit::inexact_incircle_edges(report_of({near, far})), 0u);
  EXPECT_EQ(lepp::audit::inexact_incircle_edges(report_of({near}, 1)), 0u);  // one not listed: undecided
  // Another failure of the certificate row (a gap) is not rounding.
  EXPECT_EQ(lepp::audit::inexact_incircle_edges(report_of({near, violation(Reason::BoundaryNotOnDomainBoundary, {})})), 0u);

  const auto below = violation(Reason::AngleBelowTheta, {{0, 0}, {1, 0}, {0.8660254037844469, 0.5}});
  const auto wrong = violation(Reason::AngleBelowTheta, {{0, 0}, {1, 0}, {0.866025403784447, 0.5}});
  EXPECT_EQ(lepp::audit::inexact_threshold_triangles(report_of({below}), 30), 1u);
  EXPECT_EQ(lepp::audit::inexact_threshold_triangles(report_of({below, wrong}), 30), 0u);
  EXPECT_EQ(lepp::audit::inexact_threshold_triangles(report_of({below}, 3), 30), 0u);
  // The same triangle against another theta is far from it.
  EXPECT_EQ(lepp::audit::inexact_threshold_triangles(report_of({below}), 31), 0u);
}

}  // namespace
