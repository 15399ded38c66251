// SPDX-License-Identifier: GPL-3.0-or-later
// The other roundings of a chosen point (ALGORITHM.md section 8b): when the
// formula's double cannot be inserted, the doubles around the exact point are
// tried before the triangle is left. Cold: reached only at the precision limit.
#include <vector>

#include "lepp/rounding.h"
#include "precision_stop.h"

namespace lepp::fast {
namespace {

// The doubles around the exact centroid of the terminal quad (t1's terminal edge,
// both apexes), in ascending x, then ascending y.
std::vector<Point> centroid_roundings(const TriMesh& m, const Lepp& lepp) {
  const FTri& f1 = m.t(lepp.t1);
  const Point &a = m.p(f1.v(next3(lepp.e1))), &b = m.p(f1.v(prev3(lepp.e1)));
  const Point &p = m.p(f1.v(lepp.e1)), &q = m.p(m.t(lepp.t2).v(lepp.e2));
  std::vector<Point> out;
  for (double x : doubles_around_centroid(a.x, b.x, p.x, q.x))
    for (double y : doubles_around_centroid(a.y, b.y, p.y, q.y)) out.push_back({x, y});
  return out;
}

// The doubles around the exact midpoint of u, v, in the same order.
std::vector<Point> midpoint_roundings(const Point& u, const Point& v) {
  std::vector<Point> out;
  for (double x : doubles_around_midpoint(u.x, v.x))
    for (double y : doubles_around_midpoint(u.y, v.y)) out.push_back({x, y});
  return out;
}

}  // namespace

bool round_otherwise(const TriMesh& m, const Lepp& lepp, Choice& c, SliverObstacles& obstacles) {
  const FTri& f1 = m.t(lepp.t1);
  std::vector<Point> points;
  if (c.rule == Rule::QuadCentroid || c.rule == Rule::CentroidInOther) {
    points = centroid_roundings(m, lepp);
  } else if (c.edge < 0) {  // terminal-midpoint: the unconstrained terminal edge
    points = midpoint_roundings(m.p(f1.v(next3(lepp.e1))), m.p(f1.v(prev3(lepp.e1))));
  } else {  // the midpoint of the constrained edge it splits
    const FTri& f = m.t(c.tri);
    points = midpoint_roundings(m.p(f.v(next3(c.edge))), m.p(f.v(prev3(c.edge))));
  }
  for (const Point& p : points) {
    Choice alt = c;
    alt.point = p;
    if (alt.point == c.point) continue;
    if (c.rule == Rule::CentroidInOther && !strictly_inside(m, c.tri, alt.point)) continue;  // the branch's condition
    if (choice_insertable(m, lepp, alt, obstacles)) {
      c = alt;
      return true;
    }
  }
  return false;
}

bool other_branch(TriMesh& m, const Lepp& lepp, Method method, Choice& c, SliverObstacles& obstacles) {
  if (method != Method::Centroid || lepp.t2 < 0) return false;
  if (c.rule != Rule::CentroidInOther && c.rule != Rule::SecondLongestMidpoint) return false;
  const int l1 = second_longest(m, lepp, false), l2 = second_longest(m, lepp, true);
  const bool c1 = m.t(lepp.t1).seg(l1) >= 0, c2 = m.t(lepp.t2).seg(l2) >= 0;
  if (c1 == c2) return false;  // not Remark 10's branch
  const int star = c1 ? lepp.t1 : lepp.t2, other = c1 ? lepp.t2 : lepp.t1;
  const std::vector<Point> centroids = centroid_roundings(m, lepp);
  if (c.rule == Rule::CentroidInOther) {
    bool turns = false;
    for (const Point& g : centroids) turns = turns || !strictly_inside(m, other, g);
    if (!turns) return false;
    Choice mid = split_choice(m, star, c1 ? l1 : l2, Rule::SecondLongestMidpoint);
    if (!choice_insertable(m, lepp, mid, obstacles) && !round_otherwise(m, lepp, mid, obstacles)) return false;
    c = mid;
    return true;
  }
  Choice in_other;
  in_other.rule = Rule::CentroidInOther;
  in_other.tri = other;
  for (const Point& g : centroids) {
    in_other.point = g;
    if (strictly_inside(m, other, g) && choice_insertable(m, lepp, in_other, obstacles)) {
      c = in_other;
      return true;
    }
  }
  return false;
}

bool other_constrained_edge(TriMesh& m, const Lepp& lepp, Choice& c, SliverObstacles& obstacles) {
  if (lepp.t2 < 0 || c.tri != lepp.t1 || c.edge < 0) return false;
  if (c.rule != Rule::BothSecondLongestMidpoint && c.rule != Rule::SecondLongestMidpoint) return false;
  const int l1 = second_longest(m, lepp, false), l2 = second_longest(m, lepp, true);
  if (c.edge != l1 || m.t(lepp.t1).seg(l1) < 0 || m.t(lepp.t2).seg(l2) < 0) return false;  // not both constrained
  Choice mid = split_choice(m, lepp.t2, l2, c.rule);
  if (!choice_insertable(m, lepp, mid, obstacles) && !round_otherwise(m, lepp, mid, obstacles)) return false;
  c = mid;
  return true;
}

}  // namespace lepp::fast
