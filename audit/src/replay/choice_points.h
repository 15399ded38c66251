// SPDX-License-Identifier: GPL-3.0-or-later
// The exact points a choice may be (the paper's and the deviation catalogue's):
// a terminal configuration, a candidate point with its scale for the point
// tolerance, and the constructions both kinds of choice are made of.
#pragma once
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <optional>

#include <CGAL/Interval_nt.h>
#include <CGAL/Mpzf.h>

#include "distance_filter.h"
#include "exact_constructions.h"
#include "lepp/audit/replay.h"
#include "mean_difference.h"
#include "tie_order.h"

namespace lepp::audit::replay_detail {

// A terminal configuration: terminal edge l of t1, and t2 across it (null if l is constrained).
struct Terminal {
  FH t1, t2;
  int l = -1;
};

// A point a rule may choose there.
struct Candidate {
  Rule rule;
  CPoint point;
  double scale = 0;        // largest |coordinate| of the vertices defining the point
  VH split_a, split_b;     // the constrained edge it splits, or null
  Deviation deviation = Deviation::Unknown;  // Unknown: the paper's choice; else the catalogue rule that made it
  MeanOf mean;             // point is the mean of these doubles (a midpoint, a centroid of vertices), if n > 0
};

// The point as doubles when it is one: its interval approximation a point (so are the
// input's vertices and every vertex the replay inserts); else none. Read so, no lazy
// coordinate node is built (to_double(p.x()) makes one, an allocation).
inline std::optional<Point> doubles_of(const CPoint& p) {
  const auto& a = CGAL::approx(p);
  Point d;
  if (!CGAL::fit_in_double(a.x(), d.x) || !CGAL::fit_in_double(a.y(), d.y)) return std::nullopt;
  return d;
}

// The mean of the vertices' points, when each is a point of doubles; else none (n = 0).
inline MeanOf mean_of(std::initializer_list<VH> vs) {
  MeanOf m;
  for (VH v : vs) {
    const std::optional<Point> d = doubles_of(v->point());
    if (!d) return {};
    m.x[static_cast<std::size_t>(m.n)] = d->x, m.y[static_cast<std::size_t>(m.n)] = d->y, ++m.n;
  }
  return m;
}

inline double abs_max(const CPoint& p) {
  if (const std::optional<Point> d = doubles_of(p)) return std::max(std::abs(d->x), std::abs(d->y));
  return std::max(std::abs(CGAL::to_double(p.x())), std::abs(CGAL::to_double(p.y())));
}

// The candidate's point rounded to the nearest doubles (round_nearest), without GMP
// where it is a mean of doubles (mean_nearest).
inline Point rounded_point(const Candidate& c) {
  auto coord = [&](const FT& x, const std::array<double, 4>& m) {
    const std::optional<double> r = mean_nearest(m.data(), c.mean.n);
    return r ? *r : round_nearest(x);
  };
  return {coord(c.point.x(), c.mean.x), coord(c.point.y(), c.mean.y)};
}

// The point tolerance for a choice of this scale (ReplayRules::point_tolerance_ulps).
// Under MeshReading::FloatPoints the same number of float units (FLT_EPSILON, the
// smallest subnormal float): a program that holds floats rounds there.
inline double point_tolerance(const ReplayRules& rules, double scale) {
  double ulps = std::max(rules.point_tolerance_ulps, 0.0);
  if (rules.mesh == MeshReading::FloatPoints)
    return std::max(ulps * FLT_EPSILON * scale, ulps * double(std::numeric_limits<float>::denorm_min()));
  return std::max(ulps * DBL_EPSILON * scale, ulps * std::numeric_limits<double>::denorm_min());
}

// The exact centroid of a triangle.
inline CPoint triangle_centroid(const CPoint& a, const CPoint& b, const CPoint& c) {
  return CPoint((a.x() + b.x() + c.x()) / 3, (a.y() + b.y() + c.y()) / 3);
}

// The exact midpoint of edge i of f, with the edge when it is constrained (a split).
template <class T>
Candidate midpoint(Rule rule, const T& f, int i) {
  VH a = vtx(f, Cdt::ccw(i)), b = vtx(f, Cdt::cw(i));
  Candidate c{rule, CGAL::midpoint(a->point(), b->point()), std::max(abs_max(a->point()), abs_max(b->point())), {}, {}};
  if (constrained(f, i)) c.split_a = a, c.split_b = b;
  c.mean = mean_of({a, b});
  return c;
}

// The quad's centroid under the given reading, and its scale for the
// tolerance. The area centroid's rounding error in doubles grows with M / |ab|
// (its weights are cross products: eps M^2 absolute error on an area of size
// |ab|^2), so its scale is M * max(1, M / |ab|).
template <class T>
std::optional<Candidate> quad_centroid(Rule rule, const T& t1, const T& t2, int l, CentroidReading reading) {
  VH a = vtx(t1, Cdt::ccw(l)), b = vtx(t1, Cdt::cw(l)), c = vtx(t1, l);
  VH d = vtx(t2, index_off(t2, a, b));
  double scale = std::max({abs_max(a->point()), abs_max(b->point()), abs_max(c->point()), abs_max(d->point())});
  if (reading == CentroidReading::Vertex) {
    CPoint g(((a->point().x() + b->point().x()) + (c->point().x() + d->point().x())) / 4,
             ((a->point().y() + b->point().y()) + (c->point().y() + d->point().y())) / 4);
    Candidate out{rule, g, scale, {}, {}};
    out.mean = mean_of({a, b, c, d});
    return out;
  }
  double ab = std::sqrt(CGAL::to_double(CGAL::squared_distance(a->point(), b->point())));
  if (ab > 0 && scale / ab > 1) scale *= scale / ab;
  const std::optional<CPoint> g = guarded_area_centroid(a->point(), b->point(), c->point(), d->point());
  if (!g) return std::nullopt;  // a flat quad has no area centroid: no such choice
  return Candidate{rule, *g, scale, {}, {}};
}

// True only when p is surely farther (in the max norm) than its tolerance from the
// quad's area centroid, as quad_centroid would make it, decided from the vertices'
// doubles in interval arithmetic before its lazy-exact construction (which the search
// around a point would build only to drop). Conservative on every rounding: the scale
// from a lower bound of |ab| (quad_centroid reads it through to_double), and the
// tolerance raised by 2^-10 of itself (the replay's distance reads each difference
// through to_double, up to 1e-5 of it low). False says nothing.
inline bool area_centroid_beyond(const ReplayRules& rules, const Point& p, VH a, VH b, VH c, VH d) {
  const std::optional<Point> A = doubles_of(a->point()), B = doubles_of(b->point()), C = doubles_of(c->point()),
                             D = doubles_of(d->point());
  if (!A || !B || !C || !D) return false;
  using I = CGAL::Interval_nt<true>;
  const I ax(A->x), ay(A->y), bx(B->x), by(B->y), cx(C->x), cy(C->y), dx(D->x), dy(D->y);
  const I w1 = CGAL::abs((bx - ax) * (cy - ay) - (by - ay) * (cx - ax));
  const I w2 = CGAL::abs((bx - ax) * (dy - ay) - (by - ay) * (dx - ax));
  const I w = I(3) * (w1 + w2);
  if (!(w.inf() > 0)) return false;
  const I gx = (w1 * (ax + bx + cx) + w2 * (ax + bx + dx)) / w, gy = (w1 * (ay + by + cy) + w2 * (ay + by + dy)) / w;
  const I ab2 = CGAL::square(bx - ax) + CGAL::square(by - ay);
  const double ab_lo = std::sqrt(ab2.inf()) * (1 - 0x1p-10);
  if (!(ab_lo > 0)) return false;
  const double m = std::max({std::abs(A->x), std::abs(A->y), std::abs(B->x), std::abs(B->y), std::abs(C->x), std::abs(C->y),
                             std::abs(D->x), std::abs(D->y)});
  const double scale_hi = m * std::max(1.0, m / ab_lo) * (1 + 0x1p-20);
  const double tol_hi = point_tolerance(rules, scale_hi) * (1 + 0x1p-10);
  return std::isfinite(tol_hi) && surely_farther(p, gx, gy, tol_hi);
}

// What bounds every candidate at a terminal configuration before any is built:
// the box of its vertices (every candidate is a midpoint or a centroid of them,
// of either reading) and upper bounds of the candidates' scales (quad_centroid's):
// the largest |coordinate| M of the vertices for midpoints, triangle centroids and
// the vertex reading; for the area reading M * M / |ab| when |ab| < M, with |ab|
// taken low by more than its rounding in quad_centroid (infinity when |ab|'s
// interval reaches 0).
struct TerminalBound {
  ApproxBox box;
  double scale = 0;       // no candidate of the area reading
  double area_scale = 0;  // any candidate
};

inline TerminalBound terminal_bound(const Terminal& t) {
  TerminalBound out;
  VH a = vtx(t.t1, Cdt::ccw(t.l)), b = vtx(t.t1, Cdt::cw(t.l));
  for (int i = 0; i < 3; ++i) out.box.add(t.t1->vertex(i)->point());
  if (t.t2 != FH()) out.box.add(vtx(t.t2, index_off(t.t2, a, b))->point());
  out.scale = out.area_scale = out.box.abs_max();
  if (t.t2 == FH()) return out;  // no quad: no centroid of either reading
  using I = CGAL::Interval_nt<true>;
  const auto &pa = CGAL::approx(a->point()), &pb = CGAL::approx(b->point());
  const I dx = I(pa.x().inf(), pa.x().sup()) - I(pb.x().inf(), pb.x().sup());
  const I dy = I(pa.y().inf(), pa.y().sup()) - I(pb.y().inf(), pb.y().sup());
  const double ab = CGAL::sqrt(dx * dx + dy * dy).inf() * (1 - 0x1p-10);
  const double m = out.scale;
  if (!(ab > 0)) out.area_scale = std::numeric_limits<double>::infinity();
  else if (m / ab > 1) out.area_scale = m * (m / ab) * (1 + 0x1p-10);
  return out;
}

// 1 strictly inside f farther than tol from its boundary, -1 not strictly
// inside and farther than tol from it, 0 within tol of the boundary.
template <class T>
int inside_status(const T& f, const CPoint& p, double tol) {
  bool strictly = true, near = false;
  for (int i = 0; i < 3; ++i) {
    const CPoint &u = vtx(f, Cdt::ccw(i))->point(), &v = vtx(f, Cdt::cw(i))->point();
    if (CGAL::orientation(u, v, p) != CGAL::LEFT_TURN) strictly = false;
    // Distance |det| / |uv| <= tol, squared and exact: in doubles the cross product
    // and the squared length of subnormal coordinates underflow to 0 (0/0 is never near).
    FT det = (v.x() - u.x()) * (p.y() - u.y()) - (v.y() - u.y()) * (p.x() - u.x());
    if (det * det <= FT(tol) * FT(tol) * CGAL::squared_distance(u, v)) near = true;
  }
  if (near) return 0;
  return strictly ? 1 : -1;
}

// inside_status of a candidate: where its point is a mean of doubles (a centroid of
// vertices) and f's vertices are doubles, the same two signs for each side uv, from
// the doubles: with S the sums of the mean's n coordinates, D = (v - u) x (S - n u) is n
// times the cross product, so orientation is sign(D) and "near" is D^2 <= n^2 tol^2
// |uv|^2. Intervals first, then CGAL::Mpzf (exact +, -, * on doubles): no lazy node,
// no GMP rational. A cluster a few ulps wide left the lazy comparison undecided at
// nearly every quad, each an exact evaluation (40 % of a slow fuzz_engine unit).
template <class T>
int inside_status(const T& f, const Candidate& g, double tol) {
  if (g.mean.n <= 0) return inside_status(f, g.point, tol);
  std::optional<Point> x[3];
  for (int i = 0; i < 3; ++i)
    if (!(x[i] = doubles_of(vtx(f, i)->point()))) return inside_status(f, g.point, tol);
  const MeanOf& m = g.mean;
  auto signs = [&](const Point& u, const Point& v, auto zero) {
    using NT = decltype(zero);
    NT sx = zero, sy = zero;
    for (int k = 0; k < m.n; ++k) sx = sx + NT(m.x[static_cast<std::size_t>(k)]), sy = sy + NT(m.y[static_cast<std::size_t>(k)]);
    const NT n(static_cast<double>(m.n)), ex = NT(v.x) - NT(u.x), ey = NT(v.y) - NT(u.y);
    const NT d = ex * (sy - n * NT(u.y)) - ey * (sx - n * NT(u.x));
    const NT t(tol);
    return std::make_pair(d, n * n * t * t * (ex * ex + ey * ey) - d * d);  // D, and >= 0 when near
  };
  bool strictly = true, near = false;
  for (int i = 0; i < 3; ++i) {
    const Point &u = *x[static_cast<std::size_t>(Cdt::ccw(i))], &v = *x[static_cast<std::size_t>(Cdt::cw(i))];
    int left = 2, within = 2;  // sign(D) > 0, near; 2: the intervals left it open
    {
      CGAL::Protect_FPU_rounding<true> guard;
      const auto [d, slack] = signs(u, v, CGAL::Interval_nt<false>(0));
      if (d.inf() > 0) left = 1;
      else if (d.sup() <= 0) left = 0;
      if (slack.inf() >= 0) within = 1;
      else if (slack.sup() < 0) within = 0;
    }
    if (left == 2 || within == 2) {
      const auto [d, slack] = signs(u, v, CGAL::Mpzf(0));
      left = CGAL::sign(d) > 0, within = CGAL::sign(slack) >= 0;
    }
    if (!left) strictly = false;
    if (within) near = true;
  }
  if (near) return 0;
  return strictly ? 1 : -1;
}

}  // namespace lepp::audit::replay_detail
