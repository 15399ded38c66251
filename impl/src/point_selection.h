// SPDX-License-Identifier: GPL-3.0-or-later
// Select Point (midpoint method) and New Select Point (centroid method), as
// ALGORITHM.md section 5 fixes them, with its exact double formulas.
#pragma once
#include "edge_order.h"
#include "lepp/refine.h"
#include "lepp_search.h"
#include "predicates.h"
#include "tri_mesh.h"

namespace lepp::fast {

struct Choice {
  Rule rule = Rule::QuadCentroid;
  Point point;
  // Where to insert: split constrained edge `edge` of `tri`; or, when edge < 0,
  // the point lies in the closed triangle `tri` or else in `other` (the terminal pair).
  int tri = -1, edge = -1, other = -1;
};

// Where a point inside the terminal quad lies, as the precision stop's test found
// it (precision_stop.h): triangle `tri` (-1: not known, the insertion locates the
// point itself) and its edge there (-1: strictly inside).
struct Located {
  int tri = -1, edge = -1;
};

inline Point midpoint(const Point& a, const Point& b) { return {(a.x + b.x) * 0.5, (a.y + b.y) * 0.5}; }
inline Point centroid(const Point& a, const Point& b, const Point& c, const Point& d) {
  return {((a.x + b.x) + (c.x + d.x)) * 0.25, ((a.y + b.y) + (c.y + d.y)) * 0.25};
}

// c becomes the midpoint of edge i of triangle ti, as a constrained split.
inline void set_split(Choice& c, const TriMesh& m, int ti, int i, Rule rule) {
  const FTri& f = m.t(ti);
  c.rule = rule;
  c.point = midpoint(m.p(f.v(next3(i))), m.p(f.v(prev3(i))));
  c.tri = ti, c.edge = i, c.other = -1;
}
// Midpoint of edge i of triangle ti, as a constrained split.
inline Choice split_choice(const TriMesh& m, int ti, int i, Rule rule) {
  Choice c;
  set_split(c, m, ti, i, rule);
  return c;
}

inline bool strictly_inside(const TriMesh& m, int ti, const Point& p) {
  const FTri& f = m.t(ti);
  const Point &a = m.p(f.v(0)), &b = m.p(f.v(1)), &c = m.p(f.v(2));
  return orient(a, b, p) > 0 && orient(b, c, p) > 0 && orient(c, a, p) > 0;
}

// Every branch fills and returns the one object c, so that it is made in the
// caller's place (a copy of it read back in 16-byte parts what had just been
// stored in others: a stalled store forwarding, issue 40).
inline Choice select_point(TriMesh& m, const Lepp& lepp, Method method) {
  Choice c;
  if (lepp.t2 < 0) {
    set_split(c, m, lepp.t1, lepp.e1, Rule::TerminalConstrainedMidpoint);
    return c;
  }
  const FTri &f1 = m.t(lepp.t1), &f2 = m.t(lepp.t2);
  const int l1 = second_longest(m, lepp, false), l2 = second_longest(m, lepp, true);
  const bool c1 = f1.seg(l1) >= 0, c2 = f2.seg(l2) >= 0;
  const Point &a = m.p(f1.v(next3(lepp.e1))), &b = m.p(f1.v(prev3(lepp.e1)));
  if (method == Method::Midpoint) {
    if (c1 || c2) {
      set_split(c, m, c1 ? lepp.t1 : lepp.t2, c1 ? l1 : l2, Rule::SecondLongestMidpoint);
      return c;
    }
    c.rule = Rule::TerminalMidpoint;
    c.point = midpoint(a, b);
    c.tri = lepp.t1, c.other = lepp.t2;
    return c;
  }
  if (c1 && c2) {
    set_split(c, m, lepp.t1, l1, Rule::BothSecondLongestMidpoint);
    return c;
  }
  c.point = centroid(a, b, m.p(f1.v(lepp.e1)), m.p(f2.v(lepp.e2)));
  c.tri = lepp.t1, c.other = lepp.t2;
  if (!c1 && !c2) {
    c.rule = Rule::QuadCentroid;
    return c;
  }
  // Remark 10: exactly one second-longest edge constrained.
  const int star = c1 ? lepp.t1 : lepp.t2, other = c1 ? lepp.t2 : lepp.t1;
  if (strictly_inside(m, other, c.point)) {
    c.rule = Rule::CentroidInOther;
    c.tri = other, c.other = -1;
    return c;
  }
  set_split(c, m, star, c1 ? l1 : l2, Rule::SecondLongestMidpoint);
  return c;
}

}  // namespace lepp::fast
