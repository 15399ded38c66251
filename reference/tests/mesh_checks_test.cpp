// SPDX-License-Identifier: GPL-3.0-or-later
// The test checks reject broken meshes: a check that cannot fail proves nothing.
#include <gtest/gtest.h>

#include <cmath>

#include "lepp/reference.h"
#include "mesh_checks.h"

namespace lepp::reference::testing {
namespace {

// The unit square split by its diagonal 0-2, all four sides constrained.
Pslg square() {
  Pslg p;
  p.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}};
  return p;
}
Mesh square_mesh() {
  Mesh m;
  m.vertices = square().vertices;
  m.input_vertices = 4;
  m.triangles = {{0, 1, 3}, {1, 2, 3}};
  m.constrained_edges = {{0, 1, 0}, {1, 2, 1}, {2, 3, 2}, {0, 3, 3}};
  return m;
}

TEST(MeshChecks, AcceptAGoodMesh) {
  EXPECT_EQ(check_min_angle(square_mesh(), 44), "");
  EXPECT_EQ(check_input_vertices(square_mesh(), square()), "");
  EXPECT_EQ(check_segment_chains(square_mesh(), square()), "");
  EXPECT_EQ(check_locally_delaunay(square_mesh()), "");  // cocircular: not strictly inside
  EXPECT_EQ(check_ccw(square_mesh()), "");
  EXPECT_EQ(check_max_area(square_mesh(), 0.5), "");
}

TEST(MeshChecks, RejectSmallAngle) {
  EXPECT_NE(check_min_angle(square_mesh(), 46), "");  // 45 degree angles
  EXPECT_EQ(check_min_angle(square_mesh(), 46, {{0, 1, 3}, {1, 2, 3}}), "");
}

TEST(MeshChecks, RejectMovedOrMissingInputVertex) {
  Mesh m = square_mesh();
  m.vertices[2].x = std::nextafter(1.0, 2.0);
  EXPECT_NE(check_input_vertices(m, square()), "");
  m = square_mesh();
  m.triangles = {{0, 1, 3}};
  EXPECT_NE(check_input_vertices(m, square()), "");
}

TEST(MeshChecks, RejectBrokenSegmentChain) {
  Mesh m = square_mesh();
  m.constrained_edges.pop_back();  // segment 3 lost
  EXPECT_NE(check_segment_chains(m, square()), "");
  m = square_mesh();
  m.constrained_edges[1].segment = 2;  // wrong tag
  EXPECT_NE(check_segment_chains(m, square()), "");
}

TEST(MeshChecks, RejectNonDelaunayEdge) {
  Mesh m = square_mesh();
  m.vertices[2] = {0.6, 0.6};  // inside the circle of 0, 1, 3: diagonal 1-3 is not Delaunay
  EXPECT_NE(check_locally_delaunay(m), "");
  m.constrained_edges.push_back({1, 3, -1});  // unless it is constrained
  EXPECT_EQ(check_locally_delaunay(m), "");
}

TEST(MeshChecks, RejectClockwiseTriangleAndLargeTriangle) {
  Mesh m = square_mesh();
  m.triangles[0] = {0, 3, 1};
  EXPECT_NE(check_ccw(m), "");
  EXPECT_NE(check_max_area(square_mesh(), 0.49), "");
}

}  // namespace
}  // namespace lepp::reference::testing
