// SPDX-License-Identifier: GPL-3.0-or-later
// Every check of the certifier must be able to fail: a correct mesh is broken in
// one way and the certifier must reject it for that reason (and accept the
// unbroken mesh, so the rejection is the mutation's doing).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <CGAL/Gmpq.h>

#include "certify_test_support.h"
#include "cgal_mesh.h"
#include "lepp/angle.h"
#include "lepp/certify.h"
#include "lepp/io.h"
#include "lepp/validate.h"
#include "test_pslgs.h"

namespace lepp {
namespace {

using certify::Reason;

using test::expect_certified;
using test::expect_rejected_for;
using test::expect_rejected_only_for;
using test::expect_rejected_times;
using test::run;

// The input segment id of edge a-b of an unsplit segment, or -1.
int segment_id(const Pslg& p, int a, int b) {
  for (std::size_t s = 0; s < p.segments.size(); ++s)
    if ((p.segments[s].a == a && p.segments[s].b == b) || (p.segments[s].a == b && p.segments[s].b == a)) return static_cast<int>(s);
  return -1;
}

// Triangles (a,b,c) and (b,a,d) sharing edge ab; the flip makes (a,d,c), (d,b,c).
struct Pair {
  std::size_t t1, t2;
  int a, b, c, d;
};

std::optional<Pair> find_pair(const Mesh& m, int a, int b) {
  std::optional<std::size_t> t1, t2;
  int c = -1, d = -1;
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const Tri& x = m.triangles[t];
      if (x[static_cast<std::size_t>(i)] == a && x[static_cast<std::size_t>((i + 1) % 3)] == b) t1 = t, c = x[static_cast<std::size_t>((i + 2) % 3)];
      if (x[static_cast<std::size_t>(i)] == b && x[static_cast<std::size_t>((i + 1) % 3)] == a) t2 = t, d = x[static_cast<std::size_t>((i + 2) % 3)];
    }
  if (!t1 || !t2) return std::nullopt;
  return Pair{*t1, *t2, a, b, c, d};
}

double orient(const Point& a, const Point& b, const Point& c) { return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x); }

bool flippable(const Mesh& m, const Pair& p) {
  const auto& V = m.vertices;
  auto P = [&](int i) { return V[static_cast<std::size_t>(i)]; };
  // Integer coordinates in these tests: the double orientation is exact.
  return orient(P(p.a), P(p.d), P(p.c)) > 0 && orient(P(p.d), P(p.b), P(p.c)) > 0;
}

void flip(Mesh& m, const Pair& p) {
  m.triangles[p.t1] = {p.a, p.d, p.c};
  m.triangles[p.t2] = {p.d, p.b, p.c};
}

bool is_constrained(const Mesh& m, int a, int b) {
  for (const ConstrainedEdge& e : m.constrained_edges)
    if ((e.a == a && e.b == b) || (e.a == b && e.b == a)) return true;
  return false;
}

TEST(CertifyAccepts, CgalCdtOfTestInputs) {
  for (const Pslg& p : {test::square_with_crack(), test::square_with_hole()}) expect_certified(run(p, test::cgal_cdt(p)));
}

TEST(CertifyAccepts, InputVertexInsideAHoleMayBeUnused) {
  Pslg p = test::square_with_hole();
  p.vertices.push_back({5.5, 4.5});  // inside the hole [4,6]^2, on no segment
  p = test::validated(p);
  const Mesh m = test::cgal_cdt(p);
  const auto r = run(p, m);
  expect_certified(r);
  // Our engines keep it in the vertex list, unused: still fine.
  EXPECT_EQ(m.vertices.size(), p.vertices.size());
}

TEST(CertifyAccepts, HolePointInATriangleOrOnAnEdgeRemovesItsRegion) {
  // (5, 5) lies on the diagonal the CDT draws across the square hole [4,6]^2 (an
  // unconstrained edge); (4.5, 5.25) inside one of its two triangles.
  for (const Point& h : {Point{5, 5}, Point{4.5, 5.25}}) {
    Pslg p = test::square_with_hole();
    p.holes = {h};
    Pslg no_hole = p;
    no_hole.holes.clear();
    expect_certified(run(p, test::cgal_cdt(p)));
    expect_rejected_for(run(p, test::cgal_cdt(no_hole)), Reason::MeshOutsideDomain);
  }
}

TEST(CertifyAccepts, HolePointsThatRemoveNothing) {
  // Validation keeps them, with a warning: on an input vertex, on a segment, outside
  // the outer boundary, in a hole already removed. The domain stays the one the
  // single hole point (5, 5) makes.
  Pslg p = test::square_with_hole();
  const Mesh m = test::cgal_cdt(p);
  p.holes.push_back({4, 4});      // an input vertex (a corner of the hole)
  p.holes.push_back({0, 0});      // an input vertex on the outer boundary
  p.holes.push_back({3, 10});     // on the top side
  p.holes.push_back({5, 4});      // on the hole's bottom side
  p.holes.push_back({20, 5});     // outside the outer square
  p.holes.push_back({5.5, 4.5});  // a second point in the same hole
  p = test::validated(p);
  ASSERT_EQ(p.holes.size(), 7u);
  expect_certified(run(p, m));
}

TEST(CertifyAccepts, CgalRefinedMeshesAtTwentyDegrees) {
  for (const Pslg& p : {test::square_with_crack(), test::square_with_hole()}) expect_certified(run(p, test::cgal_refined(p), 20));
}

TEST(CertifyRejects, FlippedNonDelaunayDiagonal) {
  const Pslg p = test::square_with_crack();
  const Mesh good = test::cgal_cdt(p);
  expect_certified(run(p, good));
  bool done = false;
  for (const Tri& t : good.triangles) {
    for (int i = 0; i < 3 && !done; ++i) {
      const int a = t[static_cast<std::size_t>(i)], b = t[static_cast<std::size_t>((i + 1) % 3)];
      auto pair = find_pair(good, a, b);
      if (!pair || is_constrained(good, a, b) || !flippable(good, *pair)) continue;
      Mesh bad = good;
      flip(bad, *pair);
      const auto r = run(p, bad);
      if (r.stats.cocircular_edges > 0 && !r.has(Reason::NotLocallyDelaunay)) continue;  // a cocircular quad: both diagonals Delaunay
      expect_rejected_times(r, Reason::NotLocallyDelaunay, 1u);
      done = true;
    }
    if (done) break;
  }
  EXPECT_TRUE(done) << "no flippable unconstrained edge found";
}

TEST(CertifyRejects, FlippedConstrainedEdge) {
  const Pslg p = test::square_with_crack();
  Mesh bad = test::cgal_cdt(p);
  const Segment crack = p.segments.back();  // the interior segment
  auto pair = find_pair(bad, crack.a, crack.b);
  if (!pair) pair = find_pair(bad, crack.b, crack.a);
  ASSERT_TRUE(pair);
  ASSERT_TRUE(flippable(bad, *pair));
  flip(bad, *pair);
  // The mesh still lists the crack as constrained: the certifier must see it is gone.
  expect_rejected_for(run(p, bad), Reason::SegmentMissing);
  // Also when the mesh lists no constrained edges (found by geometry alone).
  bad.constrained_edges.clear();
  expect_rejected_for(run(p, bad), Reason::SegmentMissing);
}

TEST(CertifyRejects, ClockwiseTriangle) {
  const Pslg p = test::square_with_crack();
  Mesh bad = test::cgal_cdt(p);
  std::swap(bad.triangles[3][1], bad.triangles[3][2]);
  expect_rejected_for(run(p, bad), Reason::NotCounterClockwise);
}

TEST(CertifyRejects, ZeroAreaTriangle) {
  // A square with a Steiner point on its bottom side, plus a flat triangle along
  // that side: its three corners are collinear, so it is not strictly counter-clockwise.
  Pslg p;
  p.vertices = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}};
  Mesh m;
  m.vertices = p.vertices;
  m.vertices.push_back({1, 0});
  m.input_vertices = 4;
  m.triangles = {{0, 4, 3}, {4, 2, 3}, {4, 1, 2}};
  m.constrained_edges = {{0, 4, 0}, {4, 1, 0}, {1, 2, 1}, {2, 3, 2}, {3, 0, 3}};
  expect_certified(run(p, m));
  m.triangles.push_back({0, 4, 1});
  const auto r = run(p, m);
  expect_rejected_times(r, Reason::NotCounterClockwise, 1u);
}

TEST(CertifyRejects, MissingTriangle) {
  const Pslg p = test::square_with_crack();
  Mesh bad = test::cgal_cdt(p);
  // An interior triangle (no edge on the boundary square) leaves a gap.
  auto on_boundary = [&](const Tri& t) {
    for (int v : t) {
      const Point& q = bad.vertices[static_cast<std::size_t>(v)];
      if (q.x == 0 || q.x == 10 || q.y == 0 || q.y == 10) return true;
    }
    return false;
  };
  auto it = std::find_if(bad.triangles.begin(), bad.triangles.end(), [&](const Tri& t) { return !on_boundary(t); });
  ASSERT_NE(it, bad.triangles.end());
  bad.triangles.erase(it);
  const auto r = run(p, bad);
  expect_rejected_for(r, Reason::BoundaryNotOnDomainBoundary);
  EXPECT_TRUE(r.has(Reason::EulerCharacteristic));
}

TEST(CertifyRejects, MissingTriangleAlongSegment) {
  const Pslg p = test::square_with_crack();
  Mesh bad = test::cgal_cdt(p);
  const Segment crack = p.segments.back();
  auto pair = find_pair(bad, crack.a, crack.b);
  ASSERT_TRUE(pair);
  bad.triangles.erase(bad.triangles.begin() + static_cast<long>(pair->t1));
  expect_rejected_for(run(p, bad), Reason::DomainBoundaryUncovered);
}

TEST(CertifyRejects, OverlappingTriangle) {
  const Pslg p = test::square_with_crack();
  const Mesh good = test::cgal_cdt(p);
  {  // the same triangle twice
    Mesh bad = good;
    bad.triangles.push_back(bad.triangles[2]);
    expect_rejected_for(run(p, bad), Reason::EdgeSameDirection);
  }
  {  // a triangle over two adjacent ones: their outer quad's diagonal the other way
    Mesh bad = good;
    bool added = false;
    for (const Tri& t : good.triangles) {
      for (int i = 0; i < 3 && !added; ++i) {
        auto pair = find_pair(good, t[static_cast<std::size_t>(i)], t[static_cast<std::size_t>((i + 1) % 3)]);
        if (!pair || !flippable(good, *pair)) continue;
        bad.triangles.push_back({pair->a, pair->d, pair->c});
        added = true;
      }
      if (added) break;
    }
    ASSERT_TRUE(added);
    const auto r = run(p, bad);
    EXPECT_FALSE(r.certified());
    EXPECT_TRUE(r.has(Reason::EdgeSameDirection) || r.has(Reason::EdgeOverused)) << certify::format_report(r);
  }
}

// The notch family (gen::ulpNotch, corpus/regressions/precision/notch-*): at X = 2^52
// (ulp 1) segments A -> B and w -> A leave A nearly parallel. The fast engine of
// 2026-12-01 split A -> B at its midpoint rounded half an ulp outside, across w -> A
// (the sliver clause ignored the domain's own boundary, docs/ALGORITHM.md section 8b):
// its mesh at 25 degrees overlaps itself, and before chain-edges-meet every other
// check passed it. The mesh is stored, not remade: the engine no longer makes it.
Pslg notch(const std::string& name) {
  std::vector<std::string> warnings;
  return validate(read_poly(LEPP_SOURCE_DIR "/corpus/regressions/precision/" + name + ".poly"), warnings);
}

TEST(CertifyRejects, NotchMeshWhoseChainsCross) {
  const Pslg p = notch("notch-overlap");
  const Mesh m = read_mesh(LEPP_SOURCE_DIR "/corpus/regressions/precision/notch-overlap-fast-25/out");
  certify::Options o;
  o.min_angle_deg = 25;
  const certify::Report r = certify::certify(p, m, o);
  expect_rejected_only_for(r, Reason::ChainEdgesMeet);
  const certify::Violation* v = test::first_of(r, Reason::ChainEdgesMeet);
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->edges.size(), 2u);  // A -> B's chain edge through (X + 26, X) and the edge A - w it crosses
  EXPECT_EQ(v->segment, 0);
}

// The reference's mesh of another notch at 30 degrees (stored): the chain of A -> B
// leaves A by an edge farther off its line than w -> A's first one, which the greedy
// walk took and then ran past B (a false segment-missing); depth first it certifies.
TEST(CertifyAccepts, NotchChainIsFoundDepthFirst) {
  const Pslg p = notch("notch-chain-walk");
  const Mesh m = read_mesh(LEPP_SOURCE_DIR "/corpus/regressions/precision/notch-chain-walk-reference-30/out");
  certify::Options o;
  o.min_angle_deg = 30;
  expect_certified(certify::certify(p, m, o));
}

// The fast engine's mesh at 22.1 degrees (stored) of two segments leaving A = (0.01,
// 0.01) at 3.18 degrees, refined down to ulps of A (a vertex 3 ulps from A). The first
// vertex of A -> (0.006, 0.008)'s chain, 9 and 5 ulps from A, is 0.09 ulp off the line
// of A -> (0.003, 0.006) and a straighter step along it than that segment's own first
// vertex: the walk followed the other chain until it left the line by 2^-20 |AB|, then
// crossed by an unlisted edge (197 false violations). The listed path from A that ends
// at B is taken first, and it certifies (docs/CERTIFIER.md section 3).
TEST(CertifyAccepts, ApexChainIsTheListedPathThatEndsAtB) {
  const Pslg p = notch("apex-ulps-chain-walk");
  const std::string prefix = LEPP_SOURCE_DIR "/corpus/regressions/precision/apex-ulps-chain-walk-fast-22.1/out";
  const Mesh m = read_mesh(prefix);
  certify::Options o;
  o.min_angle_deg = 22.1;
  o.unimprovable = read_unimprovable(prefix);
  ASSERT_FALSE(o.unimprovable.empty());
  expect_certified(certify::certify(p, m, o));

  // The listed path is held to the tolerance as any chain: a vertex of it moved
  // 1e-15 off the line (within 2^-20 |AB| of it, about 600 ulps) is rejected.
  Mesh moved = m;
  std::size_t v = 0;
  while (v < moved.vertices.size() && !(moved.vertices[v].x == 0.009999786376953125 && moved.vertices[v].y == 0.009999877929687501)) ++v;
  ASSERT_LT(v, moved.vertices.size());
  moved.vertices[v].y += 1e-15;
  expect_rejected_for(certify::certify(p, moved, o), Reason::SteinerOffSegment);

  // The limit of geometry alone: without the listed edges the other segment's first
  // vertex is within the tolerance of this line and the walk takes it.
  Mesh bare = m;
  bare.constrained_edges.clear();
  EXPECT_FALSE(certify::certify(p, bare, o).certified());
}

TEST(CertifyRejects, MovedInputVertex) {
  const Pslg p = test::square_with_crack();
  Mesh bad = test::cgal_cdt(p);
  ASSERT_EQ(bad.input_vertices, p.vertices.size());
  const std::size_t interior = p.vertices.size() - 1;  // an interior input vertex
  bad.vertices[interior].x = std::nextafter(bad.vertices[interior].x, 100.0);
  expect_rejected_for(run(p, bad), Reason::InputVertexMoved);
  // Without the promise that ids match, the moved vertex is a missing one.
  bad.input_vertices = 0;
  expect_rejected_for(run(p, bad), Reason::InputVertexMissing);
}

TEST(CertifyRejects, MissingInputVertex) {
  const Pslg p = test::square_with_crack();
  Pslg without = p;
  without.vertices.pop_back();  // an interior vertex on no segment
  Mesh bad = test::cgal_cdt(without);
  bad.input_vertices = 0;
  expect_certified(run(without, bad));
  expect_rejected_for(run(p, bad), Reason::InputVertexMissing);
}

TEST(CertifyRejects, SteinerPointOffItsSegment) {
  const Pslg p = test::square_with_crack();
  const Mesh good = test::cgal_refined(p);
  expect_certified(run(p, good, 20));
  // A Steiner point on the bottom side y = 0, moved inside by 1e-9.
  Mesh bad = good;
  auto it = std::find_if(bad.vertices.begin() + static_cast<long>(bad.input_vertices), bad.vertices.end(),
                         [](const Point& q) { return q.y == 0 && q.x > 0 && q.x < 10; });
  ASSERT_NE(it, bad.vertices.end()) << "CGAL put no Steiner point on the bottom side";
  it->y = 1e-9;
  expect_rejected_for(run(p, bad, 20), Reason::SteinerOffSegment);
}

TEST(CertifyRejects, SteinerToleranceIsTight) {
  // The tolerance is (k+1) ulp(M) per coordinate: a point just beyond it is off.
  const Point a{0, 0}, b{8, 8};
  const double tol = certify::segment_tolerance(a, b, 1);
  EXPECT_EQ(tol, std::ldexp(1.0, -48));  // M = 8: ulp(8) = 2^-49, times k + 1 = 2
  Pslg p;
  p.vertices = {a, b, {8, 0}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  for (double off : {tol, 3 * tol}) {
    Mesh m;
    m.vertices = {a, b, {8, 0}, {4 + off, 4}};
    m.input_vertices = 3;
    m.triangles = {{0, 2, 3}, {3, 2, 1}};
    m.constrained_edges = {{0, 3, 0}, {3, 1, 0}, {1, 2, 1}, {2, 0, 2}};
    const auto r = run(p, m);
    EXPECT_EQ(r.has(Reason::SteinerOffSegment), off > tol) << certify::format_report(r);
  }
}

TEST(CertifyAccepts, ChainIgnoresAVertexNearTheSegmentButOffIt) {
  // Segment AB with its midpoint P and a vertex Q beside it, 2^-47 off the line:
  // within the loosest tolerance (6 ulp(8) = 3 * 2^-48, six mesh vertices) and
  // nearer A than P, but not on the segment. The chain is A P B (listed, and
  // nearest the line when nothing is listed), not A Q: far from the origin
  // (corpus/hostile/far-from-origin.poly at 33 degrees) the loosest tolerance
  // reaches interior vertices and the walk took them.
  Pslg p;
  p.vertices = {{0, 0}, {8, 0}, {4, 4}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  Mesh m;
  m.vertices = {{0, 0}, {8, 0}, {4, 4}, {4, 0}, {2, std::ldexp(1.0, -47)}};
  m.input_vertices = 3;
  m.triangles = {{0, 3, 4}, {3, 1, 2}, {3, 2, 4}, {4, 2, 0}};
  m.constrained_edges = {{0, 3, 0}, {3, 1, 0}, {1, 2, 1}, {2, 0, 2}};
  expect_certified(run(p, m));
  m.constrained_edges.clear();  // a bare mesh: found by geometry alone
  expect_certified(run(p, m));
  // Q on the chain instead (the edge A-P replaced by A-Q-P): now it is off the segment.
  m.vertices[4].y = -std::ldexp(1.0, -47);  // below AB: on the chain, a sliver outside the domain
  m.triangles = {{0, 4, 3}, {0, 3, 2}, {3, 1, 2}};
  m.constrained_edges = {{0, 4, 0}, {4, 3, 0}, {3, 1, 0}, {1, 2, 1}, {2, 0, 2}};
  expect_rejected_for(run(p, m), Reason::SteinerOffSegment);
}

// The triangle (0,0), (1,0), c alone, its sides the input's segments.
test::MeshedPslg lone_triangle(Point c) {
  test::MeshedPslg t;
  t.pslg.vertices = {{0, 0}, {1, 0}, c};
  t.pslg.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  t.mesh.vertices = t.pslg.vertices;
  t.mesh.input_vertices = 3;
  t.mesh.triangles = {{0, 1, 2}};
  t.mesh.constrained_edges = {{0, 1, 0}, {1, 2, 1}, {0, 2, 2}};
  return t;
}

TEST(CertifyRejects, AngleJustUnderTheta) {
  // A lone triangle whose smallest angle is 30 degrees minus 1e-7 degrees.
  const double rad = (30 - 1e-7) * M_PI / 180;
  const auto [p, m] = lone_triangle({std::cos(rad), std::sin(rad)});
  expect_rejected_for(run(p, m, 30), Reason::AngleBelowTheta);
  expect_certified(run(p, m, 30 - 2e-7));
}

TEST(CertifyRejects, TerminalPairOver120NonDelaunay) {
  // Two flat triangles on the common longest edge (-1,0)-(1,0): the apexes
  // (0, +-0.25) see it at about 152 degrees; (0,-0.25) is inside the other's circumcircle.
  Pslg p;
  p.vertices = {{-1, 0}, {1, 0}, {0, 0.25}, {0, -0.25}};
  p.segments = {{0, 3, 0}, {3, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  Mesh m;
  m.vertices = p.vertices;
  m.input_vertices = 4;
  m.triangles = {{0, 1, 2}, {1, 0, 3}};
  m.constrained_edges = {{0, 3, 0}, {3, 1, 1}, {1, 2, 2}, {2, 0, 3}};
  const auto r = run(p, m);
  expect_rejected_times(r, Reason::TerminalAngleOver120, 2u);
  EXPECT_TRUE(r.has(Reason::NotLocallyDelaunay));
  // The Delaunay diagonal: no terminal pair is over 120 degrees.
  m.triangles = {{0, 3, 2}, {3, 1, 2}};
  expect_certified(run(p, m));
}

TEST(CertifyRejects, MeshedHole) {
  const Pslg p = test::square_with_hole();
  Pslg no_hole = p;
  no_hole.holes.clear();
  const Mesh bad = test::cgal_cdt(no_hole);
  const auto r = run(p, bad);
  expect_rejected_for(r, Reason::MeshOutsideDomain);
  // The square without its hole is a disk (V - E + F = 1), the domain an annulus (0).
  expect_rejected_for(r, Reason::EulerCharacteristic);
}

TEST(CertifyRejects, ConformingModeChecksConstrainedEdges) {
  // A rhombus split along its constrained long diagonal (-1,0)-(1,0): (0,-0.8) lies
  // inside the circumcircle of (-1,0), (1,0), (0,0.8), so the diagonal is not locally
  // Delaunay. A constrained Delaunay mesh may keep it; a conforming one may not.
  Pslg p;
  p.vertices = {{-1, 0}, {1, 0}, {0, 0.8}, {0, -0.8}};
  p.segments = {{0, 3, 0}, {3, 1, 0}, {1, 2, 0}, {2, 0, 0}, {0, 1, 0}};
  Mesh m;
  m.vertices = p.vertices;
  m.input_vertices = 4;
  m.triangles = {{0, 1, 2}, {1, 0, 3}};
  m.constrained_edges = {{0, 3, 0}, {3, 1, 1}, {1, 2, 2}, {2, 0, 3}, {0, 1, 4}};
  expect_certified(run(p, m));
  certify::Options options;
  options.conforming = true;
  const auto r = certify::certify(p, m, options);
  expect_rejected_times(r, Reason::NotLocallyDelaunay, 1u);
}

TEST(CertifyRejects, AngleWithinTheBracketIsNotCertified) {
  // theta = 20: sin^2(theta) is irrational, bracketed by two adjacent doubles lo < hi.
  // A triangle whose angle has lo <= sin^2 < hi is neither certainly below theta nor
  // certainly not: it must be reported as not certified, never passed. Found by
  // nudging the corner (cos 20, sin 20) by ulps, decided in exact rationals.
  const double theta = 20;
  const Sin2Bracket bracket = sin2_bracket(theta);
  ASSERT_LT(bracket.lo, bracket.hi);
  const double rad = theta * M_PI / 180;
  std::optional<Point> corner;
  for (int ka = -60; ka <= 60 && !corner; ++ka)
    for (int kb = -60; kb <= 60 && !corner; ++kb) {
      double a = std::cos(rad), b = std::sin(rad);
      for (int k = 0; k < std::abs(ka); ++k) a = std::nextafter(a, ka > 0 ? 2.0 : 0.0);
      for (int k = 0; k < std::abs(kb); ++k) b = std::nextafter(b, kb > 0 ? 2.0 : 0.0);
      const CGAL::Gmpq A(a), B(b), s2 = B * B / (A * A + B * B);
      if (CGAL::Gmpq(bracket.lo) <= s2 && s2 < CGAL::Gmpq(bracket.hi)) corner = Point{a, b};
    }
  ASSERT_TRUE(corner.has_value()) << "no corner with sin^2 inside the bracket among the nudges";
  const auto [p, m] = lone_triangle(*corner);
  const auto r = run(p, m, theta);
  expect_rejected_for(r, Reason::AngleNotCertified);
  EXPECT_FALSE(r.has(Reason::AngleBelowTheta));
}

TEST(CertifyRejects, BadIdsAndNonFiniteCoordinates) {
  const Pslg p = test::square_with_crack();
  Mesh bad = test::cgal_cdt(p);
  bad.triangles.push_back({0, 1, 99});
  bad.triangles.push_back({2, 2, 3});
  bad.vertices.push_back({std::nan(""), 1});
  bad.triangles.push_back({0, 1, static_cast<int>(bad.vertices.size()) - 1});
  const auto r = run(p, bad);
  expect_rejected_times(r, Reason::BadTriangle, 3u);
}

TEST(CertifyRejects, UnusedSteinerVertex) {
  const Pslg p = test::square_with_crack();
  Mesh bad = test::cgal_cdt(p);
  bad.vertices.push_back({5, 5.5});
  expect_rejected_for(run(p, bad), Reason::UnusedVertex);
}

TEST(CertifyRejects, ListedConstrainedEdgeOffSegments) {
  const Pslg p = test::square_with_crack();
  Mesh bad = test::cgal_cdt(p);
  // An unconstrained edge listed as constrained.
  for (const Tri& t : bad.triangles)
    if (!is_constrained(bad, t[0], t[1])) {
      bad.constrained_edges.push_back({t[0], t[1], -1});
      break;
    }
  expect_rejected_for(run(p, bad), Reason::ConstrainedEdgeNotOnSegment);
}

TEST(CertifyRejects, DuplicateMeshVertex) {
  const Pslg p = test::square_with_crack();
  const Mesh good = test::cgal_cdt(p);
  expect_certified(run(p, good));
  // A second copy of the interior vertex on no segment (the last input vertex),
  // used in place of the original by one of its triangles: the mesh is then cut
  // open around the copy, but the copy itself must be reported.
  Mesh bad = good;
  const int original = static_cast<int>(p.vertices.size()) - 1;
  const int copy = static_cast<int>(bad.vertices.size());
  bad.vertices.push_back(bad.vertices[static_cast<std::size_t>(original)]);
  auto it = std::find_if(bad.triangles.begin(), bad.triangles.end(),
                         [&](const Tri& t) { return std::find(t.begin(), t.end(), original) != t.end(); });
  ASSERT_NE(it, bad.triangles.end());
  std::replace(it->begin(), it->end(), original, copy);
  const auto r = run(p, bad);
  expect_rejected_times(r, Reason::DuplicateMeshVertex, 1u);
  auto v = std::find_if(r.violations.begin(), r.violations.end(), [](const certify::Violation& x) { return x.reason == Reason::DuplicateMeshVertex; });
  ASSERT_NE(v, r.violations.end());
  EXPECT_EQ(v->vertices, (std::vector<int>{original, copy}));
  // An unused copy alone of an input vertex: merged with a warning, as Triangle's .node
  // keeps an input's repeated vertex (docs/CERTIFIER.md section 1; issue 20).
  Mesh unused = good;
  unused.vertices.push_back(unused.vertices[static_cast<std::size_t>(original)]);
  const auto u = run(p, unused);
  expect_certified(u);
  EXPECT_EQ(u.warnings.size(), 1u) << certify::format_report(u);
  // An unused copy of a point that is no input vertex: a duplicate (and an unused Steiner
  // vertex), nothing else.
  Mesh steiner = good;
  const Point mid{(good.vertices[0].x + good.vertices[1].x) / 2 + 0.25, (good.vertices[0].y + good.vertices[1].y) / 2 + 0.25};
  steiner.vertices.push_back(mid);
  steiner.vertices.push_back(mid);
  const auto w = run(p, steiner);
  expect_rejected_for(w, Reason::DuplicateMeshVertex);
  EXPECT_EQ(w.count(Reason::DuplicateMeshVertex), 1u) << certify::format_report(w);
  EXPECT_EQ(w.count(Reason::UnusedVertex), 2u) << certify::format_report(w);
}

TEST(CertifyRejects, MoreInputVerticesClaimedThanTheInputHas) {
  const Pslg p = test::square_with_crack();
  Mesh bad = test::cgal_refined(p);  // Steiner vertices after the input ones
  expect_certified(run(p, bad, 20));
  ASSERT_GT(bad.vertices.size(), p.vertices.size());
  bad.input_vertices = p.vertices.size() + 1;  // a Steiner vertex claimed as an input vertex
  const auto r = run(p, bad, 20);
  expect_rejected_only_for(r, Reason::InputVertexMoved);
  EXPECT_NE(certify::format_report(r).find("claims " + std::to_string(p.vertices.size() + 1) + " input vertices"), std::string::npos)
      << certify::format_report(r);
}

TEST(CertifyRejects, ConstrainedEdgeTaggedWithAnotherSegment) {
  const Pslg p = test::square_with_crack();
  Mesh m = test::cgal_cdt(p);  // every segment one edge, listed with id -1
  ASSERT_EQ(m.constrained_edges.size(), p.segments.size());
  for (ConstrainedEdge& e : m.constrained_edges) {
    e.segment = segment_id(p, e.a, e.b);
    ASSERT_GE(e.segment, 0);
  }
  expect_certified(run(p, m));  // the right ids
  const int crack = static_cast<int>(p.segments.size()) - 1;
  auto it = std::find_if(m.constrained_edges.begin(), m.constrained_edges.end(), [&](const ConstrainedEdge& e) { return e.segment == crack; });
  ASSERT_NE(it, m.constrained_edges.end());
  it->segment = 0;  // the crack tagged as the bottom side
  const auto r = run(p, m);
  expect_rejected_only_for(r, Reason::ConstrainedEdgeWrongSegment);
  const auto v = std::find_if(r.violations.begin(), r.violations.end(),
                              [](const certify::Violation& x) { return x.reason == Reason::ConstrainedEdgeWrongSegment; });
  ASSERT_NE(v, r.violations.end());
  EXPECT_EQ(v->segment, crack);  // the segment it lies on
}

TEST(CertifyRejects, ConstrainedEdgeLeftOffTheList) {
  const Pslg p = test::square_with_crack();
  Mesh bad = test::cgal_cdt(p);
  const Segment crack = p.segments.back();
  auto it = std::find_if(bad.constrained_edges.begin(), bad.constrained_edges.end(), [&](const ConstrainedEdge& e) {
    return (e.a == crack.a && e.b == crack.b) || (e.a == crack.b && e.b == crack.a);
  });
  ASSERT_NE(it, bad.constrained_edges.end());
  bad.constrained_edges.erase(it);  // the crack is still an edge, on the segment, but no longer listed
  const auto r = run(p, bad);
  expect_rejected_only_for(r, Reason::ConstrainedEdgeUnlisted);
  ASSERT_EQ(r.violations.size(), 1u);
  EXPECT_EQ(r.violations.front().segment, static_cast<int>(p.segments.size()) - 1);
  // A mesh that lists no constrained edge at all says nothing: found by geometry alone.
  bad.constrained_edges.clear();
  expect_certified(run(p, bad));
}

TEST(CertifyAccepts, NegativeZeroIsTheSamePointAsZero) {
  // The input writes a coordinate as -0, the mesher prints it as 0 (Triangle does):
  // the same point, found whether or not the mesh claims its input vertices.
  Pslg p;
  p.vertices = {{0, -8}, {8, -8}, {8, -0.0}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  Mesh m;
  m.vertices = {{0, -8}, {8, -8}, {8, 0}};
  m.triangles = {{0, 1, 2}};
  m.constrained_edges = {{0, 1, 0}, {1, 2, 1}, {2, 0, 2}};
  for (std::size_t claimed : {std::size_t{0}, std::size_t{3}}) {
    m.input_vertices = claimed;
    expect_certified(run(p, m));
  }
  // A vertex that really moved is still caught.
  m.vertices[2] = {8, std::nextafter(0.0, 1.0)};
  m.input_vertices = 0;
  EXPECT_FALSE(run(p, m).certified());
}

TEST(CertifyUnimprovable, RuleCheckedNotTrusted) {
  const auto [p, m] = test::ten_degree_wedge();
  certify::Options options;
  options.min_angle_deg = 20;
  expect_rejected_for(certify::certify(p, m, options), Reason::AngleBelowTheta);
  // Listed: the shortest edge v1-v2 joins segments 0 and 1, meeting at v0 at 10 degrees.
  options.unimprovable = {{{0, 1, 2}, 0, 0, 1, 10}};
  const auto r = certify::certify(p, m, options);
  expect_certified(r);
  EXPECT_EQ(r.unimprovable_accepted.size(), 1u);
  // At theta = 8 the wedge is not below theta: no exemption is needed, none is counted.
  options.min_angle_deg = 8;
  const auto at8 = certify::certify(p, m, options);
  expect_certified(at8);
  EXPECT_TRUE(at8.unimprovable_accepted.empty()) << certify::format_report(at8);
  options.min_angle_deg = 20;
  // A triangle listed that is not in the mesh is reported.
  options.unimprovable = {{{0, 1, 2}, 0, 0, 1, 10}, {{0, 2, 1}, 0, 0, 1, 10}};
  EXPECT_TRUE(certify::certify(p, m, options).certified());  // same triangle, other orientation
  options.unimprovable = {{{0, 1, 2}, 0, 0, 1, 10}, {{0, 1, 5}, 0, 0, 1, 10}};
  expect_rejected_for(certify::certify(p, m, options), Reason::UnimprovableNotInMesh);
}

TEST(CertifyUnimprovable, ShortestEdgeFromTheApexIsNotTheRule) {
  // A 20-degree wedge at v0 (segments 0: v0-v1, 1: v0-v2, 2: v1-v2) with a Steiner
  // point v3 on segment 0 near the apex. Triangle (0,3,2) is skinny and its shortest
  // edge v0-v3 starts at the apex: section 8 needs both ends on the two segments away
  // from the apex, so listing it must not excuse it. Triangle (3,1,2) is the rule's own
  // case (shortest edge v1-v2 joins the two segments) and is accepted.
  const double rad = 20 * M_PI / 180;
  Pslg p;
  p.vertices = {{0, 0}, {1, 0}, {std::cos(rad), std::sin(rad)}};
  p.segments = {{0, 1, 0}, {0, 2, 0}, {1, 2, 0}};
  Mesh m;
  m.vertices = p.vertices;
  m.vertices.push_back({0.125, 0});
  m.input_vertices = 3;
  m.triangles = {{0, 3, 2}, {3, 1, 2}};
  m.constrained_edges = {{0, 3, 0}, {3, 1, 0}, {0, 2, 1}, {1, 2, 2}};
  certify::Options options;
  options.min_angle_deg = 30;
  const auto plain = certify::certify(p, m, options);
  ASSERT_EQ(plain.count(Reason::AngleBelowTheta), 2u) << certify::format_report(plain);
  options.unimprovable = {{{0, 3, 2}, 0, 0, 1, 20}, {{3, 1, 2}, 0, 0, 1, 20}};
  const auto r = certify::certify(p, m, options);
  expect_rejected_times(r, Reason::UnimprovableRuleFails, 1u);
  EXPECT_EQ(r.unimprovable_accepted.size(), 1u);
}

TEST(CertifyUnimprovable, ListedTriangleWithoutSmallInputAngleRejected) {
  // The crack square has no input angle below 90 degrees: listing its skinny
  // triangles as unimprovable must not excuse them.
  const Pslg p = test::square_with_crack();
  const Mesh m = test::cgal_cdt(p);
  certify::Options options;
  options.min_angle_deg = 30;
  const auto plain = certify::certify(p, m, options);
  ASSERT_TRUE(plain.has(Reason::AngleBelowTheta)) << "the test input needs a skinny triangle";
  for (const certify::Violation& v : plain.violations)
    if (v.reason == Reason::AngleBelowTheta) options.unimprovable.push_back({m.triangles[static_cast<std::size_t>(v.triangles[0])], 0, 0, 1, 5});
  const auto r = certify::certify(p, m, options);
  expect_rejected_times(r, Reason::UnimprovableRuleFails, plain.count(Reason::AngleBelowTheta));
  EXPECT_TRUE(r.unimprovable_accepted.empty());
}

}  // namespace
}  // namespace lepp
