// SPDX-License-Identifier: GPL-3.0-or-later
// The first trace step on hand-made configurations names the branch of the
// paper's Select Point (midpoint method) or New Select Point with Remark 10
// (centroid method) that the configuration calls for, and inserts its point.
//
// The pair: A=(0,0), B=(10,0), C=(9,3), D=(4,-6). t1 = ABC is skinny (18.4
// degrees at A, a right angle at C) with longest edge AB; t2 = ABD (angles
// 56.3, 45, 78.7) has AB longest too, and C + D < 180 degrees, so AB is a
// Delaunay terminal edge. Second-longest edges: AC in t1, BD in t2. Each
// configuration is a polygon around the pair: an edge on the polygon is
// constrained; an "ear" E (on AC) or F (on BD) makes that edge interior.
// Quad centroid ((0+10)+(9+4))/4, ((0+0)+(3-6))/4 = (5.75, -0.75): inside t2.
#include <gtest/gtest.h>

#include <vector>

#include "lepp/reference.h"
#include "mesh_checks.h"

namespace lepp::reference {
namespace {

enum : int { A, B, C, D, E, F };

Pslg polygon(std::vector<int> cycle) {
  Pslg p;
  p.vertices = {{0, 0}, {10, 0}, {9, 3}, {4, -6}, {2, 9}, {12, -8}};
  for (std::size_t i = 0; i < cycle.size(); ++i) p.segments.push_back({cycle[i], cycle[(i + 1) % cycle.size()], 0});
  return p;
}

TraceStep first_step(const Pslg& input, Method method) {
  RefineOptions options;
  options.min_angle_deg = 30;
  options.method = method;
  options.trace = true;
  RefineResult result = refine(input, options);
  EXPECT_FALSE(result.trace.empty());
  EXPECT_EQ(result.outcome, Outcome::Converged) << result.stuck;
  EXPECT_EQ(testing::check_min_angle(result.mesh, 30), "");
  return result.trace.empty() ? TraceStep{} : result.trace.front();
}

// The Lepp of the first bad triangle ABC ends at the pair ABC, ABD.
void expect_pair(const TraceStep& s) {
  EXPECT_EQ(s.bad, (Tri{A, B, C}));
  ASSERT_EQ(s.lepp.size(), 2u);
  EXPECT_EQ(s.t1, (Tri{A, B, C}));
  EXPECT_EQ(s.t2, (Tri{A, D, B}));
  EXPECT_EQ(std::min(s.terminal_edge[0], s.terminal_edge[1]), A);
  EXPECT_EQ(std::max(s.terminal_edge[0], s.terminal_edge[1]), B);
}

// Ears on both: neither second-longest edge constrained.
const std::vector<int> kBothEars{A, D, F, B, C, E};
// All four sides constrained: both second-longest edges constrained.
const std::vector<int> kNoEars{A, D, B, C};
// Ear on BD only: t1's AC constrained, t2's BD not.
const std::vector<int> kEarOnBD{A, D, F, B, C};
// Ear on AC only: t2's BD constrained, t1's AC not.
const std::vector<int> kEarOnAC{A, D, B, C, E};

// The skinny triangle (0,0), (10,0), (6,1) with its longest edge on the
// boundary of a rectangle and its apex a free vertex (so that its small angles
// are not input angles, which would make it unimprovable). It has the smallest
// key, (0,1,4), of the bad triangles.
TEST(SelectRules, SingleTriangleWithConstrainedLongestEdge) {
  Pslg p;
  p.vertices = {{0, 0}, {10, 0}, {10, 8}, {0, 8}, {6, 1}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}};
  for (Method m : {Method::Centroid, Method::Midpoint}) {
    TraceStep s = first_step(p, m);
    EXPECT_EQ(s.rule, Rule::TerminalConstrainedMidpoint) << to_string(m);
    EXPECT_EQ(s.bad, (Tri{0, 1, 4}));
    EXPECT_EQ(s.lepp, (std::vector<Tri>{{0, 1, 4}}));
    EXPECT_EQ(s.t1, (Tri{0, 1, 4}));
    EXPECT_EQ(s.t2, (Tri{-1, -1, -1}));
    EXPECT_EQ(s.point, (Point{5, 0}));
    EXPECT_EQ(s.split_segment, 0);
  }
}

TEST(SelectRules, CentroidNeitherConstrainedTakesQuadCentroid) {
  TraceStep s = first_step(polygon(kBothEars), Method::Centroid);
  expect_pair(s);
  EXPECT_EQ(s.rule, Rule::QuadCentroid);
  EXPECT_EQ(s.point, (Point{5.75, -0.75}));
  EXPECT_EQ(s.split_segment, -1);
}

TEST(SelectRules, CentroidBothConstrainedTakesMidpointOfT1sSecondLongest) {
  TraceStep s = first_step(polygon(kNoEars), Method::Centroid);
  expect_pair(s);
  EXPECT_EQ(s.rule, Rule::BothSecondLongestMidpoint);
  EXPECT_EQ(s.point, (Point{4.5, 1.5}));  // midpoint of AC, segment 3 (C -> A)
  EXPECT_EQ(s.split_segment, 3);
}

TEST(SelectRules, CentroidOneConstrainedCentroidInsideOther) {
  TraceStep s = first_step(polygon(kEarOnBD), Method::Centroid);
  expect_pair(s);
  EXPECT_EQ(s.rule, Rule::CentroidInOther);  // t* = t1, the centroid lies inside t2
  EXPECT_EQ(s.point, (Point{5.75, -0.75}));
  EXPECT_EQ(s.split_segment, -1);
}

TEST(SelectRules, CentroidOneConstrainedCentroidNotInsideOther) {
  TraceStep s = first_step(polygon(kEarOnAC), Method::Centroid);
  expect_pair(s);
  EXPECT_EQ(s.rule, Rule::SecondLongestMidpoint);  // t* = t2, the centroid is not inside t1
  EXPECT_EQ(s.point, (Point{7, -3}));               // midpoint of BD, segment 1 (D -> B)
  EXPECT_EQ(s.split_segment, 1);
}

TEST(SelectRules, MidpointNeitherConstrainedTakesTerminalMidpoint) {
  TraceStep s = first_step(polygon(kBothEars), Method::Midpoint);
  expect_pair(s);
  EXPECT_EQ(s.rule, Rule::TerminalMidpoint);
  EXPECT_EQ(s.point, (Point{5, 0}));
  EXPECT_EQ(s.split_segment, -1);
}

TEST(SelectRules, MidpointConstrainedSecondLongestOfT1First) {
  for (const auto& cycle : {kNoEars, kEarOnBD}) {
    TraceStep s = first_step(polygon(cycle), Method::Midpoint);
    expect_pair(s);
    EXPECT_EQ(s.rule, Rule::SecondLongestMidpoint);
    EXPECT_EQ(s.point, (Point{4.5, 1.5}));
  }
}

TEST(SelectRules, MidpointConstrainedSecondLongestOfT2) {
  TraceStep s = first_step(polygon(kEarOnAC), Method::Midpoint);
  expect_pair(s);
  EXPECT_EQ(s.rule, Rule::SecondLongestMidpoint);
  EXPECT_EQ(s.point, (Point{7, -3}));
  EXPECT_EQ(s.split_segment, 1);
}

}  // namespace
}  // namespace lepp::reference

namespace lepp::reference {
namespace {

// Edge order ties (ALGORITHM.md Section 3): in the skinny isosceles triangle
// (0,0), (2,0), (1,5) the two long edges have the same length; the one whose
// smaller endpoint id is smaller counts as longer, so the Lepp leaves across
// the edge from vertex 0 to the apex. Swapping the ids of the two base
// vertices mirrors the choice: the rule depends on ids, not on geometry.
// D = (-2.7,3.2) and E = (4.7,3.2) are apexes of ears on the long edges.
RefineResult isosceles(bool swap_base) {
  Pslg p;
  Point a{0, 0}, b{2, 0};
  if (swap_base) std::swap(a, b);
  p.vertices = {a, b, {1, 5}, {-2.7, 3.2}, {4.7, 3.2}};
  // Around the pentagon (0,0), (2,0), E, apex, D, whatever the ids.
  std::vector<int> cycle = swap_base ? std::vector<int>{1, 0, 4, 2, 3} : std::vector<int>{0, 1, 4, 2, 3};
  for (std::size_t i = 0; i < cycle.size(); ++i) p.segments.push_back({cycle[i], cycle[(i + 1) % cycle.size()], 0});
  RefineOptions options;
  options.trace = true;
  return refine(p, options);
}

TEST(EdgeOrder, TieGoesToTheEdgeWithTheOlderVertex) {
  for (bool swap_base : {false, true}) {
    RefineResult r = isosceles(swap_base);
    ASSERT_FALSE(r.trace.empty());
    const TraceStep& s = r.trace.front();
    EXPECT_EQ(s.bad, swap_base ? (Tri{0, 2, 1}) : (Tri{0, 1, 2}));  // counter-clockwise
    // The terminal edge is 0-2 in both cases; the triangle across it holds D
    // (id 3) when vertex 0 is (0,0), E (id 4) when vertex 0 is (2,0).
    EXPECT_EQ(std::min(s.terminal_edge[0], s.terminal_edge[1]), 0) << swap_base;
    EXPECT_EQ(std::max(s.terminal_edge[0], s.terminal_edge[1]), 2) << swap_base;
    int ear = swap_base ? 4 : 3;
    EXPECT_TRUE(s.t2[0] == ear || s.t2[1] == ear || s.t2[2] == ear) << swap_base;
    EXPECT_EQ(r.outcome, Outcome::Converged);
  }
}

}  // namespace
}  // namespace lepp::reference
