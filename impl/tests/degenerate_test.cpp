// SPDX-License-Identifier: GPL-3.0-or-later
// The degenerate cases, where docs/ALGORITHM.md's decisions meet their
// boundaries (issue 13, item 3), both engines side by side:
//  - exact ties in edge length (decided by ids: every input also with its ids permuted),
//  - orientation exactly zero (a quad centroid on its terminal edge, points on segments),
//  - in-circle exactly zero (symmetric and cocircular sets),
//  - angles exactly at the threshold (45 degrees against theta = 45) and input
//    angles at and near 0, 90 and 180 degrees,
//  - the size bound exactly at a triangle's area,
//  - hole points exactly on vertices, segments and unconstrained edges,
//  - coordinates scaled by 2^-500 and 2^+500 (the filters give up: every decision exact).
//
// The oracle: when the two engines build the same initial CDT, their runs must be
// identical step by step, cocircular ties met during insertion included (a tie
// leaves the edge as it is: the star of the new point does not depend on the flip
// order). Only the initial CDT of cocircular points is not unique (each CDT builder
// breaks the tie its own way); then both outputs must still certify.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "lepp/certify.h"
#include "lepp/fast.h"
#include "lepp/gen.h"
#include "lepp/gen_degenerate.h"
#include "lepp/reference.h"
#include "lepp/validate.h"
#include "predicates.h"
#include "result_diff.h"

namespace lepp {
namespace {

using impl_test::difference;
using impl_test::trace_difference;

const int fixed_seed = (setenv("RC_PARAMS", "seed=20261127 max_success=200", 0), 0);

Pslg validated(const Pslg& p, std::vector<std::string>* warnings_out = nullptr) {
  std::vector<std::string> warnings;
  Pslg v = validate(p, warnings);
  if (warnings_out) *warnings_out = warnings;
  return v;
}

bool same_mesh(const Mesh& a, const Mesh& b) {
  if (a.vertices != b.vertices || a.triangles != b.triangles || a.constrained_edges.size() != b.constrained_edges.size())
    return false;
  for (std::size_t i = 0; i < a.constrained_edges.size(); ++i) {
    const ConstrainedEdge &e = a.constrained_edges[i], &f = b.constrained_edges[i];
    if (e.a != f.a || e.b != f.b || e.segment != f.segment) return false;
  }
  return true;
}

// The output of a run certifies: a CDT of the domain, with min angle >= theta when
// the run converged, and its unimprovable triangles satisfying the rule.
std::string check_output(const Pslg& p, const RefineOptions& o, const RefineResult& r, const char* engine) {
  certify::Options c;
  if (r.outcome == Outcome::Converged || r.outcome == Outcome::Unimprovable) {
    c.min_angle_deg = o.min_angle_deg;
    c.unimprovable = r.unimprovable;
  }
  if (r.outcome == Outcome::Converged && !r.unimprovable.empty())
    return std::string(engine) + ": converged with unimprovable triangles left";
  if (r.outcome == Outcome::Unimprovable && r.unimprovable.empty())
    return std::string(engine) + ": outcome unimprovable with no unimprovable triangle";
  // With a size bound the angle is not all that converging promises: check the area too.
  if (o.max_area > 0 && r.outcome == Outcome::Converged)
    for (const Tri& t : r.mesh.triangles) {
      const Point &a = r.mesh.vertices[static_cast<std::size_t>(t[0])], &b = r.mesh.vertices[static_cast<std::size_t>(t[1])],
                  &d = r.mesh.vertices[static_cast<std::size_t>(t[2])];
      if (fast::area_above(a, b, d, 2 * o.max_area)) return std::string(engine) + ": a triangle above max_area after converging";
    }
  const certify::Report report = certify::certify(p, r.mesh, c);
  if (!report.certified()) return std::string(engine) + " output, outcome " + to_string(r.outcome) + ":\n" + certify::format_report(report);
  return "";
}

// Both engines on p; identical runs when their initial CDTs agree, else both certify.
void run_both(const Pslg& p, RefineOptions o) {
  o.trace = true;
  const RefineResult f = fast::refine(p, o), r = reference::refine(p, o);
  const std::string fc = check_output(p, o, f, "fast"), rcheck = check_output(p, o, r, "reference");
  if (!fc.empty()) RC_FAIL(fc);
  if (!rcheck.empty()) RC_FAIL(rcheck);
  const bool same_start = same_mesh(fast::build_cdt(p), reference::build_cdt(p));
  RC_CLASSIFY(!same_start, "initial CDTs differ (cocircular)");
  RC_CLASSIFY(same_start && f.cocircular_ties > 0, "same start, ties met");
  RC_CLASSIFY(f.steiner_points == 0, "nothing inserted");
  if (!same_start) return;
  const std::string steps = trace_difference(f.trace, r.trace);
  if (!steps.empty()) RC_FAIL("same initial CDT, different runs: " + steps);
  const std::string diff = difference(f, r);
  if (!diff.empty()) RC_FAIL("same initial CDT, different results: " + diff);
  RC_ASSERT(f.cocircular_ties == r.cocircular_ties);
  // Which degenerate decisions the run met (a step's centroid exactly on its terminal edge).
  bool on_edge = false, tie = false;
  for (const TraceStep& s : f.trace) {
    const Point &a = f.mesh.vertices[static_cast<std::size_t>(s.terminal_edge[0])],
                &b = f.mesh.vertices[static_cast<std::size_t>(s.terminal_edge[1])];
    if ((s.rule == Rule::QuadCentroid || s.rule == Rule::CentroidInOther) && fast::orient(a, b, s.point) == 0) on_edge = true;
    tie = tie || s.lepp.size() > 1;
  }
  RC_CLASSIFY(on_edge, "a centroid exactly on its terminal edge");
}

RefineOptions any_options(bool allow_size) {
  RefineOptions o;
  o.method = *rc::gen::element(Method::Centroid, Method::Midpoint);
  o.order = *rc::gen::element(QueueOrder::Fifo, QueueOrder::Lifo);
  // Integer thetas, and 45: the one integer theta a lattice angle can equal.
  o.min_angle_deg = *rc::gen::element(15.0, 20.0, 25.0, 28.0, 30.0, 33.0, 45.0);
  // A size bound of half an integer: lattice triangles of exactly that area are on the threshold.
  if (allow_size && *rc::gen::inRange(0, 3) == 0) o.max_area = *rc::gen::inRange(1, 40) * 0.5;
  o.max_steiner = 400;
  return o;
}

RC_GTEST_PROP(Degenerate, EnginesAgreeFromTheSameInitialCdt, ()) {
  const Pslg p = validated(*gen::withPermutedIds(gen::anyDegenerate()));
  RC_TAG(p.source);
  run_both(p, any_options(true));
}

// ALGORITHM.md's decisions depend only on exact signs, and a power-of-two scale
// changes no sign and no rounding (no point lands in the subnormals or overflows):
// the run at scale 2^k is the run at scale 1, times 2^k. At 2^-500 and 2^+500 the
// filters see underflow or overflow and every predicate takes its exact path.
RC_GTEST_PROP(Degenerate, PowerOfTwoScaleChangesNothing, ()) {
  const bool tiny = *rc::gen::arbitrary<bool>();
  const double s = std::ldexp(1.0, tiny ? -500 : 500);
  const Pslg p = validated(*rc::gen::oneOf(gen::anyDegenerate(), gen::anyPslg()));
  Pslg q = p;
  for (Point& v : q.vertices) v = {v.x * s, v.y * s};
  for (Point& h : q.holes) h = {h.x * s, h.y * s};
  RefineOptions o = any_options(false);
  o.max_steiner = 200;
  RC_TAG(p.source, tiny ? "2^-500" : "2^+500");
  const RefineResult a = fast::refine(p, o), b = fast::refine(q, o);
  RC_ASSERT(a.outcome == b.outcome);
  RC_ASSERT(a.steiner_points == b.steiner_points);
  RC_ASSERT(a.mesh.triangles == b.mesh.triangles);
  RC_ASSERT(a.mesh.vertices.size() == b.mesh.vertices.size());
  for (std::size_t i = 0; i < a.mesh.vertices.size(); ++i)
    RC_ASSERT(a.mesh.vertices[i].x * s == b.mesh.vertices[i].x && a.mesh.vertices[i].y * s == b.mesh.vertices[i].y);
  RC_ASSERT(a.unimprovable.size() == b.unimprovable.size());
  // And the reference agrees at that scale (its arithmetic is exact at any scale).
  run_both(q, o);
}

// ---- fixed cases --------------------------------------------------------------

Pslg polygon(const std::vector<Point>& ring, const char* name) {
  Pslg p;
  p.vertices = ring;
  for (std::size_t i = 0; i < ring.size(); ++i) p.segments.push_back({static_cast<int>(i), static_cast<int>((i + 1) % ring.size()), 1});
  p.source = name;
  return validated(p);
}

RefineResult both(const Pslg& p, const RefineOptions& o) {
  RefineResult f = fast::refine(p, o), r = reference::refine(p, o);
  EXPECT_EQ(difference(f, r), "") << p.source;
  EXPECT_EQ(trace_difference(f.trace, r.trace), "") << p.source;
  return f;
}

// A 45-degree angle is skinny at theta = 45 (the threshold rounds up) and not at
// theta = 44.99: the right isosceles triangle is refined only at 45.
TEST(DegenerateFixed, FortyFiveDegreesIsSkinnyAtThetaFortyFive) {
  const Pslg p = polygon({{0, 0}, {8, 0}, {0, 8}}, "right isosceles");
  RefineOptions o;
  o.max_steiner = 50;
  o.trace = true;
  o.min_angle_deg = 44.99;
  RefineResult below = both(p, o);
  EXPECT_EQ(below.steiner_points, 0);
  EXPECT_EQ(below.outcome, Outcome::Converged);
  o.min_angle_deg = 45;
  RefineResult at = both(p, o);
  EXPECT_TRUE(at.steiner_points > 0 || !at.unimprovable.empty());
}

// The 45-degree input corner is a small input angle at theta = 45 (the rule's
// comparison rounds up too); a right angle never is (its dot product is zero).
TEST(DegenerateFixed, UnimprovableRuleAtTheThreshold) {
  const Pslg wedge = polygon({{0, 0}, {16, 0}, {16, 16}}, "45-degree wedge");
  RefineOptions o;
  o.min_angle_deg = 45;
  o.max_steiner = 200;
  RefineResult at = both(wedge, o);
  EXPECT_FALSE(at.unimprovable.empty()) << to_string(at.outcome);
  o.min_angle_deg = 44.99;
  RefineResult below = both(wedge, o);
  EXPECT_EQ(below.outcome, Outcome::Converged);
  EXPECT_TRUE(below.unimprovable.empty());
}

// The size bound is strict: a triangle whose area is exactly max_area is not too big.
TEST(DegenerateFixed, SizeBoundExactlyAtTheArea) {
  const Pslg p = polygon({{0, 0}, {4, 0}, {0, 4}}, "area 8");
  RefineOptions o;
  o.min_angle_deg = 20;
  o.max_area = 8;
  EXPECT_EQ(both(p, o).steiner_points, 0);
  o.max_area = std::nextafter(8.0, 0.0);
  EXPECT_GT(both(p, o).steiner_points, 0);
}

// theta = 0 calls nothing skinny: S is the smallest subnormal, and a lattice
// triangle's cross product is at least 1.
TEST(DegenerateFixed, ThetaZeroRefinesNothing) {
  const Pslg p = polygon({{0, 0}, {64, 0}, {64, 1}}, "sliver");
  RefineOptions o;
  o.min_angle_deg = 0;
  const RefineResult r = both(p, o);
  EXPECT_EQ(r.steiner_points, 0);
  EXPECT_EQ(r.outcome, Outcome::Converged);
}

// Hole points (ALGORITHM.md section 2): strictly inside a triangle or on an
// unconstrained edge they remove the region around them; on a vertex or a segment
// they remove nothing (validate warns). Both engines' CDTs and the certifier's own
// expected domain agree in every case.
TEST(DegenerateFixed, HolePointsOnVerticesSegmentsAndEdges) {
  // The box [0, 16]^2, the ring (2,2) (6,2) (4,6) and the free vertex (4,4) inside it.
  const std::vector<Point> box{{0, 0}, {16, 0}, {16, 16}, {0, 16}};
  struct Case {
    Point hole;
    bool removes;
    const char* what;
  };
  const Case cases[] = {{{4, 3}, true, "inside a triangle"},  {{3, 3}, true, "on the unconstrained edge (4,4)-(2,2)"},
                        {{6, 2}, false, "on a ring vertex"},  {{4, 4}, false, "on the free vertex"},
                        {{5, 4}, false, "on a ring segment"}, {{8, 0}, false, "on the outer boundary"}};
  std::size_t removing = 0, keeping = 0;
  for (const Case& c : cases) {
    Pslg p;
    p.vertices = box;
    p.vertices.insert(p.vertices.end(), {{2, 2}, {6, 2}, {4, 6}, {4, 4}});
    p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}, {4, 5, 2}, {5, 6, 2}, {6, 4, 2}};
    p.holes = {c.hole};
    p.source = c.what;
    std::vector<std::string> warnings;
    const Pslg v = validated(p, &warnings);
    EXPECT_EQ(warnings.size(), c.removes ? 0u : 1u) << c.what;
    const Mesh f = fast::build_cdt(v), r = reference::build_cdt(v);
    EXPECT_TRUE(same_mesh(f, r)) << c.what;
    const certify::Report report = certify::certify(v, f);
    EXPECT_TRUE(report.certified()) << c.what << "\n" << certify::format_report(report);
    // The ring's inside is the three triangles around the free vertex.
    std::size_t& count = c.removes ? removing : keeping;
    if (count == 0) count = f.triangles.size();
    EXPECT_EQ(f.triangles.size(), count) << c.what;
    RefineOptions o;
    o.min_angle_deg = 25;
    o.trace = true;
    both(v, o);
  }
  EXPECT_EQ(removing + 3, keeping);
}

// Ties in edge length are decided by ids (older vertices win): the same rhombus
// with its vertices numbered in each of the four rotations and the mirror gives
// different Lepps, and both engines make the same decision every time.
TEST(DegenerateFixed, EdgeLengthTiesDecidedByIds) {
  const std::vector<Point> ring{{-4, 0}, {0, -5}, {4, 0}, {0, 5}};
  std::vector<std::vector<int>> orders{{0, 1, 2, 3}, {1, 2, 3, 0}, {2, 3, 0, 1}, {3, 0, 1, 2}, {3, 2, 1, 0}};
  for (const auto& order : orders) {
    Pslg p;
    for (int i : order) p.vertices.push_back(ring[static_cast<std::size_t>(i)]);
    for (int i = 0; i < 4; ++i) p.segments.push_back({i, (i + 1) % 4, 1});
    p.vertices.push_back({0, 0});  // the centre: four congruent right triangles, every edge tied with a mirror image
    p.source = "rhombus";
    const Pslg v = validated(p);
    for (Method m : {Method::Centroid, Method::Midpoint}) {
      RefineOptions o;
      o.method = m;
      o.min_angle_deg = 30;
      o.max_area = 2;
      o.trace = true;
      const RefineResult r = both(v, o);
      EXPECT_GT(r.steiner_points, 0);
    }
  }
}

// Section 8 needs dot(u, w) > 0: an input angle near 180 degrees has a small sine
// too, but it is no wedge. Here the bottom side bends by 2 atan(1/4) (about 28
// degrees) at v = (0, 0), below theta = 30 as an angle, and the segment p-q closes
// the sliver p v q: the skinny triangle above p-q has its shortest edge p-q joining
// the two segments that meet at v. It is refined, never listed as unimprovable.
TEST(DegenerateFixed, AngleNearOneEightyIsNoSmallInputAngle) {
  Pslg p;
  p.vertices = {{-4, 1}, {0, 0}, {4, 1}, {4, 40}, {-4, 41}};  // p, v, q, and a slanted top (no cocircular rectangle)
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 4, 1}, {4, 0, 1}, {0, 2, 2}};
  p.source = "bend of 152 degrees";
  const Pslg v = validated(p);
  for (Method m : {Method::Centroid, Method::Midpoint}) {
    RefineOptions o;
    o.method = m;
    o.min_angle_deg = 30;
    o.max_steiner = 300;
    o.trace = true;
    const RefineResult r = both(v, o);
    EXPECT_GT(r.steiner_points, 0);
    for (const UnimprovableTriangle& u : r.unimprovable) EXPECT_NE(u.apex, 1) << to_string(m);
  }
}

// Several segment pairs qualify (ALGORITHM.md 8): the thin rhombus p v1 q v2 has
// both triangles' shortest edge p-q joining segments that meet at small angles at
// v1 and at v2. The smallest pair of segment ids is reported: (0, 1) at v1, for
// both triangles, the one at v2 too.
TEST(DegenerateFixed, SmallestQualifyingSegmentPairIsReported) {
  Pslg p;
  p.vertices = {{-1, 0}, {0, 16}, {1, 0}, {0, -16}};  // p, v1, q, v2
  p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}};
  p.source = "thin rhombus";
  const Pslg v = validated(p);
  RefineOptions o;
  o.min_angle_deg = 20;
  o.trace = true;
  const RefineResult r = both(v, o);
  EXPECT_EQ(r.outcome, Outcome::Unimprovable);
  ASSERT_EQ(r.unimprovable.size(), 2u);
  for (const UnimprovableTriangle& u : r.unimprovable) {
    EXPECT_EQ(u.segment1, 0);
    EXPECT_EQ(u.segment2, 1);
    EXPECT_EQ(u.apex, 1);
  }
}

// The edge floor (ALGORITHM.md 9) at its boundary: the rounded midpoint of
// A = (1, 0), B = (2^-60, 0) is (0.5, 0), so the half toward B is 2^-60 shorter
// than the half toward A, and a floor of exactly 0.5 is crossed by that half
// only. Both sides of the boundary edge (the triangle above it, then below it):
// the new point's star meets the short half from either direction.
TEST(DegenerateFixed, EdgeFloorSeesEitherHalfOfASplitBoundaryEdge) {
  for (double side : {1.0, -1.0}) {
    Pslg p;
    p.vertices = {{1, 0}, {std::ldexp(1.0, -60), 0}, {0.5, 0.6 * side}};
    p.segments = {{0, 1, 1}, {1, 2, 1}, {2, 0, 1}};
    p.source = "split at the floor";
    const Pslg v = validated(p);
    RefineOptions o;
    o.min_angle_deg = 20;
    o.max_area = 0.2;  // the triangle (area 0.3) is too big: its longest edge A-B is split first
    o.edge_floor = 0.5;
    o.trace = true;
    const RefineResult r = both(v, o);
    EXPECT_EQ(r.outcome, Outcome::EdgeFloor) << side;
    EXPECT_EQ(r.steiner_points, 1) << side;
  }
}

// Validation's decisions at their boundaries (the engines' input, ALGORITHM.md 1):
// a crossing is reported with its real partner even when an earlier segment only
// touches the crossing one (an orientation exactly zero), and a vertex given three
// times is merged into its first copy each time.
TEST(DegenerateValidate, CrossingNamesItsPartnerNotASegmentItOnlyTouches) {
  Pslg p;
  p.vertices = {{2, 2}, {5, 5}, {0, 0}, {4, 0}, {2, -2}};
  p.segments = {{0, 1, 0}, {2, 3, 0}, {4, 0, 0}};  // the third crosses the second and touches the first at (2, 2)
  std::vector<std::string> warnings;
  try {
    validate(p, warnings);
    FAIL() << "a crossing was accepted";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("segments 3 and 2 cross"), std::string::npos) << e.what();
  }
}

TEST(DegenerateValidate, ThirdCopyOfAVertexMergesIntoTheFirst) {
  Pslg p;
  p.vertices = {{0, 0}, {1, 0}, {0, 1}, {1, 0}, {1, 0}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  std::vector<std::string> warnings;
  const Pslg v = validate(p, warnings);
  EXPECT_EQ(v.vertices.size(), 3u);
  std::string all;
  for (const std::string& w : warnings) all += w + "\n";
  EXPECT_NE(all.find("vertex 4 duplicates vertex 2"), std::string::npos) << all;
  EXPECT_NE(all.find("vertex 5 duplicates vertex 2"), std::string::npos) << all;
}

}  // namespace
}  // namespace lepp
