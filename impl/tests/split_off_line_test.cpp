// SPDX-License-Identifier: GPL-3.0-or-later
// A split of a constrained edge ab at a point p off the line ab (a rounded
// midpoint, ALGORITHM.md section 6, "A split off its line"): the triangle on the
// side p moves away from stays, with the sliver beside it, exactly when p lies
// strictly outside its circumcircle; on the circle, inside it, or on the line the
// usual split. Hand-made two-triangle meshes put p at each of those places (all
// coordinates exact in binary), and every case must end locally Delaunay.
#include <gtest/gtest.h>

#include <vector>

#include "insertion.h"
#include "predicates.h"
#include "tri_mesh.h"

namespace lepp::fast {
namespace {

struct TwoTriangles {
  Pslg pslg;
  TriMesh mesh;
  SegmentMembership mem;
};

// Triangle 0 = (c, a, b), edge 0 = ab constrained (segment 0); with d, triangle
// 1 = (d, b, a) across it, else ab is on the boundary. Vertices a, b, c, d = 0..3.
TwoTriangles two_triangles(Point a, Point b, Point c, const Point* d) {
  TwoTriangles s;
  s.pslg.vertices = {a, b, c};
  if (d) s.pslg.vertices.push_back(*d);
  s.pslg.segments = {{0, 1}};
  s.mem = make_membership(s.pslg);
  s.mesh.pts = s.pslg.vertices;
  s.mesh.grow(d ? 2 : 1);
  s.mesh.put(0, FTri{{2, 0, 1}, {d ? nbr_code(1, 0) : -1, -1, -1}, {0, 0, 0}, -1});
  if (d) s.mesh.put(1, FTri{{3, 1, 0}, {nbr_code(0, 0), -1, -1}, {0, 0, 0}, -1});
  return s;
}

// Inserts p as a split of edge 0 of triangle 0; returns the kept triangle (-1: none).
int split_at(TwoTriangles& s, Point p) {
  Inserter ins;
  Choice ch;
  ch.rule = Rule::TerminalConstrainedMidpoint;
  ch.point = p;
  ch.tri = 0;
  ch.edge = 0;
  int segment = -1;
  ins.insert(s.mesh, s.mem, ch, segment);
  EXPECT_EQ(segment, 0);
  return ins.kept();
}

// Every triangle counter-clockwise, neighbours mutual, and every unconstrained
// edge between two triangles locally Delaunay (exact in-circle).
void expect_valid_and_delaunay(const TriMesh& m) {
  for (int t = 0; t < m.size(); ++t) {
    const FTri& f = m.t(t);
    EXPECT_GT(orient(m.p(f.v(0)), m.p(f.v(1)), m.p(f.v(2))), 0) << "triangle " << t;
    for (int i = 0; i < 3; ++i) {
      if (f.nbr[i] < 0) continue;
      const FTri& g = m.t(nbr_tri(f.nbr[i]));
      EXPECT_EQ(g.nbr[nbr_edge(f.nbr[i])], nbr_code(t, i)) << "triangle " << t << " edge " << i;
      EXPECT_EQ(g.seg(nbr_edge(f.nbr[i])), f.seg(i)) << "triangle " << t << " edge " << i;
      if (f.seg(i) >= 0) continue;
      EXPECT_LE(incircle(m.p(f.v(0)), m.p(f.v(1)), m.p(f.v(2)), m.p(g.v(nbr_edge(f.nbr[i])))), 0)
          << "edge " << i << " of triangle " << t << " is not locally Delaunay";
    }
  }
}

// The circle through a = (0, 0), b = (4, 0), d = (2, -8) has its top at (2, 0.5).
const Point kA{0, 0}, kB{4, 0}, kC{2, 2}, kD{2, -8};

TEST(SplitOffLine, BeyondTheFarCircleKeepsTheNeighbour) {
  TwoTriangles s = two_triangles(kA, kB, kC, &kD);
  const std::uint32_t stamp = s.mesh.stamp[1];
  EXPECT_EQ(split_at(s, {2, 0.625}), 1);
  EXPECT_EQ(s.mesh.stamp[1], stamp) << "the kept triangle was rewritten";
  const FTri& k = s.mesh.t(1);
  EXPECT_EQ(k.v(0), 3);
  EXPECT_EQ(k.seg(0), -1) << "ab stays constrained beside the sliver";
  EXPECT_EQ(s.mesh.size(), 4);
  expect_valid_and_delaunay(s.mesh);
}

TEST(SplitOffLine, OnTheFarCircleIsTheUsualSplit) {
  TwoTriangles s = two_triangles(kA, kB, kC, &kD);
  EXPECT_EQ(split_at(s, {2, 0.5}), -1);
  EXPECT_EQ(s.mesh.size(), 4);
  EXPECT_EQ(s.mesh.t(1).v(0), 4) << "the neighbour was not split";
  expect_valid_and_delaunay(s.mesh);
}

TEST(SplitOffLine, InsideTheFarCircleOrOnTheLineIsTheUsualSplit) {
  for (Point p : {Point{2, 0.375}, Point{2, 0}}) {
    TwoTriangles s = two_triangles(kA, kB, kC, &kD);
    EXPECT_EQ(split_at(s, p), -1) << p.y;
    EXPECT_EQ(s.mesh.t(1).v(0), 4) << p.y;
    expect_valid_and_delaunay(s.mesh);
  }
}

// The mirror: p beyond ab on the neighbour's side, outside the circle of (c, a, b)
// (c = (2, 8): bottom at (2, -0.5)).
TEST(SplitOffLine, BeyondTheOwnCircleKeepsTheSplitTriangle) {
  const Point c{2, 8}, d{2, -2};
  TwoTriangles s = two_triangles(kA, kB, c, &d);
  const std::uint32_t stamp = s.mesh.stamp[0];
  EXPECT_EQ(split_at(s, {2, -0.625}), 0);
  EXPECT_EQ(s.mesh.stamp[0], stamp);
  EXPECT_EQ(s.mesh.t(0).seg(0), -1);
  expect_valid_and_delaunay(s.mesh);

  TwoTriangles tie = two_triangles(kA, kB, c, &d);
  EXPECT_EQ(split_at(tie, {2, -0.5}), -1);
  expect_valid_and_delaunay(tie.mesh);
}

// On the domain boundary (no neighbour): p outside the domain and outside the
// circle keeps the triangle and adds only the sliver; on the circle, the usual two.
TEST(SplitOffLine, BoundarySplitKeepsTheTriangleBesideItsSliver) {
  const Point c{2, 8};
  TwoTriangles s = two_triangles(kA, kB, c, nullptr);
  EXPECT_EQ(split_at(s, {2, -0.625}), 0);
  EXPECT_EQ(s.mesh.size(), 2);
  expect_valid_and_delaunay(s.mesh);

  TwoTriangles tie = two_triangles(kA, kB, c, nullptr);
  EXPECT_EQ(split_at(tie, {2, -0.5}), -1);
  EXPECT_EQ(tie.mesh.size(), 2);
  EXPECT_EQ(tie.mesh.t(0).v(0), 3) << "the triangle was not split (p is vertex 3 here)";
  expect_valid_and_delaunay(tie.mesh);
}

}  // namespace
}  // namespace lepp::fast
