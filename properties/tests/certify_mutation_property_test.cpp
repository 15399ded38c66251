// SPDX-License-Identifier: GPL-3.0-or-later
// The certifier cannot be fooled by one random mutation of a correct mesh: on
// generated PSLGs, the reference engine's refined mesh (certified first) is broken
// in one random way, and the certifier must reject it for the right reason.
// The hand-made cases are in certify_rejects_test.cpp; this is the same idea at random.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "lepp/certify.h"
#include "lepp/gen.h"
#include "lepp/reference.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

using certify::Reason;
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
K::Point_2 cg(const Point& p) { return {p.x, p.y}; }

struct Setup {
  Pslg pslg;
  Mesh mesh;
};

Setup certified_mesh() {
  std::vector<std::string> warnings;
  Setup s;
  s.pslg = validate(*rc::gen::oneOf(gen::wellShapedPslg(), gen::boxWithCracks(), gen::polygonWithHole(), gen::convexPolygon()),
                    warnings);
  RefineOptions o;
  o.min_angle_deg = 25;
  o.max_steiner = 400;
  s.mesh = reference::refine(s.pslg, o).mesh;
  RC_PRE(s.mesh.triangles.size() >= 4);
  const auto r = certify::certify(s.pslg, s.mesh);
  if (!r.certified()) RC_FAIL("the unmutated mesh does not certify\n" + certify::format_report(r));
  return s;
}

void require_rejected(const Setup& s, const Mesh& bad, Reason reason) {
  const auto r = certify::certify(s.pslg, bad);
  if (!r.has(reason)) RC_FAIL(std::string("expected ") + certify::to_string(reason) + "\n" + certify::format_report(r));
}

bool constrained(const Mesh& m, int a, int b) {
  for (const ConstrainedEdge& e : m.constrained_edges)
    if ((e.a == a && e.b == b) || (e.a == b && e.b == a)) return true;
  return false;
}

RC_GTEST_PROP(CertifyMutations, ReversedTriangleRejected, ()) {
  const Setup s = certified_mesh();
  Mesh bad = s.mesh;
  const auto t = *rc::gen::inRange<std::size_t>(0, bad.triangles.size());
  std::swap(bad.triangles[t][1], bad.triangles[t][2]);
  require_rejected(s, bad, Reason::NotCounterClockwise);
}

RC_GTEST_PROP(CertifyMutations, DroppedTriangleRejected, ()) {
  const Setup s = certified_mesh();
  Mesh bad = s.mesh;
  const auto t = *rc::gen::inRange<std::size_t>(0, bad.triangles.size());
  bad.triangles.erase(bad.triangles.begin() + static_cast<long>(t));
  const auto r = certify::certify(s.pslg, bad);
  RC_ASSERT(!r.certified());
  // A hole inside the domain, or a bare stretch of a segment, or a lost input vertex.
  const bool gap = r.has(Reason::BoundaryNotOnDomainBoundary) || r.has(Reason::DomainBoundaryUncovered) ||
                   r.has(Reason::InputVertexMissing) || r.has(Reason::UnusedVertex);
  RC_CLASSIFY(r.has(Reason::EulerCharacteristic), "Euler characteristic changed");
  if (!gap) RC_FAIL("no coverage violation\n" + certify::format_report(r));
}

RC_GTEST_PROP(CertifyMutations, DuplicatedTriangleRejected, ()) {
  const Setup s = certified_mesh();
  Mesh bad = s.mesh;
  const auto t = *rc::gen::inRange<std::size_t>(0, bad.triangles.size());
  const Tri x = bad.triangles[t];
  bad.triangles.push_back({x[1], x[2], x[0]});
  // An edge of the copy is in three triangles (inside) or twice the same way (on a segment).
  const auto r = certify::certify(s.pslg, bad);
  RC_CLASSIFY(r.has(Reason::EdgeOverused), "edge-overused");
  RC_CLASSIFY(r.has(Reason::EdgeSameDirection), "edge-same-direction");
  if (!r.has(Reason::EdgeOverused) && !r.has(Reason::EdgeSameDirection)) RC_FAIL("overlap not seen\n" + certify::format_report(r));
}

RC_GTEST_PROP(CertifyMutations, FlippedEdgeRejected, ()) {
  const Setup s = certified_mesh();
  // Interior edges whose quad is strictly convex and not cocircular: flipping gives a
  // valid triangulation that is either not Delaunay or misses a constrained edge.
  std::map<std::pair<int, int>, std::pair<std::size_t, int>> half;  // (a, b) -> (triangle, apex)
  for (std::size_t t = 0; t < s.mesh.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const Tri& x = s.mesh.triangles[t];
      half[{x[static_cast<std::size_t>(i)], x[static_cast<std::size_t>((i + 1) % 3)]}] = {t, x[static_cast<std::size_t>((i + 2) % 3)]};
    }
  struct Flip {
    std::size_t t1, t2;
    int a, b, c, d;
  };
  std::vector<Flip> flips;
  auto P = [&](int v) { return cg(s.mesh.vertices[static_cast<std::size_t>(v)]); };
  for (const auto& [edge, tc] : half) {
    const auto [a, b] = edge;
    auto other = half.find({b, a});
    if (a > b || other == half.end()) continue;
    const int c = tc.second, d = other->second.second;
    if (CGAL::orientation(P(a), P(d), P(c)) != CGAL::LEFT_TURN || CGAL::orientation(P(d), P(b), P(c)) != CGAL::LEFT_TURN) continue;
    if (CGAL::side_of_oriented_circle(P(a), P(b), P(c), P(d)) == CGAL::ON_ORIENTED_BOUNDARY) continue;
    flips.push_back({tc.first, other->second.first, a, b, c, d});
  }
  RC_PRE(!flips.empty());
  const Flip f = *rc::gen::elementOf(flips);
  Mesh bad = s.mesh;
  bad.triangles[f.t1] = {f.a, f.d, f.c};
  bad.triangles[f.t2] = {f.d, f.b, f.c};
  const bool was_constrained = constrained(s.mesh, f.a, f.b);
  RC_CLASSIFY(was_constrained, "constrained edge flipped");
  require_rejected(s, bad, was_constrained ? Reason::SegmentMissing : Reason::NotLocallyDelaunay);
}

RC_GTEST_PROP(CertifyMutations, InputVertexMovedOneUlpRejected, ()) {
  const Setup s = certified_mesh();
  Mesh bad = s.mesh;
  const auto v = *rc::gen::inRange<std::size_t>(0, s.pslg.vertices.size());
  double& x = *rc::gen::element(0, 1) ? bad.vertices[v].x : bad.vertices[v].y;
  x = std::nextafter(x, *rc::gen::element(-1.0, 1.0) * 1e300);
  require_rejected(s, bad, Reason::InputVertexMoved);
}

}  // namespace
}  // namespace lepp
