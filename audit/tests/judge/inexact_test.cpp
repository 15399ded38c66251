// SPDX-License-Identifier: GPL-3.0-or-later
// inexact-threshold and inexact-incircle (lepp/audit/judge/inexact.h) at the exact
// ends of their bounds, and a row named only when every violation is within
// rounding. The boundary points were found with exact rationals: sin^2 of the
// smallest angle of (0,0) (1,0) (x,0.5) is 0.25/(x^2+0.25), and
// sin2_bracket(30) = [0.25 - DBL_EPSILON/4, 0.25 + DBL_EPSILON/4].
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "lepp/audit/judge/checks.h"
#include "lepp/audit/judge/inexact.h"
#include "lepp/validate.h"

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

// A 6 x 6 grid of unit squares, every other column one ulp up, each square cut
// by the diagonal that is not Delaunay: 36 edges, each cocircular within
// rounding, more than the certifier lists per reason (20). check_run looks at
// every one (certifying again) and names the certificate row, or holds it with
// 36 notes under --arithmetic double; one edge made far from cocircular (a
// vertex moved by 0.1) leaves the row a bare Delaunay failure. A trace whose
// step fails is named inexact-incircle in place of missing-flips (broken:
// missing-flips), and under --arithmetic double by the catalogue alone.
TEST(InexactBounds, CheckRunLooksAtEveryViolationBeyondTheListedOnes) {
  constexpr int n = 6;
  auto build = [&](bool broken) {
    lepp::Pslg pslg;
    lepp::Mesh mesh;
    auto id = [&](int i, int j) { return i * (n + 1) + j; };
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        const double y = i % 2 ? std::nextafter(double(j), 100.0) : double(j);
        pslg.vertices.push_back({double(i), y});
      }
    if (broken) pslg.vertices[static_cast<std::size_t>(id(3, 3))].x += 0.1;
    for (int i = 0; i < n; ++i) {
      pslg.segments.push_back({id(i, 0), id(i + 1, 0)});
      pslg.segments.push_back({id(i + 1, n), id(i, n)});
      pslg.segments.push_back({id(0, i + 1), id(0, i)});
      pslg.segments.push_back({id(n, i), id(n, i + 1)});
    }
    mesh.vertices = pslg.vertices;
    for (int i = 0; i < n; ++i)
      for (int j = 0; j < n; ++j) {
        const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
        const lepp::Point &pa = mesh.vertices[a], &pb = mesh.vertices[b], &pc = mesh.vertices[c], &pd = mesh.vertices[d];
        // Diagonal a-c is Delaunay iff d is not inside the circle through a, b, c.
        const long double adx = pa.x - pd.x, ady = pa.y - pd.y, bdx = pb.x - pd.x, bdy = pb.y - pd.y, cdx = pc.x - pd.x,
                          cdy = pc.y - pd.y;
        const long double det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                                (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                                (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
        if (det > 0) mesh.triangles.push_back({a, b, c}), mesh.triangles.push_back({a, c, d});  // the wrong one
        else mesh.triangles.push_back({a, b, d}), mesh.triangles.push_back({b, c, d});
      }
    std::vector<std::string> warnings;
    return std::pair{lepp::validate(pslg, warnings), mesh};
  };
  lepp::audit::EngineRequest req;
  req.theta = 20;
  for (const bool broken : {false, true}) {
    const auto [pslg, mesh] = build(broken);
    lepp::audit::EngineRun run;
    run.mesh = mesh;
    run.trace = std::vector<Point>{{2.5, 2.5}};  // a square centroid, but no triangle is bad at 20 degrees
    for (const bool dbl : {false, true}) {
      SCOPED_TRACE(std::string(broken ? "broken " : "") + (dbl ? "double" : "exact"));
      lepp::audit::CheckOptions options;
      options.arithmetic_double = dbl;
      const lepp::audit::CaseResult c = lepp::audit::check_run(pslg, req, run, options);
      const lepp::audit::RowResult& cert = c[lepp::audit::Row::Certificate];
      const lepp::audit::RowResult& conf = c[lepp::audit::Row::Conformance];
      ASSERT_EQ(conf.verdict, lepp::audit::Verdict::Failed) << conf.detail;
      EXPECT_EQ(conf.deviation, broken ? "missing-flips" : dbl ? "good-triangle" : "inexact-incircle") << conf.detail;
      if (broken) {
        EXPECT_EQ(cert.verdict, lepp::audit::Verdict::Failed) << cert.detail;
        EXPECT_EQ(cert.deviation, "") << cert.detail;
        EXPECT_TRUE(cert.inexact_steps.empty());
      } else if (dbl) {
        EXPECT_EQ(cert.verdict, lepp::audit::Verdict::Held) << cert.detail;
        ASSERT_EQ(cert.inexact_steps.count("inexact-incircle"), 1u);
        EXPECT_EQ(cert.inexact_steps.at("inexact-incircle"), 36u);
      } else {
        EXPECT_EQ(cert.verdict, lepp::audit::Verdict::Failed);
        EXPECT_EQ(cert.deviation, "inexact-incircle") << cert.detail;
        EXPECT_EQ(cert.detail.rfind("inexact-incircle: 36 edges are not locally Delaunay", 0), 0u) << cert.detail;
      }
    }
  }
}

}  // namespace
