// SPDX-License-Identifier: GPL-3.0-or-later
// Point selection (ALGORITHM.md Section 5: the paper's Select Point and New
// Select Point with Remark 10) and insertion (Section 6).
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "triangulation.h"

namespace lepp::reference::detail {

namespace {

// The fixed IEEE formulas both engines use (no FMA: -ffp-contract=off).
Point midpoint(VH a, VH b) {
  const CPoint &p = a->point(), &q = b->point();
  double ax = CGAL::to_double(p.x()), ay = CGAL::to_double(p.y());
  double bx = CGAL::to_double(q.x()), by = CGAL::to_double(q.y());
  return {(ax + bx) * 0.5, (ay + by) * 0.5};
}
Point centroid(VH a, VH b, VH c, VH d) {
  auto x = [](VH v) { return CGAL::to_double(v->point().x()); };
  auto y = [](VH v) { return CGAL::to_double(v->point().y()); };
  return {((x(a) + x(b)) + (x(c) + x(d))) * 0.25, ((y(a) + y(b)) + (y(c) + y(d))) * 0.25};
}

Selection edge_midpoint(Rule rule, FH f, int i) {
  Selection s;
  s.rule = rule;
  s.point = midpoint(f->vertex(Cdt::ccw(i)), f->vertex(Cdt::cw(i)));
  if (f->is_constrained(i)) s.split_face = f, s.split_index = i;
  return s;
}

bool strictly_inside(FH f, const Point& p) {
  CPoint q(p.x, p.y);
  for (int i = 0; i < 3; ++i)
    if (CGAL::orientation(f->vertex(Cdt::ccw(i))->point(), f->vertex(Cdt::cw(i))->point(), q) != CGAL::LEFT_TURN) return false;
  return true;
}

}  // namespace

Selection select_point(const Lepp& lepp, Method method) {
  FH t1 = lepp.t1, t2 = lepp.t2;
  int l = lepp.edge;
  if (t2 == FH()) return edge_midpoint(Rule::TerminalConstrainedMidpoint, t1, l);

  int s1 = second_longest_edge(t1), s2 = second_longest_edge(t2);
  bool c1 = t1->is_constrained(s1), c2 = t2->is_constrained(s2);

  if (method == Method::Midpoint) {
    if (!c1 && !c2) return edge_midpoint(Rule::TerminalMidpoint, t1, l);
    return c1 ? edge_midpoint(Rule::SecondLongestMidpoint, t1, s1) : edge_midpoint(Rule::SecondLongestMidpoint, t2, s2);
  }

  // Centroid method. A, B: the terminal edge; C, D: the apexes of t1, t2.
  VH a = t1->vertex(Cdt::ccw(l)), b = t1->vertex(Cdt::cw(l)), c = t1->vertex(l);
  VH d = t2->vertex(t2->index(t1));
  if (!c1 && !c2) {
    Selection s;
    s.rule = Rule::QuadCentroid;
    s.point = centroid(a, b, c, d);
    return s;
  }
  if (c1 && c2) return edge_midpoint(Rule::BothSecondLongestMidpoint, t1, s1);
  // Exactly one, t*, has a constrained second-longest edge; o is the other.
  FH star = c1 ? t1 : t2, other = c1 ? t2 : t1;
  int star_edge = c1 ? s1 : s2;
  Point g = centroid(a, b, c, d);
  if (strictly_inside(other, g)) {
    Selection s;
    s.rule = Rule::CentroidInOther;
    s.point = g;
    return s;
  }
  return edge_midpoint(Rule::SecondLongestMidpoint, star, star_edge);
}

namespace {

// The faces around a new vertex v (made by the insertion, flags unset) are
// all in the domain, except for a split constrained edge ab: counter-clockwise
// around v from the edge v->b (the direction a->b) to v->a lies the left side
// of ab, then the right side. Flips never cross a constrained edge and reuse
// both faces on one side, so the flags set here stay right through them.
// The regions likewise: every new face takes the region of the face it was cut
// from (left, right: the two sides of a split constrained edge).
void set_domain_flags(Triangulation& tr, VH v, VH a, VH b, FaceInfo left, FaceInfo right) {
  Cdt::Face_circulator fc = tr.cdt.incident_faces(v), done = fc;
  if (a == VH()) {
    do fc->info() = left; while (++fc != done);
    return;
  }
  while (fc->vertex(Cdt::ccw(fc->index(v))) != b) ++fc;
  done = fc;
  FaceInfo side = left;
  do {
    fc->info() = side;
    if (fc->vertex(Cdt::cw(fc->index(v))) == a) side = right;  // crossing v->a to the right side
  } while (++fc != done);
}

// Lawson flips around the new vertex v, never across a constrained edge. An
// edge is flipped only when the new vertex is strictly inside the circumcircle
// of the triangle across it; a cocircular quad is left as it is and counted
// (in the domain only: a boundary split also flips outside). The order is
// ALGORITHM.md's legalization order: the faces (v, u, w) around v by increasing
// id of u (outside faces too: their flips stay outside), each legalized depth
// first, (v, u, d) before (v, d, w) after a flip. created: the domain faces made,
// in creation order.
void restore_delaunay(Triangulation& tr, VH v, std::vector<Tri>* created) {
  auto u_of = [&](FH f) { return id(f->vertex(Cdt::ccw(f->index(v)))); };
  std::vector<FH> initial;
  Cdt::Face_circulator fc = tr.cdt.incident_faces(v), done = fc;
  do initial.push_back(fc); while (++fc != done);
  std::stable_sort(initial.begin(), initial.end(), [&](FH x, FH y) { return u_of(x) < u_of(y); });
  auto record = [&](FH f) {
    if (created && !tr.cdt.is_infinite(f) && f->info().in_domain) created->push_back(key(f));
  };
  if (created) created->clear();
  for (FH f : initial) record(f);
  std::vector<FH> stack(initial.rbegin(), initial.rend());
  while (!stack.empty()) {
    FH f = stack.back();
    stack.pop_back();
    int i = f->index(v);
    FH n = f->neighbor(i);
    if (f->is_constrained(i) || tr.cdt.is_infinite(f) || tr.cdt.is_infinite(n)) continue;
    CGAL::Oriented_side side = tr.cdt.side_of_oriented_circle(n, v->point(), false);
    if (side == CGAL::ON_ORIENTED_BOUNDARY && f->info().in_domain) ++tr.cocircular_ties;
    if (side != CGAL::ON_POSITIVE_SIDE) continue;
    VH u = f->vertex(Cdt::ccw(i));
    tr.cdt.flip(f, i);  // f and n now both have v as a vertex
    FH first = f->has_vertex(u) ? f : n, second = first == f ? n : f;  // (v, u, d), (v, d, w)
    record(first);
    record(second);
    stack.push_back(second);
    stack.push_back(first);
  }
}

}  // namespace

VH insert_point(Triangulation& tr, const Selection& s, FH t1, std::vector<Tri>* created) {
  Cdt& cdt = tr.cdt;
  CPoint p(s.point.x, s.point.y);
  VH v;
  std::vector<int> segments;
  bool split = s.split_face != FH();
  // Domain flags and regions of the two sides of a split constrained edge AB:
  // left of A->B, right; of the face the point falls in otherwise (left).
  FaceInfo left, right;
  VH a, b;
  if (split) {
    FH f = s.split_face;
    int i = s.split_index;
    a = f->vertex(Cdt::ccw(i)), b = f->vertex(Cdt::cw(i));  // f is left of a->b
    left = f->info();
    right = f->neighbor(i)->info();
    auto e = edge_key(id(a), id(b));
    auto found = tr.segment_of_edge.find(e);
    if (found == tr.segment_of_edge.end())
      throw std::logic_error("reference: constrained edge (" + std::to_string(e.first) + "," + std::to_string(e.second) +
                             ") lies on no input segment");
    int segment = found->second;
    tr.segment_of_edge.erase(e);
    segments.push_back(segment);
    // Insert into the edge itself even when the rounded midpoint is half an
    // ulp off the line: CGAL then keeps both halves constrained, where a
    // located insert would drop the point into a face beside the old constraint.
    v = cdt.Cdt::Ctr::insert(p, Cdt::EDGE, f, i);
  } else {
    Cdt::Locate_type lt;
    int li;
    FH f = cdt.locate(p, lt, li, t1);
    if (lt == Cdt::VERTEX) throw std::logic_error("reference: the selected point is already a vertex");
    if (lt == Cdt::OUTSIDE_CONVEX_HULL || lt == Cdt::OUTSIDE_AFFINE_HULL || !f->info().in_domain ||
        (lt == Cdt::EDGE && f->is_constrained(li)))
      throw std::logic_error("reference: the selected point is not inside the terminal quad");
    left = f->info();  // on an unconstrained edge: both faces have the same
    v = cdt.Cdt::Ctr::insert(p, lt, f, li);
  }
  v->info().id = static_cast<int>(tr.vertex.size());
  v->info().segments = segments;
  tr.vertex.push_back(v);
  tr.coords.push_back(s.point);
  if (split) {
    tr.segment_of_edge[edge_key(id(a), id(v))] = segments[0];
    tr.segment_of_edge[edge_key(id(v), id(b))] = segments[0];
  }
  // A midpoint half an ulp off its segment must still make positive triangles.
  Cdt::Face_circulator fc = cdt.incident_faces(v), done = fc;
  do {
    if (!cdt.is_infinite(fc) &&
        CGAL::orientation(fc->vertex(0)->point(), fc->vertex(1)->point(), fc->vertex(2)->point()) != CGAL::LEFT_TURN)
      throw std::logic_error("reference: insertion made a triangle that is not counter-clockwise");
  } while (++fc != done);
  set_domain_flags(tr, v, split ? a : VH(), split ? b : VH(), left, right);
  restore_delaunay(tr, v, created);
  return v;
}

}  // namespace lepp::reference::detail
