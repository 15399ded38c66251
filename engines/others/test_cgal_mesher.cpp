// SPDX-License-Identifier: GPL-3.0-or-later
// The CGAL mesher wrapper: domain, holes, angle bound, and the budget that stops it.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "cgal_mesher.h"
#include "lepp/io.h"
#include "lepp/stats.h"
#include "lepp/validate.h"

namespace lepp::others {
namespace {

Pslg paper_problem(const std::string& name) {
  std::vector<std::string> warnings;
  return validate(read_poly(std::string(LEPP_SOURCE_DIR) + "/corpus/paper/" + name + ".poly"), warnings);
}

double mesh_area(const Mesh& m) {
  double area = 0;
  for (const Tri& t : m.triangles) {
    const Point &a = m.vertices[t[0]], &b = m.vertices[t[1]], &c = m.vertices[t[2]];
    area += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  }
  return area;
}

TEST(CgalMesher, Square400At20DegreesCoversTheSquareWithGoodAngles) {
  Pslg square = paper_problem("square400");
  CgalMeshResult r = cgal_mesh(square, 20);
  EXPECT_TRUE(r.finished);
  EXPECT_GT(r.steiner_points, 0);
  EXPECT_EQ(r.mesh.vertices.size(), square.vertices.size() + static_cast<std::size_t>(r.steiner_points));
  EXPECT_NEAR(mesh_area(r.mesh), 100.0 * 100.0, 1e-6);
  MeshStats s = mesh_stats(r.mesh, square);
  EXPECT_GE(s.min_angle_deg, 20.0 - 1e-9);
  // Input vertices keep their ids.
  for (std::size_t i = 0; i < square.vertices.size(); ++i) EXPECT_EQ(r.mesh.vertices[i], square.vertices[i]);
  // The boundary is made of constrained edges: at least the 400 input pieces.
  EXPECT_GE(r.mesh.constrained_edges.size(), 400u);
}

TEST(CgalMesher, HoleIsRemoved) {
  Pslg circles = paper_problem("circles240");
  CgalMeshResult r = cgal_mesh(circles, 20);
  EXPECT_TRUE(r.finished);
  // Annulus of two 120-gons: R = 1 outer, r = 0.2 hole.
  double polygon = 0.5 * 120 * std::sin(2 * M_PI / 120);
  EXPECT_NEAR(mesh_area(r.mesh), polygon * (1.0 - 0.04), 1e-9);
  // Every triangle is counter-clockwise.
  for (const Tri& t : r.mesh.triangles) {
    const Point &a = r.mesh.vertices[t[0]], &b = r.mesh.vertices[t[1]], &c = r.mesh.vertices[t[2]];
    EXPECT_GT((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x), 0);
  }
}

TEST(CgalMesher, PointBudgetStopsARunAndSaysSo) {
  Pslg square = paper_problem("square400");
  CgalMeshLimits limits;
  limits.max_steiner = 100;
  CgalMeshResult r = cgal_mesh(square, 20, 0, limits);
  EXPECT_FALSE(r.finished);
  EXPECT_GE(r.steiner_points, 100);
  EXPECT_LT(r.steiner_points, 100 + 300);
  EXPECT_LT(mesh_stats(r.mesh, square).min_angle_deg, 20.0);
}

}  // namespace
}  // namespace lepp::others
