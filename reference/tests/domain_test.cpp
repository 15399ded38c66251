// SPDX-License-Identifier: GPL-3.0-or-later
// The domain (ALGORITHM.md Section 2, Triangle's -p) and the split of a
// constrained edge by a rounded midpoint that is not on it (Section 6).
#include <gtest/gtest.h>

#include "lepp/reference.h"
#include "mesh_checks.h"

namespace lepp::reference {
namespace {

// [0,10]^2 with the hole [4,6]^2 (segments 4..7) and the given hole points.
Pslg square_with_hole(std::vector<Point> holes) {
  Pslg p;
  p.vertices = {{0, 0}, {10, 0}, {10, 10}, {0, 10}, {4, 4}, {6, 4}, {6, 6}, {4, 6}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}, {4, 5, 0}, {5, 6, 0}, {6, 7, 0}, {7, 4, 0}};
  p.holes = std::move(holes);
  return p;
}

TEST(Domain, HolePointRemovesTheHole) {
  Mesh m = build_cdt(square_with_hole({{4.5, 5.2}}));  // strictly inside a triangle of the hole
  EXPECT_EQ(testing::twice_area(m), 2 * (100 - 4));
  EXPECT_EQ(testing::check_ccw(m), "");
  EXPECT_EQ(m.constrained_edges.size(), 8u);
}

TEST(Domain, HolePointOnAnUnconstrainedEdgeRemovesTheHole) {
  // The hole [4,6]^2 is two triangles; (5,5) is on the diagonal whichever it is.
  Mesh m = build_cdt(square_with_hole({{5, 5}}));
  EXPECT_EQ(testing::twice_area(m), 2 * 96);
}

TEST(Domain, WithoutHolePointTheHoleIsMeshed) {
  EXPECT_EQ(testing::twice_area(build_cdt(square_with_hole({}))), 2 * 100);
}

TEST(Domain, HolePointOnASegmentOrOutsideRemovesNothing) {
  EXPECT_EQ(testing::twice_area(build_cdt(square_with_hole({{5, 4}}))), 2 * 100);   // on segment 4
  EXPECT_EQ(testing::twice_area(build_cdt(square_with_hole({{20, 5}}))), 2 * 100);  // outside
}

// On a vertex (of the hole, or of the outer square), or beyond the bounding
// box the CDT is built in: located neither in a face nor on an edge.
TEST(Domain, HolePointOnAVertexOrFarOutsideRemovesNothing) {
  for (Point h : {Point{4, 4}, Point{10, 10}, Point{1e6, 5}})
    EXPECT_EQ(testing::twice_area(build_cdt(square_with_hole({h}))), 2 * 100) << h.x << " " << h.y;
  // With a hole point that does remove the hole, one of these beside it changes nothing.
  EXPECT_EQ(testing::twice_area(build_cdt(square_with_hole({{4, 4}, {4.5, 5.2}}))), 2 * 96);
}

TEST(Domain, ConcavePolygonKeepsOnlyItsInside) {
  // An L: the CDT of its vertices covers the notch [1,2]x[1,2], the domain does not.
  Pslg p;
  p.vertices = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  for (int i = 0; i < 6; ++i) p.segments.push_back({i, (i + 1) % 6, 0});
  Mesh m = build_cdt(p);
  EXPECT_EQ(testing::twice_area(m), 2 * 3);
  RefineResult r = refine(p, RefineOptions{});
  EXPECT_EQ(r.outcome, Outcome::Converged);
  EXPECT_EQ(testing::twice_area(r.mesh), 2 * 3);
}

TEST(Domain, OpenChainEnclosesNothing) {
  Pslg p;
  p.vertices = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}};
  EXPECT_TRUE(build_cdt(p).triangles.empty());
  RefineResult r = refine(p, RefineOptions{});
  EXPECT_EQ(r.outcome, Outcome::Converged);
  EXPECT_EQ(r.steiner_points, 0);
}

// A skinny triangle (A, B, X) whose longest edge AB is a boundary segment with
// a rounded midpoint off the line AB: inside the domain for one input, outside
// for the other. The split must still replace AB by two constrained edges.
class OffLineMidpoint : public ::testing::TestWithParam<std::array<double, 4>> {};

TEST_P(OffLineMidpoint, SplitsTheSegmentAnyway) {
  auto [ax, ay, bx, by] = GetParam();
  Pslg p;
  p.vertices = {{ax, ay}, {bx, by}, {bx, 8}, {ax, 8}, {6, 1.2}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}};
  Point mid{(ax + bx) * 0.5, (ay + by) * 0.5};
  ASSERT_NE(testing::orientation(p.vertices[0], p.vertices[1], mid), 0) << "the test needs an off-line midpoint";
  RefineOptions options;
  options.trace = true;
  RefineResult r = refine(p, options);
  ASSERT_FALSE(r.trace.empty());
  EXPECT_EQ(r.trace[0].rule, Rule::TerminalConstrainedMidpoint);
  EXPECT_EQ(r.trace[0].point, mid);
  EXPECT_EQ(r.trace[0].split_segment, 0);
  EXPECT_EQ(r.mesh.vertices[5], mid);
  EXPECT_EQ(r.outcome, Outcome::Converged) << r.stuck;
  EXPECT_EQ(testing::check_segment_chains(r.mesh, p), "");
  EXPECT_EQ(testing::check_ccw(r.mesh), "");
  EXPECT_EQ(testing::check_locally_delaunay(r.mesh), "");
  EXPECT_EQ(testing::check_min_angle(r.mesh, 30), "");
}

INSTANTIATE_TEST_SUITE_P(Reference, OffLineMidpoint,
                         ::testing::Values(std::array<double, 4>{0.1, 0.0, 9.7, 0.3},    // midpoint inside
                                           std::array<double, 4>{0.3, 0.1, 9.9, 0.7}));  // midpoint outside

}  // namespace
}  // namespace lepp::reference
