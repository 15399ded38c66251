// SPDX-License-Identifier: GPL-3.0-or-later
// lepp_test_mesher: an independent Lepp-centroid / Lepp-midpoint mesher, written
// the way an outside user would write one, with switchable seeded bugs. It is the
// program under audit in audit/tests/mesher: it never calls lepp's engines. Only lepp's
// .poly reader and input validation are borrowed (file syntax, not the algorithm).
//
//   lepp_test_mesher IN.poly OUTPREFIX THETA METHOD [--bug NAME]... [--zero-based]
//
// Writes OUTPREFIX.node, OUTPREFIX.ele (Triangle's formats, 1-based unless
// --zero-based) and OUTPREFIX.trace (one "x y" line per Steiner point, %.17g).
// Its own choices, all left open by the paper (Lepp-centroid paper, Section 4 and
// Remark 10): a plain stack as processing order, ties between equal edge lengths
// broken by the endpoints' coordinates, centroid computed as (A+B+C+D)/4 left to
// right, and "a constrained second longest edge" taken from t2 when both are.
//
// Like Triangle, it exits 0 when its loop guard stops it (a warning on stderr, the
// mesh as it is written): the audit then judges the output, not the exit status.
//
// Seeded bugs (--bug): non-delaunay, drop-segment, skinny, loop, crash, garbage,
// triangle-centroid, no-remark10, shortest-edge, and one per deviation of the
// audit's catalogue: area-centroid, terminal-midpoint, centroid-not-midpoint,
// remark10-reversed, remark10-ignored (= no-remark10), other-second-longest,
// good-triangle; no-flips (named missing-flips); and the arithmetic ones,
// single-precision (every coordinate written is the float nearest the computed
// double), float-input (the input's coordinates read as float, the rest in
// double), printed-digits (written with %g's 6 digits), inexact-length (edge
// lengths compared as computed in double), inexact-threshold (theta compared with
// a few ulps of slack: a triangle below theta by less than rounding stays) and
// inexact-incircle (a last Delaunay pass with an in-circle test in double that
// flips near-cocircular quads the other way), double-flips (every insertion's
// Lawson flips decided by an in-circle test in double). Each is described at its use.
// --bug may be given more than once: a program with several deviations at once
// (area-centroid with other-second-longest: two rules for disjoint configurations).
#include <algorithm>
#include <array>
#include <chrono>
#include <cfloat>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "lepp/io.h"
#include "lepp/validate.h"

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using P2 = K::Point_2;

struct VInfo {
  int id = -1;
  std::vector<int> segments;  // input segments this vertex lies on
};
struct FInfo {
  bool in_domain = false;
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VInfo, K>;
using Fb0 = CGAL::Constrained_triangulation_face_base_2<K>;
using Fb = CGAL::Triangulation_face_base_with_info_2<FInfo, K, Fb0>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Face = Cdt::Face_handle;
using Vertex = Cdt::Vertex_handle;

enum class Bug {
  none, non_delaunay, drop_segment, skinny, loop, crash, garbage,
  triangle_centroid, no_remark10, shortest_edge,
  // The deviation catalogue's rules (docs/CONFORMANCE.md, "Deviations"), one each.
  area_centroid, terminal_midpoint, centroid_not_midpoint, remark10_reversed, other_second_longest, good_triangle,
  no_flips,  // inserts without Delaunay flips (named missing-flips: the final mesh is not Delaunay)
  // Arithmetic (docs/CONFORMANCE.md, "Arithmetic"): the coordinates it writes are
  // floats (its vertices held as float), or written with a stream's 6 digits.
  single_precision, printed_digits,
  float_input,        // reads the input's coordinates as float, then computes and writes in double
  inexact_length,     // squared edge lengths compared as computed in double, not exactly
  inexact_threshold,  // the smallest angle, in double, compared with theta (1 - 16 DBL_EPSILON)
  inexact_incircle,   // near-cocircular quads flipped the other way by an in-circle test in double
  double_flips        // every insertion's Lawson flips decided by the in-circle determinant in double
};

struct Options {
  std::string in, out;
  double theta = 0;
  bool centroid = true;
  std::set<Bug> bugs;  // --bug, given once per bug: two deviations at once
  bool zero_based = false;
  bool has(Bug b) const { return bugs.count(b) > 0; }
};

[[noreturn]] void usage(const std::string& why) {
  std::fprintf(stderr,
               "lepp_test_mesher: %s\nusage: lepp_test_mesher IN.poly OUTPREFIX THETA centroid|midpoint "
               "[--bug NAME] [--zero-based]\n",
               why.c_str());
  std::exit(2);
}

Bug parse_bug(const std::string& s) {
  static const std::map<std::string, Bug> names = {
      {"none", Bug::none}, {"non-delaunay", Bug::non_delaunay}, {"drop-segment", Bug::drop_segment},
      {"skinny", Bug::skinny}, {"loop", Bug::loop}, {"crash", Bug::crash}, {"garbage", Bug::garbage},
      {"triangle-centroid", Bug::triangle_centroid}, {"no-remark10", Bug::no_remark10},
      {"remark10-ignored", Bug::no_remark10},  // the same bug, by the name the audit gives it
      {"shortest-edge", Bug::shortest_edge}, {"area-centroid", Bug::area_centroid},
      {"terminal-midpoint", Bug::terminal_midpoint}, {"centroid-not-midpoint", Bug::centroid_not_midpoint},
      {"remark10-reversed", Bug::remark10_reversed}, {"other-second-longest", Bug::other_second_longest},
      {"good-triangle", Bug::good_triangle}, {"no-flips", Bug::no_flips},
      {"single-precision", Bug::single_precision}, {"printed-digits", Bug::printed_digits},
      {"float-input", Bug::float_input},
      {"inexact-length", Bug::inexact_length}, {"inexact-threshold", Bug::inexact_threshold},
      {"inexact-incircle", Bug::inexact_incircle}, {"double-flips", Bug::double_flips}};
  auto it = names.find(s);
  if (it == names.end()) usage("unknown bug '" + s + "'");
  return it->second;
}

Options parse(int argc, char** argv) {
  Options o;
  std::vector<std::string> pos;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--bug") {
      if (i + 1 >= argc) usage("--bug needs a name");
      o.bugs.insert(parse_bug(argv[++i]));
    } else if (a == "--zero-based") {
      o.zero_based = true;
    } else {
      pos.push_back(a);
    }
  }
  if (pos.size() != 4) usage("expected 4 positional arguments");
  o.in = pos[0];
  o.out = pos[1];
  char* end = nullptr;
  o.theta = std::strtod(pos[2].c_str(), &end);
  if (*end != '\0' || !(o.theta > 0 && o.theta < 60)) usage("THETA must be a number of degrees in (0, 60)");
  if (pos[3] == "centroid") o.centroid = true;
  else if (pos[3] == "midpoint") o.centroid = false;
  else usage("METHOD must be centroid or midpoint");
  return o;
}

// Smallest angle of a triangle in degrees, in doubles (what a user would write).
double angle_at(const P2& a, const P2& b, const P2& c) {
  double ux = b.x() - a.x(), uy = b.y() - a.y(), vx = c.x() - a.x(), vy = c.y() - a.y();
  // Scaled to unit size first: products of tiny or huge coordinates would underflow or overflow.
  const double su = std::max(std::fabs(ux), std::fabs(uy)), sv = std::max(std::fabs(vx), std::fabs(vy));
  if (su > 0 && sv > 0) ux /= su, uy /= su, vx /= sv, vy /= sv;
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180.0 / M_PI;
}
double min_angle(const P2& a, const P2& b, const P2& c) {
  return std::min({angle_at(a, b, c), angle_at(b, c, a), angle_at(c, a, b)});
}

class Mesher {
 public:
  Mesher(const lepp::Pslg& pslg, const Options& opt) : pslg_(pslg), opt_(opt) {}

  // Meshes; stops after max_insertions Steiner points (the skinny bug's rerun).
  // Returns 0 converged, 3 stopped by the loop guard.
  int run(long max_insertions);

  void write(const std::string& prefix) const;
  long insertions() const { return static_cast<long>(steiner_.size()); }

 private:
  const lepp::Pslg& pslg_;
  const Options& opt_;
  Cdt cdt_;
  std::vector<Vertex> vertex_of_id_;
  std::map<std::pair<int, int>, int> segment_of_edge_;  // constrained edge (ids sorted) -> input segment
  std::vector<P2> steiner_;
  std::set<std::array<int, 3>> given_up_;
  double floor_ = 0;  // loop guard: no edge shorter than this (a millionth of the shortest segment)
  bool too_close(Vertex v) const {
    Cdt::Vertex_circulator vc = cdt_.incident_vertices(v), done = vc;
    do {
      if (!cdt_.is_infinite(vc) && std::hypot(vc->point().x() - v->point().x(), vc->point().y() - v->point().y()) < floor_)
        return true;
    } while (++vc != done);
    return false;
  }  // bad triangles whose point could not be inserted

  static std::pair<int, int> key(int a, int b) { return a < b ? std::make_pair(a, b) : std::make_pair(b, a); }
  int id(Vertex v) const { return v->info().id; }
  bool in_domain(Face f) const { return !cdt_.is_infinite(f) && f->info().in_domain; }
  // An edge the Lepp may not cross: a constraint, or the domain's border.
  bool blocked(Face f, int i) const { return f->is_constrained(i) || !in_domain(f->neighbor(i)); }

  // Edge order: squared length (exact), ties by the endpoints' coordinates.
  bool edge_less(Face f, int i, Face g, int j) const;
  // Edge indices of f sorted shortest .. longest.
  std::array<int, 3> edges_sorted(Face f) const;
  // The good-triangle bug: a threshold 3 degrees too high. The inexact-threshold
  // bug: a few ulps of slack below theta (a triangle whose smallest angle is
  // below theta by less than double rounding counts as good, and stays).
  bool bad(Face f) const {
    const double theta = opt_.has(Bug::good_triangle)       ? opt_.theta + 3
                         : opt_.has(Bug::inexact_threshold) ? opt_.theta * (1 - 16 * DBL_EPSILON)
                                                            : opt_.theta + 1e-9;
    return min_angle(p(f, 0), p(f, 1), p(f, 2)) < theta;
  }
  bool skipped(Face f) const;  // small input angle: left as it is
  const P2& p(Face f, int i) const { return f->vertex(i)->point(); }

  void build();
  void mark_domain();
  void flood_out(Face start);
  bool process(Face f);  // one Lepp search + insertion; false if nothing can be done
  Vertex insert_point(const P2& q, Face hint);
  Vertex split_constrained(Face f, int i);
  void legalize_in_double(Vertex v);
  void set_domain_around(Vertex v, Vertex c, bool c_side, bool other_side);
  void collect_bad(std::vector<std::array<int, 3>>& stack) const;
  std::array<int, 3> face_key(Face f) const {
    std::array<int, 3> k = {id(f->vertex(0)), id(f->vertex(1)), id(f->vertex(2))};
    std::sort(k.begin(), k.end());
    return k;
  }
};

bool Mesher::edge_less(Face f, int i, Face g, int j) const {
  const P2 &a = p(f, Cdt::ccw(i)), &b = p(f, Cdt::cw(i)), &c = p(g, Cdt::ccw(j)), &d = p(g, Cdt::cw(j));
  CGAL::Comparison_result r = K().compare_distance_2_object()(a, b, c, d);
  if (opt_.has(Bug::inexact_length)) {  // the lengths as a double program computes them
    const double l1 = (a.x() - b.x()) * (a.x() - b.x()) + (a.y() - b.y()) * (a.y() - b.y());
    const double l2 = (c.x() - d.x()) * (c.x() - d.x()) + (c.y() - d.y()) * (c.y() - d.y());
    r = l1 < l2 ? CGAL::SMALLER : l1 > l2 ? CGAL::LARGER : CGAL::EQUAL;
  }
  if (r != CGAL::EQUAL) return r == CGAL::SMALLER;
  P2 lo1 = std::min(a, b), hi1 = std::max(a, b), lo2 = std::min(c, d), hi2 = std::max(c, d);
  // Ties: the edge with the lexicographically larger endpoints counts as longer.
  return std::make_pair(lo1, hi1) < std::make_pair(lo2, hi2);
}

std::array<int, 3> Mesher::edges_sorted(Face f) const {
  std::array<int, 3> e = {0, 1, 2};
  std::sort(e.begin(), e.end(), [&](int i, int j) { return edge_less(f, i, f, j); });
  return e;
}

void Mesher::build() {
  vertex_of_id_.resize(pslg_.vertices.size());
  for (std::size_t i = 0; i < pslg_.vertices.size(); ++i) {
    Vertex v = cdt_.insert(P2(pslg_.vertices[i].x, pslg_.vertices[i].y));
    v->info().id = static_cast<int>(i);
    vertex_of_id_[i] = v;
  }
  for (std::size_t s = 0; s < pslg_.segments.size(); ++s) {
    int a = pslg_.segments[s].a, b = pslg_.segments[s].b;
    cdt_.insert_constraint(vertex_of_id_[a], vertex_of_id_[b]);
    segment_of_edge_[key(a, b)] = static_cast<int>(s);
    vertex_of_id_[a]->info().segments.push_back(static_cast<int>(s));
    vertex_of_id_[b]->info().segments.push_back(static_cast<int>(s));
  }
}

void Mesher::flood_out(Face start) {
  std::vector<Face> todo = {start};
  while (!todo.empty()) {
    Face f = todo.back();
    todo.pop_back();
    if (cdt_.is_infinite(f) || !f->info().in_domain) continue;
    f->info().in_domain = false;
    for (int i = 0; i < 3; ++i)
      if (!f->is_constrained(i)) todo.push_back(f->neighbor(i));
  }
}

// Triangle's -p: eat from the convex hull and from each hole, never across a segment.
void Mesher::mark_domain() {
  for (auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f) f->info().in_domain = true;
  for (auto f = cdt_.all_faces_begin(); f != cdt_.all_faces_end(); ++f) {
    if (!cdt_.is_infinite(f)) continue;
    for (int i = 0; i < 3; ++i)
      if (!cdt_.is_infinite(f->neighbor(i)) && !f->is_constrained(i)) flood_out(f->neighbor(i));
  }
  for (const lepp::Point& h : pslg_.holes) {
    Cdt::Locate_type lt;
    int li;
    Face f = cdt_.locate(P2(h.x, h.y), lt, li);
    if (lt == Cdt::FACE) flood_out(f);
    else if (lt == Cdt::EDGE && !f->is_constrained(li)) {
      flood_out(f);
      flood_out(f->neighbor(li));
    }
  }
}

// Small input angles: a skinny triangle inside the wedge of two segments meeting at
// a vertex v at an angle below theta, its shortest edge joining the two segments,
// cannot be fixed by any insertion; it is left alone (Lepp refinement would cascade
// toward v). Unlike lepp's rule (docs/ALGORITHM.md section 8) the triangle must lie
// on v's side of that edge: one beyond the wedge's mouth is refined like any other.
bool Mesher::skipped(Face f) const {
  int e = edges_sorted(f)[0];
  Vertex a = f->vertex(Cdt::ccw(e)), b = f->vertex(Cdt::cw(e));
  for (int s1 : a->info().segments)
    for (int s2 : b->info().segments) {
      if (s1 == s2) continue;
      const lepp::Segment &x = pslg_.segments[s1], &y = pslg_.segments[s2];
      int v = -1, u = -1, w = -1;
      if (x.a == y.a) v = x.a, u = x.b, w = y.b;
      else if (x.a == y.b) v = x.a, u = x.b, w = y.a;
      else if (x.b == y.a) v = x.b, u = x.a, w = y.b;
      else if (x.b == y.b) v = x.b, u = x.a, w = y.a;
      if (v < 0 || v == id(a) || v == id(b)) continue;
      const lepp::Point &pv = pslg_.vertices[v], &pu = pslg_.vertices[u], &pw = pslg_.vertices[w];
      if (!(angle_at(P2(pv.x, pv.y), P2(pu.x, pu.y), P2(pw.x, pw.y)) < opt_.theta + 1e-9)) continue;
      // The triangle must lie in the wedge: its third vertex on the apex's side of ab
      // (a triangle beyond the wedge's mouth can be improved like any other).
      const P2& r = f->vertex(e)->point();
      if (CGAL::orientation(a->point(), b->point(), r) != CGAL::orientation(a->point(), b->point(), P2(pv.x, pv.y)))
        continue;
      return true;
    }
  return false;
}

// The double-flips bug: Lawson flips around v as a double program writes them, the
// in-circle determinant in Shewchuk's translated form evaluated in double (the
// triangle across from its smallest vertex by coordinates, v as the fourth point),
// flipped when positive; never across a constraint, never into a fold.
void Mesher::legalize_in_double(Vertex v) {
  auto incircle = [](std::array<P2, 3> t, const P2& d) {
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    const double adx = t[0].x() - d.x(), ady = t[0].y() - d.y(), bdx = t[1].x() - d.x(), bdy = t[1].y() - d.y(),
                 cdx = t[2].x() - d.x(), cdy = t[2].y() - d.y();
    const double al = adx * adx + ady * ady, bl = bdx * bdx + bdy * bdy, cl = cdx * cdx + cdy * cdy;
    return al * (bdx * cdy - cdx * bdy) + bl * (cdx * ady - adx * cdy) + cl * (adx * bdy - bdx * ady);
  };
  std::vector<Face> stack;
  Cdt::Face_circulator fc = cdt_.incident_faces(v), done = fc;
  do stack.push_back(fc); while (++fc != done);
  std::reverse(stack.begin(), stack.end());
  while (!stack.empty()) {
    Face f = stack.back();
    stack.pop_back();
    const int i = f->index(v);
    Face n = f->neighbor(i);
    if (f->is_constrained(i) || cdt_.is_infinite(f) || cdt_.is_infinite(n)) continue;
    if (!(incircle({n->vertex(0)->point(), n->vertex(1)->point(), n->vertex(2)->point()}, v->point()) > 0)) continue;
    const P2 &a = f->vertex(Cdt::ccw(i))->point(), &b = f->vertex(Cdt::cw(i))->point(), &o = n->vertex(n->index(f))->point();
    if (CGAL::orientation(v->point(), a, o) != CGAL::LEFT_TURN || CGAL::orientation(v->point(), o, b) != CGAL::LEFT_TURN) continue;
    cdt_.flip(f, i);
    stack.push_back(n);
    stack.push_back(f);
  }
}

// After inserting v on a constrained edge, faces around v on the side of c
// (a vertex that was the apex there) take c_side, the others other_side.
void Mesher::set_domain_around(Vertex v, Vertex c, bool c_side, bool other_side) {
  Cdt::Face_circulator fc = cdt_.incident_faces(v), done = fc;
  for (int n = 0; !fc->has_vertex(c); ++n, ++fc)
    if (n > 1000000) return;  // cannot happen: the edge v-c exists after the split
  done = fc;
  bool side = c_side;
  do {
    int k = fc->index(v);
    if (!cdt_.is_infinite(fc)) fc->info().in_domain = side;
    if (fc->is_constrained(Cdt::ccw(k))) side = (side == c_side) ? other_side : c_side;
    ++fc;
  } while (fc != done);
}

Vertex Mesher::split_constrained(Face f, int i) {
  Vertex a = f->vertex(Cdt::ccw(i)), b = f->vertex(Cdt::cw(i));
  Face g = f->neighbor(i);
  Vertex c = f->vertex(i);
  bool f_in = in_domain(f), g_in = in_domain(g);
  P2 m((a->point().x() + b->point().x()) / 2, (a->point().y() + b->point().y()) / 2);
  int seg = segment_of_edge_.at(key(id(a), id(b)));
  Vertex v = opt_.has(Bug::double_flips) ? cdt_.Cdt::Ctr::insert(m, Cdt::EDGE, f, i) : cdt_.insert(m, Cdt::EDGE, f, i);
  if (opt_.has(Bug::double_flips)) legalize_in_double(v);
  v->info().id = static_cast<int>(pslg_.vertices.size() + steiner_.size());
  v->info().segments = {seg};
  steiner_.push_back(m);
  vertex_of_id_.push_back(v);
  segment_of_edge_.erase(key(id(a), id(b)));
  segment_of_edge_[key(id(a), id(v))] = seg;
  segment_of_edge_[key(id(v), id(b))] = seg;
  set_domain_around(v, c, f_in, g_in);
  return v;
}

Vertex Mesher::insert_point(const P2& q, Face hint) {
  Cdt::Locate_type lt;
  int li;
  Face loc = cdt_.locate(q, lt, li, hint);
  if (lt == Cdt::VERTEX || lt == Cdt::OUTSIDE_CONVEX_HULL || lt == Cdt::OUTSIDE_AFFINE_HULL || !in_domain(loc))
    return Vertex();
  if (lt == Cdt::EDGE && loc->is_constrained(li)) return Vertex();
  // The no-flips bug: the plain constrained triangulation's insertion, no Delaunay flips after it.
  const bool own_flips = opt_.has(Bug::no_flips) || opt_.has(Bug::double_flips);
  Vertex v = own_flips ? cdt_.Cdt::Ctr::insert(q, lt, loc, li) : cdt_.insert(q, lt, loc, li);
  if (opt_.has(Bug::double_flips)) legalize_in_double(v);
  v->info().id = static_cast<int>(pslg_.vertices.size() + steiner_.size());
  steiner_.push_back(q);
  vertex_of_id_.push_back(v);
  Cdt::Face_circulator fc = cdt_.incident_faces(v), done = fc;
  do {
    fc->info().in_domain = true;
  } while (++fc != done);
  return v;
}

// Lepp(f), then the paper's (New) Select Point, then the insertion.
bool Mesher::process(Face f) {
  // The Lepp: follow longest edges (the shortest-edge bug follows shortest ones).
  auto lepp_edge = [&](Face t) {
    std::array<int, 3> e = edges_sorted(t);
    return opt_.has(Bug::shortest_edge) ? e[0] : e[2];
  };
  Face t1 = f, t2;
  int l = lepp_edge(t1);
  for (int steps = 0;; ++steps) {
    if (steps > 1000000) return false;
    if (blocked(t1, l)) break;
    Face n = t1->neighbor(l);
    int ln = lepp_edge(n);
    if (n->neighbor(ln) == t1) {
      t2 = n;
      break;
    }
    t1 = n;
    l = ln;
  }
  Vertex v;
  if (t2 == Face()) {
    v = split_constrained(t1, l);  // constrained terminal edge: its midpoint
  } else {
    int l2 = t2->index(t1);
    int s1 = edges_sorted(t1)[1], s2 = edges_sorted(t2)[1];
    bool c1 = blocked(t1, s1), c2 = blocked(t2, s2);
    const P2 &A = p(t1, Cdt::ccw(l)), &B = p(t1, Cdt::cw(l)), &C = p(t1, l), &D = p(t2, l2);
    P2 quad((A.x() + B.x() + C.x() + D.x()) / 4, (A.y() + B.y() + C.y() + D.y()) / 4);
    if (opt_.has(Bug::area_centroid)) {
      // The quad's centre of mass: the triangles' centroids weighted by their areas.
      double w1 = std::fabs((B.x() - A.x()) * (C.y() - A.y()) - (B.y() - A.y()) * (C.x() - A.x()));
      double w2 = std::fabs((B.x() - A.x()) * (D.y() - A.y()) - (B.y() - A.y()) * (D.x() - A.x()));
      quad = P2((w1 * (A.x() + B.x() + C.x()) + w2 * (A.x() + B.x() + D.x())) / (3 * (w1 + w2)),
                (w1 * (A.y() + B.y() + C.y()) + w2 * (A.y() + B.y() + D.y())) / (3 * (w1 + w2)));
    }
    if (!opt_.centroid) {
      // Select Point: midpoint of l, or of the first constrained second-longest edge.
      if (c1) v = split_constrained(t1, s1);
      else if (c2) v = split_constrained(t2, s2);
      else if (opt_.has(Bug::centroid_not_midpoint)) v = insert_point(quad, t1);  // the centroid in the midpoint method
      else v = insert_point(P2((A.x() + B.x()) / 2, (A.y() + B.y()) / 2), t1);
    } else if (!c1 && !c2) {
      if (opt_.has(Bug::triangle_centroid))  // the terminal triangle's centroid, not the quad's
        v = insert_point(P2((A.x() + B.x() + C.x()) / 3, (A.y() + B.y() + C.y()) / 3), t1);
      else if (opt_.has(Bug::terminal_midpoint))  // Lepp-midpoint's point in the centroid method
        v = insert_point(P2((A.x() + B.x()) / 2, (A.y() + B.y()) / 2), t1);
      else
        v = insert_point(quad, t1);
    } else if (c1 && c2) {
      if (opt_.has(Bug::centroid_not_midpoint)) v = insert_point(quad, t1);  // the centroid where a midpoint is asked for
      else v = split_constrained(t2, s2);  // "a constrained second longest edge": t2's
    } else {
      // Remark 10: the centroid if it lies strictly inside the other triangle,
      // else the midpoint of the constrained second-longest edge.
      Face star = c1 ? t1 : t2, other = c1 ? t2 : t1;
      int ls = c1 ? s1 : s2;
      bool inside = true;
      for (int i = 0; i < 3; ++i)
        if (CGAL::orientation(p(other, Cdt::ccw(i)), p(other, Cdt::cw(i)), quad) != CGAL::LEFT_TURN) inside = false;
      if (opt_.has(Bug::remark10_reversed)) inside = !inside;  // the centroid when it lies in t*, the midpoint otherwise
      if (inside || opt_.has(Bug::no_remark10)) {
        v = insert_point(quad, other);
      } else if (opt_.has(Bug::other_second_longest)) {
        // The wrong second-longest edge: the other triangle's, not t*'s constrained one.
        int lo = c1 ? s2 : s1;
        const P2 &U = p(other, Cdt::ccw(lo)), &W = p(other, Cdt::cw(lo));
        v = insert_point(P2((U.x() + W.x()) / 2, (U.y() + W.y()) / 2), other);
      } else {
        v = split_constrained(star, ls);
      }
    }
  }
  if (v == Vertex()) return false;
  if (opt_.has(Bug::crash) && steiner_.size() >= 2) std::raise(SIGSEGV);  // dies mid-run
  return true;
}

void Mesher::collect_bad(std::vector<std::array<int, 3>>& stack) const {
  for (auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f)
    if (f->info().in_domain && bad(f) && !skipped(f) && !given_up_.count(face_key(f))) stack.push_back(face_key(f));
}

int Mesher::run(long max_insertions) {
  build();
  mark_domain();
  if (opt_.has(Bug::drop_segment)) {
    // Forgets the constraint of one interior segment once the domain is known.
    for (auto e = cdt_.finite_edges_begin(); e != cdt_.finite_edges_end(); ++e) {
      Face f = e->first;
      int i = e->second;
      if (f->is_constrained(i) && in_domain(f) && in_domain(f->neighbor(i))) {
        segment_of_edge_.erase(key(id(f->vertex(Cdt::ccw(i))), id(f->vertex(Cdt::cw(i)))));
        cdt_.remove_constrained_edge(f, i);  // its flips stay inside the domain
        break;
      }
    }
  }
  floor_ = std::numeric_limits<double>::infinity();
  for (const lepp::Segment& sg : pslg_.segments) {
    const lepp::Point &a = pslg_.vertices[sg.a], &b = pslg_.vertices[sg.b];
    floor_ = std::min(floor_, std::hypot(a.x - b.x, a.y - b.y) * 1e-6);
  }
  long budget = 20000 + 200 * static_cast<long>(pslg_.vertices.size() + pslg_.segments.size());
  // Processing order: a plain stack, refilled by a full sweep until nothing is bad.
  std::vector<std::array<int, 3>> stack;
  collect_bad(stack);
  while (!stack.empty()) {
    std::array<int, 3> k = stack.back();
    stack.pop_back();
    for (;;) {  // while t remains in the mesh
      Face f;
      if (!cdt_.is_face(vertex_of_id_[k[0]], vertex_of_id_[k[1]], vertex_of_id_[k[2]], f)) break;
      if (!in_domain(f) || !bad(f) || skipped(f) || given_up_.count(k)) break;
      if (insertions() >= max_insertions) return 0;
      if (insertions() >= budget) {
        std::fprintf(stderr, "lepp_test_mesher: loop guard: %ld Steiner points, giving up\n", insertions());
        return 3;
      }
      if (!process(f)) {
        given_up_.insert(k);
        break;
      }
      Vertex v = vertex_of_id_.back();
      if (too_close(v)) {
        std::fprintf(stderr, "lepp_test_mesher: loop guard: an edge shorter than %g after %ld Steiner points, giving up\n",
                     floor_, insertions());
        return 3;
      }
      Cdt::Face_circulator fc = cdt_.incident_faces(v), done = fc;
      do {
        if (in_domain(fc) && bad(fc) && !skipped(fc)) stack.push_back(face_key(fc));
      } while (++fc != done);
    }
    if (stack.empty()) collect_bad(stack);
  }
  if (!given_up_.empty())
    std::fprintf(stderr, "lepp_test_mesher: %zu bad triangles could not be refined\n", given_up_.size());
  return 0;
}

// One coordinate as written: %.17g, or through the arithmetic bugs (a float
// held where a double was computed, or a stream's default 6 digits).
void write_coordinate(FILE* f, double x, const Options& opt) {
  if (opt.has(Bug::printed_digits)) std::fprintf(f, "%g", x);
  else if (opt.has(Bug::single_precision)) std::fprintf(f, "%.17g", static_cast<double>(static_cast<float>(x)));
  else std::fprintf(f, "%.17g", x);
}

void write_trace(const std::string& path, const std::vector<P2>& pts, const Options& opt) {
  FILE* f = std::fopen(path.c_str(), "w");
  if (!f) return;
  std::fprintf(f, "# lepp_test_mesher: Steiner points in insertion order\n");
  for (const P2& q : pts) {
    write_coordinate(f, q.x(), opt);
    std::fputc(' ', f);
    write_coordinate(f, q.y(), opt);
    std::fputc('\n', f);
  }
  std::fclose(f);
}

void Mesher::write(const std::string& prefix) const {
  const int base = opt_.zero_based ? 0 : 1;
  std::vector<std::array<int, 3>> tris;
  std::set<std::pair<int, int>> constrained;
  for (auto f = cdt_.finite_faces_begin(); f != cdt_.finite_faces_end(); ++f) {
    if (!f->info().in_domain) continue;
    tris.push_back({id(f->vertex(0)), id(f->vertex(1)), id(f->vertex(2))});
    for (int i = 0; i < 3; ++i)
      if (f->is_constrained(i)) constrained.insert(key(id(f->vertex(Cdt::ccw(i))), id(f->vertex(Cdt::cw(i)))));
  }
  if (opt_.has(Bug::non_delaunay)) {
    // Flips one unconstrained edge whose quad is strictly convex and not cocircular:
    // the new edge is not Delaunay.
    std::map<std::pair<int, int>, std::pair<int, int>> owner;  // directed edge -> (triangle, apex)
    for (std::size_t t = 0; t < tris.size(); ++t)
      for (int i = 0; i < 3; ++i) owner[{tris[t][i], tris[t][(i + 1) % 3]}] = {static_cast<int>(t), tris[t][(i + 2) % 3]};
    auto pt = [&](int i) { return vertex_of_id_[i]->point(); };
    for (const auto& [e, tc] : owner) {
      auto it = owner.find({e.second, e.first});
      if (it == owner.end() || constrained.count(key(e.first, e.second))) continue;
      int a = e.first, b = e.second, c = tc.second, d = it->second.second;
      // (a, b, c) and (b, a, d) counter-clockwise; the quad is a, d, b, c.
      if (CGAL::orientation(pt(a), pt(d), pt(c)) != CGAL::LEFT_TURN ||
          CGAL::orientation(pt(d), pt(b), pt(c)) != CGAL::LEFT_TURN)
        continue;
      if (CGAL::side_of_oriented_circle(pt(a), pt(b), pt(c), pt(d)) != CGAL::ON_NEGATIVE_SIDE) continue;
      tris[static_cast<std::size_t>(tc.first)] = {a, d, c};
      tris[static_cast<std::size_t>(it->second.first)] = {d, b, c};
      break;
    }
  }
  if (opt_.has(Bug::inexact_incircle)) {
    // A last Delaunay pass as a double program writes it: the translated in-circle
    // determinant in double, "not Delaunay" when it is not clearly negative (within
    // 4 DBL_EPSILON of its permanent): a near-cocircular quad is flipped the other
    // way. One pass, no triangle flipped twice.
    std::map<std::pair<int, int>, std::pair<int, int>> owner;  // directed edge -> (triangle, apex)
    for (std::size_t t = 0; t < tris.size(); ++t)
      for (int i = 0; i < 3; ++i) owner[{tris[t][i], tris[t][(i + 1) % 3]}] = {static_cast<int>(t), tris[t][(i + 2) % 3]};
    auto pt = [&](int i) { return vertex_of_id_[i]->point(); };
    std::set<int> flipped;
    for (const auto& [e, tc] : owner) {
      auto it = owner.find({e.second, e.first});
      if (it == owner.end() || constrained.count(key(e.first, e.second))) continue;
      if (flipped.count(tc.first) || flipped.count(it->second.first)) continue;
      const int a = e.first, b = e.second, c = tc.second, d = it->second.second;
      if (CGAL::orientation(pt(a), pt(d), pt(c)) != CGAL::LEFT_TURN ||
          CGAL::orientation(pt(d), pt(b), pt(c)) != CGAL::LEFT_TURN)
        continue;
      const double adx = pt(a).x() - pt(d).x(), ady = pt(a).y() - pt(d).y(), bdx = pt(b).x() - pt(d).x(),
                   bdy = pt(b).y() - pt(d).y(), cdx = pt(c).x() - pt(d).x(), cdy = pt(c).y() - pt(d).y();
      const double al = adx * adx + ady * ady, bl = bdx * bdx + bdy * bdy, cl = cdx * cdx + cdy * cdy;
      const double det = al * (bdx * cdy - cdx * bdy) + bl * (cdx * ady - adx * cdy) + cl * (adx * bdy - bdx * ady);
      const double perm = (std::fabs(bdx * cdy) + std::fabs(cdx * bdy)) * al +
                          (std::fabs(cdx * ady) + std::fabs(adx * cdy)) * bl + (std::fabs(adx * bdy) + std::fabs(bdx * ady)) * cl;
      if (det < -4 * DBL_EPSILON * perm || det == 0) continue;  // clearly Delaunay, or exactly cocircular: kept
      tris[static_cast<std::size_t>(tc.first)] = {a, d, c};
      tris[static_cast<std::size_t>(it->second.first)] = {d, b, c};
      flipped.insert(tc.first), flipped.insert(it->second.first);
    }
  }
  FILE* node = std::fopen((prefix + ".node").c_str(), "w");
  FILE* ele = std::fopen((prefix + ".ele").c_str(), "w");
  if (!node || !ele) {
    std::fprintf(stderr, "lepp_test_mesher: cannot write %s.node/.ele\n", prefix.c_str());
    std::exit(1);
  }
  if (opt_.has(Bug::garbage)) {
    std::fprintf(node, "this is not a node file\n");
    std::fprintf(ele, "%zu 3 0\n1 2 3\n@@@\n", tris.size() + 7);
  } else {
    std::fprintf(node, "%zu 2 0 0\n", vertex_of_id_.size());
    for (std::size_t i = 0; i < vertex_of_id_.size(); ++i) {
      std::fprintf(node, "%zu ", i + base);
      write_coordinate(node, vertex_of_id_[i]->point().x(), opt_);
      std::fputc(' ', node);
      write_coordinate(node, vertex_of_id_[i]->point().y(), opt_);
      std::fputc('\n', node);
    }
    std::fprintf(ele, "%zu 3 0\n", tris.size());
    for (std::size_t t = 0; t < tris.size(); ++t)
      std::fprintf(ele, "%zu %d %d %d\n", t + base, tris[t][0] + base, tris[t][1] + base, tris[t][2] + base);
  }
  std::fclose(node);
  std::fclose(ele);
  write_trace(prefix + ".trace", steiner_, opt_);
}

}  // namespace

int main(int argc, char** argv) {
  Options opt = parse(argc, argv);
  lepp::Pslg pslg;
  try {
    std::vector<std::string> warnings;
    lepp::Pslg read = lepp::read_poly(opt.in);
    if (opt.has(Bug::float_input))
      for (lepp::Point& v : read.vertices) v = {static_cast<float>(v.x), static_cast<float>(v.y)};
    pslg = lepp::validate(read, warnings);
  } catch (const lepp::InputError& e) {
    std::fprintf(stderr, "lepp_test_mesher: %s\n", e.what());
    return 2;
  }
  int status;
  if (opt.has(Bug::skinny)) {
    // Stops one insertion early: the triangle the last point was for stays bad.
    long total;
    {
      Mesher probe(pslg, opt);
      probe.run(-1 + (1L << 62));
      total = probe.insertions();
    }
    Mesher m(pslg, opt);
    status = m.run(std::max(0L, total - 1));
    m.write(opt.out);
  } else {
    Mesher m(pslg, opt);
    status = m.run(1L << 62);
    if (opt.has(Bug::loop) && m.insertions() > 0)
      for (;;) std::this_thread::sleep_for(std::chrono::seconds(1));  // never ends
    m.write(opt.out);
  }
  (void)status;  // 3 (guard) is reported on stderr only
  return 0;
}
