// SPDX-License-Identifier: GPL-3.0-or-later
// The exact decisions of ALGORITHM.md on one triangle: edge order (Section 3),
// bad triangles (Section 4), the unimprovable rule (Section 8), and Lepp(t).
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "double_predicates.h"
#include "triangulation.h"

namespace lepp::reference::detail {

namespace {

// The double coordinates of v's point in p; false if they are not doubles
// (never for a vertex: every one is made from doubles, its interval a point).
bool double_coords(VH v, Point& p) {
  const auto& q = CGAL::approx(v->point());
  p = {q.x().inf(), q.y().inf()};
  return q.x().is_point() && q.y().is_point();
}

// sign(|ab|^2 - |cd|^2), exactly: on the doubles (double_predicates.h), not in lazy Epeck.
int compare_edge_lengths(VH a, VH b, VH c, VH d) {
  Point pa, pb, pc, pd;
  if (double_coords(a, pa) && double_coords(b, pb) && double_coords(c, pc) && double_coords(d, pd))
    return compare_squared_lengths(pa, pb, pc, pd);
  return static_cast<int>(CGAL::compare(CGAL::squared_distance(a->point(), b->point()),
                                        CGAL::squared_distance(c->point(), d->point())));
}

// The edge order's tie-break, for ab and cd of one length: true iff ab is the greater.
bool tie_greater(VH a, VH b, VH c, VH d) {
  int ab_min = std::min(id(a), id(b)), ab_max = std::max(id(a), id(b));
  int cd_min = std::min(id(c), id(d)), cd_max = std::max(id(c), id(d));
  if (ab_min != cd_min) return ab_min < cd_min;  // older vertices win ties
  return ab_max < cd_max;
}

// Edge order key (squared length, -min id, -max id): true iff ab > cd.
bool edge_greater(VH a, VH b, VH c, VH d) {
  const int r = compare_edge_lengths(a, b, c, d);
  if (r != 0) return r > 0;
  return tie_greater(a, b, c, d);
}

// Vertex indices 0,1,2 of f sorted by their opposite edge, shortest first: edge_greater's
// order, with f's points read once rather than four times a comparison (the Lepp walks
// and the bad test sort every triangle they meet: a tenth of fuzz_differential under ASan).
std::array<int, 3> edges_ascending(FH f) {
  const VH v[3] = {f->vertex(0), f->vertex(1), f->vertex(2)};
  Point p[3];
  const bool doubles = double_coords(v[0], p[0]) && double_coords(v[1], p[1]) && double_coords(v[2], p[2]);
  auto greater = [&](int i, int j) {  // edge i (opposite vertex i) longer than edge j
    const int a = Cdt::ccw(i), b = Cdt::cw(i), c = Cdt::ccw(j), d = Cdt::cw(j);
    if (!doubles) return edge_greater(v[a], v[b], v[c], v[d]);
    const int r = compare_squared_lengths(p[a], p[b], p[c], p[d]);
    if (r != 0) return r > 0;
    return tie_greater(v[a], v[b], v[c], v[d]);
  };
  std::array<int, 3> e{0, 1, 2};
  std::sort(e.begin(), e.end(), [&](int i, int j) { return greater(j, i); });
  return e;
}

// Edges i and j of f have exactly the same length.
bool same_length(FH f, int i, int j) {
  return compare_edge_lengths(f->vertex(Cdt::ccw(i)), f->vertex(Cdt::cw(i)), f->vertex(Cdt::ccw(j)), f->vertex(Cdt::cw(j))) == 0;
}

}  // namespace

bool edge_greater(FH f, int i, FH g, int j) {
  return edge_greater(f->vertex(Cdt::ccw(i)), f->vertex(Cdt::cw(i)), g->vertex(Cdt::ccw(j)), g->vertex(Cdt::cw(j)));
}

int longest_edge(FH f) { return edges_ascending(f)[2]; }
int second_longest_edge(FH f) { return edges_ascending(f)[1]; }
int shortest_edge(FH f) { return edges_ascending(f)[0]; }

std::vector<int> tied_longest_edges(FH f) {
  const std::array<int, 3> e = edges_ascending(f);
  std::vector<int> out{e[2]};
  for (int k = 1; k >= 0; --k)
    if (same_length(f, e[k], e[2])) out.push_back(e[k]);
  return out;
}

std::vector<int> tied_second_edges(FH f, int e) {
  int i = Cdt::ccw(e), j = Cdt::cw(e);
  if (edge_greater(f, j, f, i)) std::swap(i, j);
  if (same_length(f, i, j)) return {i, j};
  return {i};
}

Tri key(FH f) {
  Tri t{id(f->vertex(0)), id(f->vertex(1)), id(f->vertex(2))};
  std::sort(t.begin(), t.end());
  return t;
}

Tri ccw_ids(FH f) {
  Tri t{id(f->vertex(0)), id(f->vertex(1)), id(f->vertex(2))};
  while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
  return t;
}

// The smallest angle is at the vertex opposite the shortest edge; with u, v
// the edge vectors leaving it: skinny iff cross(u,v)^2 < S |u|^2 |v|^2.
bool is_skinny(FH f, const FT& sin2) {
  int i = shortest_edge(f);
  Point o_d, b_d, c_d;
  const auto& s = CGAL::approx(sin2);  // a double in every caller: engine_sin2_threshold's
  if (s.is_point() && double_coords(f->vertex(i), o_d) && double_coords(f->vertex(Cdt::ccw(i)), b_d) &&
      double_coords(f->vertex(Cdt::cw(i)), c_d))
    return skinny_at(o_d, b_d, c_d, s.inf());
  const CPoint& o = f->vertex(i)->point();
  K::Vector_2 u = f->vertex(Cdt::ccw(i))->point() - o, v = f->vertex(Cdt::cw(i))->point() - o;
  FT cross = u.x() * v.y() - u.y() * v.x();
  return cross * cross < sin2 * u.squared_length() * v.squared_length();
}

bool is_too_big(FH f, const FT& twice_max_area) {
  const CPoint &a = f->vertex(0)->point(), &b = f->vertex(1)->point(), &c = f->vertex(2)->point();
  FT cross = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
  return CGAL::abs(cross) > twice_max_area;
}

std::optional<UnimprovableTriangle> unimprovable(const Triangulation& tr, FH f, const FT& sin2) {
  int i = shortest_edge(f);
  VH p = f->vertex(Cdt::ccw(i)), q = f->vertex(Cdt::cw(i));
  const CPoint& r = f->vertex(i)->point();
  std::optional<UnimprovableTriangle> best;
  for (int s1 : p->info().segments) {
    for (int s2 : q->info().segments) {
      if (s1 == s2) continue;
      const Segment& a = tr.input->segments[static_cast<std::size_t>(s1)];
      const Segment& b = tr.input->segments[static_cast<std::size_t>(s2)];
      // The shared endpoint v and the other endpoints of each segment.
      int v = -1, ea = -1, eb = -1;
      if (a.a == b.a) v = a.a, ea = a.b, eb = b.b;
      else if (a.a == b.b) v = a.a, ea = a.b, eb = b.a;
      else if (a.b == b.a) v = a.b, ea = a.a, eb = b.b;
      else if (a.b == b.b) v = a.b, ea = a.a, eb = b.a;
      if (v < 0 || v == id(p) || v == id(q)) continue;
      const CPoint& pv = tr.vertex[static_cast<std::size_t>(v)]->point();
      K::Vector_2 u = tr.vertex[static_cast<std::size_t>(ea)]->point() - pv;
      K::Vector_2 w = tr.vertex[static_cast<std::size_t>(eb)]->point() - pv;
      FT dot = u * w, cross = u.x() * w.y() - u.y() * w.x();
      if (!(dot > 0 && cross * cross < sin2 * u.squared_length() * w.squared_length())) continue;
      // Inside the wedge (Section 8): the third vertex on s1 or s2, or in the closed
      // sector at v between them.
      const std::vector<int>& on = f->vertex(i)->info().segments;
      if (std::find(on.begin(), on.end(), s1) == on.end() && std::find(on.begin(), on.end(), s2) == on.end()) {
        const CPoint &e1 = tr.vertex[static_cast<std::size_t>(ea)]->point(), &e2 = tr.vertex[static_cast<std::size_t>(eb)]->point();
        const int sigma = static_cast<int>(CGAL::orientation(pv, e1, e2));
        if (static_cast<int>(CGAL::orientation(pv, e1, r)) * sigma < 0 || static_cast<int>(CGAL::orientation(pv, r, e2)) * sigma < 0)
          continue;
      }
      int lo = std::min(s1, s2), hi = std::max(s1, s2);
      if (best && std::make_pair(best->segment1, best->segment2) <= std::make_pair(lo, hi)) continue;
      UnimprovableTriangle u_t;
      u_t.triangle = ccw_ids(f);
      u_t.apex = v;
      u_t.segment1 = lo;
      u_t.segment2 = hi;
      u_t.input_angle_deg = std::atan2(std::abs(CGAL::to_double(cross)), CGAL::to_double(dot)) * 180.0 / M_PI;
      best = u_t;
    }
  }
  return best;
}

namespace {

// longest_edge(f), looked up in memo and kept there when given.
int longest_edge(FH f, LongestEdgeMemo* memo) {
  if (!memo || id(f->vertex(0)) < 0 || id(f->vertex(1)) < 0 || id(f->vertex(2)) < 0) return longest_edge(f);
  int& known = memo->at(key(f));
  if (known < 0) known = id(f->vertex(longest_edge(f)));
  for (int i = 0; i < 3; ++i)
    if (id(f->vertex(i)) == known) return i;
  throw std::logic_error("reference: a remembered longest edge is not the face's");
}

}  // namespace

// ALGORITHM.md Section 3: follow longest edges while they grow; stop at a
// constrained longest edge or at an edge that is longest for both triangles.
Lepp find_lepp(FH t, LongestEdgeMemo* memo) {
  Lepp lepp;
  FH f = t;
  for (;;) {
    lepp.path.push_back(f);
    int i = longest_edge(f, memo);
    if (f->is_constrained(i)) {
      lepp.t1 = f;
      lepp.edge = i;
      return lepp;
    }
    FH n = f->neighbor(i);
    if (!n->info().in_domain) throw std::logic_error("reference: Lepp left the domain across an unconstrained edge");
    int j = n->index(f);
    if (longest_edge(n, memo) == j) {
      lepp.t1 = f;
      lepp.t2 = n;
      lepp.edge = i;
      lepp.path.push_back(n);
      return lepp;
    }
    f = n;  // n's longest edge is strictly greater: the path cannot cycle
  }
}

}  // namespace lepp::reference::detail
