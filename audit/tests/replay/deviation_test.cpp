// SPDX-License-Identifier: GPL-3.0-or-later
// The deviation catalogue's rules that the test mesher does not seed
// (circumcenter, off-center, precision, unknown), the catalogue's names, and
// Theorem 2 at a step rejecting a pair that breaks it. The seeded ones are in
// audit/tests/mesher (test_mesher_selfcheck_test.cpp, audit_test_mesher_test.cpp).
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <set>

#include "lepp/angle.h"
#include "lepp/audit/replay.h"
#include "lepp/validate.h"

namespace {

using lepp::Point;
using lepp::audit::Deviation;
using lepp::audit::Replay;
using lepp::audit::ReplayRules;

// A quadrilateral whose CDT has a skinny triangle: a long, flat box with a
// vertex pushed in.
lepp::Pslg flat_box() {
  lepp::Pslg p;
  p.vertices = {{0, 0}, {10, 0}, {10, 1}, {0, 1}, {5, 0.9}};
  p.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  std::vector<std::string> warnings;
  return lepp::validate(p, warnings);
}

double min_angle(const Point& a, const Point& b, const Point& c) {
  auto at = [](const Point& o, const Point& u, const Point& v) {
    return std::atan2(std::abs((u.x - o.x) * (v.y - o.y) - (u.y - o.y) * (v.x - o.x)),
                      (u.x - o.x) * (v.x - o.x) + (u.y - o.y) * (v.y - o.y)) * 180 / M_PI;
  };
  return std::min({at(a, b, c), at(b, c, a), at(c, a, b)});
}

TEST(DeviationCatalogue, NamesAreTheContract) {
  std::set<std::string> names;
  for (int k = 0; k < lepp::audit::kDeviations; ++k) {
    const auto d = static_cast<Deviation>(k);
    names.insert(lepp::audit::to_string(d));
    EXPECT_GT(std::string(lepp::audit::definition(d)).size(), 10u);
  }
  for (const char* n : {"area-centroid", "triangle-centroid", "terminal-midpoint", "centroid-not-midpoint", "remark10-ignored", "remark10-reversed", "inexact-length", "inexact-threshold",
                        "other-second-longest", "good-triangle", "circumcenter", "off-center", "precision", "unknown"})
    EXPECT_TRUE(names.count(n)) << n;
  EXPECT_EQ(names.size(), static_cast<std::size_t>(lepp::audit::kDeviations));
  // The two readings of the quad centroid, by the names `--centroid` takes.
  EXPECT_STREQ(lepp::audit::to_string(lepp::audit::CentroidReading::Vertex), "vertex");
  EXPECT_STREQ(lepp::audit::to_string(lepp::audit::CentroidReading::Area), "area");
}

// audit/tests/mesher/arithmetic/threshold's quad: triangle (0,0) (1,0) (x,0.5) has
// its smallest angle near 30 degrees, sin^2 = 0.25/(x^2+0.25) exactly.
lepp::Pslg near_theta(double x) {
  lepp::Pslg p;
  p.vertices = {{0, 0}, {1, 0}, {x, 0.5}, {0, 0.9}};
  p.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  std::vector<std::string> warnings;
  return lepp::validate(p, warnings);
}

// inexact-threshold on the bad side, at the exact end of its bound: sin^2 is
// 15.87 DBL_EPSILON above sin2_bracket(30).hi at x = 0.8660254037844304 (a
// rounding), 16.09 one ulp down (a wrong threshold). With --angle-tolerance 0
// the constrained longest edge's midpoint (0.5, 0) is no choice; the
// catalogue names it, and once the name is allowed (--arithmetic double) it
// is a choice tagged so. The default tolerance accepts both as the paper's.
TEST(DeviationCatalogue, InexactThresholdJustInsideAndJustOutsideTheBound) {
  for (const auto& [x, inside] : {std::pair{0.8660254037844304, true}, std::pair{0.8660254037844303, false}}) {
    SCOPED_TRACE(x);
    ReplayRules rules;
    rules.min_angle_deg = 30;
    rules.angle_tolerance_deg = 0;
    Replay replay(near_theta(x), rules);
    lepp::audit::ReplayChoice choice;
    EXPECT_FALSE(replay.match({0.5, 0}, choice));
    EXPECT_EQ(replay.diagnose({0.5, 0}).deviation, inside ? Deviation::InexactThreshold : Deviation::GoodTriangle);
    replay.allow(Deviation::InexactThreshold);
    ASSERT_EQ(replay.match({0.5, 0}, choice), inside);
    if (inside) EXPECT_EQ(choice.deviation, Deviation::InexactThreshold);
    // A point no choice makes is still none with the name allowed.
    EXPECT_FALSE(replay.match({0.25, 0}, choice));

    rules.angle_tolerance_deg = 1e-3;  // the default: near theta counts as bad either way
    Replay tolerant(near_theta(x), rules);
    ASSERT_TRUE(tolerant.match({0.5, 0}, choice));
    EXPECT_EQ(choice.deviation, Deviation::Unknown);
  }
}

TEST(DeviationCatalogue, CircumcenterOffCenterPrecisionUnknown) {
  const lepp::Pslg pslg = flat_box();
  ReplayRules rules;
  rules.min_angle_deg = 30;
  Replay replay(pslg, rules);
  const lepp::Mesh mesh = replay.mesh();
  // The skinniest triangle: bad.
  const lepp::Tri* worst = nullptr;
  double worst_angle = 90;
  for (const lepp::Tri& t : mesh.triangles) {
    double a = min_angle(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]);
    if (a < worst_angle) worst_angle = a, worst = &t;
  }
  ASSERT_TRUE(worst && worst_angle < 30);
  const Point &a = mesh.vertices[(*worst)[0]], &b = mesh.vertices[(*worst)[1]], &c = mesh.vertices[(*worst)[2]];
  // Circumcenter, in doubles (a program's formula).
  const double d = 2 * (a.x * (b.y - c.y) + b.x * (c.y - a.y) + c.x * (a.y - b.y));
  const double ux = ((a.x * a.x + a.y * a.y) * (b.y - c.y) + (b.x * b.x + b.y * b.y) * (c.y - a.y) + (c.x * c.x + c.y * c.y) * (a.y - b.y)) / d;
  const double uy = ((a.x * a.x + a.y * a.y) * (c.x - b.x) + (b.x * b.x + b.y * b.y) * (a.x - c.x) + (c.x * c.x + c.y * c.y) * (b.x - a.x)) / d;
  lepp::audit::ReplayChoice choice;
  ASSERT_FALSE(replay.match({ux, uy}, choice));
  EXPECT_EQ(replay.diagnose({ux, uy}).deviation, Deviation::Circumcenter);
  // Off-center: on the bisector of the shortest edge, angle theta at the point.
  const Point* s[3] = {&a, &b, &c};
  int e = 0;
  auto len = [&](int i) { return std::hypot(s[(i + 1) % 3]->x - s[(i + 2) % 3]->x, s[(i + 1) % 3]->y - s[(i + 2) % 3]->y); };
  for (int i = 1; i < 3; ++i)
    if (len(i) < len(e)) e = i;
  const Point &p = *s[(e + 1) % 3], &q = *s[(e + 2) % 3];
  const double mx = (p.x + q.x) / 2, my = (p.y + q.y) / 2, h = len(e) / 2 / std::tan(30 * M_PI / 360);
  const double dist = std::hypot(ux - mx, uy - my);
  ASSERT_GT(dist, h);  // a skinny triangle: the off-center is nearer than the circumcenter
  const Point off{mx + (ux - mx) * h / dist, my + (uy - my) * h / dist};
  ASSERT_FALSE(replay.match(off, choice));
  const auto m = replay.diagnose(off);
  EXPECT_EQ(m.deviation, Deviation::OffCenter) << m.what;
  // A paper choice moved by 100 times its tolerance: precision; by a lot: unknown.
  std::size_t total = 0;
  const auto all = replay.all_choices({5, 0.5}, 1, total);
  ASSERT_FALSE(all.empty());
  const Point exact = all.front().point;
  const double tol = all.front().tolerance;
  const Point rounded{exact.x + 100 * tol, exact.y};
  EXPECT_FALSE(replay.match(rounded, choice));
  const auto pm = replay.diagnose(rounded);
  EXPECT_EQ(pm.deviation, Deviation::Precision) << pm.what;
  EXPECT_LE(pm.where.distance, pm.where.tolerance);
  const auto um = replay.diagnose({1.2345, 0.0678});
  EXPECT_EQ(um.deviation, Deviation::Unknown) << um.what;
}

// Theorem 2 at a step: a pair whose apex angle is over 120 degrees is
// rejected, a right angle is not. (On the replay's own meshes, which are
// constrained Delaunay, the theorem holds: this checks the check.)
TEST(DeviationCatalogue, Theorem2CheckRejectsAnObtusePair) {
  lepp::Pslg p;
  p.vertices = {{0, 0}, {2, 0}, {1, 0.2}, {1, -1}, {1, 1}};
  p.segments = {{0, 3}, {3, 1}, {1, 4}, {4, 0}};
  std::vector<std::string> warnings;
  const lepp::Pslg pslg = lepp::validate(p, warnings);
  Replay replay(pslg, ReplayRules{});
  lepp::audit::ReplayChoice pair;
  pair.terminal_edge = {0, 1};
  pair.t1 = {0, 1, 2};  // the angle at (1, 0.2) is about 157 degrees
  pair.t2 = {0, 1, 3};
  const auto bad = replay.theorem2(pair);
  EXPECT_FALSE(bad.holds);
  EXPECT_EQ(bad.apex, 2);
  EXPECT_NEAR(bad.angle_deg, 157.38, 0.01);
  pair.t1 = {0, 1, 4};  // 90 degrees at (1, 1)
  EXPECT_TRUE(replay.theorem2(pair).holds);
  pair.t2 = {-1, -1, -1};  // a constrained terminal edge: not the theorem's case
  pair.t1 = {0, 1, 2};
  EXPECT_TRUE(replay.theorem2(pair).holds);
}

}  // namespace

// The diagnosis of a step: words and picture, for a conformance failure and
// for Theorem 2 at a step.
#include "lepp/audit/judge/diagnosis.h"

namespace {

TEST(StepDiagnosis, ConformanceAndTheorem2Drawn) {
  lepp::Pslg p;
  p.vertices = {{0, 0}, {10, 0}, {10, 1}, {0, 1}, {5, 0.9}};
  p.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  std::vector<std::string> warnings;
  const lepp::Pslg pslg = lepp::validate(p, warnings);
  lepp::audit::ConformanceOptions o;
  o.min_angle_deg = 30;
  const auto conf = lepp::audit::check_conformance(pslg, {{1.2345, 0.0678}}, o);
  ASSERT_FALSE(conf.conforms);
  EXPECT_EQ(conf.failure->deviation, "unknown");
  const auto d = lepp::audit::conformance_diagnosis(conf, 30, true);
  const std::string md = lepp::audit::diagnosis_markdown(d);
  EXPECT_NE(md.find("**Deviation: `unknown`**"), std::string::npos) << md;
  EXPECT_NE(md.find("missing Delaunay flips"), std::string::npos) << md;
  EXPECT_NE(md.find("Euclidean distances"), std::string::npos) << md;
  const std::string svg = lepp::audit::diagnosis_svg(d, "conformance step 1");
  EXPECT_NE(svg.find("the program's point, step 1"), std::string::npos) << svg.substr(svg.size() - 800);
  EXPECT_NE(svg.find("the paper"), std::string::npos);

  lepp::audit::ConformanceReport t2 = conf;
  lepp::audit::Theorem2StepFailure f;
  f.step = 0;
  f.point = {5, 0.5};
  f.mesh = conf.failure->mesh;
  f.terminal_edge = {f.mesh.triangles[0][0], f.mesh.triangles[0][1]};
  f.t1 = f.mesh.triangles[0];
  f.apex = f.mesh.triangles[0][2];
  f.angle_deg = 150;
  t2.theorem2_failure = f;
  const auto d2 = lepp::audit::theorem2_diagnosis(t2, 30);
  EXPECT_NE(lepp::audit::diagnosis_markdown(d2).find("Theorem 2 fails"), std::string::npos);
  EXPECT_NE(lepp::audit::diagnosis_svg(d2, "theorem-2 step 1").find("terminal pair of step 1"), std::string::npos);
}

}  // namespace
