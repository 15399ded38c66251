// SPDX-License-Identifier: GPL-3.0-or-later
// Replay of a trace on the exact reference, with the paper's choices at each
// step (docs/AUDIT.md, "Conformance"). Ties in the edge order are branched on
// instead of broken by ids: any total order of the edges consistent with their
// lengths is allowed, so a triangle may have several longest (or second
// longest) edges, and a Lepp several ends.
#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <deque>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>

#include "lepp/angle.h"
#include "cocircular_cells.h"
#include "double_predicates.h"
#include "exact_constructions.h"
#include "lepp/reference_replay.h"
#include "triangulation.h"

namespace lepp::reference {

using namespace detail;

namespace {

// The rules below read a triangle through these: a face of the mesh, or a
// triangle of a cocircular cell's other triangulations (cocircular_cells.h).
VH vtx(FH f, int i) { return f->vertex(i); }
VH vtx(const CellTri& t, int i) { return t.v[static_cast<std::size_t>(i)]; }
bool constrained(FH f, int i) { return f->is_constrained(i); }
bool constrained(const CellTri& t, int i) { return t.constrained[static_cast<std::size_t>(i)]; }

template <class T>
FT len2(const T& f, int i) {
  return CGAL::squared_distance(vtx(f, Cdt::ccw(i))->point(), vtx(f, Cdt::cw(i))->point());
}

// Squared length of edge i of f in doubles: a filter. The coordinates are
// doubles, so each of dx, dy, dx*dx, dy*dy and the sum is off by at most half
// an ulp: the result is within a relative 4 DBL_EPSILON of the exact value
// unless something underflowed or overflowed (checked by the caller).
template <class T>
double approx_len2(const T& f, int i) {
  const auto& a = vtx(f, Cdt::ccw(i))->point().approx();
  const auto& b = vtx(f, Cdt::cw(i))->point().approx();
  if (a.x().inf() != a.x().sup() || a.y().inf() != a.y().sup() || b.x().inf() != b.x().sup() ||
      b.y().inf() != b.y().sup())
    return std::numeric_limits<double>::quiet_NaN();  // not a double point: decide exactly
  double dx = a.x().inf() - b.x().inf(), dy = a.y().inf() - b.y().inf();
  return dx * dx + dy * dy;
}

// The double endpoints of edge i of f in p, q; false if a point is not a double.
template <class T>
bool double_edge(const T& f, int i, Point& p, Point& q) {
  const auto& a = vtx(f, Cdt::ccw(i))->point().approx();
  const auto& b = vtx(f, Cdt::cw(i))->point().approx();
  p = {a.x().inf(), a.y().inf()}, q = {b.x().inf(), b.y().inf()};
  return a.x().is_point() && a.y().is_point() && b.x().is_point() && b.y().is_point();
}

// Compares the lengths of edges i and j of f: filtered, exact when needed (on
// the doubles, double_predicates.h: lazy Epeck's Gmpq took minutes on ulp clusters).
template <class T>
CGAL::Comparison_result compare_len_exact(const T& f, int i, int j) {
  double li = approx_len2(f, i), lj = approx_len2(f, j), m = std::max(li, lj);
  if (std::isfinite(li) && std::isfinite(lj) && m > 1e-280 && std::abs(li - lj) > 16 * DBL_EPSILON * m)
    return li < lj ? CGAL::SMALLER : CGAL::LARGER;
  Point a, b, c, d;
  if (double_edge(f, i, a, b) && double_edge(f, j, c, d))
    return static_cast<CGAL::Comparison_result>(compare_squared_lengths(a, b, c, d));
  return CGAL::compare(len2(f, i), len2(f, j));
}

// Deviation::InexactLength: the Lepp's length comparisons count two squared
// lengths within 8 DBL_EPSILON (relative, exactly) of each other as a tie, the
// rounding a double computation of dx*dx + dy*dy may make on each side. Set
// around the searches that allow it (LengthTiesWithinRounding): the Lepp helpers
// here are free functions shared by the mesh's faces and the cells' triangles.
thread_local bool length_ties_within_rounding = false;

struct LengthTiesWithinRounding {
  bool saved = length_ties_within_rounding;
  explicit LengthTiesWithinRounding(bool on) { length_ties_within_rounding = on; }
  ~LengthTiesWithinRounding() { length_ties_within_rounding = saved; }
  LengthTiesWithinRounding(const LengthTiesWithinRounding&) = delete;
  LengthTiesWithinRounding& operator=(const LengthTiesWithinRounding&) = delete;
};

// Deviation::InexactThreshold: a triangle whose smallest angle alpha has
// sin^2 alpha < sin2_bracket(theta).hi + 16 DBL_EPSILON (exactly) may count as
// bad. A double program's "alpha < theta" flips only where |cos alpha - cos
// theta| is within its rounding (about 8 DBL_EPSILON: cos from a dot product
// or the law of cosines, and cos theta), and |sin^2 alpha - sin^2 theta| =
// |cos alpha - cos theta| (cos alpha + cos theta) <= 16 DBL_EPSILON; an atan2
// angle errs by a few DBL_EPSILON radians, which moves sin^2 by no more.
constexpr double kThresholdRounding = 16 * DBL_EPSILON;

// The comparison the Lepp reads: exact, or with near ties (above) as ties. The
// filter decides only beyond 16 DBL_EPSILON, outside that band.
template <class T>
CGAL::Comparison_result compare_len(const T& f, int i, int j) {
  const CGAL::Comparison_result r = compare_len_exact(f, i, j);
  if (r == CGAL::EQUAL || !length_ties_within_rounding) return r;
  const FT a = len2(f, i), b = len2(f, j);
  return CGAL::abs(a - b) <= FT(8 * DBL_EPSILON) * CGAL::max(a, b) ? CGAL::EQUAL : r;
}

template <class T>
bool is_longest(const T& f, int i) {
  return compare_len(f, i, Cdt::ccw(i)) != CGAL::SMALLER && compare_len(f, i, Cdt::cw(i)) != CGAL::SMALLER;
}

// Indices of the edges of f of maximal length (several on ties).
template <class T>
std::vector<int> longest_edges(const T& f) {
  std::vector<int> out;
  for (int i = 0; i < 3; ++i)
    if (is_longest(f, i)) out.push_back(i);
  return out;
}

// The second-longest edges of f when edge l is its longest: the longer of the
// other two, both on a tie.
template <class T>
std::vector<int> second_longest_given(const T& f, int l) {
  int j = Cdt::ccw(l), k = Cdt::cw(l);
  CGAL::Comparison_result r = compare_len(f, j, k);
  if (r == CGAL::LARGER) return {j};
  if (r == CGAL::SMALLER) return {k};
  return {j, k};
}

// The index in g of its vertex that is not a or b (the edge a-b is g's edge of that index).
template <class T>
int index_off(const T& g, VH a, VH b) {
  for (int i = 0; i < 3; ++i)
    if (vtx(g, i) != a && vtx(g, i) != b) return i;
  return -1;
}

// Smallest angle below theta (exactly: sin^2 compared as in geometry.cpp's
// is_skinny, at the vertex opposite a shortest edge).
bool skinny(const CellTri& t, const FT& sin2) {
  int i = 0;
  for (int k = 1; k < 3; ++k)
    if (compare_len_exact(t, k, i) == CGAL::SMALLER) i = k;
  const CPoint& o = vtx(t, i)->point();
  K::Vector_2 u = vtx(t, Cdt::ccw(i))->point() - o, v = vtx(t, Cdt::cw(i))->point() - o;
  FT cross = u.x() * v.y() - u.y() * v.x();
  return cross * cross < sin2 * u.squared_length() * v.squared_length();
}

bool too_big(const CellTri& t, const FT& twice_max_area) {
  const CPoint &a = vtx(t, 0)->point(), &b = vtx(t, 1)->point(), &c = vtx(t, 2)->point();
  FT cross = (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
  return CGAL::abs(cross) > twice_max_area;
}

// p in the closed triangle t or near it (a loose test in doubles, coordinates
// scaled by a power of two: only a filter before the exact distance tests).
bool near_triangle(const CellTri& t, const Point& p) {
  double m = std::max(std::abs(p.x), std::abs(p.y));
  std::array<Point, 3> q;
  for (int i = 0; i < 3; ++i) {
    q[static_cast<std::size_t>(i)] = {CGAL::to_double(vtx(t, i)->point().x()), CGAL::to_double(vtx(t, i)->point().y())};
    m = std::max({m, std::abs(q[static_cast<std::size_t>(i)].x), std::abs(q[static_cast<std::size_t>(i)].y)});
  }
  if (!(m > 0) || !std::isfinite(m)) return true;
  int e = 0;
  std::frexp(m, &e);
  const double px = std::ldexp(p.x, -e), py = std::ldexp(p.y, -e);
  for (int i = 0; i < 3; ++i) {
    const Point &u = q[static_cast<std::size_t>(i)], &v = q[static_cast<std::size_t>((i + 1) % 3)];
    const double ux = std::ldexp(u.x, -e), uy = std::ldexp(u.y, -e), dx = std::ldexp(v.x, -e) - ux, dy = std::ldexp(v.y, -e) - uy;
    if ((dx * (py - uy) - dy * (px - ux)) < -1e-9 * std::hypot(dx, dy) - 1e-300) return false;
  }
  return true;
}

double abs_max(const CPoint& p) {
  return std::max(std::abs(CGAL::to_double(p.x())), std::abs(CGAL::to_double(p.y())));
}

// A terminal configuration: terminal edge l of t1, and t2 across it (null if l is constrained).
struct Terminal {
  FH t1, t2;
  int l = -1;
};

// A point the paper's Select Point / New Select Point may choose there.
struct Candidate {
  Rule rule;
  CPoint point;
  double scale = 0;        // largest |coordinate| of the vertices defining the point
  VH split_a, split_b;     // the constrained edge it splits, or null
  Deviation deviation = Deviation::Unknown;  // Unknown: the paper's choice; else the catalogue rule that made it
};

// The exact centroid of a triangle.
CPoint triangle_centroid(const CPoint& a, const CPoint& b, const CPoint& c) {
  return CPoint((a.x() + b.x() + c.x()) / 3, (a.y() + b.y() + c.y()) / 3);
}

}  // namespace

struct Replay::Impl {
  Pslg pslg;  // a copy: the Triangulation keeps a pointer to it
  ReplayRules rules;
  Triangulation tr;
  FT sin2_;
  // sin^2 theta's certified upper end + 16 DBL_EPSILON (kThresholdRounding).
  FT sin2_rounding_;
  // Set around the searches that take triangles within double rounding of
  // theta as bad too (InexactThreshold allowed).
  mutable bool threshold_within_rounding_ = false;
  // Twice the size bound of each region (index 0: no region), as the reference
  // engine computes them (refine.cpp): the smaller of the region's and max_area.
  std::vector<std::optional<FT>> bounds_;
  VH last_;  // the last vertex inserted: where to start locating the next point

  FH hint() const { return last_ != VH() ? last_->face() : FH(); }

  Impl(const Pslg& p, const ReplayRules& r) : pslg(p), rules(r) {
    // Every rule below becomes an exact number: a NaN or an infinity would be
    // GMP's invalid operation (SIGFPE), so they are refused here.
    if (!(r.min_angle_deg > 0 && r.min_angle_deg < 60))
      throw std::invalid_argument("replay: the angle must be between 0 and 60 degrees");
    if (!std::isfinite(r.angle_tolerance_deg) || !std::isfinite(r.point_tolerance_ulps))
      throw std::invalid_argument("replay: the angle and point tolerances must be finite");
    double theta = std::min(r.min_angle_deg + std::max(r.angle_tolerance_deg, 0.0), 60.0);
    sin2_ = FT(sin2_bracket(theta).hi);
    sin2_rounding_ = FT(sin2_bracket(r.min_angle_deg).hi) + FT(kThresholdRounding);
    build_triangulation(pslg, tr);
    bounds_.push_back(r.max_area > 0 ? std::optional<FT>(FT(r.max_area) * 2) : std::nullopt);
    if (r.region_area_bounds) {
      assign_regions(tr);
      for (const Region& region : pslg.regions) {
        std::optional<FT> b = bounds_[0];
        if (region.max_area > 0 && (!b || FT(region.max_area) * 2 < *b)) b = FT(region.max_area) * 2;
        bounds_.push_back(b);
      }
    }
    // The initial CDT's cocircular edges count as ties, as in the engines
    // (docs/ALGORITHM.md section 6): another implementation may have the other diagonal.
    tr.cocircular_ties = count_cocircular_edges(tr);
  }

  bool in_domain(FH f) const { return detail::in_domain(tr, f); }

  // Bad, or within the angle tolerance of bad.
  const std::optional<FT>& bound(int region) const { return bounds_[static_cast<std::size_t>(region)]; }
  bool maybe_bad(FH f) const {
    if (is_skinny(f, sin2_) || (threshold_within_rounding_ && within_rounding_of_theta(f))) return true;
    const std::optional<FT>& b = bound(f->info().region);
    return b && is_too_big(f, *b);
  }
  bool within_rounding_of_theta(FH f) const { return is_skinny(f, sin2_rounding_); }
  bool maybe_bad(const CellTri& t) const {
    if (skinny(t, sin2_) || (threshold_within_rounding_ && skinny(t, sin2_rounding_))) return true;
    const std::optional<FT>& b = bound(t.region);
    return b && too_big(t, *b);
  }

  double tolerance(double scale) const {
    double ulps = std::max(rules.point_tolerance_ulps, 0.0);
    return std::max(ulps * DBL_EPSILON * scale, ulps * std::numeric_limits<double>::denorm_min());
  }

  template <class T>
  Candidate midpoint(Rule rule, const T& f, int i) const {
    VH a = vtx(f, Cdt::ccw(i)), b = vtx(f, Cdt::cw(i));
    Candidate c{rule, CGAL::midpoint(a->point(), b->point()), std::max(abs_max(a->point()), abs_max(b->point())), {}, {}};
    if (constrained(f, i)) c.split_a = a, c.split_b = b;
    return c;
  }

  // Every point the paper's rule allows for this terminal configuration (and,
  // under ReplayRules::variant, the variant's points there).
  std::vector<Candidate> candidates(const Terminal& t) const {
    return t.t2 == FH() ? candidates(t.t1, t.t1, false, t.l) : candidates(t.t1, t.t2, true, t.l);
  }
  std::vector<Candidate> paper_candidates(const Terminal& t) const {
    return t.t2 == FH() ? paper_candidates(t.t1, t.t1, false, t.l) : paper_candidates(t.t1, t.t2, true, t.l);
  }
  std::vector<Candidate> deviation_points(const Terminal& t) const {
    return t.t2 == FH() ? deviation_points(t.t1, t.t1, false, t.l) : deviation_points(t.t1, t.t2, true, t.l);
  }
  template <class T>
  std::vector<Candidate> candidates(const T& t1, const T& t2, bool has_t2, int l) const {
    std::vector<Candidate> out = paper_candidates(t1, t2, has_t2, l);
    if (allows_points())
      for (Candidate& c : deviation_points(t1, t2, has_t2, l))
        if (allows(c.deviation)) out.push_back(c);
    return out;
  }
  // The variants whose points are choices too (ReplayRules::variant, allow()).
  std::vector<Deviation> allowed_;
  bool allows(Deviation d) const {
    return d == rules.variant || std::find(allowed_.begin(), allowed_.end(), d) != allowed_.end();
  }
  // Some allowed variant has points of its own (InexactLength has none: it changes
  // the length comparisons), so the catalogue's points are worth computing.
  bool allows_points() const {
    auto points = [](Deviation d) {
      return d != Deviation::Unknown && d != Deviation::InexactLength && d != Deviation::InexactThreshold;
    };
    return points(rules.variant) || std::any_of(allowed_.begin(), allowed_.end(), points);
  }

  // The quad's centroid under the declared reading, and its scale for the
  // tolerance. The area centroid's rounding error in doubles grows with M / |ab|
  // (its weights are cross products: eps M^2 absolute error on an area of size
  // |ab|^2), so its scale is M * max(1, M / |ab|).
  template <class T>
  std::optional<Candidate> quad_centroid(Rule rule, const T& t1, const T& t2, int l, CentroidReading reading) const {
    VH a = vtx(t1, Cdt::ccw(l)), b = vtx(t1, Cdt::cw(l)), c = vtx(t1, l);
    VH d = vtx(t2, index_off(t2, a, b));
    double scale = std::max({abs_max(a->point()), abs_max(b->point()), abs_max(c->point()), abs_max(d->point())});
    if (reading == CentroidReading::Vertex) {
      CPoint g(((a->point().x() + b->point().x()) + (c->point().x() + d->point().x())) / 4,
               ((a->point().y() + b->point().y()) + (c->point().y() + d->point().y())) / 4);
      return Candidate{rule, g, scale, {}, {}};
    }
    double ab = std::sqrt(CGAL::to_double(CGAL::squared_distance(a->point(), b->point())));
    if (ab > 0 && scale / ab > 1) scale *= scale / ab;
    const std::optional<CPoint> g = guarded_area_centroid(a->point(), b->point(), c->point(), d->point());
    if (!g) return std::nullopt;  // a flat quad has no area centroid: no such choice
    return Candidate{rule, *g, scale, {}, {}};
  }

  // The catalogue's points at a terminal configuration (docs/CONFORMANCE.md,
  // "Deviations"): each tagged with its deviation. The paper's own choices are
  // not excluded: a point that is one matches before the catalogue is asked.
  template <class T>
  std::vector<Candidate> deviation_points(const T& t1, const T& t2, bool has_t2, int l) const {
    std::vector<Candidate> out;
    auto add = [&](Deviation d, Candidate c) {
      c.deviation = d;
      out.push_back(c);
    };
    VH a = vtx(t1, Cdt::ccw(l)), b = vtx(t1, Cdt::cw(l)), c = vtx(t1, l);
    auto tri_centroid = [&](VH x, VH y, VH z, Rule rule) {
      double scale = std::max({abs_max(x->point()), abs_max(y->point()), abs_max(z->point())});
      return Candidate{rule, triangle_centroid(x->point(), y->point(), z->point()), scale, {}, {}};
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
    const std::optional<Candidate> g_other = quad_centroid(Rule::QuadCentroid, t1, t2, l, other_reading);
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
          int inside = inside_status(other, g->point, tolerance(g->scale));
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

  // Terminal edge l of t1, and t2 across it if has_t2 (else l is constrained).
  template <class T>
  std::vector<Candidate> paper_candidates(const T& t1, const T& t2, bool has_t2, int l) const {
    std::vector<Candidate> out;
    if (!has_t2) {
      out.push_back(midpoint(Rule::TerminalConstrainedMidpoint, t1, l));
      return out;
    }
    VH a = vtx(t1, Cdt::ccw(l)), b = vtx(t1, Cdt::cw(l));
    int l2 = index_off(t2, a, b);
    std::vector<int> S1 = second_longest_given(t1, l), S2 = second_longest_given(t2, l2);
    auto centroid = [&](Rule rule) { return quad_centroid(rule, t1, t2, l, rules.centroid); };
    for (int s1 : S1) {
      for (int s2 : S2) {
        bool c1 = constrained(t1, s1), c2 = constrained(t2, s2);
        if (rules.method == Method::Midpoint) {
          if (!c1 && !c2) out.push_back(midpoint(Rule::TerminalMidpoint, t1, l));
          if (c1) out.push_back(midpoint(Rule::SecondLongestMidpoint, t1, s1));
          if (c2) out.push_back(midpoint(Rule::SecondLongestMidpoint, t2, s2));
          continue;
        }
        if (!c1 && !c2) {
          if (auto g = centroid(Rule::QuadCentroid)) out.push_back(*g);
        } else if (c1 && c2) {
          out.push_back(midpoint(Rule::BothSecondLongestMidpoint, t1, s1));
          out.push_back(midpoint(Rule::BothSecondLongestMidpoint, t2, s2));
        } else {
          // Remark 10: the centroid if it is inside the other triangle, else
          // the midpoint of the constrained second-longest edge. Within the
          // point tolerance of the other triangle's boundary, both.
          const T& star = c1 ? t1 : t2;
          const T& other = c1 ? t2 : t1;
          int star_edge = c1 ? s1 : s2;
          // A flat quad has no area centroid: not inside, so the midpoint.
          std::optional<Candidate> g = centroid(Rule::CentroidInOther);
          int inside = g ? inside_status(other, g->point, tolerance(g->scale)) : -1;
          if (inside >= 0) out.push_back(*g);
          if (inside <= 0) out.push_back(midpoint(Rule::SecondLongestMidpoint, star, star_edge));
        }
      }
    }
    return out;
  }

  // 1 strictly inside f farther than tol from its boundary, -1 not strictly
  // inside and farther than tol from it, 0 within tol of the boundary.
  template <class T>
  int inside_status(const T& f, const CPoint& p, double tol) const {
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

  static double distance(const Point& p, const CPoint& q) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return std::numeric_limits<double>::infinity();
    return std::max(std::abs(CGAL::to_double(FT(p.x) - q.x())), std::abs(CGAL::to_double(FT(p.y) - q.y())));
  }

  static double euclidean(const Point& p, const CPoint& q) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return std::numeric_limits<double>::infinity();
    return std::hypot(CGAL::to_double(FT(p.x) - q.x()), CGAL::to_double(FT(p.y) - q.y()));
  }

  // The domain triangles around p: those incident to a vertex of the
  // triangle(s) containing it (a point within tolerance of a choice lies in
  // or next to the choice's terminal triangles). wide: one ring more, for a
  // midpoint rounded half an ulp beyond its constrained edge, past a sliver
  // there into a triangle that shares no vertex with the terminal pair.
  std::vector<FH> faces_near(const Point& p, bool& at_vertex, bool wide = false) {
    Cdt::Locate_type lt;
    int li;
    FH f = tr.cdt.locate(CPoint(p.x, p.y), lt, li, hint());
    at_vertex = lt == Cdt::VERTEX;
    std::vector<FH> out;
    std::set<FH> seen;
    if (f == FH()) return out;
    std::vector<VH> around;
    for (int i = 0; i < 3; ++i) around.push_back(f->vertex(i));
    if (lt == Cdt::EDGE) around.push_back(f->neighbor(li)->vertex(f->neighbor(li)->index(f)));
    for (VH v : around) {
      if (tr.cdt.is_infinite(v)) continue;
      Cdt::Face_circulator fc = tr.cdt.incident_faces(v), done = fc;
      do {
        if (in_domain(fc) && seen.insert(fc).second) out.push_back(fc);
      } while (++fc != done);
    }
    if (!wide) return out;
    std::set<VH> ring(around.begin(), around.end());
    const std::size_t inner = out.size();
    for (std::size_t k = 0; k < inner; ++k)
      for (int i = 0; i < 3; ++i) {
        VH v = out[k]->vertex(i);
        if (!ring.insert(v).second) continue;
        Cdt::Face_circulator fc = tr.cdt.incident_faces(v), done = fc;
        do {
          if (in_domain(fc) && seen.insert(fc).second) out.push_back(fc);
        } while (++fc != done);
      }
    return out;
  }

  // Terminal configurations with a terminal triangle in faces, each once.
  std::vector<Terminal> terminals(const std::vector<FH>& faces) const {
    std::vector<Terminal> out;
    std::set<std::pair<int, int>> seen;  // terminal edge by vertex ids
    for (FH f : faces) {
      for (int l : longest_edges(f)) {
        auto e = edge_key(id(f->vertex(Cdt::ccw(l))), id(f->vertex(Cdt::cw(l))));
        if (f->is_constrained(l)) {
          // A constrained edge is terminal on each domain side separately.
          out.push_back({f, FH(), l});
          continue;
        }
        FH n = f->neighbor(l);
        if (!in_domain(n) || !is_longest(n, n->index(f))) continue;
        if (!seen.insert(e).second) continue;
        out.push_back({f, n, l});
      }
    }
    return out;
  }

  // Backwards from terminal triangle t (arrived at, terminal edge l; other
  // the triangle across l or null) along the Lepp tree to a bad triangle.
  // Returns the Lepp from the bad triangle to t, empty if none.
  std::vector<FH> bad_reaching(FH t, int l, FH other) const {
    std::map<FH, FH> next;  // face -> the next face on its Lepp
    std::deque<std::pair<FH, int>> todo;                           // face and its exit edge
    next[t] = FH();
    if (other != FH()) next[other] = FH();
    todo.push_back({t, l});
    while (!todo.empty()) {
      auto [f, exit] = todo.front();
      todo.pop_front();
      if (maybe_bad(f)) {
        std::vector<FH> path;
        for (FH g = f; g != FH(); g = next[g]) path.push_back(g);
        return path;
      }
      for (int k = 0; k < 3; ++k) {
        if (k == exit || f->is_constrained(k)) continue;
        FH g = f->neighbor(k);
        if (!in_domain(g) || next.count(g)) continue;
        int kk = g->index(f);
        // g's Lepp (under some tie resolution) crosses into f: the shared
        // edge is a longest edge of g (and no longer than f's exit, always).
        if (!is_longest(g, kk)) continue;
        next[g] = f;
        todo.push_back({g, kk});
      }
    }
    return {};
  }

  ReplayChoice describe(const Terminal& t, const Candidate& c, const Point& p, const std::vector<FH>& path) const {
    ReplayChoice r;
    if (!path.empty()) {
      r.bad = ccw_ids(path.front());
      for (FH f : path) r.lepp.push_back(ccw_ids(f));
    }
    r.terminal_edge = {id(t.t1->vertex(Cdt::ccw(t.l))), id(t.t1->vertex(Cdt::cw(t.l)))};
    r.t1 = ccw_ids(t.t1);
    if (t.t2 != FH()) r.t2 = ccw_ids(t.t2);
    r.rule = c.rule;
    r.point = {round_nearest(c.point.x()), round_nearest(c.point.y())};
    r.distance = distance(p, c.point);
    r.euclidean = euclidean(p, c.point);
    r.tolerance = tolerance(c.scale);
    if (c.split_a != VH()) r.split_edge = {id(c.split_a), id(c.split_b)};
    r.deviation = c.deviation;
    return r;
  }

  // p inserted as candidate c of terminal t passes the precision stop's test
  // (ALGORITHM.md section 8b): the split of c's edge at p makes counter-clockwise
  // triangles, or p lies in the closed pair, beyond the precision floor.
  bool insertable_as(const Point& p, const Terminal& t, const Candidate& c) const {
    Selection s;
    s.point = p;
    if (c.split_a != VH()) {
      FH f;
      int i;
      if (!tr.cdt.is_edge(c.split_a, c.split_b, f, i)) return false;
      if (!in_domain(f)) {
        FH n = f->neighbor(i);
        i = n->index(f), f = n;
      }
      s.split_face = f, s.split_index = i;
    }
    Lepp lepp;
    lepp.t1 = t.t1, lepp.t2 = t.t2, lepp.edge = t.l;
    return insertable(tr, s, lepp);
  }

  // At the precision limit several choices lie within the tolerance of p (a
  // midpoint a few ulps off its edge is also near the midpoint of the next
  // one; at subnormal coordinates the tolerance spans several choices): the
  // nearest that can be inserted at p is taken (the first of equally near
  // ones), else the first. Not the first insertable: a centroid 8 ulps away,
  // inserted into a face, keeps the constraint that the program's midpoint 0
  // ulps away split, and the replay's mesh leaves the program's.
  bool match_here(const Point& p, ReplayChoice& out, bool wide = false) {
    bool at_vertex = false, found = false, insertable_found = false;
    double nearest = 0;
    std::vector<FH> faces = faces_near(p, at_vertex, wide);
    if (at_vertex) return false;
    for (const Terminal& t : terminals(faces)) {
      std::vector<Candidate> cands = candidates(t);
      for (const Candidate& c : cands) {
        const double d = distance(p, c.point);
        if (d > tolerance(c.scale) || (insertable_found && d >= nearest)) continue;
        // The Lepp may arrive from either side of an unconstrained terminal edge.
        std::vector<FH> path = bad_reaching(t.t1, t.l, t.t2);
        Terminal used = t;
        if (path.empty() && t.t2 != FH()) {
          path = bad_reaching(t.t2, t.t2->index(t.t1), t.t1);
          if (!path.empty()) used = {t.t2, t.t1, t.t2->index(t.t1)};
        }
        if (path.empty()) continue;
        if (used.t2 != FH()) path.push_back(used.t2);
        if (insertable_as(p, used, c)) {
          out = describe(used, c, p, path);
          if (d == 0) return true;  // none nearer
          insertable_found = found = true;
          nearest = d;
          continue;
        }
        if (!found) out = describe(used, c, p, path), found = true;
      }
    }
    return found;
  }

  // An unconstrained edge between two domain triangles whose four points are
  // exactly cocircular: either diagonal is Delaunay.
  bool cocircular(FH f, int i) const { return cocircular_edge(tr, f, i); }

  bool find_edge(const EdgeIds& e, FH& f, int& i) const {
    return tr.cdt.is_edge(tr.vertex.at(static_cast<std::size_t>(e.first)), tr.vertex.at(static_cast<std::size_t>(e.second)), f, i);
  }
  // Flips a cocircular edge; returns the new edge (the other diagonal).
  EdgeIds flip(FH f, int i) {
    EdgeIds other = edge_key(id(f->vertex(i)), id(f->neighbor(i)->vertex(f->neighbor(i)->index(f))));
    tr.cdt.flip(f, i);
    return other;
  }

  // The cocircular edges where the replay's mesh may differ from the
  // implementation's: around p, and where recent insertions met ties.
  std::vector<EdgeIds> flip_candidates(const Point& p) {
    std::vector<EdgeIds> out;
    std::set<EdgeIds> seen;
    auto consider = [&](FH f, int i) {
      if (!cocircular(f, i)) return;
      EdgeIds e = edge_key(id(f->vertex(Cdt::ccw(i))), id(f->vertex(Cdt::cw(i))));
      if (e.first >= 0 && seen.insert(e).second) out.push_back(e);
    };
    bool at_vertex = false;
    for (FH f : faces_near(p, at_vertex))
      for (int i = 0; i < 3; ++i) {
        consider(f, i);
        FH n = f->neighbor(i);
        if (in_domain(n))
          for (int j = 0; j < 3; ++j) consider(n, j);
      }
    for (auto it = recent_ties_.rbegin(); it != recent_ties_.rend(); ++it) {
      FH f;
      int i;
      if (find_edge(*it, f, i)) consider(f, i);
    }
    return out;
  }

  // Lawson flips with CGAL's symbolically perturbed in-circle test, from the
  // given edges (all domain edges if empty) until none applies: the result is
  // the constrained Delaunay triangulation CGAL's own insertion builds, which
  // breaks every cocircular tie by the perturbation. Only cocircular edges of
  // a Delaunay mesh flip, so the mesh stays constrained Delaunay.
  std::int64_t perturbed_lawson(std::vector<std::pair<FH, int>> todo) {
    if (todo.empty())
      for (FH f : tr.cdt.finite_face_handles())
        if (in_domain(f))
          for (int i = 0; i < 3; ++i) todo.push_back({f, i});
    std::int64_t flips = 0;
    while (!todo.empty()) {
      auto [f, i] = todo.back();
      todo.pop_back();
      if (!in_domain(f) || f->is_constrained(i)) continue;
      FH n = f->neighbor(i);
      if (!in_domain(n)) continue;
      if (tr.cdt.side_of_oriented_circle(n, f->vertex(i)->point(), true) != CGAL::ON_POSITIVE_SIDE) continue;
      tr.cdt.flip(f, i);
      ++flips;
      for (int k = 0; k < 3; ++k) todo.push_back({f, k}), todo.push_back({n, k});
    }
    return flips;
  }

  // p is a choice of the replay's mesh, or of another constrained Delaunay
  // mesh of the same points: any triangulation of each cocircular cell (then
  // the flips that make it are kept: the implementation evidently has that
  // mesh). When that bounded search gives up: a mesh one or two cocircular
  // flips away near p or where recent insertions met ties, or CGAL's
  // perturbed constrained Delaunay mesh (then the replay follows CGAL's tie
  // rule from here on). The search of the cells comes first because it is
  // the cheapest: on a lattice box turned by -90 degrees (conformance_bench),
  // 6 ms for the whole trace against 53 ms with the local flips tried first.
  // That search is match_paper; where the lengths' near ties are allowed
  // (InexactLength) and it fails, it runs again with them as ties, and a choice
  // found so is tagged InexactLength.
  // Likewise the threshold (InexactThreshold): triangles within double
  // rounding above theta count as bad too, and with both allowed, both at once.
  bool match(const Point& p, ReplayChoice& out) {
    if (match_paper(p, out)) return true;
    const bool lengths = allows(Deviation::InexactLength), threshold = allows(Deviation::InexactThreshold);
    if (lengths) {
      LengthTiesWithinRounding relaxed(true);
      if (match_paper(p, out)) return out.deviation = Deviation::InexactLength, true;
    }
    if (!threshold) return false;
    threshold_within_rounding_ = true;
    struct Restore {
      bool& flag;
      ~Restore() { flag = false; }
    } restore{threshold_within_rounding_};
    if (match_paper(p, out)) return out.deviation = Deviation::InexactThreshold, true;
    if (!lengths) return false;
    LengthTiesWithinRounding relaxed(true);
    if (match_paper(p, out)) return out.deviation = Deviation::InexactThreshold, true;
    return false;
  }

  bool match_paper(const Point& p, ReplayChoice& out) {
    search_exhausted_ = false;
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
    if (match_here(p, out) || match_here(p, out, true)) return true;
    if (rules.follow_cocircular_flips && match_cocircular(p, out)) return true;
    return match_everywhere(p, out);
  }

  bool match_cocircular(const Point& p, ReplayChoice& out) {
    if (match_any_triangulation(p, out)) return true;
    // Only when the search of the cells ran out of budget, or at a point that
    // is no choice (where the check ends): the older, narrower searches.
    if (match_local_flips(p, out)) return true;
    if (!perturbed_) {
      std::int64_t flips = perturbed_lawson({});
      if (flips > 0) {
        perturbed_ = true;
        cocircular_flips_ += flips;
        if (match_here(p, out) || match_local_flips(p, out)) return true;
      }
    }
    return false;
  }

  // The last search, before a step is declared no choice: every bad triangle's
  // Lepp, wherever its terminal pair lies, and the nearest choice within the
  // tolerance that can be inserted (else the nearest). The searches around p
  // miss a pair when p is located far from it: a boundary edge's midpoint
  // rounded one ulp off its line to the outside of the domain lies in an
  // outside triangle whose neighbours need not touch the pair (docs/CONFORMANCE.md,
  // "A midpoint outside the domain"). Slow (the whole mesh), so only here.
  bool match_everywhere(const Point& p, ReplayChoice& out) const {
    bool found = false, insertable_found = false;
    double nearest = 0;
    for_each_bad_lepp_end([&](const std::vector<FH>& lepp, const Terminal& t) {
      for (const Candidate& c : candidates(t)) {
        const double d = distance(p, c.point);
        if (d > tolerance(c.scale)) continue;
        const bool ins = insertable_as(p, t, c);
        const bool better = !found || (ins && !insertable_found) || (ins == insertable_found && d < nearest);
        if (!better) continue;
        out = describe(t, c, p, lepp);
        found = true;
        insertable_found = ins;
        nearest = d;
      }
    });
    return found;
  }

  // ---- any triangulation of the cocircular cells (cocircular_cells.h) ----
  //
  // The same search as match_here, over the triangles that some
  // triangulation of each cell has instead of the faces of the mesh: the
  // terminal configurations whose quad holds p, then backwards along the Lepp
  // tree to a bad triangle, keeping the triangles of one path pairwise
  // compatible (no two overlapping in one cell). A path found is made real by
  // flipping cocircular diagonals in its cells (the mesh stays constrained
  // Delaunay), and match_here confirms it on the mesh. Bounded: at most
  // rules.cocircular_search_budget triangles are looked at.

  struct PathNode {
    CellTri t;
    int exit;  // the edge towards the terminal edge
    int next;  // index of the next node on the Lepp, -1 at the terminal triangle
  };

  static std::array<int, 3> tri_key(const CellTri& t) {
    std::array<int, 3> k{{id(t.v[0]), id(t.v[1]), id(t.v[2])}};
    std::sort(k.begin(), k.end());
    return k;
  }

  bool spend(std::size_t& used) {
    if (++used <= rules.cocircular_search_budget) return true;
    search_exhausted_ = true;
    return false;
  }

  // Backwards from t (exit edge l; other the triangle across it, if any) to a
  // bad triangle: the path from it to t, empty if none.
  std::vector<CellTri> cell_bad_reaching(CellMap& cells, const CellTri& t, int l, const CellTri* other, std::size_t& used) {
    std::vector<PathNode> nodes{{t, l, -1}};
    std::set<std::array<int, 3>> seen{tri_key(t)};
    if (other) seen.insert(tri_key(*other));
    std::vector<CellTri> across;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      if (maybe_bad(nodes[k].t)) {
        std::vector<CellTri> path;
        for (int j = static_cast<int>(k); j >= 0; j = nodes[static_cast<std::size_t>(j)].next)
          path.push_back(nodes[static_cast<std::size_t>(j)].t);
        return path;
      }
      for (int e = 0; e < 3; ++e) {
        const CellTri f = nodes[k].t;
        if (e == nodes[k].exit || constrained(f, e)) continue;
        across.clear();
        cells.across(f, e, across);
        for (const CellTri& g : across) {
          if (!spend(used)) return {};
          if (seen.count(tri_key(g))) continue;
          int ge = index_off(g, vtx(f, Cdt::ccw(e)), vtx(f, Cdt::cw(e)));
          if (!is_longest(g, ge)) continue;
          bool fits = !(other && cells.overlap(g, *other));
          for (int j = static_cast<int>(k); fits && j >= 0; j = nodes[static_cast<std::size_t>(j)].next)
            fits = !cells.overlap(g, nodes[static_cast<std::size_t>(j)].t);
          if (!fits) continue;
          seen.insert(tri_key(g));
          nodes.push_back({g, ge, static_cast<int>(k)});
        }
      }
    }
    return {};
  }

  // A terminal configuration of some triangulation (t2 null: l constrained):
  // when one of its choices is p and a bad triangle's Lepp reaches it, the
  // mesh is flipped to have it and match_here decides.
  bool try_cell_terminal(CellMap& cells, const CellTri& t1, const CellTri* t2, int l, const Point& p, ReplayChoice& out,
                         std::size_t& used) {
    for (const Candidate& c : t2 ? candidates(t1, *t2, true, l) : candidates(t1, t1, false, l)) {
      if (distance(p, c.point) > tolerance(c.scale)) continue;
      std::vector<CellTri> path = cell_bad_reaching(cells, t1, l, t2, used);
      if (path.empty() && t2) path = cell_bad_reaching(cells, *t2, index_off(*t2, vtx(t1, Cdt::ccw(l)), vtx(t1, Cdt::cw(l))), &t1, used);
      if (path.empty()) continue;
      if (t2) path.push_back(path.back().v == t1.v ? *t2 : t1);
      std::vector<EdgeIds> flips;
      if (realize(tr, cells, path, flips) && match_here(p, out)) {
        cocircular_flips_ += static_cast<std::int64_t>(flips.size());
        return true;
      }
      undo_flips(tr, flips);  // cannot happen: the path's triangles fit in one triangulation
    }
    return false;
  }

  bool match_any_triangulation(const Point& p, ReplayChoice& out) {
    bool at_vertex = false;
    std::vector<FH> near = faces_near(p, at_vertex);
    if (at_vertex) return false;
    CellMap cells(tr);
    std::set<int> near_cells;
    for (FH f : near) near_cells.insert(cells.cell_of(f));
    std::size_t used = 0;
    std::set<std::array<int, 4>> tried;  // terminal configurations by vertex ids
    std::vector<CellTri> across;
    for (int c : near_cells) {
      const int n = static_cast<int>(cells.cell(c).ring.size());
      for (int a = 0; a < n; ++a)
        for (int b = a + 1; b < n; ++b)
          for (int d = b + 1; d < n; ++d) {
            if (!spend(used)) return false;
            const CellTri t = cells.triangle(c, a, b, d);
            if (!near_triangle(t, p)) continue;
            // t holds p: it is t1 or t2 of the configuration, the other across a longest edge of both.
            for (int l : longest_edges(t)) {
              if (constrained(t, l)) {
                std::array<int, 4> key{{id(vtx(t, Cdt::ccw(l))), id(vtx(t, Cdt::cw(l))), id(vtx(t, l)), -1}};
                if (tried.insert(key).second && try_cell_terminal(cells, t, nullptr, l, p, out, used)) return true;
                continue;
              }
              across.clear();
              cells.across(t, l, across);
              for (const CellTri& u : across) {
                if (!spend(used)) return false;
                int ul = index_off(u, vtx(t, Cdt::ccw(l)), vtx(t, Cdt::cw(l)));
                if (!is_longest(u, ul)) continue;
                // The terminal edge, then the two apexes.
                std::array<int, 4> key{{id(vtx(t, Cdt::ccw(l))), id(vtx(t, Cdt::cw(l))), id(vtx(t, l)), id(vtx(u, ul))}};
                std::sort(key.begin(), key.begin() + 2);
                std::sort(key.begin() + 2, key.end());
                if (tried.insert(key).second && try_cell_terminal(cells, t, &u, l, p, out, used)) return true;
              }
            }
          }
    }
    return false;
  }

  bool match_local_flips(const Point& p, ReplayChoice& out) {
    std::vector<EdgeIds> cands = flip_candidates(p);
    if (cands.empty()) return false;
    std::size_t attempts = 0;
    for (std::size_t a = 0; a < cands.size(); ++a) {
      FH f;
      int i;
      if (!find_edge(cands[a], f, i) || !cocircular(f, i)) continue;
      EdgeIds fa = flip(f, i);
      if (match_here(p, out)) {
        ++cocircular_flips_;
        return true;
      }
      for (std::size_t b = a + 1; b < cands.size() && attempts < 400; ++b, ++attempts) {
        FH g;
        int j;
        if (!find_edge(cands[b], g, j) || !cocircular(g, j)) continue;
        EdgeIds fb = flip(g, j);
        if (match_here(p, out)) {
          cocircular_flips_ += 2;
          return true;
        }
        if (find_edge(fb, g, j)) flip(g, j);
      }
      if (find_edge(fa, f, i)) flip(f, i);
    }
    return false;
  }

  // After an insertion: the edges opposite v whose quads are cocircular (the
  // Lawson flips met a tie there).
  void record_ties(VH v) {
    Cdt::Face_circulator fc = tr.cdt.incident_faces(v), done = fc;
    do {
      if (in_domain(fc)) {
        int i = fc->index(v);
        if (cocircular(fc, i)) recent_ties_.push_back(edge_key(id(fc->vertex(Cdt::ccw(i))), id(fc->vertex(Cdt::cw(i)))));
      }
    } while (++fc != done);
    if (recent_ties_.size() > 32) recent_ties_.erase(recent_ties_.begin(), recent_ties_.end() - 32);
  }

  std::vector<EdgeIds> recent_ties_;
  std::int64_t cocircular_flips_ = 0;
  bool search_exhausted_ = false;  // the last match's search of the cells ran out of its budget
  bool perturbed_ = false;  // following CGAL's perturbed tie rule

  void insert(const Point& p, const ReplayChoice& choice) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw std::runtime_error("not a finite point");
    Selection s;
    s.point = p;
    FH f;
    int i = -1;
    if (choice.split_edge[0] >= 0) {
      VH a = tr.vertex.at(static_cast<std::size_t>(choice.split_edge[0]));
      VH b = tr.vertex.at(static_cast<std::size_t>(choice.split_edge[1]));
      if (!tr.cdt.is_edge(a, b, f, i)) throw std::runtime_error("the edge to split is not in the mesh");
      if (!in_domain(f)) {  // a boundary edge: split from its domain side, as the engines do (insertable_as)
        FH n = f->neighbor(i);
        i = n->index(f), f = n;
      }
      s.split_face = f, s.split_index = i;
    } else {
      Cdt::Locate_type lt;
      f = tr.cdt.locate(CPoint(p.x, p.y), lt, i, hint());
      if (lt == Cdt::VERTEX) throw std::runtime_error("the point is already a vertex");
      if (lt == Cdt::EDGE && f->is_constrained(i)) s.split_face = f, s.split_index = i;  // exactly on a constrained edge
    }
    VH v;
    try {
      v = insert_point(tr, s, f);
    } catch (const std::logic_error& e) {
      throw std::runtime_error(e.what());
    }
    last_ = v;
    if (perturbed_) {
      std::vector<std::pair<FH, int>> todo;
      Cdt::Face_circulator fc = tr.cdt.incident_faces(v), done = fc;
      do todo.push_back({fc, fc->index(v)}); while (++fc != done);
      cocircular_flips_ += perturbed_lawson(todo);
    }
    record_ties(v);
  }

  // Forward: every end of Lepp(t) under every tie resolution (capped).
  void lepp_ends(FH f, int entry, std::vector<FH>& path, std::vector<std::pair<std::vector<FH>, Terminal>>& out,
                 std::size_t cap) const {
    for (int l : longest_edges(f)) {
      if (out.size() >= cap) return;
      if (l == entry) continue;
      if (f->is_constrained(l)) {
        out.push_back({path, {f, FH(), l}});
        continue;
      }
      FH n = f->neighbor(l);
      if (!in_domain(n) || std::find(path.begin(), path.end(), n) != path.end()) continue;
      int j = n->index(f);
      if (is_longest(n, j)) {
        std::vector<FH> full = path;
        full.push_back(n);
        out.push_back({full, {f, n, l}});
      }
      path.push_back(n);
      // Continue through n only across an edge at least as long (a tie
      // resolved the other way, or a strictly longer edge).
      lepp_ends(n, j, path, out, cap);
      path.pop_back();
    }
  }

  // ---- the deviation catalogue (docs/CONFORMANCE.md, "Deviations") ----

  // The bad triangle's circumcenter and off-center (Ungor: on the bisector of
  // its shortest edge pq, where the triangle pq-point has the angle theta at
  // the point; the circumcenter when that is nearer). The off-center is
  // irrational (a tangent): it is computed in long double from the exact
  // circumcenter, the only catalogue point that is not an exact rational.
  std::vector<Candidate> triangle_points(FH f) const {
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

  static std::string tri_text(const Tri& t) { return "(" + std::to_string(t[0]) + "," + std::to_string(t[1]) + "," + std::to_string(t[2]) + ")"; }

  // One line: which point of which configuration the match is.
  static std::string what(const DeviationMatch& m) {
    const ReplayChoice& w = m.where;
    const std::string edge = "(" + std::to_string(w.terminal_edge[0]) + "," + std::to_string(w.terminal_edge[1]) + ")";
    const bool good = m.deviation == Deviation::GoodTriangle || m.deviation == Deviation::InexactThreshold;
    const std::string lepp = "the Lepp of " + std::string(good ? "good" : "bad") + " triangle " + tri_text(w.bad);
    switch (m.deviation) {
      case Deviation::AreaCentroid: return "the area centroid of the terminal quad of edge " + edge + " (" + lepp + ")";
      case Deviation::VertexCentroid: return "the vertex average of the terminal quad of edge " + edge + " (" + lepp + ")";
      case Deviation::TriangleCentroid: return "the centroid of one terminal triangle of edge " + edge + " (" + lepp + ")";
      case Deviation::TerminalMidpoint: return "the midpoint of terminal edge " + edge + " (" + lepp + ")";
      case Deviation::CentroidNotMidpoint: return "the quad centroid at terminal edge " + edge + ", where the paper asks for a midpoint (" + lepp + ")";
      case Deviation::Remark10Ignored:
        return "the quad centroid at terminal edge " + edge + ", outside the triangle across from the constrained second-longest "
               "edge, where Remark 10 asks for that edge's midpoint (" + lepp + ")";
      case Deviation::Remark10Reversed: return "Remark 10 the wrong way round at terminal edge " + edge + " (" + lepp + ")";
      case Deviation::OtherSecondLongest:
        return "the midpoint of another edge of a terminal triangle of edge " + edge +
               " than the terminal edge and the paper's second-longest edge (" + lepp + ")";
      case Deviation::Circumcenter: return "the circumcenter of bad triangle " + tri_text(w.bad);
      case Deviation::OffCenter: return "the off-center of bad triangle " + tri_text(w.bad);
      case Deviation::InexactThreshold:
        return "the paper's choice at terminal edge " + edge + " for " + lepp +
               ", whose smallest angle is above theta by no more than double rounding";
      case Deviation::GoodTriangle: return "the paper's choice at terminal edge " + edge + " for " + lepp;
      case Deviation::InexactLength:
        return "the paper's choice at terminal edge " + edge + " for " + lepp +
               ", reached by taking a comparison of two edge lengths within double rounding of each other the other way";
      case Deviation::Precision: return "near the paper's choice at terminal edge " + edge + " (" + lepp + "), beyond the tolerance";
      case Deviation::Unknown: break;
    }
    return "no rule of the catalogue";
  }

  // One table (deviation_points, triangle_points, the paper's choices for good
  // triangles and at 1000 times the tolerance), one loop: the first rule in
  // catalogue order with a point within its tolerance of p names it.
  DeviationMatch diagnose(const Point& p) const {
    DeviationMatch best;
    int best_rank = kDeviations;
    double best_d = std::numeric_limits<double>::infinity();
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return best;
    auto consider = [&](const Candidate& c, double tol, const Terminal* t, const std::vector<FH>& lepp) {
      const int rank = static_cast<int>(c.deviation);
      if (rank > best_rank) return;
      // A point out of the doubles' range (the circumcenter of a nearly flat
      // triangle) has an infinite scale: it would match every point.
      if (!std::isfinite(tol)) return;
      const double d = distance(p, c.point);
      if (!(d <= tol) || (rank == best_rank && d >= best_d)) return;
      best_rank = rank, best_d = d;
      best.deviation = c.deviation;
      best.paper.clear();
      if (t) {
        best.where = describe(*t, c, p, lepp);
        for (const Candidate& k : paper_candidates(*t)) best.paper.push_back(describe(*t, k, p, lepp));
        if (!best.paper.empty()) best.where.rule = best.paper.front().rule;
      } else {
        ReplayChoice r;
        r.bad = ccw_ids(lepp.front());
        r.lepp = {r.bad};
        r.point = {round_nearest(c.point.x()), round_nearest(c.point.y())};
        r.distance = d;
        r.euclidean = euclidean(p, c.point);
        best.where = r;
      }
      best.where.tolerance = tol;
    };
    for (FH f : tr.cdt.finite_face_handles()) {
      if (!in_domain(f)) continue;
      const bool bad = maybe_bad(f);
      std::vector<FH> path{f};
      std::vector<std::pair<std::vector<FH>, Terminal>> ends;
      lepp_ends(f, -1, path, ends, 64);
      if (bad)
        for (const Candidate& c : triangle_points(f)) consider(c, tolerance(c.scale), nullptr, path);
      for (const auto& [lepp, t] : ends) {
        if (!bad) {
          // Good by no more than double rounding: the program's threshold rounded, not wrong.
          const Deviation good = within_rounding_of_theta(f) ? Deviation::InexactThreshold : Deviation::GoodTriangle;
          for (Candidate c : paper_candidates(t)) {
            c.deviation = good;
            consider(c, tolerance(c.scale), &t, lepp);
          }
          continue;
        }
        for (const Candidate& c : deviation_points(t)) consider(c, tolerance(c.scale), &t, lepp);
        for (Candidate c : paper_candidates(t)) {
          c.deviation = Deviation::Precision;
          consider(c, 1000 * tolerance(c.scale), &t, lepp);
        }
      }
    }
    // The paper's choices again, with the lengths' near ties as ties: only when
    // no rule before it matched (another walk of every Lepp).
    if (best_rank > static_cast<int>(Deviation::InexactLength)) {
      LengthTiesWithinRounding relaxed(true);
      for_each_bad_lepp_end([&](const std::vector<FH>& lepp, const Terminal& t) {
        for (Candidate c : paper_candidates(t)) {
          c.deviation = Deviation::InexactLength;
          consider(c, tolerance(c.scale), &t, lepp);
        }
      });
    }
    best.what = what(best);
    return best;
  }

  // Theorem 2 on a choice's terminal pair, exactly: the angle at apex c of
  // terminal edge ab is over 120 degrees iff dot(ca, cb) < 0 and
  // 4 dot^2 > |ca|^2 |cb|^2.
  Theorem2Check theorem2(const ReplayChoice& choice) const {
    Theorem2Check out;
    if (choice.t2[0] < 0 || choice.terminal_edge[0] < 0) return out;  // a constrained terminal edge: not the theorem's case
    auto V = [&](int i) { return tr.vertex.at(static_cast<std::size_t>(i))->point(); };
    const int ia = choice.terminal_edge[0], ib = choice.terminal_edge[1];
    for (const Tri& t : {choice.t1, choice.t2}) {
      int ic = -1;
      for (int v : t)
        if (v != ia && v != ib) ic = v;
      if (ic < 0) continue;
      const CPoint &A = V(ia), &B = V(ib), &C = V(ic);
      const K::Vector_2 u = A - C, v = B - C;
      const FT dot = u * v;
      if (!(dot < 0) || !(4 * dot * dot > u.squared_length() * v.squared_length())) continue;
      out.holds = false;
      out.apex = ic;
      const double cosv = CGAL::to_double(dot) / std::sqrt(CGAL::to_double(u.squared_length()) * CGAL::to_double(v.squared_length()));
      out.angle_deg = std::acos(std::max(-1.0, std::min(1.0, cosv))) * 180 / M_PI;
      return out;
    }
    return out;
  }

  // Calls f(lepp, terminal) for every Lepp end (under every tie resolution, at
  // most 64 each) of every domain triangle that may be bad.
  template <class F>
  void for_each_bad_lepp_end(F&& f) const {
    for (FH face : tr.cdt.finite_face_handles()) {
      if (!in_domain(face) || !maybe_bad(face)) continue;
      std::vector<FH> path{face};
      std::vector<std::pair<std::vector<FH>, Terminal>> ends;
      lepp_ends(face, -1, path, ends, 64);
      for (const auto& [lepp, t] : ends) f(lepp, t);
    }
  }

  std::vector<ReplayChoice> all_choices(const Point& p, std::size_t limit, std::size_t& total) const {
    std::vector<ReplayChoice> all;
    for_each_bad_lepp_end([&](const std::vector<FH>& lepp, const Terminal& t) {
      for (const Candidate& c : candidates(t)) all.push_back(describe(t, c, p, lepp));
    });
    std::sort(all.begin(), all.end(), [](const ReplayChoice& a, const ReplayChoice& b) { return a.distance < b.distance; });
    total = all.size();
    if (all.size() > limit) all.resize(limit);
    return all;
  }
};

const char* to_string(CentroidReading reading) { return reading == CentroidReading::Area ? "area" : "vertex"; }

const char* to_string(Deviation d) {
  switch (d) {
    case Deviation::AreaCentroid: return "area-centroid";
    case Deviation::VertexCentroid: return "vertex-centroid";
    case Deviation::TriangleCentroid: return "triangle-centroid";
    case Deviation::TerminalMidpoint: return "terminal-midpoint";
    case Deviation::CentroidNotMidpoint: return "centroid-not-midpoint";
    case Deviation::Remark10Ignored: return "remark10-ignored";
    case Deviation::Remark10Reversed: return "remark10-reversed";
    case Deviation::OtherSecondLongest: return "other-second-longest";
    case Deviation::Circumcenter: return "circumcenter";
    case Deviation::OffCenter: return "off-center";
    case Deviation::InexactThreshold: return "inexact-threshold";
    case Deviation::GoodTriangle: return "good-triangle";
    case Deviation::InexactLength: return "inexact-length";
    case Deviation::Precision: return "precision";
    case Deviation::Unknown: return "unknown";
  }
  return "unknown";
}

const char* definition(Deviation d) {
  switch (d) {
    case Deviation::AreaCentroid:
      return "the area centroid (centre of mass) of the terminal quad instead of the average of its four vertices (Lemma 11)";
    case Deviation::VertexCentroid:
      return "the average of the terminal quad's four vertices where the declared reading is the area centroid";
    case Deviation::TriangleCentroid: return "the centroid of one terminal triangle instead of the quad's";
    case Deviation::TerminalMidpoint: return "the terminal edge's midpoint where the paper chooses another point";
    case Deviation::CentroidNotMidpoint:
      return "the quad centroid where the paper asks for a midpoint (both second-longest edges constrained, or the midpoint method)";
    case Deviation::Remark10Ignored:
      return "no Remark 10: the quad centroid wherever exactly one second-longest edge is constrained, also where it is not "
             "inside the other triangle (the paper: the constrained edge's midpoint there)";
    case Deviation::Remark10Reversed:
      return "Remark 10 the wrong way round: the centroid where it is not inside the other triangle, or the constrained "
             "second-longest edge's midpoint where it is";
    case Deviation::OtherSecondLongest:
      return "the midpoint of another edge of a terminal triangle than the terminal edge and the paper's second-longest edge";
    case Deviation::Circumcenter: return "the circumcenter of a bad triangle (Ruppert, Chew)";
    case Deviation::OffCenter: return "the off-center of a bad triangle (Ungor)";
    case Deviation::InexactThreshold:
      return "the paper's choice for the Lepp of a triangle that is not bad, whose smallest angle is above theta by no more "
             "than a double computation of it may err (sin^2 within 16 DBL_EPSILON): the threshold compared in double";
    case Deviation::GoodTriangle: return "the paper's choice for the Lepp of a triangle that is not bad: a wrong threshold";
    case Deviation::InexactLength:
      return "the paper's choice for a Lepp reached by taking a length comparison the other way where the exact squared "
             "lengths differ by no more than a double computation of them may err (8 DBL_EPSILON relative)";
    case Deviation::Precision: return "within 1000 times the point tolerance of a paper choice: rounding beyond the tolerance";
    case Deviation::Unknown: return "no rule of the catalogue";
  }
  return "";
}

bool has_variant(Deviation d) {
  switch (d) {
    case Deviation::AreaCentroid: case Deviation::VertexCentroid: case Deviation::TriangleCentroid:
    case Deviation::TerminalMidpoint: case Deviation::CentroidNotMidpoint: case Deviation::Remark10Ignored:
    case Deviation::Remark10Reversed:
    case Deviation::OtherSecondLongest: case Deviation::InexactLength: case Deviation::InexactThreshold: return true;
    default: return false;
  }
}

Replay::Replay(const Pslg& pslg, const ReplayRules& rules) : impl_(std::make_unique<Impl>(pslg, rules)) {}
Replay::~Replay() = default;
bool Replay::match(const Point& p, ReplayChoice& choice) { return impl_->match(p, choice); }
void Replay::insert(const Point& p, const ReplayChoice& choice) { impl_->insert(p, choice); }
void Replay::allow(Deviation variant) {
  if (has_variant(variant) && !impl_->allows(variant)) impl_->allowed_.push_back(variant);
}
std::vector<ReplayChoice> Replay::all_choices(const Point& p, std::size_t limit, std::size_t& total) {
  return impl_->all_choices(p, limit, total);
}
DeviationMatch Replay::diagnose(const Point& p) const { return impl_->diagnose(p); }
Theorem2Check Replay::theorem2(const ReplayChoice& choice) const { return impl_->theorem2(choice); }
Mesh Replay::mesh() const { return extract_mesh(impl_->tr); }
std::size_t Replay::steiner_points() const { return impl_->tr.vertex.size() - impl_->tr.input_vertices; }
std::int64_t Replay::cocircular_ties() const { return impl_->tr.cocircular_ties; }
std::int64_t Replay::cocircular_flips() const { return impl_->cocircular_flips_; }
bool Replay::cocircular_search_exhausted() const { return impl_->search_exhausted_; }

}  // namespace lepp::reference
