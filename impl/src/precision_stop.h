// SPDX-License-Identifier: GPL-3.0-or-later
// The precision stop (ALGORITHM.md section 8b): can the chosen point, as
// rounded to doubles, be inserted where its insertion needs it? If not, the
// bad triangle is left (listed as unimprovable at double precision).
#pragma once
#include <algorithm>
#include <cfloat>
#include <cmath>

#include "lepp/refine.h"
#include "lepp_search.h"
#include "point_selection.h"
#include "predicates.h"
#include "sliver_obstacles.h"
#include "tri_mesh.h"

namespace lepp::fast {

// A constrained split of edge i of ti: every triangle the split makes, on
// each domain side of the edge, is counter-clockwise (the rounded midpoint
// may be half an ulp off the edge's line, or on an endpoint), and no new edge
// is below the precision floor (lepp::below_precision_floor: a few ulps).
// On the domain boundary with p strictly outside, the split also covers the
// closed sliver a, p, b: no vertex may be in it and no constrained edge meet
// it, the domain's own boundary included (the sliver clause: SliverObstacles,
// an index built the first time this branch is reached).
inline bool split_insertable(const TriMesh& m, int ti, int i, const Point& p, SliverObstacles& obstacles) {
  const FTri& f = m.t(ti);
  const Point &a = m.p(f.v(next3(i))), &b = m.p(f.v(prev3(i))), &c = m.p(f.v(i));
  if (orient(a, p, c) <= 0 || orient(p, b, c) <= 0) return false;
  if (below_precision_floor(p, a) || below_precision_floor(p, b) || below_precision_floor(p, c)) return false;
  if (f.nbr[i] < 0 && orient(a, b, p) < 0)
    return !obstacles.blocks(m, f.v(next3(i)), f.v(prev3(i)), p);
  if (f.nbr[i] < 0) return true;
  const FTri& g = m.t(nbr_tri(f.nbr[i]));
  const Point& d = m.p(g.v(nbr_edge(f.nbr[i])));
  return orient(b, p, d) > 0 && orient(p, a, d) > 0 && !below_precision_floor(p, d);
}

// p within the precision floor (a few ulps) of a vertex of the terminal pair.
inline bool near_pair_vertex(const TriMesh& m, const Lepp& lepp, const Point& p) {
  // below_precision_floor's quick answer once for the four vertices (t1's and t2's
  // apex): a difference of at least M * 2^-50, M the largest magnitude of all five
  // points, is at least 4 ulps of each pair's own largest magnitude (issue 40).
  if (lepp.t1 >= 0 && (lepp.t2 < 0 || lepp.e2 >= 0)) {
    const FTri& f = m.t(lepp.t1);
    const Point* v[4] = {&m.p(f.v(0)), &m.p(f.v(1)), &m.p(f.v(2)), nullptr};
    const int n = lepp.t2 >= 0 ? 4 : 3;
    if (n == 4) v[3] = &m.p(m.t(lepp.t2).v(lepp.e2));
    double big = std::max(std::fabs(p.x), std::fabs(p.y));
    for (int k = 0; k < n; ++k) big = std::max(big, std::max(std::fabs(v[k]->x), std::fabs(v[k]->y)));
    const double far = big * 0x1p-50;
    bool apart = far >= DBL_MIN;
    for (int k = 0; k < n; ++k) apart = apart && (std::fabs(p.x - v[k]->x) >= far || std::fabs(p.y - v[k]->y) >= far);
    if (apart) return false;
  }
  for (int t : {lepp.t1, lepp.t2}) {
    if (t < 0) continue;
    for (int i = 0; i < 3; ++i)
      if (below_precision_floor(p, m.p(m.t(t).v(i)))) return true;
  }
  return false;
}

// Where p lies in the closed triangle ti: 1 strictly inside, 2 on the interior
// of an unconstrained edge, 0 outside, -1 on a vertex or on a constrained edge.
// With `at`, where a point that can be inserted there lies (1 or 2).
inline int place_in(const TriMesh& m, int ti, const Point& p, Located* at = nullptr) {
  const FTri& f = m.t(ti);
  int o[3];
  for (int i = 0; i < 3; ++i) o[i] = orient(m.p(f.v(next3(i))), m.p(f.v(prev3(i))), p);
  if (o[0] < 0 || o[1] < 0 || o[2] < 0) return 0;
  const int zeros = (o[0] == 0) + (o[1] == 0) + (o[2] == 0);
  if (zeros == 0) {
    if (at) *at = Located{ti, -1};
    return 1;
  }
  if (zeros >= 2) return -1;
  const int e = o[0] == 0 ? 0 : o[1] == 0 ? 1 : 2;
  if (f.seg(e) >= 0 || f.nbr[e] < 0) return -1;
  if (at) *at = Located{ti, e};
  return 2;
}

// A point for a CDT insertion: in the closed terminal quad (t1, else t2),
// off its vertices and off constrained edges, and farther than the precision
// floor from the vertices of the pair. With `at`, where such a point lies (the
// insertion then need not locate it again); left as it was otherwise.
inline bool choice_insertable(const TriMesh& m, const Lepp& lepp, const Choice& c, SliverObstacles& obstacles,
                              Located* at = nullptr) {
  if (c.edge >= 0) return split_insertable(m, c.tri, c.edge, c.point, obstacles);
  if (near_pair_vertex(m, lepp, c.point)) return false;
  const int in_first = place_in(m, c.tri, c.point, at);
  if (in_first != 0 || c.other < 0) return in_first > 0;
  return place_in(m, c.other, c.point, at) > 0;
}

// When choice's point cannot be inserted: the doubles around the exact point
// (each coordinate rounded down and up), in ascending x then y, the first that
// can (and, for centroid-in-other, is still strictly inside the other triangle)
// replaces it. False when none can: the triangle is left.
bool round_otherwise(const TriMesh& m, const Lepp& lepp, Choice& c, SliverObstacles& obstacles);

// Remark 10 at the limit: when the branch's point cannot be inserted at any
// rounding, the other branch, if a double around the exact centroid turns the
// branch (a rounding outside the other triangle: the midpoint of l*, as
// rounded; else the roundings strictly inside it: the centroid there). The
// certifier counts both (CERTIFIER.md section 5c). False: neither can.
bool other_branch(TriMesh& m, const Lepp& lepp, Method method, Choice& c, SliverObstacles& obstacles);

// Both second-longest edges constrained (centroid rule 3; the midpoint method's
// rule 3 with both): when t1's midpoint cannot be inserted at any rounding,
// t2's, the formula's double then its other roundings. The paper allows either
// constrained edge; the certifier counts both (CERTIFIER.md section 5c). False:
// t2's cannot be inserted either (or the rule is another).
bool other_constrained_edge(TriMesh& m, const Lepp& lepp, Choice& c, SliverObstacles& obstacles);

// Select Point's choice c for this Lepp as the engine inserts it (section 8b, in
// this order): the formula's double, its other roundings, Remark 10's other branch,
// the other constrained second-longest edge. True iff one can be inserted (then c
// holds it; else c is unchanged).
// With `at`, where the formula's double lies when it is the one (else not known).
inline bool settle_choice(TriMesh& m, const Lepp& lepp, Method method, Choice& c, SliverObstacles& obstacles,
                          Located* at = nullptr) {
  if (at) *at = Located{};
  return choice_insertable(m, lepp, c, obstacles, at) || round_otherwise(m, lepp, c, obstacles) ||
         other_branch(m, lepp, method, c, obstacles) || other_constrained_edge(m, lepp, c, obstacles);
}

// The other resolutions of exact length ties (section 8b, "Every tie resolution"):
// when the edge order's Lepp of bad triangle t has no insertable choice, every Lepp
// of t and every second-longest edge under exact ties, depth first in the edge
// order, each settled as settle_choice says. True iff one can be inserted: lepp and
// c then hold it (lepp.m1, lepp.m2 its second-longest edges); else both unchanged.
// At most max_states Lepp states (RefineOptions::tie_search_states; 0: no bound).
// *cut (when given): when nothing is found, whether the bound left some state unseen.
bool other_tie_resolution(TriMesh& m, int t, Method method, std::size_t max_states, Lepp& lepp, Choice& c,
                          SliverObstacles& obstacles, bool* cut = nullptr);

}  // namespace lepp::fast
