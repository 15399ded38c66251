// SPDX-License-Identifier: GPL-3.0-or-later
// Statements about one triangle and its longest-edge bisection (Fig. 3):
// Proposition 3, Lemma 4, and the chain of Theorem 9.
#include <cmath>

#include "exact.h"
#include "lepp/theorems/checks.h"

namespace lepp::theorems {
using namespace exact;

std::string show(const GridTriangle& t) {
  std::string s = "triangle";
  for (auto& p : t.p) s += " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
  return s;
}

namespace {

Fig3 label(const GridTriangle& g, Labelling l) {
  P a = pt(g.p[0]), b = pt(g.p[1]), c = pt(g.p[2]);
  return l == Labelling::Fig3 ? fig3(a, b, c) : fig3_as_given(a, b, c);
}
// The Fig. 3 hypothesis BC <= CA <= BA (always true for Labelling::Fig3).
bool fig3_order(const Fig3& t) { return t.bc2 <= t.ca2 && t.ca2 <= t.ba2; }
bool degenerate(const GridTriangle& g) {
  return (g.p[1].x - g.p[0].x) * (g.p[2].y - g.p[0].y) - (g.p[1].y - g.p[0].y) * (g.p[2].x - g.p[0].x) == 0;
}
// A degenerate input meets no hypothesis; nothing fails and nothing ties. (Named
// fields: a positional initializer once put the label in `tie` when a field was added.)
Verdict degenerate_verdict(const GridTriangle& g) {
  Verdict v;
  v.hypothesis = false;
  v.label = "degenerate";
  v.detail = show(g);
  return v;
}
std::string angles(const Fig3& t) {
  auto d = [](const FT& c) { return std::to_string(angle_deg(c).lo); };
  return "alpha0 " + d(t.cos_alpha0) + ", alpha1 " + d(t.cos_alpha1) + ", beta " + d(t.cos_beta) + ", gamma " +
         d(t.cos_gamma);
}
// cos of an angle below theta, decided exactly for 30 degrees and alpha_limit.
Cmp angle_below(const FT& cos_angle, double theta_deg, bool* tie) {
  if (theta_deg == 30) return cos_angle > cos_deg30() ? Cmp::Yes : Cmp::No;
  Cmp c = ge_const(angle_deg(cos_angle), theta_deg);
  if (c == Cmp::Tie) *tie = true;
  return c == Cmp::No ? Cmp::Yes : Cmp::No;
}
std::string shape(const Fig3& t) { return is_obtuse(t) ? "obtuse" : is_acute(t) ? "acute" : "right"; }

}  // namespace

Verdict check_prop3a(const GridTriangle& g, Labelling l) {
  Verdict v;
  if (degenerate(g)) return degenerate_verdict(g);
  Fig3 t = label(g, l);
  v.hypothesis = fig3_order(t);
  bool half = angle_ge(t.cos_alpha1, cos_half(t.cos_alpha0));
  bool three_halves = angle_ge(t.cos_beta, cos_three_halves(t.cos_alpha0));
  v.conclusion = half && three_halves;
  v.label = shape(t);
  v.detail = show(g) + ": " + angles(t) + (half ? "" : "; alpha1 < alpha0/2") + (three_halves ? "" : "; beta < 3 alpha0/2");
  return v;
}

Verdict check_prop3b(const GridTriangle& g, Labelling l) {
  Verdict v;
  if (degenerate(g)) return degenerate_verdict(g);
  Fig3 t = label(g, l);
  v.hypothesis = fig3_order(t) && is_obtuse(t);
  bool a1 = angle_ge(t.cos_alpha1, t.cos_alpha0);
  bool b2 = angle_ge(t.cos_beta, cos_double(t.cos_alpha0));
  v.conclusion = a1 && b2;
  v.label = shape(t);
  v.detail = show(g) + ": " + angles(t) + (a1 ? "" : "; alpha1 < alpha0") + (b2 ? "" : "; beta < 2 alpha0");
  return v;
}

namespace {
// Lemma 4's three conclusions, measured: t_B = BMC improved (smallest angle > alpha0),
// t_A = AMC bad (smallest angle < theta) and the angle AMC = pi - beta compared with 90.
struct Lemma4Parts {
  bool improved, bad, obtuse, right;
};
Lemma4Parts lemma4_parts(const Fig3& t, double theta, bool* tie) {
  Lemma4Parts p;
  p.improved = min_angle_cos(t.B, t.M, t.C) < t.cos_alpha0;
  p.bad = angle_below(min_angle_cos(t.A, t.M, t.C), theta, tie) == Cmp::Yes;
  int s = CGAL::sign(cos_at(t.M, t.A, t.C));
  p.obtuse = s < 0;
  p.right = s == 0;
  return p;
}
}  // namespace

Verdict check_lemma4(const GridTriangle& g, double theta, Labelling l) {
  Verdict v;
  if (degenerate(g)) return degenerate_verdict(g);
  Fig3 t = label(g, l);
  v.hypothesis = fig3_order(t) && angle_below(t.cos_alpha0, theta, &v.tie) == Cmp::Yes;
  auto p = lemma4_parts(t, theta, &v.tie);
  v.conclusion = p.improved && p.bad && p.obtuse;
  v.label = shape(t);
  v.detail = show(g) + ": " + angles(t) + (p.improved ? "" : "; t_B not improved") + (p.bad ? "" : "; t_A not bad") +
             (p.obtuse ? "" : p.right ? "; t_A right, not obtuse" : "; t_A acute");
  return v;
}

// Narrowed: the statement holds when BC < CA strictly. When BC = CA the median CM
// is the altitude: t_A and t_B are congruent right triangles, t_B keeps alpha0.
Verdict check_lemma4_narrowed(const GridTriangle& g, double theta, Labelling l) {
  Verdict v = check_lemma4(g, theta, l);
  if (degenerate(g)) return v;
  Fig3 t = label(g, l);
  v.hypothesis = v.hypothesis && t.bc2 < t.ca2;
  return v;
}

Verdict check_theorem9_chain(const GridTriangle& g, double theta) {
  Verdict v;
  if (degenerate(g)) return degenerate_verdict(g);
  Fig3 t = label(g, Labelling::Fig3);
  AngleBracket alpha0 = angle_deg(t.cos_alpha0);
  // Hypothesis: a bad triangle that can be a Delaunay terminal triangle (largest angle <= 120), theta <= alpha_limit.
  v.hypothesis = theta <= alpha_limit_deg() + 1e-12 && angle_below(t.cos_alpha0, theta, &v.tie) == Cmp::Yes &&
                 angle_ge(cos_deg120(), t.cos_gamma);
  v.detail = show(g) + ": alpha0 " + std::to_string(alpha0.lo);
  P B = t.B, A = t.A, C = t.C;
  const int bound = static_cast<int>(std::ceil(std::log(90.0 / std::max(alpha0.lo, 1e-9)) / std::log(1.5))) + 2;
  for (int j = 1;; ++j) {
    Fig3 tj = fig3(B, A, C);
    AngleBracket beta = angle_deg(tj.cos_beta);
    Cmp c = ge(beta, std::pow(1.5, j), alpha0);
    if (c == Cmp::Tie) v.tie = true;
    if (c == Cmp::No) {
      v.conclusion = false;
      v.detail += "; beta_" + std::to_string(j) + " = " + std::to_string(beta.lo) + " < (3/2)^" + std::to_string(j) + " alpha0";
      v.label = "fails at step " + std::to_string(j);
      return v;
    }
    // t_Bj = B M C: the son keeping edge CB.
    A = tj.M;
    B = tj.B;
    C = tj.C;
    bool tie = false;
    if (angle_below(min_angle_cos(A, B, C), theta, &tie) == Cmp::No) {
      v.label = "good after " + std::to_string(j) + (j == 1 ? " step" : " steps");
      return v;
    }
    if (j > bound) {
      v.conclusion = false;
      v.detail += "; still bad after " + std::to_string(j) + " steps";
      v.label = "not finite";
      return v;
    }
  }
}

}  // namespace lepp::theorems
