// SPDX-License-Identifier: GPL-3.0-or-later
// The certifier's decisions at their own boundaries (issue 22): duplicate mesh
// vertices in every arrangement of the sort, --split-crossings points matched
// where another mesher rounded the first crossing otherwise, the edge order's
// tie rule where it decides a terminal edge for Theorem 2, the small-input-angle
// exemption's disk at exactly its radius, and a cluster of small input angles
// across a notch. Each test names the mutant of tools/mutation/mutants.txt it
// kills (the condition removed or moved by one).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <set>

#include "cgal_mesh.h"
#include "lepp/stats.h"
#include "lepp/certify.h"
#include "lepp/input.h"
#include "lepp/io.h"
#include "lepp/validate.h"
#include "lepp/small_input_angles.h"
#include "test_pslgs.h"

namespace lepp {
namespace {

Pslg validated(Pslg p) {
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

Pslg polygon(const std::vector<Point>& pts) {
  Pslg p;
  p.vertices = pts;
  for (int i = 0; i < static_cast<int>(pts.size()); ++i) p.segments.push_back({i, (i + 1) % static_cast<int>(pts.size()), 0});
  return validated(p);
}

// ---- duplicate mesh vertices -------------------------------------------------
// The mesh of a 4 x 4 square with the Steiner points `extra` appended (the
// triangles do not matter for this check: only that the pair is reported).
certify::Report with_points(const std::vector<Point>& extra) {
  const Pslg sq = polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  Mesh m = test::cgal_cdt(sq);
  for (const Point& e : extra) m.vertices.push_back(e);
  return certify::certify(sq, m, {});
}

bool reports_pair(const certify::Report& r, int a, int b) {
  for (const certify::Violation& v : r.violations)
    if (v.reason == certify::Reason::DuplicateMeshVertex && v.vertices.size() == 2 &&
        std::min(v.vertices[0], v.vertices[1]) == a && std::max(v.vertices[0], v.vertices[1]) == b)
      return true;
  return false;
}

// Kills cert-duplicate-sort-by-x-only: a third vertex with the same x, numbered
// between the pair, keeps them apart when the sort looks at x alone.
TEST(CertifyBoundary, DuplicatesFoundWhateverSharesTheirXOrY) {
  // Mesh vertices 0-3 are the square's corners; the extras are 4, 5, 6, ...
  struct Arrangement {
    const char* what;
    std::vector<Point> extra;
    int a, b;
  };
  const std::vector<Arrangement> cases = {
      {"alone", {{1, 1}, {1, 1}}, 4, 5},
      {"a third vertex between them with the same x", {{1, 1}, {1, 2}, {1, 1}}, 4, 6},
      {"a third vertex with the same x, smaller y", {{1, 1}, {1, 0.5}, {1, 1}}, 4, 6},
      {"a third vertex between them with the same y", {{1, 1}, {2, 1}, {1, 1}}, 4, 6},
      {"several with the same x on both sides", {{1, 3}, {1, 1}, {1, 2}, {1, 0.5}, {1, 1}, {1, 2.5}}, 5, 8},
      {"the same x as a corner of the square", {{0, 1}, {0, 1}}, 4, 5},
  };
  for (const Arrangement& c : cases) {
    const certify::Report r = with_points(c.extra);
    EXPECT_TRUE(reports_pair(r, c.a, c.b)) << c.what << "\n" << certify::format_report(r);
    EXPECT_EQ(r.count(certify::Reason::DuplicateMeshVertex), 1u) << c.what;
  }
}

// Kills cert-duplicate-first-pair-skipped: the pair that sorts first (the smallest x of the mesh).
TEST(CertifyBoundary, DuplicateThatSortsFirstIsFound) {
  const Pslg sq = polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  Mesh m = test::cgal_cdt(sq);
  m.vertices.push_back({-1, 2});
  m.vertices.push_back({-1, 2});
  const certify::Report r = certify::certify(sq, m, {});
  EXPECT_TRUE(reports_pair(r, 4, 5)) << certify::format_report(r);
}

// Issue 20: Triangle keeps an input's exactly repeated vertex in its .node, unused,
// and its triangles use the other copy. Such a copy (of an input vertex, in no
// triangle) is merged with a warning, whichever copy comes first; a repeated
// Steiner point, or two copies both in triangles, stays a violation.
TEST(CertifyBoundary, UnusedDuplicateOfAnInputVertexIsMerged) {
  const Pslg sq = polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  Mesh m;  // as read from another mesher's files: no vertex promised to be an input vertex
  m.vertices = sq.vertices;
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  ASSERT_TRUE(certify::certify(sq, m, {}).certified());
  for (bool first : {true, false}) {
    // The copy in no triangle before the used one (Triangle's order), or after it.
    Mesh d = m;
    d.vertices.push_back(d.vertices[1]);
    if (first) d.triangles[0] = {0, 4, 2};
    const certify::Report r = certify::certify(sq, d, {});
    EXPECT_TRUE(r.certified()) << (first ? "unused copy first" : "unused copy last") << "\n" << certify::format_report(r);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].find(first ? "mesh vertex 1 duplicates mesh vertex 4 (4, 0)" : "mesh vertex 4 duplicates mesh vertex 1 (4, 0)"),
              std::string::npos)
        << r.warnings[0];
  }
  // Both copies in triangles: two vertices at one point, not a merge.
  Mesh both = m;
  both.vertices.push_back(both.vertices[0]);
  both.triangles[0] = {4, 1, 2};
  const certify::Report r2 = certify::certify(sq, both, {});
  EXPECT_TRUE(reports_pair(r2, 0, 4)) << certify::format_report(r2);
  EXPECT_TRUE(r2.warnings.empty());
  // A repeated point that is no input vertex, in no triangle: still a violation.
  Mesh steiner = m;
  steiner.vertices.push_back({1, 1});
  steiner.vertices.push_back({1, 1});
  const certify::Report r3 = certify::certify(sq, steiner, {});
  EXPECT_TRUE(reports_pair(r3, 4, 5)) << certify::format_report(r3);
  EXPECT_TRUE(r3.warnings.empty());
}

// Three copies of an input vertex, two of them in triangles: two duplicate pairs, and
// the input vertex is present (a copy in triangles stands for it), wherever the unused
// copy comes. Kills cert-input-table-unused-copy-first (unused first) and
// cert-input-table-last-vertex (unused last).
TEST(CertifyBoundary, AnInputVertexInTrianglesIsPresentBesideItsUnusedCopy) {
  const Pslg sq = polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  for (const int unused : {0, 4, 5}) {  // which of the three copies of (0, 0) no triangle uses
    Mesh m;  // as read from files: input vertices found by their coordinates
    m.vertices = sq.vertices;
    m.vertices.push_back({0, 0});
    m.vertices.push_back({0, 0});
    std::vector<int> used;
    for (const int c : {0, 4, 5})
      if (c != unused) used.push_back(c);
    m.triangles = {{used[0], 1, 2}, {used[1], 2, 3}};
    const certify::Report r = certify::certify(sq, m, {});
    EXPECT_EQ(r.count(certify::Reason::DuplicateMeshVertex), 2u) << "unused copy " << unused << "\n" << certify::format_report(r);
    EXPECT_EQ(r.count(certify::Reason::InputVertexMissing), 0u) << "unused copy " << unused << "\n" << certify::format_report(r);
  }
}

// ---- --split-crossings ------------------------------------------------------
Pslg crossing_pslg() { return test::crossing_split(LEPP_SOURCE_DIR); }
using test::as_read;

// Kills cert-crossing-first-not-matched: the FIRST crossing vertex (the
// boundary of `i + crossing_vertices >= n`), rounded an ulp away by another mesher.
TEST(CertifyBoundary, FirstCrossingRoundedOtherwiseCertifies) {
  const Pslg p = crossing_pslg();
  ASSERT_GE(p.crossing_vertices, 2u);
  const std::size_t first = p.vertices.size() - p.crossing_vertices;
  for (std::size_t x : {first, first + 1, p.vertices.size() - 1}) {
    Mesh m = as_read(test::cgal_cdt(p));
    m.vertices[x].y = std::nextafter(m.vertices[x].y, -HUGE_VAL);
    const certify::Report r = certify::certify(p, m, {});
    EXPECT_TRUE(r.certified()) << "crossing vertex " << x << "\n" << certify::format_report(r);
  }
  // One place before the first crossing is an input vertex of the file: moved, it is not matched.
  Mesh m = as_read(test::cgal_cdt(p));
  m.vertices[first - 1].y = std::nextafter(m.vertices[first - 1].y, -HUGE_VAL);
  EXPECT_FALSE(certify::certify(p, m, {}).certified());
}

// Kills cert-crossing-missing-not-reported: the first crossing, rounded
// otherwise and left out of every triangle, is an input vertex missing.
TEST(CertifyBoundary, RoundedCrossingInNoTriangleIsMissing) {
  const Pslg p = crossing_pslg();
  const std::size_t x = p.vertices.size() - p.crossing_vertices;
  Mesh m = as_read(test::cgal_cdt(p));
  m.vertices[x].x = std::nextafter(m.vertices[x].x, HUGE_VAL);
  m.triangles.erase(std::remove_if(m.triangles.begin(), m.triangles.end(),
                                   [&](const Tri& t) { return std::find(t.begin(), t.end(), static_cast<int>(x)) != t.end(); }),
                    m.triangles.end());
  m.constrained_edges.clear();
  const certify::Report r = certify::certify(p, m, {});
  EXPECT_TRUE(r.has(certify::Reason::InputVertexMissing)) << certify::format_report(r);
}

// ---- the edge order's tie rule, where it decides Theorem 2 -----------------
// v=0 (0,0), a=1 (10,0), b=2 (8,6): |va| = |vb| = 10, a tie with the same
// smaller id (0); the order's third key (-max id) makes v-a the longest edge
// of triangle vab. Across v-a, c=3 (5,-1) makes v-a the longest edge of vca
// too, with a 157-degree angle at c: a terminal pair over 120 degrees. Across
// v-b, d=4 (-6,8): b-d is vbd's longest edge, so v-b is no terminal edge. With
// the tie broken for the larger max id (mutant cert-edge-tie-second-key) v-b
// would be vab's longest edge and no terminal pair would exist.
TEST(CertifyBoundary, EdgeOrderTieDecidesTheTerminalEdge) {
  Pslg p;
  p.vertices = {{0, 0}, {10, 0}, {8, 6}, {5, -1}, {-6, 8}};
  p.segments = {{3, 1, 0}, {1, 2, 0}, {2, 4, 0}, {4, 0, 0}, {0, 3, 0}};
  p = validated(p);
  Mesh m;
  m.vertices = p.vertices;
  m.input_vertices = 5;
  m.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 4}};
  certify::Options o;
  o.theorem2 = true;
  const certify::Report r = certify::certify(p, m, o);
  EXPECT_EQ(r.count(certify::Reason::TerminalAngleOver120), 1u) << certify::format_report(r);
  EXPECT_EQ(r.stats.terminal_pairs_checked, 1u);
  // The same triangles with a and b renumbered (b older than a): now v-b is the
  // longest edge of vab, its neighbour vbd does not agree, and no pair is terminal.
  Pslg q;
  q.vertices = {{0, 0}, {8, 6}, {10, 0}, {5, -1}, {-6, 8}};
  q.segments = {{3, 2, 0}, {2, 1, 0}, {1, 4, 0}, {4, 0, 0}, {0, 3, 0}};
  q = validated(q);
  Mesh n;
  n.vertices = q.vertices;
  n.input_vertices = 5;
  n.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 1, 4}};
  const certify::Report s = certify::certify(q, n, o);
  EXPECT_EQ(s.count(certify::Reason::TerminalAngleOver120), 0u) << certify::format_report(s);
  EXPECT_EQ(s.stats.terminal_pairs_checked, 0u);
}

// ---- the exemption's disk at exactly its radius ------------------------------
// A 36.87-degree input angle at V=(0,0) between E1=(65,0) and E2=(56,42) (the
// other two angles 77.9 and 65.2 degrees: no other small angle). The disk's
// radius is 65 (the shorter segment). X=(56,33) is at exactly 65 from V
// (56^2 + 33^2 = 4225), inside the triangle; q=(55,33) is inside the disk;
// both are input vertices off the arms, so only the disk rule can exempt the
// CDT's skinny triangles on the short edge X-q (kills cert-exempt-disk-open).
// With X's y one ulp larger (just outside the disk) the same triangles are not exempt.
std::vector<int> triangles_with(const Mesh& m, int a, int b) {
  std::vector<int> out;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const Tri& x = m.triangles[t];
    if (std::find(x.begin(), x.end(), a) != x.end() && std::find(x.begin(), x.end(), b) != x.end()) out.push_back(static_cast<int>(t));
  }
  return out;
}

certify::Report exemption_run(const Point& x, Mesh& mesh) {
  Pslg p;
  p.vertices = {{0, 0}, {65, 0}, {56, 42}, x, {55, 33}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  p = validated(p);
  mesh = test::cgal_cdt(p);
  certify::Options o;
  o.min_angle_deg = 30;
  o.exempt_small_input_angles = true;
  return certify::certify(p, mesh, o);
}

TEST(CertifyBoundary, ExemptionDiskIncludesItsRadius) {
  Mesh m;
  const certify::Report r = exemption_run({56, 33}, m);
  ASSERT_EQ(r.small_angles.size(), 1u);
  const std::vector<int> on_xq = triangles_with(m, 3, 4);
  ASSERT_FALSE(on_xq.empty());
  for (int t : on_xq) {
    const Tri& x = m.triangles[static_cast<std::size_t>(t)];
    ASSERT_LT(min_angle_deg(m.vertices[static_cast<std::size_t>(x[0])], m.vertices[static_cast<std::size_t>(x[1])],
                            m.vertices[static_cast<std::size_t>(x[2])]),
              30)
        << "the triangle must be below theta for the rule to matter";
    EXPECT_NE(std::find(r.exempt_triangles.begin(), r.exempt_triangles.end(), t), r.exempt_triangles.end())
        << "triangle " << t << " (shortest edge X-q, X exactly at the radius) must be exempt\n" << certify::format_report(r);
  }
}

TEST(CertifyBoundary, ExemptionDiskEndsAtItsRadius) {
  Mesh m;
  const certify::Report r = exemption_run({56, std::nextafter(33.0, 34.0)}, m);
  const std::vector<int> on_xq = triangles_with(m, 3, 4);
  ASSERT_FALSE(on_xq.empty());
  bool some_below = false;
  for (int t : on_xq) {
    const Tri& x = m.triangles[static_cast<std::size_t>(t)];
    if (min_angle_deg(m.vertices[static_cast<std::size_t>(x[0])], m.vertices[static_cast<std::size_t>(x[1])],
                      m.vertices[static_cast<std::size_t>(x[2])]) >= 30)
      continue;
    some_below = true;
    EXPECT_EQ(std::find(r.exempt_triangles.begin(), r.exempt_triangles.end(), t), r.exempt_triangles.end())
        << "triangle " << t << " has a vertex just outside the disk: not exempt\n" << certify::format_report(r);
  }
  EXPECT_TRUE(some_below);
  EXPECT_TRUE(r.has(certify::Reason::AngleBelowTheta));
}

// Two equal shortest edges: every shortest edge is tried (kills
// cert-exempt-shortest-strict, where a tie leaves none). Another mesher split
// the arm V-E1 at P=(10,0) and Q=(20,0) and put Y=(15,0.5) above: the flat
// triangle PQY has |PY| = |QY| (25.25 squared) and 5.7-degree angles at P and
// Q; P and Y are in the disk (radius 65), so it is exempt by the disk rule.
TEST(CertifyBoundary, ExemptionTriesEveryShortestEdgeOfATie) {
  Pslg p;
  p.vertices = {{0, 0}, {65, 0}, {56, 42}, {15, 0.5}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  p = validated(p);
  Pslg split = p;  // the same input with the arm split at P and Q: the other mesher's points
  split.vertices.push_back({10, 0});
  split.vertices.push_back({20, 0});
  split = validated(split);
  Mesh m = test::cgal_cdt(split);
  m.input_vertices = 0;  // as read: input vertices found by their coordinates, P and Q Steiner points
  m.constrained_edges.clear();
  int P = -1, Q = -1, Y = -1;
  for (std::size_t i = 0; i < m.vertices.size(); ++i) {
    if (m.vertices[i] == Point{10, 0}) P = static_cast<int>(i);
    if (m.vertices[i] == Point{20, 0}) Q = static_cast<int>(i);
    if (m.vertices[i] == Point{15, 0.5}) Y = static_cast<int>(i);
  }
  ASSERT_GE(std::min({P, Q, Y}), 0);
  int pqy = -1;
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    const Tri& x = m.triangles[t];
    if (std::find(x.begin(), x.end(), P) != x.end() && std::find(x.begin(), x.end(), Q) != x.end() &&
        std::find(x.begin(), x.end(), Y) != x.end())
      pqy = static_cast<int>(t);
  }
  ASSERT_GE(pqy, 0) << "the CDT has the flat triangle on the arm";
  certify::Options o;
  o.min_angle_deg = 30;
  o.exempt_small_input_angles = true;
  const certify::Report r = certify::certify(p, m, o);
  EXPECT_NE(std::find(r.exempt_triangles.begin(), r.exempt_triangles.end(), pqy), r.exempt_triangles.end())
      << certify::format_report(r);
}

// ---- a cluster of small input angles across a notch ---------------------------
// Four segments from V=(0,0) to (100,0), (100,27), (100,57), (100,90) (about 0,
// 15.1, 29.7 and 42 degrees). With a crack: the triangle V (100,0) (100,57)
// (its right side through (100,27)) with the segment V-(100,27) inside it:
// every pair of the three is a small input angle at V (15.1, 14.6 and 29.7
// degrees; the last spans two wedges; kills cert-small-angle-no-clusters and
// cert-small-angle-wrong-wedge); the corners are 90, 74.9, 105 and 60.3
// degrees: none small. With a notch: two triangles touching at V, V (100,0)
// (100,27) and V (100,57) (100,90); the wedge between 15.1 and 29.7 degrees
// is outside: at V only each triangle's own angle is small, no pair across
// the notch (kills cert-small-angle-wrong-wedge and cert-small-angle-outside-domain);
// the second triangle has a 48-degree corner at (100,90).
std::set<std::array<int, 3>> keys(const std::vector<certify::SmallInputAngle>& angles) {
  std::set<std::array<int, 3>> out;
  for (const certify::SmallInputAngle& a : angles) out.insert({a.apex, std::min(a.end1, a.end2), std::max(a.end1, a.end2)});
  return out;
}

TEST(CertifyBoundary, ClusterAcrossDomainWedges) {
  Pslg p;
  p.vertices = {{0, 0}, {100, 0}, {100, 27}, {100, 57}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}, {0, 2, 0}};
  const std::set<std::array<int, 3>> want = {{0, 1, 2}, {0, 2, 3}, {0, 1, 3}};
  EXPECT_EQ(keys(certify::small_input_angles(validated(p))), want);
}

TEST(CertifyBoundary, ClusterStopsAtANotch) {
  Pslg p;
  p.vertices = {{0, 0}, {100, 0}, {100, 27}, {100, 57}, {100, 90}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}, {0, 3, 0}, {3, 4, 0}, {4, 0, 0}};
  const std::set<std::array<int, 3>> want = {{0, 1, 2}, {0, 3, 4}, {4, 0, 3}};
  EXPECT_EQ(keys(certify::small_input_angles(validated(p))), want);
}

// Kills cert-small-angle-45: a 50-degree input angle is small (below 60), a 62-degree one is not.
TEST(CertifyBoundary, SixtyDegreesIsTheThreshold) {
  auto wedge = [](double deg) {
    const double r = deg * M_PI / 180;
    return polygon({{0, 0}, {10, 0}, {10 * std::cos(r), 10 * std::sin(r)}});
  };
  bool apex_small = false;
  for (const certify::SmallInputAngle& a : certify::small_input_angles(wedge(50))) apex_small = apex_small || a.apex == 0;
  EXPECT_TRUE(apex_small);
  for (const certify::SmallInputAngle& a : certify::small_input_angles(wedge(62))) EXPECT_NE(a.apex, 0);
}

}  // namespace
}  // namespace lepp
