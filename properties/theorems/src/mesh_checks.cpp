// SPDX-License-Identifier: GPL-3.0-or-later
// Statements that measure d(M), the distance from the terminal edge's midpoint
// to the nearest vertex of the whole mesh: Proposition 6 (a) read in a mesh,
// Lemma 8, Theorem 9 (a)(b). Distances are exact integers: 4|V - M|^2 = |2V - A - B|^2.
#include "exact.h"
#include "lepp/theorems/checks.h"

namespace lepp::theorems {
using namespace exact;

namespace {
using I = __int128;

struct Measured {
  Fig3 t;
  I dM4 = 0;  // 4 d(M)^2 over every mesh vertex
  I bc2 = 0, bm4 = 0, cm4 = 0;
  bool pair_ok = false;
  std::string why;
};

I sq(I v) { return v * v; }

// > 0 when d is strictly inside the circumcircle of abc (exact in 128 bits for grid coordinates).
int in_circle(const GridPoint& a, const GridPoint& b, const GridPoint& c, const GridPoint& d) {
  I adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y, cdx = c.x - d.x, cdy = c.y - d.y;
  I det = (adx * adx + ady * ady) * (bdx * cdy - bdy * cdx) - (bdx * bdx + bdy * bdy) * (adx * cdy - ady * cdx) +
          (cdx * cdx + cdy * cdy) * (adx * bdy - ady * bdx);
  I o = (I(b.x) - a.x) * (I(c.y) - a.y) - (I(b.y) - a.y) * (I(c.x) - a.x);
  int sd = det > 0 ? 1 : det < 0 ? -1 : 0, so = o > 0 ? 1 : o < 0 ? -1 : 0;
  return sd * so;
}

// Both terminal triangles of the pair, measured in the mesh.
std::vector<Measured> measure(const TerminalInMesh& m, bool own_triangle = false) {
  const TerminalQuad& q = m.quad;
  std::vector<Measured> out;
  std::string why;
  bool ok = is_delaunay_terminal_pair(q, &why);
  // The mesh is Delaunay around the pair: no vertex strictly inside either circumcircle.
  for (auto& v : m.vertices)
    if (ok && (in_circle(q.A, q.B, q.C, v) > 0 || in_circle(q.A, q.B, q.D, v) > 0)) {
      ok = false;
      why = "a mesh vertex lies inside a circumcircle of the pair";
    }
  I dM4 = -1;
  for (auto& v : m.vertices) {
    I d = sq(I(2) * v.x - q.A.x - q.B.x) + sq(I(2) * v.y - q.A.y - q.B.y);
    if (dM4 < 0 || d < dM4) dM4 = d;
  }
  for (const GridPoint& apex : {q.C, q.D}) {
    if (own_triangle) {  // d(M) to A, B and this apex only
      dM4 = std::min(sq(I(q.A.x) - q.B.x) + sq(I(q.A.y) - q.B.y),
                     sq(I(2) * apex.x - q.A.x - q.B.x) + sq(I(2) * apex.y - q.A.y - q.B.y));
    }
    // B: the terminal edge endpoint nearer the apex (BC the shortest edge).
    I da = sq(I(apex.x) - q.A.x) + sq(I(apex.y) - q.A.y), db = sq(I(apex.x) - q.B.x) + sq(I(apex.y) - q.B.y);
    const GridPoint& B = db <= da ? q.B : q.A;
    const GridPoint& A = db <= da ? q.A : q.B;
    Measured r;
    r.t = fig3_as_given(pt(B), pt(A), pt(apex));
    r.dM4 = dM4;
    r.bc2 = std::min(da, db);
    r.bm4 = sq(I(A.x) - B.x) + sq(I(A.y) - B.y);
    r.cm4 = sq(I(2) * apex.x - q.A.x - q.B.x) + sq(I(2) * apex.y - q.A.y - q.B.y);
    r.pair_ok = ok;
    r.why = why;
    out.push_back(r);
  }
  return out;
}

// d(M) > c |BC| (strict) or >= (c_strict false), with c = num/den: 4 d^2 den^2 vs 4 num^2 bc^2.
bool dM_at_least(const Measured& r, I num, I den, bool strict) {
  I lhs = r.dM4 * den * den, rhs = I(4) * num * num * r.bc2;
  return strict ? lhs > rhs : lhs >= rhs;
}
std::string ratio(const Measured& r) {
  return std::to_string(std::sqrt(static_cast<double>(r.dM4) / 4.0 / static_cast<double>(r.bc2)));
}
std::string shape(const Fig3& t) { return is_obtuse(t) ? "obtuse" : is_acute(t) ? "acute" : "right"; }

// alpha <= deg, exactly for 30 and alpha_limit, bracketed otherwise.
bool alpha_at_most(const Fig3& t, double deg, bool* tie) {
  if (deg == 30) return t.cos_alpha0 >= cos_deg30();
  Cmp c = ge_const(angle_deg(t.cos_alpha0), deg);
  if (c == Cmp::Tie) *tie = true;
  return c != Cmp::Yes || c == Cmp::Tie;
}
bool alpha_at_most_limit(const Fig3& t) { return t.cos_alpha0 >= cos_alpha_limit(); }

template <class F>
Verdict over_pair(const TerminalInMesh& m, F one, bool own_triangle = false) {
  Verdict v;
  v.hypothesis = false;
  v.detail = show(m.quad);
  for (const Measured& r : measure(m, own_triangle)) {
    if (!r.pair_ok) {
      v.detail += " [" + r.why + "]";
    }
    Verdict w = one(r);
    if (!w.conclusion) v.conclusion_everywhere = false;
    if (!w.hypothesis) continue;
    if (!w.conclusion) {
      v.conclusion = false;
      v.detail += "; " + w.detail;
    }
    if (!r.pair_ok) continue;  // a negative test may feed a pair that is not Delaunay
    v.hypothesis = true;
    v.tie = v.tie || w.tie;
    v.label = w.label;
    if (!w.conclusion) {
      v.conclusion = false;
      v.detail += "; " + w.detail;
    }
  }
  if (v.label.empty()) v.label = "not applicable";
  return v;
}

// Applies the conclusion only where the statement's angle/shape hypotheses hold.
Verdict part(const Measured& r, bool applies, bool conclusion, const std::string& what) {
  Verdict v;
  v.hypothesis = applies;
  v.conclusion = conclusion;
  v.label = shape(r.t);
  v.detail = what + ", d(M)/BC = " + ratio(r) + ", alpha " + std::to_string(angle_deg(r.t.cos_alpha0).lo);
  return v;
}
}  // namespace

Verdict check_lemma8(const TerminalInMesh& m, Lemma8Part p) {
  Verdict out = over_pair(m, [p](const Measured& r) {
    bool tie = false;
    const Fig3& t = r.t;
    Verdict v;
    switch (p) {
      case Lemma8Part::a_i: v = part(r, is_acute(t) && alpha_at_most_limit(t), dM_at_least(r, 13, 10, true), "(a)(i) acute, alpha <= alpha_limit, d(M) <= 1.3 |BC|"); break;
      case Lemma8Part::a_ii: v = part(r, is_acute(t) && alpha_at_most(t, 30, &tie), dM_at_least(r, 96, 100, true), "(a)(ii) acute, alpha <= 30, d(M) <= 0.96 |BC|"); break;
      case Lemma8Part::b_i: v = part(r, is_obtuse(t) && alpha_at_most(t, 14, &tie), dM_at_least(r, 1, 1, true), "(b)(i) obtuse, alpha <= 14, d(M) <= |BC|"); break;
      case Lemma8Part::b_ii: v = part(r, is_obtuse(t) && alpha_at_most_limit(t), dM_at_least(r, 66, 100, true), "(b)(ii) obtuse, alpha <= alpha_limit, d(M) <= 0.66 |BC|"); break;
      case Lemma8Part::b_iii: v = part(r, is_obtuse(t) && alpha_at_most(t, 30, &tie), dM_at_least(r, 1, 2, false), "(b)(iii) obtuse, alpha <= 30, d(M) < 0.5 |BC|"); break;
      case Lemma8Part::c: {
        Cmp above14 = ge_const(angle_deg(t.cos_alpha0), 14.0);
        Cmp beta28 = ge_const(angle_deg(t.cos_beta), 28.0);
        tie = above14 == Cmp::Tie || beta28 == Cmp::Tie;
        v = part(r, is_obtuse(t) && above14 == Cmp::Yes, beta28 == Cmp::Yes, "(c) obtuse, alpha > 14, beta <= 28 (beta " + std::to_string(angle_deg(t.cos_beta).lo) + ")");
        break;
      }
    }
    v.tie = tie;
    return v;
  });
  return out;
}

Verdict check_lemma8_narrowed(const TerminalInMesh& m, Lemma8Narrowed p) {
  return over_pair(
      m,
      [p](const Measured& r) {
        const Fig3& t = r.t;
        if (p == Lemma8Narrowed::a_i_own_129)
          return part(r, is_acute(t) && alpha_at_most_limit(t), dM_at_least(r, 129, 100, true),
                      "(a)(i) narrowed: acute, alpha <= alpha_limit, d(M) to A, B, C <= 1.29 |BC|");
        bool tie = false;
        Verdict v = part(r, is_acute(t) && alpha_at_most(t, 30, &tie), dM_at_least(r, 96, 100, true),
                         "(a)(ii) narrowed: acute, alpha <= 30, d(M) to A, B, C <= 0.96 |BC|");
        v.tie = tie;
        return v;
      },
      /*own_triangle=*/true);
}

Verdict check_prop6a_mesh(const TerminalInMesh& m) {
  return over_pair(m, [](const Measured& r) {
    const Fig3& t = r.t;
    bool applies = t.cos_alpha0 >= cos_deg30() && (is_acute(t) || is_obtuse(t));
    bool ok = is_acute(t) ? r.dM4 == r.bm4 : r.dM4 == r.cm4;
    return part(r, applies, ok, is_acute(t) ? "(i) acute but d(M) != BM" : "(ii) obtuse but d(M) != CM");
  });
}

Verdict check_theorem9_distances(const TerminalInMesh& m, double theta) {
  return over_pair(m, [theta](const Measured& r) {
    const Fig3& t = r.t;
    bool tie = false;
    Cmp bad = ge_const(angle_deg(t.cos_alpha0), theta);  // No: alpha < theta
    bool small = alpha_at_most(t, 14, &tie);
    bool applies = theta <= alpha_limit_deg() + 1e-12 && bad == Cmp::No;
    Verdict v;
    if (small)
      v = part(r, applies, dM_at_least(r, 1, 1, false), "(a) alpha <= 14 but d(M) < |BC|");
    else
      v = part(r, applies && is_obtuse(t), dM_at_least(r, 66, 100, false), "(b) obtuse, alpha > 14, d(M) < 0.66 |BC|");
    v.tie = tie || bad == Cmp::Tie;
    if (applies) v.label = small ? "alpha <= 14" : "alpha > 14";
    return v;
  });
}

}  // namespace lepp::theorems
