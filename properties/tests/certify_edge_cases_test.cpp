// SPDX-License-Identifier: GPL-3.0-or-later
// The certifier at the edges of its checks, each a case the default ctest did not
// reach before (docs/COVERAGE.md): ids and coordinates bad in every corner, meshes
// with fewer vertices than they claim, segment endpoints and split points absent,
// a segment with no domain side, listed edges with ids out of range, a zero-area
// triangle, an empty mesh, and segment_tolerance() at zero and among subnormals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "cgal_mesh.h"
#include "lepp/certify.h"
#include "lepp/validate.h"
#include "test_pslgs.h"

namespace lepp {
namespace {

using certify::Reason;

certify::Report run(const Pslg& pslg, const Mesh& mesh) { return certify::certify(pslg, mesh); }

std::size_t total(const certify::Report& r) {
  std::size_t n = 0;
  for (std::size_t c : r.count_by_reason) n += c;
  return n;
}

// The messages of the listed violations of one reason.
std::vector<std::string> messages(const certify::Report& r, Reason reason) {
  std::vector<std::string> out;
  for (const certify::Violation& v : r.violations)
    if (v.reason == reason) out.push_back(v.message);
  return out;
}

bool any_contains(const std::vector<std::string>& texts, const std::string& part) {
  return std::any_of(texts.begin(), texts.end(), [&](const std::string& t) { return t.find(part) != std::string::npos; });
}

// square_with_crack() without its last input vertex (interior, on no segment).
Pslg without_last_vertex(const Pslg& p) {
  Pslg q = p;
  q.vertices.pop_back();
  return q;
}

TEST(CertifyEdgeCases, BadIdsAndNonFiniteCoordinatesInEveryCorner) {
  const Pslg p = test::square_with_crack();
  Mesh bad = test::cgal_cdt(p);
  const int nan_x = static_cast<int>(bad.vertices.size()), inf_y = nan_x + 1;
  bad.vertices.push_back({std::nan(""), 1});
  bad.vertices.push_back({1, std::numeric_limits<double>::infinity()});  // x finite, y not
  const std::vector<Tri> broken = {
      {0, -1, 1},     // a negative id
      {2, 3, 3},      // second and third the same
      {3, 2, 3},      // first and third the same
      {nan_x, 0, 1},  // a NaN coordinate in the first corner
      {0, inf_y, 1},  // an infinite coordinate in the second corner
  };
  bad.triangles.insert(bad.triangles.end(), broken.begin(), broken.end());
  const auto r = run(p, bad);
  EXPECT_EQ(r.count(Reason::BadTriangle), broken.size()) << certify::format_report(r);
  EXPECT_EQ(messages(r, Reason::BadTriangle).size(), broken.size());
  // The two vertices are in no valid triangle: unused Steiner vertices, nothing else.
  EXPECT_EQ(r.count(Reason::UnusedVertex), 2u) << certify::format_report(r);
  EXPECT_EQ(total(r), broken.size() + 2) << certify::format_report(r);
}

TEST(CertifyEdgeCases, FewerMeshVerticesThanTheInputVerticesClaimed) {
  // The mesh promises input_vertices = n but has n - 1 vertices: input vertex n - 1
  // is absent, so it is moved (from the promise) and missing (from the domain).
  const Pslg p = test::square_with_crack();
  Mesh bad = test::cgal_cdt(without_last_vertex(p));
  bad.input_vertices = p.vertices.size();
  ASSERT_EQ(bad.vertices.size() + 1, p.vertices.size());
  const auto r = run(p, bad);
  EXPECT_EQ(r.count(Reason::InputVertexMoved), 1u) << certify::format_report(r);
  EXPECT_TRUE(any_contains(messages(r, Reason::InputVertexMoved), "(absent)")) << certify::format_report(r);
  EXPECT_EQ(r.count(Reason::InputVertexMissing), 1u) << certify::format_report(r);
  EXPECT_EQ(total(r), 2u) << certify::format_report(r);
}

TEST(CertifyEdgeCases, MovedUnusedInputVertexIsReportedOnceAsMoved) {
  // Mesh vertex n - 1 is promised to be input vertex n - 1 but lies elsewhere and is
  // in no triangle: one violation (moved), not also missing or an unused Steiner vertex.
  const Pslg p = test::square_with_crack();
  Mesh bad = test::cgal_cdt(without_last_vertex(p));
  const Point last = p.vertices.back();
  bad.vertices.push_back({last.x + 0.5, last.y});
  bad.input_vertices = p.vertices.size();
  const auto r = run(p, bad);
  EXPECT_EQ(r.count(Reason::InputVertexMoved), 1u) << certify::format_report(r);
  EXPECT_EQ(total(r), 1u) << certify::format_report(r);
}

TEST(CertifyEdgeCases, SegmentEndpointAbsentFromTheMesh) {
  const Pslg p = test::square_with_crack();
  const Segment crack = p.segments.back();
  for (int end : {crack.a, crack.b}) {
    Mesh bad = test::cgal_cdt(p);
    bad.input_vertices = 0;  // vertices found by their coordinates
    Point& v = bad.vertices[static_cast<std::size_t>(end)];
    v.x = std::nextafter(v.x, 100.0);  // one ulp away: input vertex `end` is not in the mesh
    const auto r = run(p, bad);
    EXPECT_EQ(r.count(Reason::InputVertexMissing), 1u) << certify::format_report(r);
    EXPECT_EQ(r.count(Reason::SegmentMissing), 1u) << certify::format_report(r);
    EXPECT_TRUE(any_contains(messages(r, Reason::SegmentMissing), "an endpoint is not in the mesh")) << certify::format_report(r);
  }
}

// The triangle (0,0) (10,0) (0,10) with a vertex at (4,0) on its bottom side:
// validation splits that side into two pieces of one file segment.
Pslg triangle_with_split_side() {
  Pslg p;
  p.vertices = {{0, 0}, {10, 0}, {0, 10}, {4, 0}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  return test::validated(p);
}

TEST(CertifyEdgeCases, SplitSegmentWithItsSplitPointAbsent) {
  const Pslg p = triangle_with_split_side();
  ASSERT_EQ(p.segments.size(), 4u);
  ASSERT_EQ(p.segment_origin.size(), p.segments.size());
  const Mesh good = test::cgal_cdt(p);
  EXPECT_TRUE(run(p, good).certified()) << certify::format_report(run(p, good));
  // The mesh of the unsplit triangle: (4,0) is absent, the pieces have an endpoint
  // missing; where the side was split cannot be checked, and is not a crash.
  Pslg unsplit;
  unsplit.vertices = {{0, 0}, {10, 0}, {0, 10}};
  unsplit.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  Mesh bad = test::cgal_cdt(test::validated(unsplit));
  bad.input_vertices = 0;
  const auto r = run(p, bad);
  EXPECT_EQ(r.count(Reason::InputVertexMissing), 1u) << certify::format_report(r);
  EXPECT_EQ(r.count(Reason::SegmentMissing), 2u) << certify::format_report(r);  // both pieces
  EXPECT_FALSE(r.has(Reason::SteinerOffSegment)) << certify::format_report(r);
}

TEST(CertifyEdgeCases, SplitSegmentWithAnEndAbsent) {
  const Pslg p = triangle_with_split_side();
  // An end of the split side one ulp away in the mesh (ids not promised): the split
  // point cannot be held to the line through ends the mesh does not have.
  for (int end : {0, 1}) {
    Mesh bad = test::cgal_cdt(p);
    bad.input_vertices = 0;
    Point& v = bad.vertices[static_cast<std::size_t>(end)];
    v.y = std::nextafter(v.y, -1.0);
    const auto r = run(p, bad);
    EXPECT_EQ(r.count(Reason::InputVertexMissing), 1u) << certify::format_report(r);
    EXPECT_TRUE(r.has(Reason::SegmentMissing)) << certify::format_report(r);
    EXPECT_FALSE(r.has(Reason::SteinerOffSegment)) << certify::format_report(r);
  }
}

TEST(CertifyEdgeCases, SegmentAcrossAHoleNeedsNoChain) {
  // A diagonal of the square hole, with a hole point on each side: both of its
  // sides are removed, so the mesh need not (and does not) have it as an edge,
  // though both its ends are mesh vertices.
  Pslg p = test::square_with_hole();
  p.segments.push_back({4, 6, 2});  // (4,4)-(6,6)
  p.holes = {{5.5, 4.5}, {4.5, 5.5}};
  p = test::validated(p);
  const Mesh m = test::cgal_cdt(p);
  const auto r = run(p, m);
  EXPECT_TRUE(r.certified()) << certify::format_report(r);
  // One hole point only: the other half of the hole is domain, and a mesh without it is not.
  Pslg half = p;
  half.holes.pop_back();
  const auto h = run(half, m);
  EXPECT_TRUE(h.has(Reason::DomainBoundaryUncovered)) << certify::format_report(h);
  EXPECT_TRUE(h.has(Reason::SegmentMissing)) << certify::format_report(h);
}

TEST(CertifyEdgeCases, ListedConstrainedEdgeWithIdsOutOfRange) {
  const Pslg p = test::square_with_crack();
  Mesh bad = test::cgal_cdt(p);
  bad.constrained_edges.push_back({0, 999, -1});
  bad.constrained_edges.push_back({-1, 2, -1});
  const auto r = run(p, bad);
  EXPECT_EQ(r.count(Reason::ConstrainedEdgeNotOnSegment), 2u) << certify::format_report(r);
  EXPECT_EQ(total(r), 2u) << certify::format_report(r);
  for (const std::string& m : messages(r, Reason::ConstrainedEdgeNotOnSegment)) EXPECT_NE(m.find("out of range"), std::string::npos) << m;
}

TEST(CertifyEdgeCases, ZeroAreaTriangleIsNotJudgedByInCircle) {
  // The square (0,0) (4,0) (4,4) (0,4) with its centre E = (2,2) and a Steiner
  // vertex F = (1,1) on the diagonal A-E. Triangle 0, (A, E, F), has zero area; its
  // edges pair properly with triangles on both sides (A-E with (A,B,E), A-F and F-E
  // with (D,A,F) and (D,F,E)), so the mesh is otherwise consistent. Its in-circle
  // tests are meaningless (no circle through three collinear points): the triangle
  // is reported once, as not counter-clockwise, and its edges are not in-circle tested.
  Pslg p;
  p.vertices = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 2}};  // A B C D E
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}};
  p = test::validated(p);
  Mesh m;
  m.vertices = p.vertices;
  m.vertices.push_back({1, 1});  // F = 5
  m.input_vertices = 5;
  m.triangles = {{0, 4, 5}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 5}, {3, 5, 4}};
  const auto r = run(p, m);
  EXPECT_EQ(r.count(Reason::NotCounterClockwise), 1u) << certify::format_report(r);
  EXPECT_EQ(total(r), 1u) << certify::format_report(r);
}

TEST(CertifyEdgeCases, EmptyMeshIsRejectedWithoutACrash) {
  const Pslg p = test::square_with_crack();
  Mesh empty;
  const auto r = run(p, empty);
  EXPECT_FALSE(r.certified());
  EXPECT_EQ(r.count(Reason::InputVertexMissing), p.vertices.size()) << certify::format_report(r);
  EXPECT_EQ(r.count(Reason::SegmentMissing), p.segments.size()) << certify::format_report(r);
  EXPECT_TRUE(r.has(Reason::EulerCharacteristic));
  EXPECT_EQ(r.stats.triangles, 0u);
  EXPECT_EQ(r.stats.avg_lepp_size, 0.0);
}

TEST(CertifyEdgeCases, SegmentToleranceAtZeroAndAmongSubnormals) {
  // Both ends at the origin: M = 0, no tolerance at all.
  EXPECT_EQ(certify::segment_tolerance({0, 0}, {0, 0}, 5), 0.0);
  // M subnormal: ulp(M) is the smallest subnormal 2^-1074, not 2^(exponent - 53),
  // which would underflow to zero.
  const double tiny = std::ldexp(1.0, -1060);
  EXPECT_EQ(certify::segment_tolerance({0, 0}, {tiny, 0}, 0), std::ldexp(1.0, -1074));
  EXPECT_EQ(certify::segment_tolerance({0, 0}, {tiny, 0}, 2), 3 * std::ldexp(1.0, -1074));
  // The smallest normal: 2^-1022 = 0.5 * 2^-1021, ulp = 2^(-1021 - 53) = 2^-1074 exactly.
  EXPECT_EQ(certify::segment_tolerance({0, 0}, {0, std::ldexp(1.0, -1022)}, 0), std::ldexp(1.0, -1074));
  EXPECT_EQ(certify::segment_tolerance({0, 0}, {0, 1}, 0), std::ldexp(1.0, -52));  // ulp(1) = 2^-52
}

}  // namespace
}  // namespace lepp
