// SPDX-License-Identifier: GPL-3.0-or-later
// Point selection (ALGORITHM.md Section 5: the paper's Select Point and New
// Select Point with Remark 10) and insertion (Section 6).
#include <cmath>
#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "lepp/rounding.h"
#include "paper_choices.h"
#include "insert_unflipped.h"
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
  const bool has_t2 = t2 != FH();
  int s1 = has_t2 ? second_longest_of(lepp, false) : -1, s2 = has_t2 ? second_longest_of(lepp, true) : -1;
  bool c1 = has_t2 && t1->is_constrained(s1), c2 = has_t2 && t2->is_constrained(s2);
  // The centroid of the quad: A, B the terminal edge, C, D the apexes of t1, t2.
  auto quad_centroid = [&] { return centroid(t1->vertex(Cdt::ccw(l)), t1->vertex(Cdt::cw(l)), t1->vertex(l), t2->vertex(t2->index(t1))); };
  // The first row of the paper's table (paper_choices.h) whose condition holds.
  for (const PaperOption& o : paper_options(method, has_t2, c1, c2)) {
    if (o.point == PaperPoint::TerminalEdgeMidpoint) return edge_midpoint(o.rule, t1, l);
    if (o.when != PaperCondition::Always) {
      // Remark 10: is the centroid strictly inside the triangle other than t*?
      FH other = o.triangle == 1 ? t2 : t1;
      if (strictly_inside(other, quad_centroid()) != (o.when == PaperCondition::CentroidInsideOther)) continue;
    }
    if (o.point == PaperPoint::SecondLongestMidpoint)
      return o.triangle == 1 ? edge_midpoint(o.rule, t1, s1) : edge_midpoint(o.rule, t2, s2);
    Selection s;
    s.rule = o.rule;
    s.point = quad_centroid();
    return s;
  }
  throw std::logic_error("reference: no row of the paper's table applies");  // every configuration has one that holds
}

namespace {

CGAL::Orientation orient(VH a, const CPoint& p, VH c) { return CGAL::orientation(a->point(), p, c->point()); }
CGAL::Orientation orient(const CPoint& p, VH b, VH c) { return CGAL::orientation(p, b->point(), c->point()); }

// Where p lies in the closed face f: 1 strictly inside, 2 on the interior of an
// unconstrained edge between domain faces, 0 outside, -1 on a vertex or on a
// constrained (or domain boundary) edge.
int place_in(const Triangulation& tr, FH f, const CPoint& p) {
  int zeros = 0, on = -1;
  for (int i = 0; i < 3; ++i) {
    CGAL::Orientation o = CGAL::orientation(f->vertex(Cdt::ccw(i))->point(), f->vertex(Cdt::cw(i))->point(), p);
    if (o == CGAL::RIGHT_TURN) return 0;
    if (o == CGAL::COLLINEAR) ++zeros, on = i;
  }
  if (zeros == 0) return 1;
  if (zeros >= 2) return -1;
  FH n = f->neighbor(on);
  return f->is_constrained(on) || tr.cdt.is_infinite(n) || !n->info().in_domain ? -1 : 2;
}

// Within the precision floor (a few ulps, lepp::below_precision_floor) of vertex v.
bool near(const Triangulation& tr, const Point& p, VH v) {
  return id(v) >= 0 && lepp::below_precision_floor(p, tr.coords[static_cast<std::size_t>(id(v))]);
}

// A split of the constrained edge ab of face f at p can go into the edge itself:
// both faces it makes across ab, in the domain or outside, are counter-clockwise.
bool splits_in_edge(const Triangulation& tr, FH f, int i, const CPoint& p) {
  FH n = f->neighbor(i);
  if (tr.cdt.is_infinite(n)) return true;
  VH a = f->vertex(Cdt::ccw(i)), b = f->vertex(Cdt::cw(i)), d = n->vertex(n->index(f));
  return orient(b, p, d) == CGAL::LEFT_TURN && orient(p, a, d) == CGAL::LEFT_TURN;
}

// A boundary split whose outside faces would not be counter-clockwise: earlier
// rounded midpoints made the boundary a few ulps concave, so the outside face
// across ab is a sliver along it and p, half an ulp off ab, lies beyond it. The
// split (a, p, c), (p, b, c) is a valid mesh unless the thin triangle a, p, b (p
// outside ab) holds another vertex or a constrained edge enters it: the sliver
// clause (ALGORITHM.md section 8b), which the fast engine tests on the input
// outside the domain; here the same tests on every vertex and constrained edge, a
// superset (when the outside face holds p, it holds the sliver and the clause
// holds). Rare (only when the outside test fails), so a scan.
bool outside_clear(const Triangulation& tr, VH a, VH b, const CPoint& p) {
  const CPoint &pa = a->point(), &pb = b->point();
  if (CGAL::orientation(pa, pb, p) != CGAL::RIGHT_TURN) return true;  // p in the domain face or on ab
  for (VH w : tr.vertex) {
    if (w == a || w == b) continue;
    const CPoint& q = w->point();
    if (CGAL::orientation(pa, p, q) != CGAL::RIGHT_TURN && CGAL::orientation(p, pb, q) != CGAL::RIGHT_TURN &&
        CGAL::orientation(pb, pa, q) != CGAL::RIGHT_TURN)
      return false;
  }
  const K::Segment_2 ap(pa, p), pb_(p, pb);
  for (const auto& [key, segment] : tr.segment_of_edge) {
    VH u = tr.vertex[static_cast<std::size_t>(key.first)], w = tr.vertex[static_cast<std::size_t>(key.second)];
    if ((u == a && w == b) || (u == b && w == a)) continue;
    if (w == a || w == b) std::swap(u, w);
    const CPoint& q = w->point();
    // An edge from a (or b) enters the triangle iff it leaves into the angle at a (or b).
    if (u == a) {
      if (CGAL::orientation(pa, pb, q) == CGAL::RIGHT_TURN && CGAL::orientation(pa, p, q) != CGAL::RIGHT_TURN) return false;
    } else if (u == b) {
      if (CGAL::orientation(pa, pb, q) == CGAL::RIGHT_TURN && CGAL::orientation(p, pb, q) != CGAL::RIGHT_TURN) return false;
    } else {
      const K::Segment_2 e(u->point(), q);
      if (CGAL::do_intersect(e, ap) || CGAL::do_intersect(e, pb_)) return false;
    }
  }
  return true;
}

void set_constrained(Cdt& cdt, VH u, VH w, bool on) {
  FH f;
  int i;
  if (!cdt.is_edge(u, w, f, i)) throw std::logic_error("reference: a boundary split lost an edge of its triangles");
  f->set_constraint(i, on);
  f->neighbor(i)->set_constraint(f->neighbor(i)->index(f), on);
}

// The split of boundary edge ab (face f = abc in the domain) at p when the
// outside faces forbid splitting the edge itself (outside_clear holds): the
// domain gets the fast engine's faces (a, p, c), (p, b, c), the outside is
// triangulated around p anew. p strictly inside abc: inserted in the face, ab
// leaves the domain with (a, b, p). p outside ab: inserted where it lies, av
// and vb become constraints (ab stays constrained meanwhile, so no flip reaches
// the domain), then ab, between abc and the empty triangle (a, p, b), is flipped.
VH split_past_outside(Triangulation& tr, FH f, int i, const CPoint& p) {
  Cdt& cdt = tr.cdt;
  VH a = f->vertex(Cdt::ccw(i)), b = f->vertex(Cdt::cw(i));
  VH v;
  if (CGAL::orientation(a->point(), b->point(), p) == CGAL::LEFT_TURN) {
    v = cdt.Cdt::Ctr::insert(p, Cdt::FACE, f, -1);
    set_constrained(cdt, a, v, true);
    set_constrained(cdt, v, b, true);
    set_constrained(cdt, a, b, false);
    return v;
  }
  Cdt::Locate_type lt;
  int li;
  FH loc = cdt.locate(p, lt, li, f->neighbor(i));
  if (lt != Cdt::FACE && lt != Cdt::EDGE) throw std::logic_error("reference: a boundary split's point is on a vertex outside");
  v = cdt.Cdt::Ctr::insert(p, lt, loc, li);
  cdt.Cdt::Ctr::insert_constraint(a, v);
  cdt.Cdt::Ctr::insert_constraint(v, b);
  FH g;
  int k;
  if (!cdt.is_edge(a, b, g, k)) throw std::logic_error("reference: a boundary split lost its edge");
  if (!g->has_vertex(v)) {
    FH h = g->neighbor(k);
    k = h->index(g);
    g = h;
  }
  if (!g->has_vertex(v) || g->neighbor(k)->has_vertex(v)) throw std::logic_error("reference: a boundary split left vertices beside its edge");
  set_constrained(cdt, a, b, false);
  cdt.flip(g, k);
  return v;
}

}  // namespace

bool insertable(const Triangulation& tr, const Selection& s, const Lepp& lepp) {
  const CPoint p(s.point.x, s.point.y);
  if (s.split_face != FH()) {
    // Every face the split of edge ab makes is counter-clockwise: on both sides
    // in the domain, and outside it too, where the CDT has faces the fast engine
    // does not keep (a rounded midpoint may be half an ulp off the line).
    FH f = s.split_face;
    int i = s.split_index;
    VH a = f->vertex(Cdt::ccw(i)), b = f->vertex(Cdt::cw(i)), c = f->vertex(i);
    if (orient(a, p, c) != CGAL::LEFT_TURN || orient(p, b, c) != CGAL::LEFT_TURN) return false;
    if (near(tr, s.point, a) || near(tr, s.point, b) || near(tr, s.point, c)) return false;
    FH n = f->neighbor(i);
    if (tr.cdt.is_infinite(n)) return true;
    VH d = n->vertex(n->index(f));
    // The far side's apex is held to the floor only in the domain (the fast engine's view).
    if (n->info().in_domain && near(tr, s.point, d)) return false;
    // Across a domain face: the fast engine's test. Outside: the fast engine's view,
    // the outside triangulated anew if need be (split_past_outside).
    return splits_in_edge(tr, f, i, p) || (!n->info().in_domain && outside_clear(tr, a, b, p));
  }
  for (FH t : {lepp.t1, lepp.t2})
    if (t != FH())
      for (int k = 0; k < 3; ++k)
        if (near(tr, s.point, t->vertex(k))) return false;
  // A located insertion: in the closed terminal pair, off its vertices and off
  // constrained edges (a centroid in the other triangle is strictly inside it).
  int in_t1 = place_in(tr, lepp.t1, p);
  if (in_t1 != 0 || lepp.t2 == FH()) return in_t1 > 0;
  return place_in(tr, lepp.t2, p) > 0;
}

namespace {

double x_of(VH v) { return CGAL::to_double(v->point().x()); }
double y_of(VH v) { return CGAL::to_double(v->point().y()); }

// The doubles around the exact midpoint of a, b (lepp/rounding.h), ascending x then y.
std::vector<Point> midpoint_roundings(VH a, VH b) {
  std::vector<Point> out;
  for (double x : doubles_around_midpoint(x_of(a), x_of(b)))
    for (double y : doubles_around_midpoint(y_of(a), y_of(b))) out.push_back({x, y});
  return out;
}

// The doubles around the exact centroid of the terminal quad (t1's terminal edge, both apexes).
std::vector<Point> centroid_roundings(const Lepp& lepp) {
  FH t1 = lepp.t1;
  int l = lepp.edge;
  VH a = t1->vertex(Cdt::ccw(l)), b = t1->vertex(Cdt::cw(l)), c = t1->vertex(l), d = lepp.t2->vertex(lepp.t2->index(t1));
  std::vector<Point> out;
  for (double x : doubles_around_centroid(x_of(a), x_of(b), x_of(c), x_of(d)))
    for (double y : doubles_around_centroid(y_of(a), y_of(b), y_of(c), y_of(d))) out.push_back({x, y});
  return out;
}

}  // namespace

bool round_otherwise(const Triangulation& tr, const Lepp& lepp, Selection& s) {
  FH t1 = lepp.t1;
  int l = lepp.edge;
  VH a = t1->vertex(Cdt::ccw(l)), b = t1->vertex(Cdt::cw(l));
  std::vector<Point> points;
  FH other;  // centroid-in-other: the triangle the point must stay strictly inside
  if (s.rule == Rule::QuadCentroid || s.rule == Rule::CentroidInOther) {
    points = centroid_roundings(lepp);
    if (s.rule == Rule::CentroidInOther) other = strictly_inside(t1, s.point) ? t1 : lepp.t2;
  } else {
    if (s.split_face != FH()) a = s.split_face->vertex(Cdt::ccw(s.split_index)), b = s.split_face->vertex(Cdt::cw(s.split_index));
    points = midpoint_roundings(a, b);
  }
  for (const Point& p : points) {
    Selection alt = s;
    alt.point = p;
    if (alt.point == s.point || (other != FH() && !strictly_inside(other, alt.point))) continue;
    if (insertable(tr, alt, lepp)) {
      s = alt;
      return true;
    }
  }
  return false;
}

bool other_branch(const Triangulation& tr, const Lepp& lepp, Method method, Selection& s) {
  if (method != Method::Centroid || lepp.t2 == FH()) return false;
  if (s.rule != Rule::CentroidInOther && s.rule != Rule::SecondLongestMidpoint) return false;
  FH t1 = lepp.t1, t2 = lepp.t2;
  int s1 = second_longest_of(lepp, false), s2 = second_longest_of(lepp, true);
  bool c1 = t1->is_constrained(s1), c2 = t2->is_constrained(s2);
  if (c1 == c2) return false;  // not Remark 10's branch
  FH star = c1 ? t1 : t2, other = c1 ? t2 : t1;
  const std::vector<Point> centroids = centroid_roundings(lepp);
  if (s.rule == Rule::CentroidInOther) {
    bool turns = false;
    for (const Point& g : centroids) turns = turns || !strictly_inside(other, g);
    if (!turns) return false;
    Selection mid = edge_midpoint(Rule::SecondLongestMidpoint, star, c1 ? s1 : s2);
    if (!insertable(tr, mid, lepp) && !round_otherwise(tr, lepp, mid)) return false;
    s = mid;
    return true;
  }
  Selection in_other;
  in_other.rule = Rule::CentroidInOther;
  for (const Point& g : centroids) {
    in_other.point = g;
    if (strictly_inside(other, g) && insertable(tr, in_other, lepp)) {
      s = in_other;
      return true;
    }
  }
  return false;
}

bool other_constrained_edge(const Triangulation& tr, const Lepp& lepp, Selection& s) {
  if (lepp.t2 == FH() || s.split_face != lepp.t1) return false;
  if (s.rule != Rule::BothSecondLongestMidpoint && s.rule != Rule::SecondLongestMidpoint) return false;
  FH t1 = lepp.t1, t2 = lepp.t2;
  int s1 = second_longest_of(lepp, false), s2 = second_longest_of(lepp, true);
  if (s.split_index != s1 || !t1->is_constrained(s1) || !t2->is_constrained(s2)) return false;  // not both constrained
  Selection mid = edge_midpoint(s.rule, t2, s2);
  if (!insertable(tr, mid, lepp) && !round_otherwise(tr, lepp, mid)) return false;
  s = mid;
  return true;
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

namespace {

// A split of constrained edge ab (face f = (c, a, b), c left of a->b) at p
// strictly off the line ab keeps the triangle on the side p moves away from when
// p lies strictly outside its circumcircle (ALGORITHM.md section 6, "A split off
// its line"): the usual split would leave the edge from p to that triangle's apex
// not locally Delaunay, and no flip opposite p repairs it. Returns that apex (d
// across ab, p on c's side; c, p beyond ab), or null for the usual split.
VH kept_apex(const Triangulation& tr, FH f, int i, const CPoint& p) {
  VH a = f->vertex(Cdt::ccw(i)), b = f->vertex(Cdt::cw(i)), c = f->vertex(i);
  const CGAL::Orientation side = CGAL::orientation(a->point(), b->point(), p);
  if (side == CGAL::LEFT_TURN) {
    FH n = f->neighbor(i);
    if (tr.cdt.is_infinite(n) || !n->info().in_domain) return VH();
    VH d = n->vertex(n->index(f));
    return CGAL::side_of_oriented_circle(d->point(), b->point(), a->point(), p) == CGAL::ON_NEGATIVE_SIDE ? d : VH();
  }
  if (side == CGAL::RIGHT_TURN)
    return CGAL::side_of_oriented_circle(c->point(), a->point(), b->point(), p) == CGAL::ON_NEGATIVE_SIDE ? c : VH();
  return VH();
}

// The kept triangle (a, b, x): the usual split made (p, a, x), (p, x, b) or the
// mirror; flipping px gives (a, b, x) back and the sliver between ab and the
// constrained edges ap, pb, both on x's side of them (info). Returns the face.
FH keep_beside_sliver(Triangulation& tr, VH v, VH a, VH b, VH x, const FaceInfo& info) {
  Cdt& cdt = tr.cdt;
  FH g;
  int k;
  if (!cdt.is_edge(v, x, g, k)) throw std::logic_error("reference: a split off its line lost the edge to the kept apex");
  cdt.flip(g, k);
  FH kept, sliver;
  if (!cdt.is_face(a, b, x, kept) || !cdt.is_face(a, b, v, sliver))
    throw std::logic_error("reference: a split off its line did not give back the kept triangle");
  kept->info() = info;
  sliver->info() = info;
  set_constrained(cdt, a, b, false);
  set_constrained(cdt, a, v, true);
  set_constrained(cdt, v, b, true);
  return kept;
}

}  // namespace

VH insert_point(Triangulation& tr, const Selection& s, FH t1, std::vector<Tri>* created, FH* kept) {
  VH v = insert_point_unflipped(tr, s, t1, kept);
  restore_delaunay(tr, v, created);
  return v;
}

VH insert_point_unflipped(Triangulation& tr, const Selection& s, FH t1, FH* kept) {
  Cdt& cdt = tr.cdt;
  CPoint p(s.point.x, s.point.y);
  VH v;
  std::vector<int> segments;
  bool split = s.split_face != FH();
  VH kept_x;  // the kept triangle's apex, if any
  bool kept_left = false;  // on the left side of a->b (the split face's)
  if (kept) *kept = FH();
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
    // Unless the faces that makes outside the domain would not be counter-clockwise.
    kept_x = kept_apex(tr, f, i, p);
    kept_left = kept_x == f->vertex(i);
    const bool outside_anew = !splits_in_edge(tr, f, i, p) && !right.in_domain;
    v = outside_anew ? split_past_outside(tr, f, i, p) : cdt.Cdt::Ctr::insert(p, Cdt::EDGE, f, i);
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
  if (kept_x != VH()) {
    FH k = keep_beside_sliver(tr, v, a, b, kept_x, kept_left ? left : right);
    if (kept) *kept = k;
  }
  return v;
}

}  // namespace lepp::reference::detail
