// SPDX-License-Identifier: GPL-3.0-or-later
// The precision-limit exemption (docs/CERTIFIER.md section 5c): a triangle below
// theta is exempt only when the certifier, recomputing every choice the paper
// allows at every rounding, finds none that can be inserted. It accepts the
// triangles lepp leaves at double precision, without reading lepp's list, and
// rejects a mesh that claims the exemption where a point can be inserted, or
// that writes an inverted triangle there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "lepp/certify.h"
#include "lepp/fast.h"
#include "lepp/reference.h"
#include "lepp/input.h"
#include "lepp/gen_precision.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

Pslg cluster34() {
  std::vector<std::string> warnings;
  return validate(read_input(LEPP_SOURCE_DIR "/corpus/regressions/precision/cluster34.node", warnings), DomainOptions{}, warnings);
}

RefineResult refine_at(const Pslg& p, double theta) {
  RefineOptions o;
  o.min_angle_deg = theta;
  return fast::refine(p, o);
}

std::vector<UnimprovableTriangle> at_precision(const RefineResult& r) {
  std::vector<UnimprovableTriangle> out;
  for (const UnimprovableTriangle& u : r.unimprovable)
    if (u.reason == LeftReason::DoublePrecision) out.push_back(u);
  return out;
}

// The index of mesh triangle `t` (any rotation), or -1.
int index_of(const Mesh& m, Tri t) {
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    Tri x = m.triangles[i], y = t;
    std::sort(x.begin(), x.end());
    std::sort(y.begin(), y.end());
    if (x == y) return static_cast<int>(i);
  }
  return -1;
}

// lepp's own list is held to the rule, and the rule alone (no list) exempts the same triangles.
TEST(CertifyPrecision, LeppsTrianglesLeftAtDoublePrecisionAreExemptByTheRuleAlone) {
  const Pslg p = cluster34();
  const RefineResult r = refine_at(p, 33);
  const auto left = at_precision(r);
  ASSERT_FALSE(left.empty()) << "the cluster at 33 degrees must reach the precision stop";

  certify::Options with_list;
  with_list.min_angle_deg = 33;
  with_list.unimprovable = r.unimprovable;
  const certify::Report listed = certify::certify(p, r.mesh, with_list);
  EXPECT_TRUE(listed.certified()) << certify::format_report(listed);
  EXPECT_EQ(listed.unimprovable_accepted.size(), r.unimprovable.size());

  certify::Options rule;
  rule.min_angle_deg = 33;
  rule.exempt_precision_limited = true;
  const certify::Report alone = certify::certify(p, r.mesh, rule);
  EXPECT_TRUE(alone.certified()) << certify::format_report(alone);
  EXPECT_EQ(alone.precision_exempt_count, alone.precision_exempt_triangles.size());
  for (const UnimprovableTriangle& u : left) {
    const int t = index_of(r.mesh, u.triangle);
    ASSERT_GE(t, 0);
    const bool below = std::find(alone.precision_exempt_triangles.begin(), alone.precision_exempt_triangles.end(), t) !=
                       alone.precision_exempt_triangles.end();
    // Listed triangles below theta are exempt; a listed one at or above theta needs no exemption.
    if (!below) {
      certify::Options strict;
      strict.min_angle_deg = 33;
      const certify::Report s = certify::certify(p, r.mesh, strict);
      for (const certify::Violation& v : s.violations)
        EXPECT_FALSE(std::find(v.triangles.begin(), v.triangles.end(), t) != v.triangles.end())
            << "triangle " << t << " is below theta but not exempt";
    }
  }

  // Without the rule or the list the same mesh fails at 33 degrees: the exemption is doing the work.
  certify::Options none;
  none.min_angle_deg = 33;
  EXPECT_TRUE(certify::certify(p, r.mesh, none).has(certify::Reason::AngleBelowTheta));
}

// A mesh stopped early by the budget claims its skinny triangles are precision-limited:
// a point can be inserted for each, so the claim fails and the angle is a violation.
TEST(CertifyPrecision, RejectsAWrongClaim) {
  Pslg p;
  p.vertices = {{0, 0}, {8, 0}, {8, 1}, {0, 1}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}};
  std::vector<std::string> warnings;
  p = validate(p, warnings);
  RefineOptions o;
  o.min_angle_deg = 30;
  o.max_steiner = 2;
  const RefineResult r = fast::refine(p, o);
  ASSERT_EQ(r.outcome, Outcome::SteinerBudget);
  certify::Options strict;
  strict.min_angle_deg = 30;
  const certify::Report before = certify::certify(p, r.mesh, strict);
  ASSERT_TRUE(before.has(certify::Reason::AngleBelowTheta));
  const int t = before.violations.front().triangles.front();

  UnimprovableTriangle claim;
  claim.triangle = r.mesh.triangles[static_cast<std::size_t>(t)];
  claim.reason = LeftReason::DoublePrecision;
  certify::Options claimed = strict;
  claimed.unimprovable = {claim};
  const certify::Report rep = certify::certify(p, r.mesh, claimed);
  EXPECT_FALSE(rep.certified());
  EXPECT_TRUE(rep.has(certify::Reason::UnimprovableRuleFails)) << certify::format_report(rep);

  certify::Options rule = strict;
  rule.exempt_precision_limited = true;
  const certify::Report alone = certify::certify(p, r.mesh, rule);
  EXPECT_EQ(alone.precision_exempt_count, 0u);
  EXPECT_TRUE(alone.has(certify::Reason::AngleBelowTheta));
}


// Remark 10 at the precision limit (issue 20's subnormal fuzz findings): t1 = (0, 0), (10, 0),
// (0, 1) and t2 = (0, 1), (10, 0), (1, 4), in units of the smallest subnormal. t1's second-longest
// edge lies on the boundary, t2's does not, so the choice is the centroid (11/4, 5/4) if it is
// strictly inside t2, else the midpoint (5, 0) of t1's boundary edge. Every rounding of the
// centroid, (2 or 3, 1 or 2), is strictly inside t2 and within the precision floor of (0, 1): no
// mesher may take the midpoint, which could be inserted, so both triangles are precision-limited.
Pslg subnormal_pair() {
  const double s = std::numeric_limits<double>::denorm_min();
  Pslg p;
  p.vertices = {{0, 0}, {10 * s, 0}, {0, s}, {s, 4 * s}, {9 * s, 10 * s}};
  p.segments = {{0, 1, 0}, {1, 4, 0}, {4, 3, 0}, {3, 2, 0}, {2, 0, 0}};
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

TEST(CertifyPrecision, CentroidInOtherBelowTheFloorLeavesNoMidpointChoice) {
  const Pslg p = subnormal_pair();
  for (const bool fast_engine : {true, false}) {
    RefineOptions o;
    o.min_angle_deg = 20;
    const RefineResult r = fast_engine ? fast::refine(p, o) : reference::refine(p, o);
    ASSERT_EQ(r.outcome, Outcome::Unimprovable) << (fast_engine ? "fast" : "reference");
    ASSERT_EQ(r.steiner_points, 0);
    const auto left = at_precision(r);
    ASSERT_EQ(left.size(), 2u);
    for (const UnimprovableTriangle& u : left) EXPECT_EQ(u.rule, Rule::CentroidInOther);

    certify::Options listed;
    listed.min_angle_deg = 20;
    listed.unimprovable = r.unimprovable;
    const certify::Report rep = certify::certify(p, r.mesh, listed);
    EXPECT_TRUE(rep.certified()) << certify::format_report(rep);

    certify::Options rule;
    rule.min_angle_deg = 20;
    rule.exempt_precision_limited = true;
    const certify::Report alone = certify::certify(p, r.mesh, rule);
    EXPECT_TRUE(alone.certified()) << certify::format_report(alone);
    EXPECT_EQ(alone.precision_exempt_count, 2u);
  }
}


// A mesher that writes the precision-limited triangle inverted is not excused.
TEST(CertifyPrecision, RejectsAnInvertedTriangleThere) {
  const Pslg p = cluster34();
  RefineResult r = refine_at(p, 33);
  const auto left = at_precision(r);
  ASSERT_FALSE(left.empty());
  const int t = index_of(r.mesh, left.front().triangle);
  ASSERT_GE(t, 0);
  Mesh bad = r.mesh;
  std::swap(bad.triangles[static_cast<std::size_t>(t)][1], bad.triangles[static_cast<std::size_t>(t)][2]);
  certify::Options rule;
  rule.min_angle_deg = 33;
  rule.exempt_precision_limited = true;
  rule.unimprovable = r.unimprovable;
  const certify::Report rep = certify::certify(p, bad, rule);
  EXPECT_FALSE(rep.certified());
  EXPECT_TRUE(rep.has(certify::Reason::NotCounterClockwise)) << certify::format_report(rep);
}

// The sliver clause's input (gen_precision.h), validated.
Pslg sliver_input(double dy) {
  std::vector<std::string> warnings;
  return validate(gen::sliverClauseInput(dy), warnings);
}

bool exempt(const certify::Report& rep, int t) {
  return std::find(rep.precision_exempt_triangles.begin(), rep.precision_exempt_triangles.end(), t) != rep.precision_exempt_triangles.end();
}

// The sliver clause (CERTIFIER.md section 5c): with vertex 3 on AP the split at P is
// not insertable, so ABC, which the engines leave there, is exempt by the rule alone
// (before the clause the certifier found P insertable and rejected the stop). With
// the vertex one ulp lower, off the sliver, the same triangle is not exempt.
TEST(CertifyPrecision, SliverClauseExemptsTheStopAtAVertexOutside) {
  const Pslg p = sliver_input(0);
  const RefineResult r = refine_at(p, 30);
  const int abc = index_of(r.mesh, {0, 1, 2});
  ASSERT_GE(abc, 0);
  certify::Options rule;
  rule.min_angle_deg = 30;
  rule.exempt_precision_limited = true;
  const certify::Report rep = certify::certify(p, r.mesh, rule);
  EXPECT_TRUE(rep.certified()) << certify::format_report(rep);
  EXPECT_TRUE(exempt(rep, abc));

  const Pslg off = sliver_input(-std::ldexp(1.0, -12));
  Mesh moved = r.mesh;
  moved.vertices[3] = off.vertices[3];
  const certify::Report claim = certify::certify(off, moved, rule);
  EXPECT_FALSE(exempt(claim, abc)) << certify::format_report(claim);
  EXPECT_FALSE(claim.certified());
}

// A mesh whose triangles cover an input vertex outside the domain (here on the edge
// from A to P) is no triangulation of its vertices there: rejected, though that vertex
// is in no triangle and the coverage checks (sides of segments, Euler) do not see it.
// The same mesh with the vertex one ulp off the sliver certifies.
TEST(CertifyPrecision, RejectsAMeshCoveringAVertexOutsideTheDomain) {
  const Pslg off = sliver_input(-std::ldexp(1.0, -12));
  const RefineResult r = refine_at(off, 30);
  certify::Options plain;
  const certify::Report fine = certify::certify(off, r.mesh, plain);
  EXPECT_TRUE(fine.certified()) << certify::format_report(fine);

  const Pslg on = sliver_input(0);
  Mesh covering = r.mesh;
  covering.vertices[3] = on.vertices[3];
  const certify::Report rep = certify::certify(on, covering, plain);
  EXPECT_EQ(rep.count(certify::Reason::InputVertexMissing), 1u) << certify::format_report(rep);
  EXPECT_FALSE(rep.certified());
}

// Two segments leave (0.01, 0.01) at 3.18 degrees and a vertex 3 ulps from it makes
// both engines refine down to ulps of the apex, where the first vertex of one chain is
// within an ulp of the other's line (corpus/regressions/precision/apex-ulps-chain-walk.poly,
// shrunk from fuzz_engine's finding at 22.1 degrees). Both engines make the same mesh,
// and it certifies with their lists: the certifier takes the listed path from A that
// ends at B (docs/CERTIFIER.md section 3), not the other chain.
TEST(CertifyPrecision, ApexRefinedToUlpsCertifiesFromBothEngines) {
  std::vector<std::string> warnings;
  const Pslg p = validate(read_input(LEPP_SOURCE_DIR "/corpus/regressions/precision/apex-ulps-chain-walk.poly", warnings),
                          DomainOptions{}, warnings);
  for (const double theta : {10.0, 20.0, 22.1, 25.0, 30.0}) {
    SCOPED_TRACE(theta);
    RefineOptions o;
    o.min_angle_deg = theta;
    const RefineResult f = fast::refine(p, o);
    const RefineResult r = reference::refine(p, o);
    EXPECT_EQ(f.mesh.vertices, r.mesh.vertices);
    EXPECT_EQ(f.mesh.triangles, r.mesh.triangles);
    certify::Options c;
    c.min_angle_deg = theta;
    c.unimprovable = f.unimprovable;
    const certify::Report rep = certify::certify(p, f.mesh, c);
    EXPECT_TRUE(rep.certified()) << certify::format_report(rep);
  }
}

// At offset 2^35 an ulp (2^-17) is many times 2^-20 |AB| of a segment 0.3 long, and
// the chain of segment 0-4 through a cluster of vertices a few ulps apart bends by
// ulps (corpus/regressions/precision/offset-cluster-listed-path-ulps.poly, fuzz_refine's
// finding at 18.5 degrees, midpoint, lifo). The listed path lets a vertex through within
// the walk's loosest tolerance too, so the mesh both engines make certifies; the same
// mesh with one of that chain's Steiner points moved off the segment does not.
TEST(CertifyPrecision, ListedPathAtOffsetWithinUlpsCertifiesFromBothEngines) {
  std::vector<std::string> warnings;
  const Pslg p = validate(
      read_input(LEPP_SOURCE_DIR "/corpus/regressions/precision/offset-cluster-listed-path-ulps.poly", warnings),
      DomainOptions{}, warnings);
  RefineOptions o;
  o.method = Method::Midpoint;
  o.min_angle_deg = 18.5;
  o.order = QueueOrder::Lifo;
  const RefineResult f = fast::refine(p, o);
  const RefineResult r = reference::refine(p, o);
  EXPECT_EQ(f.mesh.vertices, r.mesh.vertices);
  EXPECT_EQ(f.mesh.triangles, r.mesh.triangles);
  certify::Options c;
  c.min_angle_deg = 18.5;
  c.precision_method = Method::Midpoint;
  c.unimprovable = f.unimprovable;
  const certify::Report rep = certify::certify(p, f.mesh, c);
  EXPECT_TRUE(rep.certified()) << certify::format_report(rep);

  // A Steiner point of a constrained edge, moved 2^-10 across: off its segment.
  Mesh moved = f.mesh;
  const std::size_t inputs = p.vertices.size();
  std::size_t steiner = moved.vertices.size();
  for (const ConstrainedEdge& e : moved.constrained_edges)
    if (static_cast<std::size_t>(e.a) >= inputs) {
      steiner = static_cast<std::size_t>(e.a);
      break;
    }
  ASSERT_LT(steiner, moved.vertices.size());
  moved.vertices[steiner].y += std::ldexp(1.0, -10);
  const certify::Report off = certify::certify(p, moved, c);
  EXPECT_FALSE(off.certified()) << certify::format_report(off);
}

// The chain walk goes round a split's sliver (ALGORITHM.md section 6, "A split off its
// line"; docs/CERTIFIER.md, the walk): in lepp's mesh of
// split-off-line-midpoint-2e40.poly the triangle beside the sliver is kept, so the vertex
// before the point is joined to the segment's end by the sliver's unlisted base too.
// The listed path covers it while every chain edge is listed; the walk is taken when
// one is not. Dropping each listed edge from the list in turn, the report names that
// edge, and the walk, still going round through the point, finds every other edge on
// its chain. One drop is the exception: the edge from the point to the vertex before
// it (161-165 here): no listed step then leads on from that vertex, so the walk ends
// at the segment's end by the sliver's base, names the base as the unlisted edge and
// the point's other edge as on no chain (the mesh is rejected, the edges named are
// not the dropped one). A walk that ended by the base whenever it could named the
// chain's edges through the point as on no chain for nine more drops.
TEST(CertifyPrecision, ChainWalkGoesRoundTheSliverWithAnEdgeUnlisted) {
  std::vector<std::string> warnings;
  const Pslg p = validate(read_input(LEPP_SOURCE_DIR "/corpus/regressions/precision/split-off-line-midpoint-2e40.poly", warnings),
                          DomainOptions{}, warnings);
  RefineOptions o;
  o.method = Method::Midpoint;
  o.min_angle_deg = 17.899999999999999;
  const RefineResult f = fast::refine(p, o);
  ASSERT_TRUE(certify::certify(p, f.mesh, {}).certified());
  int other = 0;
  std::string reports;
  for (std::size_t k = 0; k < f.mesh.constrained_edges.size(); ++k) {
    Mesh dropped = f.mesh;
    const ConstrainedEdge e = dropped.constrained_edges[k];
    dropped.constrained_edges.erase(dropped.constrained_edges.begin() + static_cast<std::ptrdiff_t>(k));
    const certify::Report rep = certify::certify(p, dropped, {});
    bool named = false;
    for (const certify::Violation& v : rep.violations)
      for (const auto& ed : v.edges)
        named = named || (v.reason == certify::Reason::ConstrainedEdgeUnlisted &&
                          std::min(ed[0], ed[1]) == std::min(e.a, e.b) && std::max(ed[0], ed[1]) == std::max(e.a, e.b));
    if (!named || rep.violations.size() != 1) {
      ++other;
      reports += "dropped " + std::to_string(e.a) + "-" + std::to_string(e.b) + ":\n" + certify::format_report(rep);
    }
  }
  EXPECT_LE(other, 1) << "drops whose report does not name the dropped edge alone:\n" << reports;
}

}  // namespace
}  // namespace lepp
