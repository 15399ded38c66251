// SPDX-License-Identifier: GPL-3.0-or-later
// One group of checks alone (lepp/certify/checks.h): rejects a mesh broken in its group, accepts a good one.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lepp/certify.h"
#include "lepp/certify/checks.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

using certify::Check;
using certify::Reason;

// A flat rhombus a(0,0) b(2,-1) c(4,0) d(2,1): the short diagonal bd is Delaunay, the long one ac is not.
Pslg rhombus() {
  Pslg p;
  p.vertices = {{0, 0}, {2, -1}, {4, 0}, {2, 1}};
  p.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

Mesh rhombus_mesh(bool long_diagonal) {
  Mesh m;
  m.vertices = {{0, 0}, {2, -1}, {4, 0}, {2, 1}};
  m.input_vertices = 4;
  m.triangles = long_diagonal ? std::vector<Tri>{{0, 1, 2}, {0, 2, 3}} : std::vector<Tri>{{0, 1, 3}, {1, 2, 3}};
  return m;
}

using GroupCheck = certify::Report (*)(const Pslg&, const Mesh&, const certify::Options&);
const GroupCheck kGroups[] = {certify::check_topology, certify::check_input_vertices, certify::check_constraints,
                              certify::check_delaunay,  certify::check_min_angle,      certify::check_theorem2,
                              certify::check_size_bound};

TEST(CertifyOneCheck, EveryGroupAloneAcceptsAGoodMesh) {
  certify::Options o;
  o.min_angle_deg = 30;
  o.max_area = 10;
  for (GroupCheck check : kGroups) {
    const certify::Report r = check(rhombus(), rhombus_mesh(false), o);
    EXPECT_TRUE(r.certified()) << certify::format_report(r);
  }
}

TEST(CertifyOneCheck, DelaunayAloneRejectsTheLongDiagonal) {
  const certify::Report r = certify::check_delaunay(rhombus(), rhombus_mesh(true));
  EXPECT_FALSE(r.certified());
  EXPECT_EQ(r.count(Reason::NotLocallyDelaunay), 1u);
  ASSERT_EQ(r.violations.size(), 1u);
  // The same violation, word for word, as the whole certificate lists.
  const certify::Report all = certify::certify(rhombus(), rhombus_mesh(true));
  ASSERT_EQ(all.count(Reason::NotLocallyDelaunay), 1u);
  for (const certify::Violation& v : all.violations)
    if (v.reason == Reason::NotLocallyDelaunay) EXPECT_EQ(v.message, r.violations[0].message);
}

TEST(CertifyOneCheck, AGroupAloneIgnoresAnotherGroupsViolation) {
  // The long diagonal is only a Delaunay fault: topology and the angle check pass it.
  EXPECT_TRUE(certify::check_topology(rhombus(), rhombus_mesh(true)).certified());
  certify::Options o;
  o.min_angle_deg = 5;
  EXPECT_TRUE(certify::check_min_angle(rhombus(), rhombus_mesh(true), o).certified());
}

TEST(CertifyOneCheck, TopologyAloneRejectsAClockwiseTriangle) {
  Mesh m = rhombus_mesh(false);
  m.triangles[0] = {0, 3, 1};
  const certify::Report r = certify::check_topology(rhombus(), m);
  EXPECT_GT(r.count(Reason::NotCounterClockwise), 0u);
  for (const certify::Violation& v : r.violations) EXPECT_EQ(certify::check_of(v.reason), Check::Topology);
}

TEST(CertifyOneCheck, MinAngleAloneRejectsBelowTheta) {
  certify::Options o;
  o.min_angle_deg = 60;  // the rhombus's triangles have an angle of about 53 degrees
  const certify::Report r = certify::check_min_angle(rhombus(), rhombus_mesh(false), o);
  EXPECT_EQ(r.count(Reason::AngleBelowTheta), 2u);
}

}  // namespace
}  // namespace lepp
