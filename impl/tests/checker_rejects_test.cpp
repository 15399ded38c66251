// SPDX-License-Identifier: GPL-3.0-or-later
// The invariant checker of impl's tests rejects broken meshes: each check can fail.
#include <gtest/gtest.h>

#include <algorithm>

#include "lepp/fast.h"
#include "lepp/validate.h"
#include "mesh_invariants.h"

namespace lepp::impl_test {
namespace {

// The unit square with an interior point near a corner: four triangles.
Pslg square() {
  Pslg p;
  p.vertices = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {1, 3}};
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}};
  std::vector<std::string> w;
  return validate(p, w);
}

bool mentions(const std::vector<std::string>& problems, const std::string& what) {
  return std::any_of(problems.begin(), problems.end(), [&](const std::string& s) { return s.find(what) != std::string::npos; });
}

TEST(CheckerRejects, GoodMeshPasses) {
  Pslg p = square();
  EXPECT_TRUE(check_invariants(p, fast::build_cdt(p), {}).empty());
}

TEST(CheckerRejects, ClockwiseTriangle) {
  Pslg p = square();
  Mesh m = fast::build_cdt(p);
  std::swap(m.triangles[0][1], m.triangles[0][2]);
  EXPECT_TRUE(mentions(check_invariants(p, m, {}), "counter-clockwise"));
}

TEST(CheckerRejects, NonDelaunayEdge) {
  Pslg p;
  p.vertices = {{0, 0}, {10, 0}, {10, 1}, {0, 1}};
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}};
  Mesh m;
  m.vertices = p.vertices;
  m.input_vertices = 4;
  // A rectangle is cocircular: make it a kite so that one diagonal is wrong.
  m.vertices[2] = {10, 2};
  p.vertices[2] = {10, 2};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};  // diagonal 0-2: (0,1) lies inside the circle through (0,0), (10,0), (10,2)
  m.constrained_edges = {{0, 1, 0}, {1, 2, 1}, {2, 3, 2}, {3, 0, 3}};
  EXPECT_TRUE(mentions(check_invariants(p, m, {}), "not locally Delaunay"));
  m.triangles = {{0, 1, 3}, {1, 2, 3}};
  EXPECT_FALSE(mentions(check_invariants(p, m, {}), "not locally Delaunay"));
}

TEST(CheckerRejects, MissingConstrainedEdge) {
  Pslg p = square();
  Mesh m = fast::build_cdt(p);
  m.constrained_edges.pop_back();
  auto problems = check_invariants(p, m, {});
  EXPECT_TRUE(mentions(problems, "not constrained") || mentions(problems, "chain"));
}

TEST(CheckerRejects, SkinnyAndLargeTriangles) {
  Pslg p = square();
  Mesh m = fast::build_cdt(p);
  InvariantOptions o;
  o.min_angle_deg = 30;
  EXPECT_TRUE(mentions(check_invariants(p, m, o), "below 30"));
  o.min_angle_deg = 0;
  o.max_area = 1;
  EXPECT_TRUE(mentions(check_invariants(p, m, o), "larger than"));
}

TEST(CheckerRejects, OverlappingTriangles) {
  Pslg p = square();
  Mesh m = fast::build_cdt(p);
  m.triangles.push_back(m.triangles[0]);
  EXPECT_TRUE(mentions(check_invariants(p, m, {}), "same direction"));
}

// The global overlap check: a triangle folded across the mesh shares no edge with
// what it covers, so only overlapping_triangles sees it; neighbours touching along
// an edge or at a vertex are no overlap.
TEST(CheckerRejects, TriangleAcrossTheMesh) {
  Pslg p = square();
  Mesh m = fast::build_cdt(p);
  EXPECT_TRUE(overlapping_triangles(m).empty());
  m.vertices.push_back({2, 1});
  m.vertices.push_back({3, 1});
  m.vertices.push_back({2, 2});
  const int n = static_cast<int>(m.vertices.size());
  m.triangles.push_back({n - 3, n - 2, n - 1});  // inside the square, over its triangles
  EXPECT_TRUE(mentions(overlapping_triangles(m), "overlap"));
}

}  // namespace
}  // namespace lepp::impl_test
