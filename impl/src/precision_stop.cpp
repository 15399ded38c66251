// SPDX-License-Identifier: GPL-3.0-or-later
// The other roundings of a chosen point (ALGORITHM.md section 8b): when the
// formula's double cannot be inserted, the doubles around the exact point are
// tried before the triangle is left. Cold: reached only at the precision limit.
#include <gmpxx.h>

#include <cmath>
#include <vector>

#include "precision_stop.h"

namespace lepp::fast {
namespace {

// The doubles next to the exact value q, ascending (one when q is a double).
// GMP's get_d truncates toward zero; the other neighbour is one step away from zero.
std::vector<double> around(const mpq_class& q) {
  const double d = q.get_d();
  if (mpq_class(d) == q) return {d};
  const double e = std::nextafter(d, q > 0 ? HUGE_VAL : -HUGE_VAL);
  return d < e ? std::vector<double>{d, e} : std::vector<double>{e, d};
}

// The exact centroid of the terminal quad (t1's terminal edge, both apexes).
void exact_centroid(const TriMesh& m, const Lepp& lepp, mpq_class& x, mpq_class& y) {
  const FTri& f1 = m.t(lepp.t1);
  const Point &a = m.p(f1.v[next3(lepp.e1)]), &b = m.p(f1.v[prev3(lepp.e1)]);
  const Point &p = m.p(f1.v[lepp.e1]), &q = m.p(m.t(lepp.t2).v[lepp.e2]);
  x = (mpq_class(a.x) + mpq_class(b.x) + mpq_class(p.x) + mpq_class(q.x)) / 4;
  y = (mpq_class(a.y) + mpq_class(b.y) + mpq_class(p.y) + mpq_class(q.y)) / 4;
}

}  // namespace

bool round_otherwise(const TriMesh& m, const Lepp& lepp, Choice& c, SliverObstacles& obstacles) {
  mpq_class x, y;
  const FTri& f1 = m.t(lepp.t1);
  const Point &a = m.p(f1.v[next3(lepp.e1)]), &b = m.p(f1.v[prev3(lepp.e1)]);
  if (c.rule == Rule::QuadCentroid || c.rule == Rule::CentroidInOther) {
    exact_centroid(m, lepp, x, y);
  } else if (c.edge < 0) {  // terminal-midpoint: the unconstrained terminal edge
    x = (mpq_class(a.x) + mpq_class(b.x)) / 2, y = (mpq_class(a.y) + mpq_class(b.y)) / 2;
  } else {  // the midpoint of the constrained edge it splits
    const FTri& f = m.t(c.tri);
    const Point &u = m.p(f.v[next3(c.edge)]), &v = m.p(f.v[prev3(c.edge)]);
    x = (mpq_class(u.x) + mpq_class(v.x)) / 2, y = (mpq_class(u.y) + mpq_class(v.y)) / 2;
  }
  for (double px : around(x))
    for (double py : around(y)) {
      Choice alt = c;
      alt.point = {px, py};
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
  const int l1 = middle_edge(m, lepp.t1), l2 = middle_edge(m, lepp.t2);
  const bool c1 = m.t(lepp.t1).seg[l1] >= 0, c2 = m.t(lepp.t2).seg[l2] >= 0;
  if (c1 == c2) return false;  // not Remark 10's branch
  const int star = c1 ? lepp.t1 : lepp.t2, other = c1 ? lepp.t2 : lepp.t1;
  mpq_class x, y;
  exact_centroid(m, lepp, x, y);
  std::vector<Point> centroids;
  for (double px : around(x))
    for (double py : around(y)) centroids.push_back({px, py});
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
  const int l1 = middle_edge(m, lepp.t1), l2 = middle_edge(m, lepp.t2);
  if (c.edge != l1 || m.t(lepp.t1).seg[l1] < 0 || m.t(lepp.t2).seg[l2] < 0) return false;  // not both constrained
  Choice mid = split_choice(m, lepp.t2, l2, c.rule);
  if (!choice_insertable(m, lepp, mid, obstacles) && !round_otherwise(m, lepp, mid, obstacles)) return false;
  c = mid;
  return true;
}

}  // namespace lepp::fast
