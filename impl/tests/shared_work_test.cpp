// SPDX-License-Identifier: GPL-3.0-or-later
// The fast engine's shortcuts of issue 40, item 2 (work one step had done and the
// next did again), each against the long way it replaces, at its boundary: the
// edge floor from the squared lengths judge computed, the precision floor's quick
// answer taken once for the terminal pair, the insertion placed where the
// precision stop's test found the point, the second-longest edge from two
// lengths, and the output's buckets sorted by insertion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "edge_order.h"
#include "insertion.h"
#include "lepp/fast.h"
#include "lepp/mesh.h"
#include "lepp/angle.h"
#include "lepp_search.h"
#include "point_selection.h"
#include "precision_stop.h"
#include "quality.h"
#include "sliver_obstacles.h"
#include "tri_mesh.h"

namespace lepp::fast {
namespace {

// A mesh of the given points and counter-clockwise triangles (neighbours linked,
// every edge unconstrained; the domain boundary has no neighbour).
TriMesh mesh_of(const std::vector<Point>& pts, const std::vector<Tri>& tris) {
  TriMesh m;
  m.pts = pts;
  for (const Tri& t : tris) {
    const int v[3] = {t[0], t[1], t[2]}, n[3] = {-1, -1, -1};
    const std::int8_t s[3] = {-1, -1, -1};
    m.tris.emplace_back(v, n, s);
    m.stamp.push_back(0);
  }
  for (int ti = 0; ti < m.size(); ++ti)
    for (int i = 0; i < 3; ++i)
      for (int tj = 0; tj < m.size(); ++tj)
        for (int j = 0; j < 3; ++j)
          if (tj != ti && m.t(ti).v(next3(i)) == m.t(tj).v(prev3(j)) && m.t(ti).v(prev3(i)) == m.t(tj).v(next3(j)))
            m.t(ti).nbr[i] = nbr_code(tj, j);
  return m;
}

Pslg pslg_of(const std::vector<Point>& pts) {
  Pslg p;
  p.vertices = pts;
  return p;
}

// judge_made's floor test is sqlen_below of both spokes, and its verdict judge's:
// spokes exactly at the floor, a few ulps either side, one below and one above,
// at scales from 2^-500 to 2^500 (the floor test's filter undecided, then decided).
TEST(SharedWork, EdgeFloorFromJudgesLengthsIsSqlenBelowOfBothSpokes) {
  std::mt19937 rng(4002);
  int below = 0, undecided = 0, cases = 0, skinnies = 0, too_big = 0;
  for (int scale : {-500, -60, -1, 0, 7, 300, 500}) {
    const double unit = std::ldexp(1.0, scale);
    for (int round = 0; round < 400; ++round) {
      // Spoke lengths r1 (p to u) and r2 (p to w) near `floor`, in ulps of it.
      const double floor = unit * (1 + static_cast<double>(rng() % 1000) / 1000);
      auto near_floor = [&](int k) { return floor + k * std::ldexp(floor, -52); };
      const int k1 = static_cast<int>(rng() % 9) - 4, k2 = static_cast<int>(rng() % 9) - 4;
      double r1 = near_floor(k1), r2 = near_floor(k2);
      if (round % 4 == 1) r2 = 3 * floor;    // one spoke clearly above
      if (round % 4 == 2) r1 = floor / 3;    // one spoke clearly below
      if (round % 4 == 3) r1 *= 1 + 1e-9;    // just above, beyond the ulps
      const Point p{unit, -unit}, u{unit + r1, -unit}, w{unit, -unit + r2};
      const double twice_area = round % 2 ? 0 : floor * floor;  // sized and not
      const TriMesh base = mesh_of({p, u, w}, {{0, 1, 2}});
      const Pslg pslg = pslg_of({p, u, w});
      const SegmentMembership mem = make_membership(pslg);
      const Quality q(pslg, mem, engine_sin2_threshold(30), twice_area / 2);
      TriMesh a = base, b = base;
      const Quality::Verdict made = q.judge_made(a, 0, floor), plain = q.judge(b, 0);
      const bool expected = sqlen_below(p, u, floor) || sqlen_below(p, w, floor);
      EXPECT_EQ(made.below_floor, expected) << scale << " " << round << " " << k1 << " " << k2;
      EXPECT_EQ(made.skinny, plain.skinny);
      EXPECT_EQ(made.too_big, plain.too_big);
      // Both against the predicates themselves (the verdict travels as bits).
      const int sh = EdgeOrder(b, 0).rank().shortest;
      const bool skinny = skinny_at(b.p(b.t(0).v(sh)), b.p(b.t(0).v(next3(sh))), b.p(b.t(0).v(prev3(sh))), engine_sin2_threshold(30));
      EXPECT_EQ(plain.skinny, skinny) << scale << " " << round;
      EXPECT_EQ(plain.too_big, q.too_big(b, 0)) << scale << " " << round;
      skinnies += skinny, too_big += plain.too_big;
      EXPECT_EQ(a.t(0).longest(), b.t(0).longest());
      bool processed_below = !expected;
      EXPECT_EQ(q.processed_made(a, 0, floor, &processed_below), q.processed(b, 0));
      EXPECT_EQ(processed_below, expected);
      const double l = std::min(sqlen(p, u), sqlen(p, w)), f = floor * floor;
      undecided += detail::filtered_sign(f - l, f + l, 4) == 2;
      below += expected;
      ++cases;
    }
  }
  // Both answers, and the filter's undecided band (exact ties), were reached.
  EXPECT_GT(below, cases / 5);
  EXPECT_LT(below, cases - cases / 5);
  EXPECT_GT(undecided, 50);
  EXPECT_GT(skinnies, cases / 10);
  EXPECT_LT(skinnies, cases - cases / 10);
  EXPECT_GT(too_big, cases / 10);
  EXPECT_LT(too_big, cases / 2);
}

// near_pair_vertex's quick answer (one largest magnitude for the terminal pair's
// four vertices) is below_precision_floor of each of the pair's vertices: points
// a few ulps from a vertex, at 2^-50 of the largest magnitude and either side of
// it, and at scales where that is subnormal (the quick answer does not apply).
TEST(SharedWork, PrecisionFloorOnceForThePairIsEachVertexsOwn) {
  std::mt19937 rng(4003);
  int near = 0, cases = 0;
  for (int scale : {-1070, -1030, -1000, -20, 0, 1, 40, 1000}) {
    const double unit = std::ldexp(1.0, scale);
    // The kite a, b (the terminal edge), c above and d below: t1 = (a, b, c), t2 = (b, a, d).
    const Point a{0, 0}, b{4 * unit, 0}, c{2 * unit, unit}, d{2 * unit, -unit};
    const TriMesh m = mesh_of({a, b, c, d}, {{0, 1, 2}, {1, 0, 3}});
    Lepp lepp;
    lepp.t1 = 0, lepp.e1 = 2, lepp.t2 = 1, lepp.e2 = 2;
    for (int round = 0; round < 300; ++round) {
      const Point& v = m.p(static_cast<int>(rng() % 4));
      const double big = std::max(4 * unit, std::max(std::fabs(v.x), std::fabs(v.y)));
      // Offsets of k ulps of the vertex's scale, or about 2^-50 of the largest magnitude.
      const double ulp = std::max(std::ldexp(1.0, std::ilogb(big) - 52), std::numeric_limits<double>::denorm_min());
      const double step = round % 3 == 0 ? ulp : std::ldexp(big, -50);
      const double kx = static_cast<double>(rng() % 9) - 4, ky = static_cast<double>(rng() % 9) - 4;
      const double nudge = round % 3 == 2 ? 1 + (static_cast<double>(rng() % 3) - 1) * 0x1p-40 : 1;
      const Point pt{v.x + kx * step * nudge, v.y + ky * step};
      bool expected = false;
      for (int t : {0, 1})
        for (int i = 0; i < 3; ++i) expected = expected || below_precision_floor(pt, m.p(m.t(t).v(i)));
      EXPECT_EQ(near_pair_vertex(m, lepp, pt), expected) << scale << " " << round;
      near += expected;
      ++cases;
    }
  }
  EXPECT_GT(near, cases / 10);
  EXPECT_LT(near, cases - cases / 10);
}

// The insertion placed where choice_insertable found the point makes the same
// mesh as the insertion that locates it: the quad centroid strictly inside t1,
// strictly inside t2 (found in the other triangle), and on the terminal edge.
TEST(SharedWork, InsertionWhereTheTestFoundThePointIsTheLocatedOne) {
  std::mt19937 rng(4004);
  int on_edge = 0, in_first = 0, in_other = 0;
  for (int round = 0; round < 300; ++round) {
    // A convex quad around the terminal edge a b: c above, d below, at heights
    // that put the centroid above, below or on ab (equal heights).
    const double hc = 1 + static_cast<double>(rng() % 4) / 4, hd = round % 3 == 0 ? hc : 1 + static_cast<double>(rng() % 4) / 4;
    const double xc = 1.5 + static_cast<double>(rng() % 5) / 8, xd = 1.5 + static_cast<double>(rng() % 5) / 8;
    const std::vector<Point> pts = {{0, 0}, {4, 0}, {xc, hc}, {xd, -hd}, {2, 6}, {2, -6}};
    // t1 = (a, b, c), t2 = (b, a, d), and a triangle beyond each so that flips happen.
    const TriMesh base = mesh_of(pts, {{0, 1, 2}, {1, 0, 3}, {2, 1, 4}, {3, 0, 5}});
    TriMesh search = base;
    Lepp lepp;
    lepp_search(search, 0, lepp);
    ASSERT_EQ(lepp.t1, 0);
    ASSERT_EQ(lepp.t2, 1);
    const Choice choice = select_point(search, lepp, Method::Centroid);
    ASSERT_EQ(choice.rule, Rule::QuadCentroid);
    const Pslg pslg = pslg_of(pts);
    SegmentMembership mem_a = make_membership(pslg), mem_b = make_membership(pslg);
    SliverObstacles obstacles(pslg, mem_a);
    Located at;
    ASSERT_TRUE(choice_insertable(search, lepp, choice, obstacles, &at));
    ASSERT_GE(at.tri, 0);
    on_edge += at.edge >= 0;
    in_first += at.tri == 0 && at.edge < 0;
    in_other += at.tri == 1 && at.edge < 0;
    TriMesh with = search, without = search;
    Inserter ia, ib;
    int sa = -1, sb = -1;
    const int ra = ia.insert(with, mem_a, choice, sa, at), rb = ib.insert(without, mem_b, choice, sb);
    EXPECT_EQ(ra, rb);
    EXPECT_EQ(sa, sb);
    ASSERT_EQ(with.size(), without.size());
    for (int ti = 0; ti < with.size(); ++ti)
      for (int i = 0; i < 3; ++i) {
        EXPECT_EQ(with.t(ti).v(i), without.t(ti).v(i)) << round;
        EXPECT_EQ(with.t(ti).nbr[i], without.t(ti).nbr[i]) << round;
      }
    EXPECT_EQ(with.stamp, without.stamp);
  }
  EXPECT_GT(on_edge, 0);
  EXPECT_GT(in_first, 0);
  EXPECT_GT(in_other, 0);
}

// middle_edge (the two edges other than the longest compared alone) is the edge
// order's middle: triangles on a small integer grid, where exact length ties
// (isosceles triangles, decided by the vertex ids) are common, with shuffled ids.
TEST(SharedWork, MiddleEdgeFromTwoLengthsIsTheEdgeOrdersMiddle) {
  std::mt19937 rng(4005);
  int ties = 0;
  for (int round = 0; round < 3000; ++round) {
    std::vector<Point> pts(6);
    for (Point& q : pts) q = {static_cast<double>(rng() % 5), static_cast<double>(rng() % 5)};
    int a = static_cast<int>(rng() % 6), b = static_cast<int>(rng() % 6), c = static_cast<int>(rng() % 6);
    if (a == b || b == c || a == c || orient(pts[a], pts[b], pts[c]) == 0) continue;
    if (orient(pts[a], pts[b], pts[c]) < 0) std::swap(b, c);
    TriMesh m = mesh_of(pts, {{a, b, c}});
    const EdgeRank r = EdgeOrder(m, 0).rank();
    EXPECT_EQ(middle_edge(m, 0), r.middle) << round;
    const int i = next3(r.longest), j = prev3(r.longest);
    ties += EdgeOrder(m, 0).same_length(i, j);
  }
  EXPECT_GT(ties, 50);
}

// take_canonical_mesh's buckets (an insertion sort, std::sort past 16 triangles)
// give canonicalize's order: a refined mesh, and a fan whose centre, vertex 0, is
// the smallest id of all its 40 triangles (no Steiner point: the CDT itself).
TEST(SharedWork, CanonicalBucketsAreCanonicalizesOrder) {
  Pslg fan;
  fan.vertices.push_back({0, 0});
  const int n = 40;
  for (int k = 0; k < n; ++k) {
    const double t = 2 * M_PI * k / n;
    fan.vertices.push_back({std::cos(t), std::sin(t)});
    fan.segments.push_back({1 + k, 1 + (k + 1) % n});
  }
  for (double max_area : {0.0, 0.01}) {
    RefineOptions o;
    o.max_area = max_area;
    o.min_angle_deg = max_area > 0 ? 30 : 0;
    o.max_steiner = max_area > 0 ? -1 : 0;
    const RefineResult r = fast::refine(fan, o);
    Mesh again = r.mesh;
    std::reverse(again.triangles.begin(), again.triangles.end());
    canonicalize(again);
    EXPECT_EQ(again.triangles, r.mesh.triangles) << max_area;
    int at_centre = 0;
    for (const Tri& t : r.mesh.triangles) at_centre += t[0] == 0;
    if (max_area == 0) EXPECT_EQ(at_centre, n);
  }
}

}  // namespace
}  // namespace lepp::fast
