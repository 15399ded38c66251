// SPDX-License-Identifier: GPL-3.0-or-later
// The certifier at the edges of its checks, each a case the default ctest did not
// reach before (docs/COVERAGE.md): ids and coordinates bad in every corner, meshes
// with fewer vertices than they claim, segment endpoints, split points and crossing
// points absent, a segment with no domain side, listed edges with ids out of range,
// two candidates for the next chain vertex, a nearer listed edge of another
// segment at a small input angle, vertices exactly at the tolerance and
// near-line bounds, a zero-area triangle, an empty mesh, angles on both sides of
// the sin^2 bracket in one triangle, the section 8 rule's three conditions (apex
// in the mesh, input angle below theta, triangle inside the wedge), an input angle
// within an ulp of 60 degrees, the cap on listed violations, the Theorem 2 check
// switched off, and segment_tolerance() at zero and among subnormals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CGAL/Gmpq.h>

#include "certify_test_support.h"
#include "cgal_mesh.h"
#include "lepp/angle.h"
#include "lepp/certify.h"
#include "lepp/input.h"
#include "lepp/io.h"
#include "lepp/small_input_angles.h"
#include "lepp/validate.h"
#include "test_pslgs.h"

namespace lepp {
namespace {

using certify::Reason;

using test::first_of;
using test::messages;
using test::run;
using test::total;

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
  // The angle check skips them too.
  const auto at20 = run(p, bad, 20);
  EXPECT_EQ(at20.count(Reason::BadTriangle), broken.size()) << certify::format_report(at20);
}

TEST(CertifyEdgeCases, ViolationsBeyondTheCapAreCountedNotListed) {
  const Pslg p = test::square_with_crack();
  Mesh bad = test::cgal_cdt(p);
  for (int k = 0; k < 3; ++k) bad.triangles.push_back({0, 1, 99 + k});  // three bad triangles
  certify::Options options;
  options.max_listed_per_reason = 2;
  const auto r = certify::certify(p, bad, options);
  EXPECT_EQ(r.count(Reason::BadTriangle), 3u);
  EXPECT_EQ(messages(r, Reason::BadTriangle).size(), 2u);
  EXPECT_NE(certify::format_report(r).find("3 x bad-triangle"), std::string::npos) << certify::format_report(r);
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
  const std::vector<ConstrainedEdge> listed = {{0, 999, -1}, {999, 0, -1}, {-1, 2, -1}, {2, -1, -1}};
  bad.constrained_edges.insert(bad.constrained_edges.end(), listed.begin(), listed.end());
  const auto r = run(p, bad);
  EXPECT_EQ(r.count(Reason::ConstrainedEdgeNotOnSegment), listed.size()) << certify::format_report(r);
  EXPECT_EQ(total(r), listed.size()) << certify::format_report(r);
  for (const std::string& m : messages(r, Reason::ConstrainedEdgeNotOnSegment)) EXPECT_NE(m.find("out of range"), std::string::npos) << m;
}

// The triangle A B C with A = o, B = o + (len, 0), C = o + (len/2, len/2).
Pslg triangle_abc(Point o = {0, 0}, double len = 8) {
  Pslg p;
  p.vertices = {o, {o.x + len, o.y}, {o.x + len / 2, o.y + len / 2}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  return test::validated(p);
}

// Its mesh with P = o + (len/2, 0) on AB and Q = o + (len/4, y) beside it, A joined
// to both and Q to P; vertex ids A B C 0 1 2, then P Q (Q P with q_first).
// Q inside (y > 0): triangles (A,P,Q), (P,B,C), (P,C,Q), (Q,C,A). Q outside
// (y < 0): the sliver (A,Q,P) under the chord A-P, and (A,P,C), (P,B,C).
struct TwoCandidates {
  Mesh mesh;
  int P, Q;
};
TwoCandidates two_candidates(double y, bool q_first, Point o = {0, 0}, double len = 8) {
  TwoCandidates t;
  t.P = q_first ? 4 : 3;
  t.Q = q_first ? 3 : 4;
  const int P = t.P, Q = t.Q;
  Mesh& m = t.mesh;
  m.vertices = triangle_abc(o, len).vertices;
  m.vertices.resize(5);
  m.vertices[static_cast<std::size_t>(P)] = {o.x + len / 2, o.y};
  m.vertices[static_cast<std::size_t>(Q)] = {o.x + len / 4, o.y + y};
  m.input_vertices = 3;
  if (y > 0) m.triangles = {{0, P, Q}, {P, 1, 2}, {P, 2, Q}, {Q, 2, 0}};
  else m.triangles = {{0, Q, P}, {0, P, 2}, {P, 1, 2}};
  return t;
}

TEST(CertifyEdgeCases, ChainTakesTheListedNeighbourInTheTighterTier) {
  // Q 2^-47 off AB (4 ulp(8)), P on it, and both A-P and A-Q listed on segment 0:
  // the walk takes P, within 1 ulp, before the nearer Q, within 4, whatever the
  // numbering; Q's listed edge is then on no chain. (Before, the nearest listed
  // neighbour near the line was taken: at a small input angle that was another
  // segment's, ChainFollowsItsOwnListedEdgeBeforeANearerOneOfAnotherSegment.)
  const Pslg p = triangle_abc();
  for (bool q_first : {false, true}) {
    TwoCandidates t = two_candidates(std::ldexp(1.0, -47), q_first);
    t.mesh.constrained_edges = {{0, t.P, 0}, {0, t.Q, 0}, {t.P, 1, 0}, {1, 2, 1}, {2, 0, 2}};
    const auto r = run(p, t.mesh);
    EXPECT_FALSE(r.has(Reason::SteinerOffSegment)) << certify::format_report(r);
    const certify::Violation* v = first_of(r, Reason::ConstrainedEdgeNotOnSegment);
    ASSERT_NE(v, nullptr) << certify::format_report(r);
    EXPECT_EQ(v->vertices, (std::vector<int>{0, t.Q})) << v->message;
  }
}

TEST(CertifyEdgeCases, ChainTakesTheNearestOfTwoNeighboursWithinATolerance) {
  // A bare mesh (nothing listed), Q rounded 2^-51 outside the segment: P and Q are
  // both within 1 ulp(8) of AB. The chain is A Q P B, nearest first, so the sliver
  // (A,Q,P) lies inside it, in the domain; its only fault is its circumcircle, which
  // holds C. Had the walk taken P first, the sliver would be outside the domain.
  const Pslg p = triangle_abc();
  for (bool q_first : {false, true}) {
    const auto r = run(p, two_candidates(-std::ldexp(1.0, -51), q_first).mesh);
    EXPECT_EQ(r.count(Reason::NotLocallyDelaunay), 1u) << certify::format_report(r);
    EXPECT_EQ(total(r), 1u) << certify::format_report(r);
    EXPECT_EQ(r.stats.constrained_edges, 5u);  // A-Q, Q-P, P-B, B-C, C-A
  }
}

TEST(CertifyEdgeCases, AVertexWithinAnUlpOfASegmentIsReadAsOnItUnlessTheMeshListsItsEdges) {
  // Q 2^-51 inside the domain over AB (within 1 ulp(8) of it), a correct CDT whose
  // chain of AB is A P B. A mesh that lists nothing has its chain found by geometry
  // alone, and Q, indistinguishable from a Steiner point rounded onto AB, is taken
  // into it: the chain A Q P B leaves the sliver (A,P,Q) on its outer side, and the
  // mesh is rejected (a known limit, docs/CERTIFIER.md). Listing the constrained
  // edges, as Triangle's .poly output and lepp's do, settles it: certified.
  const Pslg p = triangle_abc();
  for (bool q_first : {false, true}) {
    TwoCandidates t = two_candidates(std::ldexp(1.0, -51), q_first);
    const auto bare = run(p, t.mesh);
    EXPECT_TRUE(bare.has(Reason::MeshOutsideDomain)) << certify::format_report(bare);
    EXPECT_TRUE(bare.has(Reason::BoundaryNotOnDomainBoundary)) << certify::format_report(bare);
    t.mesh.constrained_edges = {{0, t.P, 0}, {t.P, 1, 0}, {1, 2, 1}, {2, 0, 2}};
    const auto listed = run(p, t.mesh);
    EXPECT_TRUE(listed.certified()) << certify::format_report(listed);
  }
}

TEST(CertifyEdgeCases, AnInputVertexNearASegmentNeverStandsInForItsChain) {
  // D, an input vertex 2^-51 inside the triangle over AB (within 1 ulp(8) of AB, so
  // within any chain tolerance), is not on AB: validate() would have split AB at it.
  // The CDT keeps AB and the sliver (A,B,D). A mesh that drops the sliver and runs
  // the chain A D B is wrong, listed or not; the correct one certifies.
  Pslg p;
  p.vertices = {{0, 0}, {8, 0}, {4, 4}, {2, std::ldexp(1.0, -51)}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  p = test::validated(p);
  ASSERT_EQ(p.segments.size(), 3u);
  Mesh good;
  good.vertices = p.vertices;
  good.input_vertices = 4;
  good.triangles = {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  Mesh through_d = good;
  through_d.triangles = {{1, 2, 3}, {2, 0, 3}};
  for (bool listed : {false, true}) {
    if (listed) {
      good.constrained_edges = {{0, 1, 0}, {1, 2, 1}, {2, 0, 2}};
      through_d.constrained_edges = {{0, 3, 0}, {3, 1, 0}, {1, 2, 1}, {2, 0, 2}};
    }
    const auto g = run(p, good);
    EXPECT_TRUE(g.certified()) << "listed " << listed << "\n" << certify::format_report(g);
    const auto d = run(p, through_d);
    EXPECT_TRUE(d.has(Reason::SegmentMissing)) << "listed " << listed << "\n" << certify::format_report(d);
  }
}

TEST(CertifyEdgeCases, ListedEdgeWithinTheLoosestToleranceIsFollowed) {
  // A segment 2^-12 long at x = 2^20 (ulp 2^-32): Q, 2^-30 off it, is not within
  // 2^-20 |AB| = 2^-32 of the line, but within the loosest tolerance, (5 + 1) ulp
  // with five mesh vertices. The listed edge A-Q is followed, before P (on the line,
  // not listed from A) is, and Q is then held to the chain's own tolerance (k = 2:
  // 3 ulp) and found off the segment.
  const Point o{std::ldexp(1.0, 20), 0};
  const double len = std::ldexp(1.0, -12);
  const Pslg p = triangle_abc(o, len);
  TwoCandidates t = two_candidates(std::ldexp(1.0, -30), false, o, len);
  t.mesh.constrained_edges = {{0, t.Q, 0}, {t.P, 1, 0}, {1, 2, 1}, {2, 0, 2}};
  const auto r = run(p, t.mesh);
  const certify::Violation* v = first_of(r, Reason::SteinerOffSegment);
  ASSERT_NE(v, nullptr) << certify::format_report(r);
  EXPECT_EQ(v->vertices.front(), t.Q) << v->message;
}

TEST(CertifyEdgeCases, ChainFollowsItsOwnListedEdgeBeforeANearerOneOfAnotherSegment) {
  // Two segments from A = (0,0) at 2^-10 rad: AB on the x-axis and AD, D = (4, 2^-8).
  // Q = (2^-8, 2^-18), the chain vertex of AD next to A, is 2^-18 off AB: within
  // 2^-20 |AB| = 2^-17 of its line, and nearer ahead than P = (2, 0), AB's own
  // chain vertex. Both edges from A are listed (with or without segment ids). The
  // walk of AB must take P (on the line) and not Q, from which no edge continues
  // along AB (a fuzz_refine finding: a 2.3 degree input angle refined down to the
  // edge floor, docs/FUZZING.md). The mesh is a correct CDT of the input.
  Pslg p;
  p.vertices = {{0, 0}, {8, 0}, {0, 8}, {4, std::ldexp(1.0, -8)}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}, {0, 3, 0}};
  p = test::validated(p);
  Mesh m;
  m.vertices = p.vertices;
  m.vertices.push_back({2, 0});                                          // P = 4, on AB
  m.vertices.push_back({std::ldexp(1.0, -8), std::ldexp(1.0, -18)});   // Q = 5, on AD
  m.input_vertices = 4;
  m.triangles = {{0, 4, 5}, {5, 4, 3}, {4, 1, 3}, {1, 2, 3}, {2, 0, 5}, {2, 5, 3}};
  for (bool ids : {true, false}) {
    m.constrained_edges = {{0, 4, 0}, {4, 1, 0}, {1, 2, 1}, {2, 0, 2}, {0, 5, 3}, {5, 3, 3}};
    if (!ids)
      for (ConstrainedEdge& e : m.constrained_edges) e.segment = -1;
    const auto r = run(p, m);
    EXPECT_EQ(total(r), 0u) << "ids " << ids << "\n" << certify::format_report(r);
    EXPECT_EQ(r.stats.constrained_edges, 6u);
  }
  // Not loosened: with P moved 2^-18 off AB (as far as Q) the mesh is rejected.
  m.vertices[4].y = std::ldexp(1.0, -18);
  EXPECT_GT(total(run(p, m)), 0u);
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

// (a, b) near (cos theta, sin theta) with lo <= sin^2 < hi for the angle at the
// origin between (1, 0) and (a, b): within one ulp of theta, not certified either
// way. Searched among the ulp-neighbours of the rounded point, decided exactly.
std::optional<Point> corner_in_bracket(double theta) {
  const Sin2Bracket bracket = sin2_bracket(theta);
  const double rad = theta * M_PI / 180;
  for (int ka = -60; ka <= 60; ++ka)
    for (int kb = -60; kb <= 60; ++kb) {
      double a = std::cos(rad), b = std::sin(rad);
      for (int k = 0; k < std::abs(ka); ++k) a = std::nextafter(a, ka > 0 ? 2.0 : 0.0);
      for (int k = 0; k < std::abs(kb); ++k) b = std::nextafter(b, kb > 0 ? 2.0 : 0.0);
      const CGAL::Gmpq A(a), B(b), s2 = B * B / (A * A + B * B);
      if (CGAL::Gmpq(bracket.lo) <= s2 && s2 < CGAL::Gmpq(bracket.hi)) return Point{a, b};
    }
  return std::nullopt;
}

TEST(CertifyEdgeCases, AngleCertainlyBelowThetaWinsOverOneWithinTheBracket) {
  // O = (0,0), P = (1/8, 0), Q near (cos 20, sin 20): the angle at O is within one ulp
  // of 20 degrees (the scale of OP cancels exactly), the angle at Q about 2.4 degrees,
  // certainly below. The triangle is below theta, not "not certified", whichever
  // corner comes first.
  const double theta = 20;
  const auto q = corner_in_bracket(theta);
  ASSERT_TRUE(q.has_value()) << "no corner inside the sin^2 bracket among the nudges";
  Pslg p;
  p.vertices = {{0, 0}, {0.125, 0}, *q};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  p = test::validated(p);
  for (const Tri& t : {Tri{0, 1, 2}, Tri{2, 0, 1}}) {  // the uncertain corner first, then last
    Mesh m;
    m.vertices = p.vertices;
    m.input_vertices = 3;
    m.triangles = {t};
    const auto r = run(p, m, theta);
    EXPECT_EQ(r.count(Reason::AngleBelowTheta), 1u) << certify::format_report(r);
    EXPECT_FALSE(r.has(Reason::AngleNotCertified)) << certify::format_report(r);
  }
}

TEST(CertifyEdgeCases, CrossingPointMatchedToAnUnusedVertexIsMissing) {
  // corpus/triangle-formats/crossing.poly with --split-crossings: a crossing point
  // another mesher rounded otherwise is matched to the nearest mesh vertex within
  // 2^-40. Here the triangles' vertex is two ulps away and an unused vertex one ulp
  // away: the match is the unused one, so the crossing point is in no triangle.
  std::vector<std::string> warnings;
  DomainOptions split;
  split.split_crossings = true;
  const Pslg p = validate(read_poly(LEPP_SOURCE_DIR "/corpus/triangle-formats/crossing.poly"), split, warnings);
  ASSERT_GT(p.crossing_vertices, 0u);
  Mesh m = test::cgal_cdt(p);
  m.input_vertices = 0;  // as read from files: vertices found by their coordinates
  const std::size_t x = p.vertices.size() - 1;  // a crossing point
  Point near = m.vertices[x];
  near.x = std::nextafter(near.x, HUGE_VAL);
  m.vertices[x].x = std::nextafter(near.x, HUGE_VAL);
  m.vertices.push_back(near);
  EXPECT_TRUE(run(p, test::cgal_cdt(p)).certified());
  const auto r = run(p, m);
  ASSERT_EQ(r.count(Reason::InputVertexMissing), 1u) << certify::format_report(r);
  const auto v = std::find_if(r.violations.begin(), r.violations.end(),
                              [](const certify::Violation& y) { return y.reason == Reason::InputVertexMissing; });
  EXPECT_EQ(v->vertices.front(), static_cast<int>(x));
}

TEST(CertifyEdgeCases, TheoremTwoCheckSwitchedOff) {
  // Two flat triangles on the common edge (-1,0)-(1,0), apexes at (0, +-0.25): a
  // terminal pair at about 152 degrees (and not Delaunay). Options::theorem2 = false
  // (lepp certify --no-theorem2) skips the Theorem 2 check, nothing else.
  Pslg p;
  p.vertices = {{-1, 0}, {1, 0}, {0, 0.25}, {0, -0.25}};
  p.segments = {{0, 3, 0}, {3, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  p = test::validated(p);
  Mesh m;
  m.vertices = p.vertices;
  m.input_vertices = 4;
  m.triangles = {{0, 1, 2}, {1, 0, 3}};
  certify::Options options;
  const auto with = certify::certify(p, m, options);
  EXPECT_EQ(with.count(Reason::TerminalAngleOver120), 2u) << certify::format_report(with);
  EXPECT_EQ(with.stats.terminal_pairs_checked, 1u);
  options.theorem2 = false;
  const auto without = certify::certify(p, m, options);
  EXPECT_FALSE(without.has(Reason::TerminalAngleOver120)) << certify::format_report(without);
  EXPECT_EQ(without.stats.terminal_pairs_checked, 0u);
  EXPECT_EQ(without.count(Reason::NotLocallyDelaunay), with.count(Reason::NotLocallyDelaunay));
  EXPECT_EQ(total(without), total(with) - 2);
}

TEST(CertifyEdgeCases, SteinerPointExactlyAtTheToleranceBound) {
  // Segment (0,0)-(8,8) with one interior chain vertex P = (4 + off, 4): the bound is
  // |cross| <= tol (|dx| + |dy|), tol = 2 ulp(8) = 2^-48, i.e. off <= 2 tol. At the
  // bound (equality, decided as an exact zero) P is on the segment; one ulp further not.
  const Point a{0, 0}, b{8, 8};
  const double tol = certify::segment_tolerance(a, b, 1);
  Pslg p;
  p.vertices = {a, b, {8, 0}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  p = test::validated(p);
  const double at = 4 + 2 * tol;
  for (double x : {at, std::nextafter(at, 5.0)}) {
    Mesh m;
    m.vertices = {a, b, {8, 0}, {x, 4}};
    m.input_vertices = 3;
    m.triangles = {{0, 2, 3}, {3, 2, 1}};
    m.constrained_edges = {{0, 3, 0}, {3, 1, 0}, {1, 2, 1}, {2, 0, 2}};
    const auto r = run(p, m);
    EXPECT_EQ(r.has(Reason::SteinerOffSegment), x != at) << certify::format_report(r);
  }
}

TEST(CertifyEdgeCases, ListedNeighbourExactlyAtTheNearLineBound) {
  // Q = (2, y) listed from A on segment (0,0)-(8,0): near the line iff
  // |cross| <= 2^-20 |AB|^2, i.e. y <= 2^-17. At the bound Q is followed (and found
  // off the segment); one ulp further it is not, and its listed edge is on no chain.
  const Pslg p = triangle_abc();
  const double at = std::ldexp(1.0, -17);
  for (double y : {at, std::nextafter(at, 1.0)}) {
    TwoCandidates t = two_candidates(y, false);
    t.mesh.constrained_edges = {{0, t.Q, 0}, {t.P, 1, 0}, {1, 2, 1}, {2, 0, 2}};
    const auto r = run(p, t.mesh);
    const certify::Violation* off = first_of(r, Reason::SteinerOffSegment);
    if (y == at) {
      ASSERT_NE(off, nullptr) << certify::format_report(r);
      EXPECT_EQ(off->vertices.front(), t.Q);
    } else {
      EXPECT_EQ(off, nullptr) << certify::format_report(r);
      EXPECT_TRUE(r.has(Reason::ConstrainedEdgeNotOnSegment)) << certify::format_report(r);
    }
  }
}

// A wedge of `deg` degrees at V = (0,0) between U = (1,0) and W = (cos, sin), closed by U-W.
Pslg wedge(double deg) {
  const double rad = deg * M_PI / 180;
  Pslg p;
  p.vertices = {{0, 0}, {1, 0}, {std::cos(rad), std::sin(rad)}};
  p.segments = {{0, 1, 0}, {0, 2, 0}, {1, 2, 0}};
  return test::validated(p);
}

TEST(CertifyEdgeCases, UnimprovableRuleNeedsTheApexInTheMesh) {
  // The 10-degree wedge listed unimprovable at theta = 20 (accepted, RuleCheckedNotTrusted),
  // but the apex a hair away in a mesh that does not promise ids: the two segments
  // meet at an input vertex the mesh does not have, and the rule does not hold.
  const Pslg p = wedge(10);
  Mesh m;
  m.vertices = p.vertices;
  m.triangles = {{0, 1, 2}};
  certify::Options options;
  options.min_angle_deg = 20;
  options.unimprovable = {{{0, 1, 2}, 0, 0, 1, 10}};
  ASSERT_TRUE(certify::certify(p, m, options).certified()) << certify::format_report(certify::certify(p, m, options));
  m.vertices[0] = {std::ldexp(1.0, -60), std::ldexp(1.0, -64)};  // still inside the wedge
  const auto r = certify::certify(p, m, options);
  EXPECT_EQ(r.count(Reason::UnimprovableRuleFails), 1u) << certify::format_report(r);
  EXPECT_TRUE(r.unimprovable_accepted.empty());
  EXPECT_EQ(r.count(Reason::InputVertexMissing), 1u) << certify::format_report(r);
}

TEST(CertifyEdgeCases, UnimprovableRuleNeedsTheInputAngleBelowTheta) {
  // A 30-degree wedge with Steiner points P1 = (1/2, 0) and Q1 = W/2 on its arms:
  // triangle (P1, U, Q1) has an angle of about 23.8 degrees at U and its shortest
  // edge P1-Q1 joins the two segments, but they meet at 30 degrees, not below
  // theta = 25: listed unimprovable, it is rejected.
  const Pslg p = wedge(30);
  const Point& w = p.vertices[2];
  Mesh m;
  m.vertices = p.vertices;
  m.vertices.push_back({0.5, 0});             // P1 = 3
  m.vertices.push_back({w.x / 2, w.y / 2});   // Q1 = 4
  m.input_vertices = 3;
  m.triangles = {{0, 3, 4}, {3, 1, 4}, {4, 1, 2}};
  certify::Options options;
  options.min_angle_deg = 25;
  const auto plain = certify::certify(p, m, options);
  ASSERT_EQ(plain.count(Reason::AngleBelowTheta), 1u) << certify::format_report(plain);
  options.unimprovable = {{{3, 1, 4}, 0, 0, 1, 30}};
  const auto r = certify::certify(p, m, options);
  EXPECT_EQ(r.count(Reason::UnimprovableRuleFails), 1u) << certify::format_report(r);
  EXPECT_TRUE(r.unimprovable_accepted.empty());
}

// Two cracks from V = (0,0) (vertex 4) inside the square [-10,10]^2: V-U, U = (4,0)
// (vertex 5), and V-W, W = 4 (cos 20, sin 20) (vertex 6): a 20-degree input angle.
Pslg cracks_at_twenty_degrees() {
  const double rad = 20 * M_PI / 180;
  Pslg p;
  p.vertices = {{-10, -10}, {10, -10}, {10, 10}, {-10, 10}, {0, 0}, {4, 0}, {4 * std::cos(rad), 4 * std::sin(rad)}};
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}, {4, 5, 0}, {4, 6, 0}};
  return test::validated(p);
}

// The cracks' vertices and R (vertex 7), meshed by `triangles` alone.
Mesh cracks_meshed(const Pslg& cracks, Point r, std::vector<Tri> triangles) {
  Mesh m;
  m.vertices = cracks.vertices;
  m.vertices.push_back(r);
  m.input_vertices = cracks.vertices.size();
  m.triangles = std::move(triangles);
  return m;
}

// Both triangles listed unimprovable: the rule fails for the first (triangle 0)
// alone, and the second, the wedge's own (V,U,W), is accepted.
void expect_rule_fails_for_the_first_only(const certify::Report& r) {
  EXPECT_EQ(r.count(Reason::UnimprovableRuleFails), 1u) << certify::format_report(r);
  const certify::Violation* v = first_of(r, Reason::UnimprovableRuleFails);
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->triangles, std::vector<int>{0});
  ASSERT_EQ(r.unimprovable_accepted.size(), 1u);
  EXPECT_EQ(r.unimprovable_accepted[0].triangle, (Tri{4, 5, 6}));
}

TEST(CertifyEdgeCases, UnimprovableRuleNeedsTheTriangleInsideTheWedge) {
  // Two cracks from V = (0,0) inside the square [-10,10]^2: V-U, U = (4,0), and V-W,
  // W = 4 (cos 20, sin 20): a 20-degree input angle. Triangle (V,U,W) lies in the
  // wedge, is skinny at V and unimprovable. Triangle (W,U,R), R = (5,-1.5), is skinny
  // (about 13 and 11 degrees) and its shortest edge W-U joins the two segments, but R
  // lies beyond the arm V-U (its edge W-R passes beyond U, the arm's end): outside
  // the wedge, the rule does not hold. Only the two listed triangles matter here;
  // the rest of the square is not meshed.
  const Pslg p = cracks_at_twenty_degrees();
  const Mesh m = cracks_meshed(p, {5, -1.5}, {{6, 5, 7}, {4, 5, 6}});
  certify::Options options;
  options.min_angle_deg = 25;
  options.unimprovable = {{{6, 5, 7}, 4, 4, 5, 20}, {{4, 5, 6}, 4, 4, 5, 20}};
  expect_rule_fails_for_the_first_only(certify::certify(p, m, options));
}

TEST(CertifyEdgeCases, UnimprovableRuleNeedsTheTriangleInsideTheWedgeOnTheSecondSideToo) {
  // The same cracks, the other side: triangle (U,R,W), R = (6.5, 3.2), is skinny at R
  // (about 18 degrees) and its shortest edge U-W joins the two segments, but R lies
  // ccw beyond the arm V-W (at 26 degrees from V, the arm at 20): inside the first
  // side of the wedge, outside the second, and the rule does not hold.
  const Pslg p = cracks_at_twenty_degrees();
  const Mesh m = cracks_meshed(p, {6.5, 3.2}, {{5, 7, 6}, {4, 5, 6}});
  certify::Options options;
  options.min_angle_deg = 25;
  const auto plain = certify::certify(p, m, options);
  ASSERT_EQ(plain.count(Reason::AngleBelowTheta), 2u) << certify::format_report(plain);
  options.unimprovable = {{{5, 7, 6}, 4, 4, 5, 20}, {{4, 5, 6}, 4, 4, 5, 20}};
  expect_rule_fails_for_the_first_only(certify::certify(p, m, options));
}

TEST(CertifyEdgeCases, InputAngleAtTheDoubleNearestSixtyDegreesIsDecidedExactly) {
  // W = (1/2, the double nearest sqrt(3)/2): the angle at V between U = (1,0) and W
  // is within an ulp of 60 degrees, where the interval filter cannot decide; the
  // exact answer (4 cross^2 < 3 |u|^2 |w|^2 in rationals) decides whether it is small.
  Pslg p;
  p.vertices = {{0, 0}, {1, 0}, {0.5, std::sqrt(3.0) / 2}};
  p.segments = {{0, 1, 0}, {0, 2, 0}, {1, 2, 0}};
  p = test::validated(p);
  const CGAL::Gmpq x(p.vertices[2].x), y(p.vertices[2].y);
  const bool below = 4 * y * y < 3 * (x * x + y * y);  // u = (1, 0): cross = y
  const auto angles = certify::small_input_angles(p);
  const bool found = std::any_of(angles.begin(), angles.end(), [](const certify::SmallInputAngle& a) { return a.apex == 0; });
  EXPECT_EQ(found, below);
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

namespace lepp {
namespace {

// Two isosceles triangles on edge 0-1, each with a second edge exactly as long (integer
// coordinates: 3-4-5): the tie goes to the edge with the smaller ids (ALGORITHM.md
// section 3), 0-1 in both, so they are a terminal pair. Kills a longest-edge pass that
// kept the first of two equal edges (0-3 in the second triangle, and no pair).
TEST(CertifyEdgeCases, LongestEdgeTieGoesToTheSmallerIdsMakingATerminalPair) {
  Pslg p;
  p.vertices = {{0, 0}, {5, 0}, {4, 3}, {4, -3}};
  p.segments = {{0, 3}, {3, 1}, {1, 2}, {2, 0}};
  Mesh m;
  m.vertices = p.vertices;
  m.input_vertices = 4;
  m.triangles = {{0, 1, 2}, {0, 3, 1}};  // in the second, half-edge 0->3 comes before 1->0
  certify::Options o;
  o.min_angle_deg = 0;
  const certify::Report r = certify::certify(test::validated(p), m, o);
  EXPECT_TRUE(r.certified()) << certify::format_report(r);
  EXPECT_EQ(r.stats.terminal_pairs_checked, 1u) << certify::format_report(r);
}

}  // namespace
}  // namespace lepp
