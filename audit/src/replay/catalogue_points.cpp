// SPDX-License-Identifier: GPL-3.0-or-later
// The deviation catalogue's points at a terminal configuration and at a bad
// triangle (catalogue_points.h), each tagged with the deviation that makes it.
#include "catalogue_points.h"

namespace lepp::audit::replay_detail {

template <class T>
std::vector<Candidate> catalogue_points(const ReplayRules& rules, const T& t1, const T& t2, bool has_t2, int l,
                                        const Point* near) {
  std::vector<Candidate> out;
  auto add = [&](Deviation d, Candidate c) {
    c.deviation = d;
    out.push_back(c);
  };
  VH a = vtx(t1, Cdt::ccw(l)), b = vtx(t1, Cdt::cw(l)), c = vtx(t1, l);
  auto tri_centroid = [&](VH x, VH y, VH z, Rule rule) {
    double scale = std::max({abs_max(x->point()), abs_max(y->point()), abs_max(z->point())});
    Candidate out{rule, triangle_centroid(x->point(), y->point(), z->point()), scale, {}, {}};
    out.mean = mean_of({x, y, z});
    return out;
  };
  // The midpoints of a terminal triangle's two other edges.
  auto other_edges = [&](const T& f, int term) {
    for (int e : {Cdt::ccw(term), Cdt::cw(term)}) add(Deviation::OtherSecondLongest, midpoint(Rule::SecondLongestMidpoint, f, e));
  };
  if (!has_t2) {
    add(Deviation::TriangleCentroid, tri_centroid(a, b, c, Rule::TerminalConstrainedMidpoint));
    other_edges(t1, l);
    return out;
  }
  const int l2 = index_off(t2, a, b);
  VH d = vtx(t2, l2);
  const CentroidReading reading = rules.centroid;
  const CentroidReading other_reading = reading == CentroidReading::Vertex ? CentroidReading::Area : CentroidReading::Vertex;
  // The area reading has no point on a flat quad (none: no such deviation there).
  const std::optional<Candidate> g = quad_centroid(Rule::QuadCentroid, t1, t2, l, reading);
  // The other reading's centroid, only where it is another point (on a
  // parallelogram both readings are the same point: no deviation of reading).
  const bool other_far = near && other_reading == CentroidReading::Area && area_centroid_beyond(rules, *near, a, b, c, d);
  const std::optional<Candidate> g_other =
      other_far ? std::nullopt : quad_centroid(Rule::QuadCentroid, t1, t2, l, other_reading);
  if (g_other && (!g || g_other->point != g->point))
    add(reading == CentroidReading::Vertex ? Deviation::AreaCentroid : Deviation::VertexCentroid, *g_other);
  add(Deviation::TriangleCentroid, tri_centroid(a, b, c, Rule::QuadCentroid));
  add(Deviation::TriangleCentroid, tri_centroid(a, b, d, Rule::QuadCentroid));
  // On a parallelogram the terminal midpoint is the quad centroid: then the
  // centroid's rules (below) name it.
  const Candidate m = midpoint(Rule::TerminalMidpoint, t1, l);
  if (!g || m.point != g->point) add(Deviation::TerminalMidpoint, m);
  for (int s1 : second_longest_given(t1, l))
    for (int s2 : second_longest_given(t2, l2)) {
      bool c1 = constrained(t1, s1), c2 = constrained(t2, s2);
      if (!g) continue;  // the rules below are about the centroid
      if (rules.method == Method::Midpoint || (c1 && c2)) {
        add(Deviation::CentroidNotMidpoint, *g);
      } else if (c1 != c2) {
        const T& star = c1 ? t1 : t2;
        const T& other = c1 ? t2 : t1;
        int inside = inside_status(other, *g, point_tolerance(rules, g->scale));
        // The paper: the midpoint only. Both programs take the centroid here;
        // Remark10Ignored ranks first, the trace tells them apart (conformance.cpp).
        if (inside < 0) add(Deviation::Remark10Ignored, *g), add(Deviation::Remark10Reversed, *g);
        if (inside > 0) add(Deviation::Remark10Reversed, midpoint(Rule::SecondLongestMidpoint, star, c1 ? s1 : s2));
      }
    }
  other_edges(t1, l);
  other_edges(t2, l2);
  return out;
}

template std::vector<Candidate> catalogue_points(const ReplayRules&, const FH&, const FH&, bool, int, const Point*);
template std::vector<Candidate> catalogue_points(const ReplayRules&, const CellTri&, const CellTri&, bool, int, const Point*);

// The bad triangle's circumcenter and off-center (Ungor: on the bisector of
// its shortest edge pq, where the triangle pq-point has the angle theta at
// the point; the circumcenter when that is nearer). The off-center is
// irrational (a tangent): it is computed in long double from the exact
// circumcenter, the only catalogue point that is not an exact rational.
std::vector<Candidate> triangle_points(const ReplayRules& rules, FH f) {
  std::vector<Candidate> out;
  const CPoint &a = f->vertex(0)->point(), &b = f->vertex(1)->point(), &c = f->vertex(2)->point();
  const std::optional<CPoint> center = guarded_circumcenter(a, b, c);
  if (!center) return out;  // a flat triangle has neither point
  const CPoint& cc = *center;
  double scale = std::max({abs_max(a), abs_max(b), abs_max(c), abs_max(cc)});
  out.push_back({Rule::QuadCentroid, cc, scale, {}, {}, Deviation::Circumcenter});
  int e = 0;
  for (int k = 1; k < 3; ++k)
    if (compare_len_exact(f, k, e) == CGAL::SMALLER) e = k;
  const CPoint &p = f->vertex(Cdt::ccw(e))->point(), &q = f->vertex(Cdt::cw(e))->point();
  using LD = long double;
  const LD mx = (LD(CGAL::to_double(p.x())) + LD(CGAL::to_double(q.x()))) / 2;
  const LD my = (LD(CGAL::to_double(p.y())) + LD(CGAL::to_double(q.y()))) / 2;
  const LD cx = LD(CGAL::to_double(cc.x())), cy = LD(CGAL::to_double(cc.y()));
  const LD half = std::sqrt(LD(CGAL::to_double(CGAL::squared_distance(p, q)))) / 2;
  const LD h = half / std::tan(LD(rules.min_angle_deg) * LD(M_PI) / 360);
  const LD dist = std::hypot(cx - mx, cy - my);
  if (dist > h && dist > 0) {
    const double ox = static_cast<double>(mx + (cx - mx) * (h / dist)), oy = static_cast<double>(my + (cy - my) * (h / dist));
    if (std::isfinite(ox) && std::isfinite(oy))
      out.push_back({Rule::QuadCentroid, CPoint(ox, oy), std::max(scale, std::max(std::abs(ox), std::abs(oy))), {}, {},
                     Deviation::OffCenter});
  }
  return out;
}

}  // namespace lepp::audit::replay_detail
