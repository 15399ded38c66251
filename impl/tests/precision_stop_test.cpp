// SPDX-License-Identifier: GPL-3.0-or-later
// The precision stop (docs/ALGORITHM.md section 8b, issue 20): on inputs at the
// limit of double precision both engines end with exit 0 or 3 (never an internal
// error), give the same mesh, and the mesh certifies: every triangle left below
// theta is one the certifier itself finds precision-limited.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "lepp/certify.h"
#include "lepp/fast.h"
#include "lepp/gen_precision.h"
#include "lepp/input.h"
#include "lepp/io.h"
#include "lepp/validate.h"
#include "lepp/reference.h"
#include "cdt_build.h"
#include "mesh_invariants.h"
#include "precision_stop.h"
#include "result_diff.h"

namespace lepp {
namespace {

using impl_test::difference;

const int fixed_seed = (setenv("RC_PARAMS", "seed=20261201 max_success=25", 0), 0);

const std::string kPrecision = LEPP_SOURCE_DIR "/corpus/regressions/precision/";

bool long_tests() {
  const char* v = std::getenv("LEPP_LONG_TESTS");
  return v && std::string(v) == "1";
}
// Every integer theta from 10 to 33 with LEPP_LONG_TESTS=1; six of them by default (ctest's time).
std::vector<int> thetas() {
  std::vector<int> t;
  for (int theta = 10; theta <= 33; ++theta) t.push_back(theta);
  if (!long_tests()) t = {10, 15, 20, 25, 30, 33};
  return t;
}

Pslg load(const std::string& file) {
  std::vector<std::string> warnings;
  return validate(read_input(kPrecision + file, warnings), DomainOptions{}, warnings);
}

// The certificate at theta, the engine's list held to the certifier's rules.
certify::Report certificate(const Pslg& pslg, const RefineResult& r, double theta, Method method, bool angles) {
  certify::Options o;
  o.min_angle_deg = angles ? theta : 0;
  o.unimprovable = r.unimprovable;
  o.precision_method = method;
  return certify::certify(pslg, r.mesh, o);
}

std::size_t at_precision(const RefineResult& r) {
  std::size_t n = 0;
  for (const UnimprovableTriangle& u : r.unimprovable) n += u.reason == LeftReason::DoublePrecision;
  return n;
}

// Both engines on one input at one theta: no exception, exit 0 or 3, the same run, certified.
// reference = false: the fast engine alone (the reference is exact and slow on 10^5 points).
void both_engines(const Pslg& pslg, double theta, Method method, const std::string& what, bool reference = true) {
  RefineOptions o;
  o.min_angle_deg = theta;
  o.method = method;
  RefineResult fast_run, reference_run;
  ASSERT_NO_THROW(fast_run = fast::refine(pslg, o)) << what;
  if (reference) {
    ASSERT_NO_THROW(reference_run = reference::refine(pslg, o)) << what;
    EXPECT_EQ(difference(fast_run, reference_run), "") << what;
  }
  const bool ended = fast_run.outcome == Outcome::Converged || fast_run.outcome == Outcome::Unimprovable;
  const certify::Report rep = certificate(pslg, fast_run, theta, method, ended);
  EXPECT_TRUE(rep.certified()) << what << ": " << to_string(fast_run.outcome) << "\n" << certify::format_report(rep);
  std::printf("[ outcome  ] %s: %s, %lld Steiner points, %lld precision stops, %zu left at double precision\n", what.c_str(),
              to_string(fast_run.outcome), static_cast<long long>(fast_run.steiner_points),
              static_cast<long long>(fast_run.precision_stops), at_precision(fast_run));
}

// Issue 20's first input: a cluster a few ulps apart near (0.5, 0.5) and points on
// the unit square's diagonal. Both engines stopped with exit 1 at 30 and 33 degrees.
TEST(PrecisionStop, UlpClusterEndsCleanlyFrom10To33Degrees) {
  const Pslg p = load("cluster34.node");
  for (int theta : thetas()) both_engines(p, theta, Method::Centroid, fmt::format("cluster34 at {}", theta));
  for (int theta : {20, 25}) both_engines(p, theta, Method::Midpoint, fmt::format("cluster34 midpoint at {}", theta));
}

// The cluster turned by half a turn (x -> -x, y -> -y: exact). The exact points
// the stop re-rounds now have negative coordinates, where GMP's truncation
// toward zero is the upper neighbour and the other one lies below: both
// engines still agree, the stop is reached, and the mesh certifies.
TEST(PrecisionStop, HalfTurnedClusterEndsCleanly) {
  Pslg p = load("cluster34.node");
  for (Point& q : p.vertices) q = {-q.x, -q.y};
  for (int theta : {30, 33}) both_engines(p, theta, Method::Centroid, fmt::format("cluster34 turned at {}", theta));
  RefineOptions o;
  o.min_angle_deg = 33;
  const RefineResult r = fast::refine(p, o);
  EXPECT_GT(r.precision_stops, 0);
  EXPECT_GT(at_precision(r), 0u);
}

// Issue 20's second input, shrunk: near-duplicates a few ulps apart far from the
// origin (as in Triangle's greenland.node). The full 30000-point set is behind
// LEPP_LONG_TESTS=1 (NearDuplicatesLong).
TEST(PrecisionStop, NearDuplicatesEndCleanlyFrom10To33Degrees) {
  for (const char* file : {"neardup-outside-quad.node", "neardup-on-vertex.node"}) {
    const Pslg p = load(file);
    for (int theta : thetas()) both_engines(p, theta, Method::Centroid, fmt::format("{} at {}", file, theta));
  }
}

// Shrunk from neardup30k.node at 30 degrees: a hull edge split again and again, its
// rounded midpoints a few ulps off the line, so the boundary turns a few ulps concave
// and the reference's faces outside the domain become slivers along it. A later
// split would invert one: the reference left the triangle where the fast engine,
// which keeps no outside faces, went on (ALGORITHM.md section 8b, "The faces outside the domain").
// Now the reference triangulates the outside anew around such a point.
TEST(PrecisionStop, BoundarySliverOutsideDoesNotStopTheReference) {
  const Pslg p = load("boundary-sliver.node");
  for (int theta : thetas()) both_engines(p, theta, Method::Centroid, fmt::format("boundary-sliver at {}", theta));
  for (int theta : {20, 25}) both_engines(p, theta, Method::Midpoint, fmt::format("boundary-sliver midpoint at {}", theta));
}

// The sliver clause's input (gen_precision.h), validated.
Pslg sliver_input(double dy) {
  std::vector<std::string> warnings;
  return validate(gen::sliverClauseInput(dy), warnings);
}

bool same_triangle(Tri x, Tri y) {
  std::sort(x.begin(), x.end());
  std::sort(y.begin(), y.end());
  return x == y;
}
bool has_triangle(const Mesh& m, Tri t) {
  return std::any_of(m.triangles.begin(), m.triangles.end(), [&](const Tri& x) { return same_triangle(x, t); });
}

// The vertex on AP: the split at P would cover it, so ABC is left at double precision
// (both engines, the mesh certifies: the certifier exempts the stop). Without the
// clause the fast engine split AB there and the engines parted.
TEST(PrecisionStop, SliverClauseVertexOnTheSliverLeavesTheTriangle) {
  const Pslg p = sliver_input(0);
  for (Method method : {Method::Centroid, Method::Midpoint}) {
    both_engines(p, 30, method, "sliver, vertex on AP");
    RefineOptions o;
    o.min_angle_deg = 30;
    o.method = method;
    const RefineResult r = fast::refine(p, o);
    EXPECT_TRUE(has_triangle(r.mesh, {0, 1, 2}));
    bool listed = false;
    for (const UnimprovableTriangle& t : r.unimprovable)
      if (t.reason == LeftReason::DoublePrecision && same_triangle(t.triangle, {0, 1, 2})) listed = true;
    EXPECT_TRUE(listed);
  }
}

// One ulp below AP the vertex is off the sliver: the split at P goes in.
TEST(PrecisionStop, SliverClauseVertexOneUlpOffAllowsTheSplit) {
  const double X = std::ldexp(1.0, 40), u = std::ldexp(1.0, -12);
  const Pslg p = sliver_input(-u);
  both_engines(p, 30, Method::Centroid, "sliver, vertex one ulp off");
  RefineOptions o;
  o.min_angle_deg = 30;
  const RefineResult r = fast::refine(p, o);
  EXPECT_FALSE(has_triangle(r.mesh, {0, 1, 2}));
  EXPECT_NE(std::find(r.mesh.vertices.begin(), r.mesh.vertices.end(), Point{X + 6 * u, X}), r.mesh.vertices.end());
}

// The clause's geometry (lepp/boundary_sliver.h) on a wide sliver a = (0, 0), p = (6, 0),
// b = (12, 1), with the fast engine's predicate: closed, vertices and segments both.
TEST(PrecisionStop, SliverClauseGeometryIsClosed) {
  const Point a{0, 0}, p{6, 0}, b{12, 1};
  auto blocked = [&](OutsideInput o) {
    return sliver_blocked(o, a, b, p, [](const Point& x, const Point& y, const Point& z) { return fast::orient(x, y, z); });
  };
  EXPECT_TRUE(blocked({{{2, 0}}, {}}));    // a vertex on ap
  EXPECT_TRUE(blocked({{{9, 0.5}}, {}}));  // on pb
  EXPECT_TRUE(blocked({{{6, 0.25}}, {}}));  // inside
  EXPECT_FALSE(blocked({{{2, -0x1p-50}}, {}}));  // just below ap
  EXPECT_FALSE(blocked({{a, b}, {}}));     // a and b themselves
  EXPECT_TRUE(blocked({{}, {{Point{3, -1}, Point{3, 1}}}}));     // crosses ap and ab
  EXPECT_TRUE(blocked({{}, {{Point{3, -1}, Point{3, 0}}}}));     // ends on ap
  EXPECT_FALSE(blocked({{}, {{Point{7, -1}, Point{7, 0.125}}}}));  // stops below pb (at x = 7 it is at 1/6)
  EXPECT_TRUE(blocked({{}, {{a, Point{3, 0.1}}}}));   // from a into the sliver
  EXPECT_TRUE(blocked({{}, {{Point{12, 0}, a}}}));    // from a along ap (closed)
  EXPECT_FALSE(blocked({{}, {{a, Point{3, -0.1}}}}));  // from a, below ap
  EXPECT_FALSE(blocked({{}, {{b, Point{20, 1}}}}));    // from b, away
  EXPECT_TRUE(blocked({{}, {{Point{6, 0.25}, b}}}));   // from b into the sliver
}

// Found by the precision campaign's second sitting (offset 2^39, centroid, 20 degrees;
// corpus/regressions/fuzz_refine/*-remark10-other-branch-*.bin): at Remark 10 the
// formula's centroid is strictly inside the other triangle, within the precision floor,
// as is every rounding inside it, but a double around the exact centroid lies outside
// that triangle: a mesher rounding so takes the midpoint of l*, which can be inserted
// (CERTIFIER.md section 5c). The engines left the triangle and the strict certifier
// rejected their claim; now they try that branch too (ALGORITHM.md section 8b).
TEST(PrecisionStop, Remark10OtherBranchIsTriedAtTheLimit) {
  for (const char* file : {"remark10-other-branch-corner.poly", "remark10-other-branch-hole.poly"}) {
    const Pslg p = load(file);
    both_engines(p, 20, Method::Centroid, fmt::format("{} at 20", file));
    RefineOptions o;
    o.min_angle_deg = 20;
    const RefineResult r = fast::refine(p, o);
    EXPECT_EQ(r.outcome, Outcome::Unimprovable) << file;  // still at the limit: the rule fires
    EXPECT_GT(at_precision(r), 0u) << file;
  }
}

// Found by the notch property (gen::ulpNotch at X = 2^52, ulp 1; offsets in ulps from
// (X, X); CERTIFIER.md section 5c, "Finding (lepp's rule: the other constrained edge)"):
// a terminal pair both of whose second-longest edges are constrained, t1's midpoint
// within the precision floor of t1's vertices at every rounding, t2's insertable. The
// engines tried t1's edge only, left t1, and the strict certifier rejected the claim (the
// reference's meshes from then, stored beside the inputs, still are:
// PrecisionExemption.NotchStopWithAnInsertableT2EdgeIsRejected). Now both engines split
// t2's edge there (ALGORITHM.md section 8b). Without other_constrained_edge in the two
// engines every run below failed its certificate and t1 was left (run 2026-12-02).
struct OtherEdgeCase {
  const char* file;
  double theta;
  Method method;
  bool pinned;                              // t1 and t2's midpoint below are this run's
  std::array<std::array<double, 2>, 3> t1;  // in ulps from (X, X)
  std::array<double, 2> t2_midpoint;        // the formula's double: insertable
};

TEST(PrecisionStop, OtherConstrainedSecondLongestEdgeIsTriedAtTheLimit) {
  const std::array<std::array<double, 2>, 3> notch_t1{{{58, -3}, {65, 2}, {58, 1}}};
  const std::vector<OtherEdgeCase> cases = {
      {"notch-exemption-t2-second-longest.poly", 30, Method::Centroid, true, notch_t1, {62, -3}},
      {"notch-exemption-t2-second-longest.poly", 33, Method::Centroid, false, notch_t1, {}},
      {"notch-exemption-t2-second-longest.poly", 35, Method::Centroid, false, notch_t1, {}},
      {"notch-exemption-t2-second-longest.poly", 30, Method::Midpoint, false, notch_t1, {}},
      {"notch-exemption-t2-second-longest.poly", 33, Method::Midpoint, false, notch_t1, {}},
      {"notch-exemption-t2-second-longest.poly", 35, Method::Midpoint, false, notch_t1, {}},
      {"notch-exemption-t2-second-longest-midpoint.poly", 35, Method::Midpoint, true, {{{27, 44}, {22, 36}, {27, 38}}},
       {22, 44}}};
  const double X = std::ldexp(1.0, 52);
  auto at = [&](const std::array<double, 2>& u) { return Point{X + u[0], X + u[1]}; };
  for (const OtherEdgeCase& c : cases) {
    const std::string what = fmt::format("{} at {}, {}", c.file, c.theta, to_string(c.method));
    const Pslg p = load(c.file);
    both_engines(p, c.theta, c.method, what);  // the same run, certified by the strict rule
    if (!c.pinned) continue;
    RefineOptions o;
    o.min_angle_deg = c.theta;
    o.method = c.method;
    const RefineResult r = fast::refine(p, o);
    const auto& v = r.mesh.vertices;
    EXPECT_NE(std::find(v.begin(), v.end(), at(c.t2_midpoint)), v.end()) << what << ": t2's midpoint not inserted";
    for (const UnimprovableTriangle& u : r.unimprovable) {
      int on_t1 = 0;
      for (int i : u.triangle)
        for (const auto& w : c.t1) on_t1 += v[static_cast<std::size_t>(i)] == at(w);
      EXPECT_LT(on_t1, 3) << what << ": t1 left (" << to_string(u.reason) << ")";
    }
  }
}

// Both engines at every theta of the notch property, both methods: the same run, the
// fast mesh has no two triangles overlapping (a check of its own, independent of the
// certifier's chain check), and it certifies.
void engines_agree_without_overlap(const Pslg& p, const std::string& what) {
  for (double theta : {20.0, 25.0, 30.0, 33.0, 35.0})
    for (Method method : {Method::Centroid, Method::Midpoint}) {
      RefineOptions o;
      o.min_angle_deg = theta;
      o.method = method;
      const std::string at = fmt::format("{} at {}, {}", what, theta, to_string(method));
      RefineResult fast_run, reference_run;
      ASSERT_NO_THROW(fast_run = fast::refine(p, o)) << at;
      ASSERT_NO_THROW(reference_run = reference::refine(p, o)) << at;
      EXPECT_EQ(difference(fast_run, reference_run), "") << at;
      EXPECT_EQ(impl_test::overlapping_triangles(fast_run.mesh), std::vector<std::string>{}) << at;
      const bool ended = fast_run.outcome == Outcome::Converged || fast_run.outcome == Outcome::Unimprovable;
      const certify::Report rep = certificate(p, fast_run, theta, method, ended);
      EXPECT_TRUE(rep.certified()) << at << "\n" << certify::format_report(rep);
    }
}

// Found by the notch property (gen::ulpNotch) before the fast engine's sliver clause
// saw the domain's own boundary: a rounded midpoint of a subsegment of A -> B landed
// across w -> A, the fast engine inserted it (overlapping triangles), the reference
// refused (corpus/regressions/precision/README.md).
TEST(PrecisionStop, NotchesAgreeWithoutOverlap) {
  for (const char* file : {"notch-2e20.poly", "notch-2e20-step.poly", "notch-2e52.poly", "notch-overlap.poly"})
    engines_agree_without_overlap(load(file), file);
}

// A notch at X = 2^52 (ulp 1, half that below X) in gen::ulpNotch's shape: A = (X, X),
// B = A + (11, 2), w = A + (wx, 2), the box around A as the generator's.
Pslg notch_at_2e52(int wx) {
  const double X = std::ldexp(1.0, 52);
  auto at = [&](int x, int y) { return Point{X + x, X + y}; };
  Pslg p;
  p.vertices = {at(0, 0), at(11, 2), at(11, 12), at(-4, 12), at(-4, -6), at(wx, -6), at(wx, 2)};
  for (int i = 0; i < 7; ++i) p.segments.push_back({i, (i + 1) % 7, 1});
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

// The clause at its boundary on the domain's own boundary: AB's midpoint A + (5.5, 1)
// rounds (to even) to P = A + (6, 1), just below AB. With wx = 12 the boundary segment
// w -> A runs through P, along the sliver's side AP (closed: blocked); with wx = 13 it
// leaves A one ulp (at w) below that side, outside the sliver (allowed). Removing the
// domain's segment chains from SliverObstacles::blocks (the outside input alone, as
// before) allowed both: the first expectation failed (run 2026-12-02).
TEST(PrecisionStop, SliverClauseSeesTheDomainsOwnBoundary) {
  const double X = std::ldexp(1.0, 52);
  const Point a{X, X}, b{X + 11, X + 2}, p{X + 6, X + 1};
  ASSERT_EQ((Point{(a.x + b.x) / 2, (a.y + b.y) / 2}), p);
  ASSERT_LT(fast::orient(a, b, p), 0);
  for (int wx : {12, 13}) {
    const Pslg pslg = notch_at_2e52(wx);
    const fast::SegmentMembership mem = fast::make_membership(pslg);
    const fast::TriMesh m = fast::build_initial_cdt(pslg, mem, 0, 0);
    fast::SliverObstacles obstacles(pslg, mem);
    EXPECT_EQ(obstacles.blocks(m, 0, 1, p), wx == 12) << "wx = " << wx;
    engines_agree_without_overlap(pslg, fmt::format("notch at 2^52, wx = {}", wx));
  }
}

// The chain edges at the ends of the triangle's range (sliver_obstacles.cpp): a chain of
// the input outside the domain whose one edge passes through the sliver a, p, b below the
// boundary edge ab, from a vertex inside the sliver's box (but outside the sliver) to one
// beyond the box's range along the chain: the edge leaving the range last, then the edge
// entering it first. Its vertices alone do not block; the edge does. A seeded bug that
// skipped the last edge leaving the range survived the whole ctest (issue 28).
TEST(PrecisionStop, SliverClauseSeesTheChainEdgesAtTheRangesEnds) {
  const Point p{6, -1};  // below ab = (0, 0) -> (12, 0): the sliver a, p, b
  struct Case {
    Point q, r;
    bool blocks;
    const char* what;
  };
  const Case cases[] = {
      {{2, -1}, {14, -0.2}, true, "the edge leaving the range (2, -1) -> (14, -0.2)"},
      {{-2, -0.2}, {10, -1}, true, "the edge entering the range (-2, -0.2) -> (10, -1)"},
      {{1, -1}, {14, -1.5}, false, "below p, leaving the range (1, -1) -> (14, -1.5)"},
      {{-2, -1.5}, {11, -1}, false, "below p, entering the range (-2, -1.5) -> (11, -1)"},
  };
  for (const Case& c : cases) {
    Pslg pslg;
    pslg.vertices = {{0, 0}, {12, 0}, {12, 10}, {0, 10}, c.q, c.r};
    pslg.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}, {4, 5, 0}};
    const fast::SegmentMembership mem = fast::make_membership(pslg);
    const fast::TriMesh m = fast::build_initial_cdt(pslg, mem, 0, 0);
    fast::SliverObstacles obstacles(pslg, mem);
    EXPECT_EQ(obstacles.blocks(m, 0, 1, p), c.blocks) << c.what;
    // The certifier's geometry says the same of the edge itself.
    const OutsideInput edge{{}, {{c.q, c.r}}};
    EXPECT_EQ(sliver_blocked(edge, pslg.vertices[0], pslg.vertices[1], p,
                             [](const Point& x, const Point& y, const Point& z) { return fast::orient(x, y, z); }),
              c.blocks)
        << c.what;
  }
}

// The clause's answers are remembered until a segment is split (sliver_obstacles.h):
// a chain of the input outside the domain, (4, -3) -> (14, -0.5), passes below the
// sliver a, p, b (at x = 12 it is at -1, below b), so the sliver is free (a deeper one
// on the same edge, through (6, -2.8), is not: each point its own answer); a Steiner
// vertex (7, -0.6) on that chain lies inside the sliver, and from that split on the
// same question is answered anew: blocked. A remembered answer kept across the split
// said free.
TEST(PrecisionStop, SliverClauseAnswersAgainAfterASplit) {
  const Point p{6, -1};
  Pslg pslg;
  pslg.vertices = {{0, 0}, {12, 0}, {12, 10}, {0, 10}, {4, -3}, {14, -0.5}};
  pslg.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}, {4, 5, 0}};
  const fast::SegmentMembership mem = fast::make_membership(pslg);
  fast::TriMesh m = fast::build_initial_cdt(pslg, mem, 0, 0);
  fast::SliverObstacles obstacles(pslg, mem);
  EXPECT_FALSE(obstacles.blocks(m, 0, 1, p));
  EXPECT_FALSE(obstacles.blocks(m, 0, 1, p));  // asked again: remembered, the same
  EXPECT_TRUE(obstacles.blocks(m, 0, 1, {6, -2.8}));  // a deeper sliver, on the same edge, meets the chain
  m.pts.push_back({7, -0.6});  // only its point: the clause reads no triangle
  const int v = static_cast<int>(m.pts.size()) - 1;
  const Point &a = pslg.vertices[0], &b = pslg.vertices[1];  // inside the sliver a, p, b (counter-clockwise)
  ASSERT_TRUE(fast::orient(a, p, m.pts.back()) > 0 && fast::orient(p, b, m.pts.back()) > 0 && fast::orient(b, a, m.pts.back()) > 0);
  obstacles.on_split(m, 4, v);
  EXPECT_TRUE(obstacles.blocks(m, 0, 1, p));
  fast::SliverObstacles fresh(pslg, mem);
  fresh.blocks(m, 0, 1, p);  // builds its index from the chains without v
  fresh.on_split(m, 4, v);
  EXPECT_TRUE(fresh.blocks(m, 0, 1, p));
}

// A midpoint rounded off its constrained edge's line, on the side away from a
// triangle whose circumcircle it lies outside: the usual split left the edge
// from it to that triangle's apex not locally Delaunay, in both engines (lepp
// 0.2 too; ALGORITHM.md section 6, "A split off its line"). Every order.
TEST(PrecisionStop, SplitOffItsLineKeepsTheTriangleBesideItsSliver) {
  const Pslg p = load("split-off-line-midpoint-2e40.poly");
  for (QueueOrder order : {QueueOrder::Fifo, QueueOrder::Lifo, QueueOrder::Flip, QueueOrder::Random, QueueOrder::SmallestAngle}) {
    RefineOptions o;
    o.min_angle_deg = 17.899999999999999;
    o.method = Method::Midpoint;
    o.order = order;
    const RefineResult f = fast::refine(p, o), r = reference::refine(p, o);
    EXPECT_EQ(difference(f, r), "") << to_string(order);
    const certify::Report rep = certificate(p, f, o.min_angle_deg, o.method, true);
    EXPECT_TRUE(rep.certified()) << to_string(order) << "\n" << certify::format_report(rep);
  }
}

TEST(PrecisionStop, NearDuplicatesLong) {
  if (!long_tests()) GTEST_SKIP() << "LEPP_LONG_TESTS=1 runs the 30000-point set";
  const Pslg p = load("neardup30k.node");
  for (int theta : thetas())
    both_engines(p, theta, Method::Centroid, fmt::format("neardup30k at {}", theta), theta == 20 || theta == 30);
}

// The rule can fire at all: on the cluster, some theta leaves triangles at double precision.
TEST(PrecisionStop, TheStopIsReached) {
  const Pslg p = load("cluster34.node");
  RefineOptions o;
  o.min_angle_deg = 33;
  const RefineResult r = fast::refine(p, o);
  EXPECT_GT(r.precision_stops, 0);
  EXPECT_GT(at_precision(r), 0u);
  EXPECT_EQ(r.outcome, Outcome::Unimprovable);
}

// The floor of a split is held against the far side's apex only in the domain
// (ALGORITHM.md section 8b; the fast engine keeps no outside faces): an input
// vertex D outside the domain, half an ulp below the bottom edge's midpoint, is
// within the floor of that midpoint, and the split goes ahead in both engines.
TEST(PrecisionStop, VertexOutsideTheDomainDoesNotHoldTheFloor) {
  Pslg raw;
  const Point d{0.5, -std::ldexp(1.0, -54)};
  raw.vertices = {{0, 0}, {1, 0}, {0.875, 0.25}, {0, 0.3125}, d};
  raw.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}};
  std::vector<std::string> warnings;
  const Pslg p = validate(raw, warnings);
  ASSERT_TRUE(below_precision_floor({0.5, 0}, d));
  both_engines(p, 30, Method::Centroid, "vertex outside at 30");
  for (bool fast_engine : {true, false}) {
    RefineOptions o;
    o.trace = true;
    const RefineResult r = fast_engine ? fast::refine(p, o) : reference::refine(p, o);
    EXPECT_EQ(r.outcome, Outcome::Converged) << (fast_engine ? "fast" : "reference");
    EXPECT_EQ(r.precision_stops, 0) << (fast_engine ? "fast" : "reference");
    bool split = false;
    for (const TraceStep& s : r.trace) split |= s.point.x == 0.5 && s.point.y == 0;
    EXPECT_TRUE(split) << (fast_engine ? "fast" : "reference") << ": the bottom edge was not split at its midpoint";
  }
}

// Found for the mutation harness (issue 22) by searching gen:ulp-segments inputs:
// the other roundings of a centroid-in-other point, where an earlier rounding has
// left the other triangle (beyond the terminal edge, or on an edge of the other),
// and of a constrained split whose rounded midpoint makes a flat triangle with its
// apex (by both methods). Both engines agree and the mesh certifies.
TEST(PrecisionStop, OtherRoundingsAtTinySegmentsAgree) {
  for (int theta : {20, 25, 30, 33}) {
    both_engines(load("ulp-segments-centroid-in-other.poly"), theta, Method::Centroid,
                 fmt::format("centroid-in-other at {}", theta));
    both_engines(load("ulp-segments-off-the-other.poly"), theta, Method::Centroid,
                 fmt::format("off the other at {}", theta));
    for (Method method : {Method::Centroid, Method::Midpoint})
      both_engines(load("ulp-segments-collinear-split.poly"), theta, method,
                   fmt::format("collinear split {} at {}", method == Method::Centroid ? "centroid" : "midpoint", theta));
  }
}

// ALGORITHM.md section 8b, "Every tie resolution": on each input a triangle whose
// Lepp in the edge order (ties by ids) ends at no insertable point, while another
// resolution of an exact length tie reaches one. Until 2026-12-03 both engines left
// it and the strict certificate rejected their claim (stored meshes of that version:
// properties/tests/certify_cli_test.sh). Now both take the other resolution, agree,
// and the mesh certifies by the strict rule.
// notch-second-longest-tie.poly (gen:ulp-notch, shrunk): a terminal triangle whose two
// other edges tie exactly, where only the other second-longest edge's choice can be
// inserted; a seeded bug that kept the edge order's second-longest edge in either
// engine's search survived every other test (mutants *-ties-second-first-only).
TEST(PrecisionStop, AnotherTieResolutionIsTriedAtTheLimit) {
  struct Case {
    const char* file;
    Method method;
    double theta;
  };
  for (const Case& c : {Case{"tie-finding.poly", Method::Centroid, 20}, Case{"tie-finding-subnormal-midpoint.poly", Method::Midpoint, 20},
                        Case{"notch-second-longest-tie.poly", Method::Centroid, 33}}) {
    const Pslg p = load(c.file);
    RefineOptions o;
    o.min_angle_deg = c.theta;
    o.method = c.method;
    const RefineResult r = fast::refine(p, o);
    EXPECT_EQ(difference(r, reference::refine(p, o)), "") << c.file;
    EXPECT_GT(r.tie_resolutions, 0) << c.file << ": no insertion through another tie resolution";
    const certify::Report rep = certificate(p, r, c.theta, c.method, true);
    EXPECT_TRUE(rep.certified()) << c.file << "\n" << certify::format_report(rep);
  }
}

// Points a few ulps apart on one line (make_on_edge_ulps.py 7: the unit square, its
// diagonals, a grid of ulps at (0.5, 0.5)), the kind of input CDT libraries test
// "points on an edge" with. Before issue 28 both engines left triangles there that
// another tie resolution refines (centroid at 20, midpoint at 10 to 20 degrees: the
// strict certificate rejected them); now every run certifies strictly, fast == reference.
TEST(PrecisionStop, PointsUlpsApartOnAnEdgeCertifyStrictly) {
  const Pslg p = load("on-edge-ulps.poly");
  for (int theta : {10, 15, 20, 25, 30}) both_engines(p, theta, Method::Centroid, fmt::format("on-edge-ulps at {}", theta));
  for (int theta : {10, 15, 20, 22}) both_engines(p, theta, Method::Midpoint, fmt::format("on-edge-ulps midpoint at {}", theta));
}

// fuzz_refine's input of issue 28 (a polygon with copies of (0, 0) a few ulps apart,
// grid step 2^-10): at 20 degrees the reference took 119 s (the fast engine 1 s, the
// same mesh), most of it exact length comparisons in lazy Epeck that its interval
// filters could not decide, and the fuzzers timed out in their band. Now a few seconds
// (docs/BENCHMARKS.md, "The reference on ulp clusters"); the same mesh, certified.
TEST(PrecisionStop, ReferenceSlowClusterAgreesAt20Degrees) {
  both_engines(load("reference-slow-cluster.poly"), 20, Method::Centroid, "reference-slow-cluster at 20");
}

// One generated input at the limit of doubles (properties/gen gen_precision.h):
// the run of either engine ends (no exception), both agree, the mesh certifies.
void generated_case(const Pslg& raw, double theta, Method method) {
  std::vector<std::string> warnings;
  Pslg p;
  try {
    p = validate(raw, warnings);
  } catch (const InputError&) {
    RC_DISCARD("not a valid PSLG");
  }
  RefineOptions o;
  o.min_angle_deg = theta;
  o.method = method;
  o.max_steiner = 1500;  // a bound on the test's time; a budget stop is still certified (without angles)
  RefineResult fast_run, reference_run;
  try {
    fast_run = fast::refine(p, o);
    reference_run = reference::refine(p, o);
  } catch (const std::exception& e) {
    RC_FAIL(fmt::format("{} at theta {}: internal error: {}", raw.source, theta, e.what()));
  }
  auto vertices = [&] {
    std::string points;
    for (const Point& v : p.vertices) points += fmt::format(" ({:.17g}, {:.17g})", v.x, v.y);
    return points;
  };
  if (const std::string d = difference(fast_run, reference_run); !d.empty())
    RC_FAIL(fmt::format("{} at theta {}, {}: the engines differ: {}; vertices{}", raw.source, theta, to_string(method), d, vertices()));
  const bool ended = fast_run.outcome == Outcome::Converged || fast_run.outcome == Outcome::Unimprovable;
  const certify::Report rep = certificate(p, fast_run, theta, method, ended);
  // Strict (docs/CERTIFIER.md section 5c): every resolution of exact length ties counts,
  // and the engines try them all before leaving a triangle (ALGORITHM.md section 8b).
  if (!rep.certified())
    RC_FAIL(fmt::format("{} at theta {}, {}: {} not certified; vertices{}\n{}", raw.source, theta, to_string(method),
                        to_string(fast_run.outcome), vertices(), certify::format_report(rep)));
  RC_CLASSIFY(fast_run.tie_resolutions > 0, "refined through another tie resolution");
  RC_CLASSIFY(at_precision(fast_run) > 0, "left at double precision");
  RC_CLASSIFY(ended, "converged or unimprovable");
}

// The generated families: clusters a few ulps wide and near-duplicates.
RC_GTEST_PROP(PrecisionStop, GeneratedClustersAndNearDuplicatesEndCleanly, ()) {
  const Pslg raw = *gen::atPrecisionLimit();
  const double theta = *rc::gen::element(20.0, 25.0, 30.0, 33.0);
  generated_case(raw, theta, Method::Centroid);
}

// Clusters with segments a few ulps long, by both methods: constrained edges at the
// precision floor, where the stop decides splits of a second-longest edge and
// centroid-in-other points (and their other roundings).
RC_GTEST_PROP(PrecisionStop, GeneratedClustersWithSegmentsEndCleanly, ()) {
  const Pslg raw = *gen::ulpClusterWithSegments();
  const double theta = *rc::gen::element(20.0, 25.0, 30.0, 33.0);
  const Method method = *rc::gen::element(Method::Centroid, Method::Midpoint);
  generated_case(raw, theta, method);
}

// Notches thinner than an ulp (gen::ulpNotch): a rounded midpoint of one boundary
// segment at the wedge can land across the other, so the sliver clause must see the
// domain's own boundary (docs/ALGORITHM.md section 8b), as the reference does. Before
// the fast engine did, this failed after 6 runs here (the engines differ). At other
// seeds about 1 run in 120 was rejected by the certifier with fast == reference until
// the engines tried the other constrained second-longest edge (ALGORITHM.md section
// 8b): RC_PARAMS="max_success=300 seed=1" up to seed=5 all met it then, all pass now.
RC_GTEST_PROP(PrecisionStop, GeneratedNotchesEndCleanly, ()) {
  const Pslg raw = *gen::ulpNotch();
  const double theta = *rc::gen::element(20.0, 25.0, 30.0, 33.0, 35.0);
  const Method method = *rc::gen::element(Method::Centroid, Method::Midpoint);
  generated_case(raw, theta, method);
}

}  // namespace
}  // namespace lepp
