// SPDX-License-Identifier: GPL-3.0-or-later
// Every check can fail: for each statement, a configuration that drops one of
// its hypotheses and violates its conclusion, rejected by the very check
// function the property calls (hypothesis false, conclusion false).
#include <gtest/gtest.h>

#include "lepp/theorems/checks.h"

using namespace lepp::theorems;

namespace {
GridTriangle tri(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t cx, std::int64_t cy) {
  return GridTriangle{{{ax, ay}, {bx, by}, {cx, cy}}};
}
TerminalQuad quad(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by, std::int64_t cx, std::int64_t cy,
                  std::int64_t dx, std::int64_t dy) {
  return TerminalQuad{{ax, ay}, {bx, by}, {cx, cy}, {dx, dy}};
}
// The pair's own four vertices plus one more, near the midpoint M of AB: not a Delaunay mesh.
TerminalInMesh with_vertex_near_M(const TerminalQuad& q, GridPoint extra) {
  return TerminalInMesh{q, {q.A, q.B, q.C, q.D, extra}};
}
void expect_rejected(const Verdict& v) {
  EXPECT_FALSE(v.hypothesis) << v.detail;
  EXPECT_TRUE(v.rejected()) << "the conclusion holds: " << v.detail;
}
// Acute terminal triangle ABC with alpha = 17.5 degrees, and an acute neighbour.
const TerminalQuad kAcute = quad(0, 0, 20, 0, 19, 6, 10, -12);
// Obtuse triangle ABC with alpha = 13.87 and angle C = 119.66 degrees.
const TerminalQuad kObtuse = quad(0, 0, 100, 0, 81, 20, 50, -80);
// Acute isosceles BA = CA with alpha0 = 53.13: alpha1 = 29.7, far below alpha0.
const TerminalQuad kWideIsosceles = quad(0, 0, 10, 0, 6, 8, 5, -6);
}  // namespace

TEST(Theorem1Rejects, ShortestEdgeBisectionHalvesTheAngleBound) {
  // Bisecting the shortest edge instead of the longest: angles collapse, classes never close.
  const GridTriangle t = tri(0, 0, 10, 0, 3, 4);
  expect_rejected(check_theorem1_min_angle(t, Bisection::ShortestEdge));
  expect_rejected(check_theorem1_finite_classes(t, Bisection::ShortestEdge));
  expect_rejected(check_theorem1_quasi_equilateral(t, Bisection::ShortestEdge));
  // and the same triangle passes with the longest edge
  EXPECT_TRUE(check_theorem1_min_angle(t).conclusion);
  EXPECT_TRUE(check_theorem1_finite_classes(t).conclusion);
  EXPECT_TRUE(check_theorem1_quasi_equilateral(t).conclusion);
}

TEST(Theorem2Rejects, NonDelaunayPairWithA127DegreeAngle) {
  // D inside the circumcircle of ABC; the angle at C is 126.87 degrees.
  expect_rejected(check_theorem2(quad(0, 0, 4, 0, 2, 1, 2, -3)));
}

TEST(Theorem2Rejects, EqualityCaseWithDMovedInsideTheCircle) {
  // C on the 120-degree arc (s = 0: the isosceles 30-30-120 triangle), D moved from the
  // equilateral apex towards AB: inside the circumcircle, ABD not equilateral.
  Theorem2EqualityInput in;
  in.A = {0, 0};
  in.B = {10, 0};
  in.s_num = 0;
  in.s_den = 1;
  in.dx = 0;
  in.dy = 1;
  in.d_den = 1;
  expect_rejected(check_theorem2_equality(in));
  in.dy = 0;  // at the apex: every conclusion holds
  Verdict at_apex = check_theorem2_equality(in);
  EXPECT_TRUE(at_apex.hypothesis && at_apex.conclusion) << at_apex.detail;
}

TEST(Proposition3Rejects, BisectingANonLongestEdge) {
  // B, A, C as given: BA is the shortest edge, alpha0 = 173.7 degrees.
  expect_rejected(check_prop3a(tri(0, 0, 1, 0, 10, 1), Labelling::AsGiven));
}

TEST(Proposition3Rejects, AcuteTriangleForPartB) {
  // Acute: alpha0 = 23.96, alpha1 = 21.0 < alpha0.
  expect_rejected(check_prop3b(tri(0, 0, 10, 0, 9, 4)));
}

TEST(Lemma4Rejects, IsoscelesWithBCEqualToCA) {
  // The finding: t_A right, t_B congruent to it. The narrowed check excludes it by hypothesis.
  const GridTriangle t = tri(0, 0, 4, 0, 2, 1);
  Verdict v = check_lemma4(t);
  EXPECT_TRUE(v.hypothesis);
  EXPECT_FALSE(v.conclusion) << v.detail;
  expect_rejected(check_lemma4_narrowed(t));
}

TEST(Proposition6Rejects, NonTerminalTriangleIsObtuseAtB) {
  // AB is not the longest edge of ABC: obtuse at B, and d(M) = BM, not CM.
  expect_rejected(check_prop6a_own_vertices(quad(0, 0, 4, 0, 6, 3, 2, -1)));
}

TEST(Proposition6Rejects, NonTerminalAcuteTriangleBelowTheIsoscelesRatio) {
  // |AC| > |AB|: alpha0 = 28.07, d(M)/BC = 0.992 < 1/(4 sin 14.04) = 1.03.
  expect_rejected(check_prop6b(quad(0, 0, 16, 0, 15, 8, 8, -5)));
}

TEST(Proposition6Rejects, A159DegreeTriangleBelowThe120Ratio) {
  // Angle at C = 158.9 > 120 (cannot be Delaunay terminal): CM/BC = 0.54 < 3.0.
  expect_rejected(check_prop6c(quad(0, 0, 12, 0, 4, 1, 6, -5)));
}

TEST(Lemma7Rejects, WideIsoscelesBreaksEveryRatio) {
  expect_rejected(check_lemma7_Ia(kWideIsosceles));
  expect_rejected(check_lemma7_Ib(kWideIsosceles));
  expect_rejected(check_lemma7_Ic(kWideIsosceles));
  expect_rejected(check_lemma7_Id(kWideIsosceles));
  expect_rejected(check_lemma7_II(kWideIsosceles));
}

TEST(Lemma8Rejects, AVertexInsideTheCircumcircleNextToM) {
  const TerminalInMesh acute = with_vertex_near_M(kAcute, {10, 1});
  expect_rejected(check_lemma8(acute, Lemma8Part::a_i));
  expect_rejected(check_lemma8(acute, Lemma8Part::a_ii));
  const TerminalInMesh obtuse = with_vertex_near_M(kObtuse, {50, 1});
  expect_rejected(check_lemma8(obtuse, Lemma8Part::b_i));
  expect_rejected(check_lemma8(obtuse, Lemma8Part::b_ii));
  expect_rejected(check_lemma8(obtuse, Lemma8Part::b_iii));
  expect_rejected(check_theorem9_distances(obtuse, 20));
  expect_rejected(check_prop6a_mesh(acute));  // d(M) = 1, not BM
  // Without the extra vertex the same pairs pass.
  EXPECT_TRUE(check_lemma8(TerminalInMesh{kAcute, {kAcute.A, kAcute.B, kAcute.C, kAcute.D}}, Lemma8Part::a_ii).holds());
}

TEST(Lemma8Rejects, NarrowedBoundsAboveAlphaLimit) {
  // Nearly isosceles, alpha0 = 23.96 > alpha_limit: d(M)/BC = 5/sqrt(17) = 1.21 < 1.29.
  const TerminalQuad q = quad(0, 0, 10, 0, 9, 4, 5, -6);
  expect_rejected(check_lemma8_narrowed(TerminalInMesh{q, {q.A, q.B, q.C, q.D}}, Lemma8Narrowed::a_i_own_129));
  // Acute isosceles BA = CA with alpha0 = 36.87 > 30: d(M)/BC = 5/sqrt(40) = 0.79 < 0.96.
  const TerminalQuad w = quad(0, 0, 10, 0, 8, 6, 5, -9);
  expect_rejected(check_lemma8_narrowed(TerminalInMesh{w, {w.A, w.B, w.C, w.D}}, Lemma8Narrowed::a_ii_own_096));
}

TEST(Lemma8Rejects, NonTerminalObtuseWithSmallBeta) {
  // AB not the longest edge of ABC (obtuse at B), alpha = 18.4 > 14, beta = 21.8 < 28.
  const TerminalQuad q = quad(0, 0, 10, 0, 30, 10, 5, -3);
  expect_rejected(check_lemma8(TerminalInMesh{q, {q.A, q.B, q.C, q.D}}, Lemma8Part::c));
}

TEST(Lemma11Rejects, DInsideTheCircumcircle) {
  // ABC obtuse (135 degrees at C); D = (10, -1) inside CC(ABC): b_D > b_min.
  expect_rejected(check_lemma11(quad(0, 0, 20, 0, 8, 4, 10, -1)));
  expect_rejected(check_lemma11_narrowed(quad(0, 0, 20, 0, 8, 4, 10, -1)));
}

TEST(Remark13Rejects, NonDelaunayFlatNeighbour) {
  // ABD is the worse triangle (5.7 degrees, obtuse), D nearly on AB: d(Q)/BC = 0.18.
  expect_rejected(check_remark13_case(quad(0, 0, 20, 0, 8, 4, 10, -1), Remark13Case::Obtuse, 0.69));
  expect_rejected(check_remark13(quad(0, 0, 20, 0, 8, 4, 10, -1)));
}

TEST(Remark13Rejects, NonTerminalKite) {
  // |BC| > |AB|: a mirror kite whose worse triangles (29.05 degrees, non-obtuse) give d(Q)/BC = 0.588 < 0.61.
  expect_rejected(check_remark13_case(quad(0, 0, 20, 0, 2, 10, 2, -10), Remark13Case::NonObtuse, 0.61));
}

TEST(Theorem14Rejects, TheKiteIsCollinearButNotRightIsosceles) {
  // A mirror kite: Q = (1.5, 0) on AB. The narrowed check accepts it (equal heights).
  const TerminalQuad q = quad(4, 0, 0, 0, 1, 2, 1, -2);
  Verdict v = check_theorem14(q);
  EXPECT_TRUE(v.hypothesis);
  EXPECT_FALSE(v.conclusion);
  EXPECT_TRUE(check_theorem14_narrowed(q).holds());
  // Q at a vertex of the terminal edge (C far beyond: not terminal) is rejected by the narrowed check.
  expect_rejected(check_theorem14_narrowed(quad(0, 0, 20, 0, 43, 8, 17, -8)));
}

TEST(Corollary12Rejects, TallerWorseTriangle) {
  // Delaunay terminal pair: ABC better (29.74 > 29.60) but Q inside ABD: the finding;
  // ABD is the taller, so the narrowed statement does not apply.
  const TerminalQuad q = quad(-28, -32, -20, -20, -16, -26, -27, -18);
  Verdict v = check_corollary12(q);
  EXPECT_TRUE(v.hypothesis);
  EXPECT_FALSE(v.conclusion);
  expect_rejected(check_corollary12_narrowed(q));
  // Not terminal: ABC (smallest angle 19.4) is better than ABD (0.5) and taller, yet Q = (5, 7.25)
  // lies outside it, beyond edge AC: the quad is not convex.
  expect_rejected(check_corollary12_narrowed(quad(0, 0, 20, 0, 40, 30, -40, -1)));
}

TEST(Theorem9Rejects, ChainFromATriangleWiderThan120) {
  // Largest angle above 120 (no Delaunay terminal triangle looks like this), alpha0 = 17.42 < theta = 20:
  // beta_2 = 36.33 < (3/2)^2 alpha0 = 39.2.
  expect_rejected(check_theorem9_chain(tri(-9, 10, 8, -3, -3, 1), 20));
}

// A flat input meets no statement's hypothesis: it is neither a failure nor a tie.
TEST(TriangleChecks, DegenerateInputMeetsNoHypothesisAndNoTie) {
  const GridTriangle flat = tri(0, 0, 1, 1, 2, 2);
  for (const Verdict& v : {check_prop3a(flat), check_prop3b(flat), check_lemma4(flat), check_lemma4_narrowed(flat),
                           check_theorem9_chain(flat, 30)}) {
    EXPECT_FALSE(v.hypothesis);
    EXPECT_TRUE(v.conclusion);
    EXPECT_TRUE(v.conclusion_everywhere);
    EXPECT_FALSE(v.tie);
    EXPECT_EQ(v.label, "degenerate");
    EXPECT_NE(v.detail.find("triangle (0, 0)"), std::string::npos) << v.detail;
  }
}
