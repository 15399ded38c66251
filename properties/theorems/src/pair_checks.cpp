// SPDX-License-Identifier: GPL-3.0-or-later
// Statements about a pair of Delaunay terminal triangles ABC, ABD sharing the
// unconstrained terminal edge AB: Theorem 2, Proposition 6, Lemma 7, Lemma 11,
// Corollary 12, Remark 13, Theorem 14.
#include <cstdio>

#include "exact.h"
#include "lepp/theorems/checks.h"
#include "lepp/theorems/lemma7_checks.h"

namespace lepp::theorems {
using namespace exact;

std::string show(const TerminalQuad& q) {
  auto s = [](const GridPoint& p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; };
  return "A " + s(q.A) + " B " + s(q.B) + " C " + s(q.C) + " D " + s(q.D);
}

namespace {

// > 0 when d is strictly inside the circumcircle of abc (any orientation of abc).
int in_circle(const P& a, const P& b, const P& c, const P& d) {
  P ad = a - d, bd = b - d, cd = c - d;
  FT det = norm2(ad) * cross(bd, cd) - norm2(bd) * cross(ad, cd) + norm2(cd) * cross(ad, bd);
  return CGAL::sign(det) * orient(a, b, c);
}

bool pair_hypothesis(const P& A, const P& B, const P& C, const P& D, std::string* why) {
  auto fail = [&](const char* w) {
    if (why) *why = w;
    return false;
  };
  if (orient(A, B, C) * orient(A, B, D) >= 0) return fail("C and D not strictly on opposite sides of AB");
  FT ab = dist2(A, B);
  if (dist2(A, C) > ab || dist2(B, C) > ab) return fail("AB is not a longest edge of ABC");
  if (dist2(A, D) > ab || dist2(B, D) > ab) return fail("AB is not a longest edge of ABD");
  if (in_circle(A, B, C, D) > 0) return fail("D strictly inside the circumcircle of ABC (not locally Delaunay)");
  return true;
}

struct Pair {
  P A, B, C, D;
  bool hypothesis;
  std::string why;
};
Pair make_pair(const TerminalQuad& q) {
  Pair p{pt(q.A), pt(q.B), pt(q.C), pt(q.D), false, ""};
  p.hypothesis = pair_hypothesis(p.A, p.B, p.C, p.D, &p.why);
  return p;
}

// A terminal triangle with terminal edge PQ and apex R, labelled as in Fig. 3:
// C = R, B the endpoint nearer R (BC shortest), A the other one.
Fig3 terminal_fig3(const P& p, const P& q, const P& r) {
  return dist2(r, p) <= dist2(r, q) ? fig3_as_given(p, q, r) : fig3_as_given(q, p, r);
}

std::string deg(const FT& c) { return std::to_string(angle_deg(c).lo); }
std::string shape(const Fig3& t) { return is_obtuse(t) ? "obtuse" : is_acute(t) ? "acute" : "right"; }

// Run `one` on both terminal triangles of the pair: ABC (apex C) and ABD (apex D).
template <class F>
Verdict both(const TerminalQuad& q, F one) {
  Pair p = make_pair(q);
  Verdict v;
  v.hypothesis = false;  // becomes true if the statement applies to either triangle
  v.detail = show(q) + (p.hypothesis ? "" : " [" + p.why + "]");
  Fig3 ts[2] = {terminal_fig3(p.A, p.B, p.C), terminal_fig3(p.A, p.B, p.D)};
  for (const Fig3& t : ts) {
    Verdict w = one(t);
    if (!w.conclusion) v.conclusion_everywhere = false;
    // The conclusion is reported wherever the triangle's own hypotheses hold, so a
    // negative test can show it failing on a pair that is not Delaunay terminal.
    if (!w.hypothesis) continue;
    if (!w.conclusion) {
      v.conclusion = false;
      v.detail += "; " + w.detail;
    }
    if (!p.hypothesis) continue;
    v.hypothesis = true;
    v.tie = v.tie || w.tie;
    if (v.label.empty()) v.label = w.label;
  }
  if (v.label.empty()) v.label = "not applicable";
  return v;
}

FT own_dM2(const Fig3& t) { return std::min(dist2(t.M, t.B), dist2(t.M, t.C)); }
bool small_alpha0(const Fig3& t) { return t.cos_alpha0 >= cos_deg30(); }  // alpha0 <= 30

}  // namespace

bool is_delaunay_terminal_pair(const TerminalQuad& q, std::string* why) {
  return pair_hypothesis(pt(q.A), pt(q.B), pt(q.C), pt(q.D), why);
}

Verdict check_theorem2(const TerminalQuad& q) {
  Pair p = make_pair(q);
  Verdict v;
  v.hypothesis = p.hypothesis;
  FT cc = cos_at(p.C, p.A, p.B), cd = cos_at(p.D, p.A, p.B);
  v.conclusion = cc >= cos_deg120() && cd >= cos_deg120();
  FT worst = std::min(cc, cd);
  v.label = worst > FT(0) ? "both acute" : worst > FT(-0.25) ? "largest angle 90-104.5" : "largest angle > 104.5";
  v.detail = show(q) + ": angles at C " + deg(cc) + ", at D " + deg(cd) + (p.hypothesis ? "" : " [" + p.why + "]");
  return v;
}

Verdict check_theorem2_equality(const Theorem2EqualityInput& in) {
  P A = pt(in.A), B = pt(in.B);
  P u = B - A;
  FT l = CGAL::sqrt(norm2(u));
  P e = FT(1) / l * u;
  P n{-e.y, e.x};  // unit normal, C's side
  P M = midpoint(A, B);
  FT r = l / CGAL::sqrt(FT(3));
  P O = M + (FT(-0.5) * r) * n;  // centre of the arc on which angle ACB = 120
  FT t = FT(2) + FT(static_cast<double>(in.s_num)) / FT(static_cast<double>(in.s_den)) * CGAL::sqrt(FT(3));
  FT cphi = (FT(1) - t * t) / (FT(1) + t * t), sphi = FT(2) * t / (FT(1) + t * t);
  P C = O + r * (cphi * e + sphi * n);
  P apex = M + (FT(-1) * l * CGAL::sqrt(FT(3)) / FT(2)) * n;
  FT dd = FT(static_cast<double>(in.d_den));
  P D = apex + P{FT(static_cast<double>(in.dx)) / dd, FT(static_cast<double>(in.dy)) / dd};
  Verdict v;
  std::string why;
  // The exact zero tests are costly on nested radicals: decide the cheap hypothesis first.
  v.hypothesis = pair_hypothesis(A, B, C, D, &why);
  bool at120 = !v.hypothesis || cos_at(C, A, B) == cos_deg120();
  v.hypothesis = v.hypothesis && at120;
  v.label = in.dx == 0 && in.dy == 0 ? "D at the apex" : v.hypothesis ? "D off the apex, hypotheses hold" : "D off the apex";
  FT ab = dist2(A, B);
  bool equilateral = dist2(A, D) == ab && dist2(B, D) == ab;
  bool cocircular = in_circle(A, B, C, D) == 0;
  // Circumcentre of ABC from the perpendicular bisectors: |MO| = r/2.
  FT dC = FT(2) * cross(B - A, C - A);
  FT ox = (norm2(B - A) * (C.y - A.y) - norm2(C - A) * (B.y - A.y)) / dC;
  FT oy = (norm2(C - A) * (B.x - A.x) - norm2(B - A) * (C.x - A.x)) / dC;
  P O2 = A + P{ox, oy};
  bool half = dist2(M, O2) * FT(4) == dist2(O2, A);
  v.conclusion = equilateral && cocircular && half;
  v.detail = "A (" + std::to_string(in.A.x) + ", " + std::to_string(in.A.y) + ") B (" + std::to_string(in.B.x) + ", " +
             std::to_string(in.B.y) + ") C " + show(C) + " D " + show(D) + (at120 ? "" : " angle C != 120") +
             (equilateral ? "" : "; ABD not equilateral") + (cocircular ? "" : "; not cocircular") +
             (half ? "" : "; |MO| != r/2") + (why.empty() ? "" : " [" + why + "]");
  return v;
}

Verdict check_prop6a_own_vertices(const TerminalQuad& q) {
  return both(q, [](const Fig3& t) {
    Verdict v;
    v.hypothesis = small_alpha0(t) && !(!is_acute(t) && !is_obtuse(t));
    FT mb = dist2(t.M, t.B), mc = dist2(t.M, t.C);
    v.conclusion = is_acute(t) ? own_dM2(t) == mb : own_dM2(t) == mc;
    v.label = shape(t);
    v.detail = shape(t) + " " + (v.conclusion ? "" : "d(M) is not the predicted distance");
    return v;
  });
}

Verdict check_prop6b(const TerminalQuad& q) {
  return both(q, [](const Fig3& t) {
    Verdict v;
    v.hypothesis = small_alpha0(t) && is_acute(t);
    // Isosceles BA = CA with apex angle alpha0: d(M)/BC = 1 / (4 sin(alpha0/2)), squared 1/(8 (1 - cos alpha0)).
    FT bound2 = FT(1) / (FT(8) * (FT(1) - t.cos_alpha0));
    v.conclusion = own_dM2(t) >= bound2 * t.bc2;
    v.label = "acute";
    v.detail = "d(M)/BC below the isosceles ratio at alpha0 " + deg(t.cos_alpha0);
    return v;
  });
}

Verdict check_prop6c(const TerminalQuad& q) {
  return both(q, [](const Fig3& t) {
    Verdict v;
    v.hypothesis = small_alpha0(t) && is_obtuse(t);
    // The triangle of angles 120, alpha0, 60 - alpha0: sides proportional to the sines
    // BC = sin alpha0, CA = sin(60 - alpha0), BA = sin 120; d(M) = CM, the median.
    FT c = t.cos_alpha0, s = CGAL::sqrt(FT(1) - c * c);
    FT bc = s, ca = CGAL::sqrt(FT(3)) / FT(2) * c - s / FT(2), ba2 = FT(0.75);
    FT cm2 = (FT(2) * ca * ca + FT(2) * bc * bc - ba2) / FT(4);
    v.conclusion = own_dM2(t) * bc * bc >= cm2 * t.bc2;
    v.label = "obtuse";
    v.detail = "d(M)/BC below the 120-degree triangle's ratio at alpha0 " + deg(t.cos_alpha0);
    return v;
  });
}

namespace {
Verdict lemma7_ratio(const Fig3& t, bool hypothesis, double k, const char* what) {
  Verdict v;
  v.hypothesis = hypothesis;
  Cmp c = ge(angle_deg(t.cos_alpha1), k, angle_deg(t.cos_alpha0));
  v.tie = c == Cmp::Tie;
  v.conclusion = c != Cmp::No;
  v.label = shape(t);
  v.detail = std::string(what) + ": alpha0 " + deg(t.cos_alpha0) + " alpha1 " + deg(t.cos_alpha1);
  return v;
}
}  // namespace

namespace {
std::string constant(double k) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", k);
  return buf;
}
}  // namespace

Verdict check_lemma7_I_at(const TerminalQuad& q, Lemma7Part part, double k) {
  const std::string ks = constant(k);
  switch (part) {
    case Lemma7Part::a:
      return both(q, [&](const Fig3& t) {
        return lemma7_ratio(t, is_acute(t) && small_alpha0(t), k, ("alpha1 < " + ks + " alpha0").c_str());
      });
    case Lemma7Part::b:
      return both(q, [&](const Fig3& t) {
        return lemma7_ratio(t, is_acute(t) && t.cos_alpha0 >= cos_alpha_limit(), k, ("alpha1 < " + ks + " alpha0").c_str());
      });
    // (c) as checkable statements: a right triangle has alpha1 = alpha0 exactly (M is its
    // circumcentre); an acute one with alpha0 <= 5 degrees has alpha1 >= k alpha0.
    case Lemma7Part::c:
      return both(q, [&](const Fig3& t) {
        bool right = !is_acute(t) && !is_obtuse(t);
        if (right) {
          Verdict v;
          v.conclusion = t.cos_alpha1 == t.cos_alpha0;
          v.label = "right";
          v.detail = "right triangle with alpha1 != alpha0";
          return v;
        }
        Cmp small = ge_const(angle_deg(t.cos_alpha0), 5.0);
        Verdict v = lemma7_ratio(t, is_acute(t) && small == Cmp::No, k,
                                 ("alpha1 < " + ks + " alpha0 with alpha0 <= 5").c_str());
        v.label = "acute, alpha0 <= 5";
        return v;
      });
    case Lemma7Part::d: break;
  }
  return both(q, [&](const Fig3& t) {
    Verdict v;
    v.hypothesis = is_acute(t) && small_alpha0(t);
    Cmp c = ge(angle_deg(t.cos_beta), k, angle_deg(t.cos_alpha0));
    v.tie = c == Cmp::Tie;
    v.conclusion = c != Cmp::No;
    v.label = shape(t);
    v.detail = "beta " + deg(t.cos_beta) + " < " + ks + " alpha0, alpha0 " + deg(t.cos_alpha0);
    return v;
  });
}
Verdict check_lemma7_Ia(const TerminalQuad& q) { return check_lemma7_I_at(q, Lemma7Part::a, 0.79); }
Verdict check_lemma7_Ib(const TerminalQuad& q) { return check_lemma7_I_at(q, Lemma7Part::b, 0.866); }
Verdict check_lemma7_Ic(const TerminalQuad& q) { return check_lemma7_I_at(q, Lemma7Part::c, 0.99); }
Verdict check_lemma7_Id(const TerminalQuad& q) { return check_lemma7_I_at(q, Lemma7Part::d, 1.79); }
Verdict check_lemma7_II(const TerminalQuad& q) {
  return both(q, [](const Fig3& t) {
    Verdict v;
    v.hypothesis = is_obtuse(t);
    v.conclusion = t.cos_alpha1 < t.cos_alpha0;  // alpha1 > alpha0, strictly
    v.label = "obtuse";
    v.detail = "alpha1 " + deg(t.cos_alpha1) + " <= alpha0 " + deg(t.cos_alpha0);
    return v;
  });
}

namespace {
// Simpson's longest-edge coordinates of a terminal triangle BAC: origin B, x along BA, C above.
struct LeCoords {
  P B, A;
  FT l;
  int side;
  FT a(const P& p) const { return dot(p - B, A - B) / l; }
  FT b(const P& p) const { return FT(side) * cross(A - B, p - B) / l; }
};
P reflect(const P& p, const P& a, const P& b) {  // p reflected across line ab
  P d = b - a;
  FT t = dot(p - a, d) / norm2(d);
  P foot = a + t * d;
  return foot + (foot - p);
}
P circumcentre(const P& A, const P& B, const P& C) {
  FT dC = FT(2) * cross(B - A, C - A);
  FT ox = (norm2(B - A) * (C.y - A.y) - norm2(C - A) * (B.y - A.y)) / dC;
  FT oy = (norm2(C - A) * (B.x - A.x) - norm2(B - A) * (C.x - A.x)) / dC;
  return A + P{ox, oy};
}
}  // namespace

namespace {
Verdict lemma11_impl(const TerminalQuad& q, bool strict_b_upper);
}
Verdict check_lemma11(const TerminalQuad& q) { return lemma11_impl(q, true); }
Verdict check_lemma11_narrowed(const TerminalQuad& q) { return lemma11_impl(q, false); }
namespace {
Verdict lemma11_impl(const TerminalQuad& q, bool strict_b_upper) {
  Pair p = make_pair(q);
  Verdict v;
  v.detail = show(q);
  // ABC is the obtuse triangle of the pair (either one, checked both ways).
  bool any = false;
  for (int k = 0; k < 2; ++k) {
    P C = k == 0 ? p.C : p.D, D = k == 0 ? p.D : p.C;
    Fig3 t = terminal_fig3(p.A, p.B, C);
    if (!is_obtuse(t)) continue;
    any = true;
    LeCoords le{t.B, t.A, CGAL::sqrt(t.ba2), orient(t.B, t.A, C)};
    P O = circumcentre(t.A, t.B, C);
    P U = reflect(t.B, t.A, O);  // second intersection of circle(A, |AB|) with CC(ABC)
    P W = reflect(t.A, t.B, O);  // second intersection of circle(B, |AB|) with CC(ABC)
    FT amin = std::min(le.a(U), le.a(W)), amax = std::max(le.a(U), le.a(W)), bmin = le.b(U);
    P Q = FT(0.25) * (t.A + t.B + C + D);
    FT aQ = le.a(Q), bQ = le.b(Q), bD = le.b(D), bC = le.b(C);
    bool a_lo = amin / FT(4) + le.l / FT(4) < aQ, a_hi = aQ < amax / FT(4) + le.l / FT(2);
    bool b_lo = bD / FT(4) < bQ, b_hi = strict_b_upper ? bQ < (bC + bmin) / FT(4) : bQ <= (bC + bmin) / FT(4);
    if (bD == bmin) v.label = "D at U or W";
    bool ok = a_lo && a_hi && b_lo && b_hi;
    v.label = le.b(U) == le.b(W) ? "obtuse" : "obtuse, b(U) != b(W)";
    if (!ok) {
      v.conclusion = false;
      v.detail += std::string("; ") + (a_lo ? "" : " a_Q <= a_min/4 + l/4") + (a_hi ? "" : " a_Q >= a_max/4 + l/2") +
                  (b_lo ? "" : " b_Q <= b_D/4") + (b_hi ? "" : " b_Q >= (b_C + b_min)/4") + " (b_D " +
                  std::to_string(CGAL::to_double(bD)) + ", b_min " + std::to_string(CGAL::to_double(bmin)) + ")";
    }
  }
  v.hypothesis = any && p.hypothesis;
  if (!any) v.label = "no obtuse triangle";
  return v;
}
}  // namespace

namespace {
bool strictly_inside(const P& q, const P& a, const P& b, const P& c) {
  int o = orient(a, b, c);
  return orient(a, b, q) == o && orient(b, c, q) == o && orient(c, a, q) == o;
}
}  // namespace

Verdict check_corollary12(const TerminalQuad& q) {
  Pair p = make_pair(q);
  Verdict v;
  v.hypothesis = p.hypothesis;
  P Q = FT(0.25) * (p.A + p.B + p.C + p.D);
  FT mc = min_angle_cos(p.A, p.B, p.C), md = min_angle_cos(p.A, p.B, p.D);  // smaller cos = better
  bool inC = strictly_inside(Q, p.A, p.B, p.C), inD = strictly_inside(Q, p.A, p.B, p.D);
  v.conclusion = mc < md ? inC : md < mc ? inD : (inC || inD);
  v.label = mc == md ? "equal smallest angles" : (mc < md) == inC ? "in the better triangle" : "in the worse triangle";
  v.detail = show(q) + ": smallest angles ABC " + deg(mc) + ", ABD " + deg(md) + "; Q " + show(Q) +
             (inC ? " inside ABC" : inD ? " inside ABD" : " on AB") + (p.hypothesis ? "" : " [" + p.why + "]");
  return v;
}

// Narrowed to the exact condition: b_Q = (b_C + b_D)/4, so Q is inside the
// triangle whose apex is farther from AB. When the better triangle is also the
// taller one (strictly), Q lies strictly inside it.
Verdict check_corollary12_narrowed(const TerminalQuad& q) {
  Verdict v = check_corollary12(q);
  Pair p = make_pair(q);
  FT mc = min_angle_cos(p.A, p.B, p.C), md = min_angle_cos(p.A, p.B, p.D);
  FT hc = CGAL::abs(cross(p.B - p.A, p.C - p.A)), hd = CGAL::abs(cross(p.B - p.A, p.D - p.A));
  bool better_is_taller = (mc < md && hc > hd) || (md < mc && hd > hc) || (mc == md && hc != hd);
  v.hypothesis = v.hypothesis && better_is_taller;
  return v;
}

namespace {
// d(Q) >= c |BC| for the worse triangle(s) of the pair; `want` filters the case.
Verdict remark13_impl(const TerminalQuad& q, int want /* -1 both, 0 obtuse, 1 non-obtuse */, const FT& c) {
  Pair p = make_pair(q);
  Verdict v;
  P Q = FT(0.25) * (p.A + p.B + p.C + p.D);
  FT dQ = std::min(std::min(dist2(Q, p.A), dist2(Q, p.B)), std::min(dist2(Q, p.C), dist2(Q, p.D)));
  FT mc = min_angle_cos(p.A, p.B, p.C), md = min_angle_cos(p.A, p.B, p.D);
  bool any = false;
  for (int k = 0; k < 2; ++k) {
    if ((k == 0 && mc < md) || (k == 1 && md < mc)) continue;  // only the worse triangle(s)
    Fig3 t = terminal_fig3(p.A, p.B, k == 0 ? p.C : p.D);
    int which = is_obtuse(t) ? 0 : 1;
    if (!small_alpha0(t) || (want >= 0 && want != which)) continue;
    any = true;
    v.label = which == 0 ? "(1) worse triangle obtuse" : "(2) worse triangle non-obtuse";
    if (dQ < c * c * t.bc2) {
      v.conclusion = false;
      v.detail = show(q) + ": d(Q)/BC = " + std::to_string(std::sqrt(CGAL::to_double(dQ / t.bc2))) + " < " +
                 std::to_string(CGAL::to_double(c)) + " (" + v.label + ", alpha0 " + deg(t.cos_alpha0) + ")";
    }
  }
  v.hypothesis = any && p.hypothesis;
  if (!any) v.label = "not applicable";
  return v;
}
}  // namespace

Verdict check_remark13_case(const TerminalQuad& q, Remark13Case which, double c) {
  return remark13_impl(q, which == Remark13Case::Obtuse ? 0 : 1, FT(c));
}

Verdict check_remark13(const TerminalQuad& q) { return remark13_impl(q, -1, FT(0.75)); }

Verdict check_theorem14(const TerminalQuad& q) {
  Pair p = make_pair(q);
  Verdict v;
  v.hypothesis = p.hypothesis;
  P Q = FT(0.25) * (p.A + p.B + p.C + p.D);
  bool collinear = orient(p.A, p.B, Q) == 0;
  auto right_isosceles = [](const P& a, const P& b, const P& c) {
    return dot(a - c, b - c) == FT(0) && dist2(a, c) == dist2(b, c);
  };
  bool both_ri = right_isosceles(p.A, p.B, p.C) && right_isosceles(p.A, p.B, p.D);
  v.conclusion = !collinear || both_ri;
  v.label = collinear ? (both_ri ? "collinear, right isosceles pair" : "collinear") : "not collinear";
  v.detail = show(q) + ": Q " + show(Q) + (collinear ? " lies on line AB" : "") + (both_ri ? " (right isosceles pair)" : "");
  return v;
}

// Narrowed: Q is on line AB exactly when C and D are equally far from AB, and
// then Q lies strictly between A and B (never at a vertex of the terminal edge).
Verdict check_theorem14_narrowed(const TerminalQuad& q) {
  Pair p = make_pair(q);
  Verdict v;
  v.hypothesis = p.hypothesis;
  P Q = FT(0.25) * (p.A + p.B + p.C + p.D);
  bool collinear = orient(p.A, p.B, Q) == 0;
  FT hc = CGAL::abs(cross(p.B - p.A, p.C - p.A)), hd = CGAL::abs(cross(p.B - p.A, p.D - p.A));
  bool equal_heights = hc == hd;
  bool between = !collinear || (dot(Q - p.A, p.B - p.A) > FT(0) && dot(Q - p.B, p.A - p.B) > FT(0));
  v.conclusion = collinear == equal_heights && between;
  v.label = collinear ? "collinear (equal heights)" : "not collinear";
  v.detail = show(q) + ": Q " + show(Q) + (collinear ? " on AB" : "") + (equal_heights ? " equal heights" : "") +
             (between ? "" : " Q not strictly between A and B");
  return v;
}

}  // namespace lepp::theorems
