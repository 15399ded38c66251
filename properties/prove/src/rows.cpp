// SPDX-License-Identifier: GPL-3.0-or-later
// Every row of docs/THEOREMS.md as a proof obligation. Frame: B = (0, 0),
// A = (1, 0), C = (x1, y1) above AB, D = (x2, y2) below. The pair's hypotheses
// are invariant under the reflection x -> 1 - x (A and B swap names) and under
// exchanging the two triangles (reflection in AB), so a claim made of "either
// triangle of the pair" is proved for ABC with C nearer B (x1 <= 1/2, the
// paper's Fig. 3 labelling: BC <= CA) and that covers both.
#include <cmath>

#include "obligation.h"

namespace lepp::prove {
namespace {
using z3::expr;
using namespace lepp::theorems;

// --- Fig. 3 quantities of the triangle B A P, P = (x, y) with y > 0, x <= 1/2.
struct Apex {
  Obligation& o;
  expr x, y;
  std::string tag;  // "C", "D"
  expr ca2() const { return (1 - x) * (1 - x) + y * y; }
  expr bc2() const { return x * x + y * y; }
  expr cm2() const { return (o.num("1/2") - x) * (o.num("1/2") - x) + y * y; }
  // (A - P).(B - P): < 0 obtuse at P, > 0 acute.
  expr dot() const { return x * x - x + y * y; }
  expr obtuse() const { return dot() < 0; }
  expr acute() const { return dot() > 0; }
  // alpha0 <= 30 degrees: cos alpha0 = (1 - x)/|CA| >= sqrt(3)/2, with 1 - x > 0.
  expr le30() const { return (1 - x) * (1 - x) >= 3 * y * y; }
  expr lt30() const { return (1 - x) * (1 - x) > 3 * y * y; }
  // alpha0 <= alpha_limit: cos^2 alpha_limit = 1/(1 + tan^2) = (7 + 3 sqrt 5)/16.
  expr le_limit() const { return 16 * (1 - x) * (1 - x) >= (7 + 3 * o.root("s5", o.num("5"))) * ca2(); }
  expr ca() const { return o.root("ca" + tag, ca2()); }
  expr bc() const { return o.root("bc" + tag, bc2()); }
  expr cm() const { return o.root("cm" + tag, cm2()); }
  expr cos_alpha0() const { return o.quotient("cosa0" + tag, 1 - x, ca()); }
  expr cos_alpha1() const {  // angle MCA
    return o.quotient("cosa1" + tag, (o.num("1/2") - x) * (1 - x) + y * y, cm() * ca());
  }
  expr cos_beta() const { return o.quotient("cosb" + tag, o.num("1/2") - x, cm()); }  // angle BMC
  // The circumcentre O = (1/2, oy) (oy < 0 when obtuse at P) and the circumradius R.
  expr oy() const { return o.quotient("oy" + tag, dot(), 2 * y); }
  expr R() const { return o.root("R" + tag, o.num("1/4") + oy() * oy()); }
  // V = (vx, vy) not strictly inside the circle through B, A, P.
  expr outside(const expr& vx, const expr& vy) const {
    return y * (vx * vx + vy * vy - vx) - vy * (x * x + y * y - x) >= 0;
  }
  // d(M) to the triangle's own vertices: min(|MB|, |MC|) > k |BC| (or >=).
  expr own_dM_above(const expr& k, bool strict) const {
    expr r = k * k * bc2();
    return strict ? (o.num("1/4") > r && cm2() > r) : (o.num("1/4") >= r && cm2() >= r);
  }
};

// The pair: C above AB, D below; AB a longest edge of both; D not strictly inside CC(ABC).
struct Pair {
  Obligation& o;
  expr x1, y1, x2, y2;
  Apex C() const { return {o, x1, y1, "C"}; }
  // Squared lengths from D.
  expr ad2() const { return (1 - x2) * (1 - x2) + y2 * y2; }
  expr bd2() const { return x2 * x2 + y2 * y2; }
  // > 0 when D is strictly inside the circle through B, A, C (C above AB).
  expr in_circle() const { return y2 * (x1 * x1 + y1 * y1 - x1) - y1 * (x2 * x2 + y2 * y2 - x2); }
  void hypotheses(bool wlog_c_nearer_b) const {
    o.hyp("C above AB", y1 > 0);
    o.hyp("D below AB", y2 < 0);
    o.hyp("AB longest in ABC", C().ca2() <= 1 && C().bc2() <= 1);
    o.hyp("AB longest in ABD", ad2() <= 1 && bd2() <= 1);
    o.hyp("Delaunay", in_circle() <= 0);
    if (wlog_c_nearer_b) o.hyp("C nearer B (frame)", x1 <= o.num("1/2"));
  }
  // Centroid Q of the quad.
  expr qx() const { return (1 + x1 + x2) / 4; }
  expr qy() const { return (y1 + y2) / 4; }
};

Pair make_pair(Obligation& o) {
  expr x1 = o.ctx.real_const("x1"), y1 = o.ctx.real_const("y1"), x2 = o.ctx.real_const("x2"),
       y2 = o.ctx.real_const("y2");
  o.primary = {x1, y1, x2, y2};
  return {o, x1, y1, x2, y2};
}
Apex make_triangle(Obligation& o) {
  expr x = o.ctx.real_const("x1"), y = o.ctx.real_const("y1");
  o.primary = {x, y};
  o.hyp("C above AB (frame)", y > 0);
  o.hyp("BC <= CA", x <= o.num("1/2"));
  o.hyp("BA longest", Apex{o, x, y, "C"}.ca2() <= 1);
  return {o, x, y, "C"};
}
// A mesh vertex V, not strictly inside either circumcircle of the pair (the mesh is
// Delaunay). V ranges over A, B, C, D and every other vertex, so a claim for all V is
// the claim for d(M) over the whole mesh.
struct MeshVertex {
  expr x, y;
};
MeshVertex make_mesh_vertex(Obligation& o, const Pair& p) {
  expr x3 = o.ctx.real_const("x3"), y3 = o.ctx.real_const("y3");
  o.primary.push_back(x3);
  o.primary.push_back(y3);
  expr pv = x3 * x3 + y3 * y3 - x3;
  o.hyp("V outside CC(ABC)", p.C().outside(x3, y3));
  o.hyp("V outside CC(ABD)", p.y2 * pv - y3 * (p.x2 * p.x2 + p.y2 * p.y2 - p.x2) <= 0);
  return {x3, y3};
}

// a/sqrt(ra2) < b/sqrt(rb2) for a, b >= 0 (cosines of angles at A or B of a terminal triangle).
expr cos_lt(const expr& a, const expr& ra2, const expr& b, const expr& rb2) { return a * a * rb2 < b * b * ra2; }

// The smallest angles of ABC and ABD compared through their largest cosines (at A or B).
struct Smallest {
  expr c_better, d_better;  // ABC's smallest angle strictly larger / ABD's strictly larger
};
Smallest smallest_angles(const Pair& p) {
  Apex c = p.C();
  expr cA = 1 - p.x1, cB = p.x1, dA = 1 - p.x2, dB = p.x2;
  expr ca2 = c.ca2(), cb2 = c.bc2(), da2 = p.ad2(), db2 = p.bd2();
  auto lt = [&](const expr& a, const expr& ra, const expr& b, const expr& rb) { return cos_lt(a, ra, b, rb); };
  // max(cos at A, cos at B) of ABC < that of ABD.
  expr c_better = (lt(cA, ca2, dA, da2) || lt(cA, ca2, dB, db2)) && (lt(cB, cb2, dA, da2) || lt(cB, cb2, dB, db2));
  expr d_better = (lt(dA, da2, cA, ca2) || lt(dA, da2, cB, cb2)) && (lt(dB, db2, cA, ca2) || lt(dB, db2, cB, cb2));
  return {c_better, d_better};
}

// ABC the worse triangle (C nearer B): the angles of ABD at A and at B are at least alpha0,
// through tangents: tan(DAB) = -y2/(1 - x2) >= y1/(1 - x1) and tan(DBA) = -y2/x2 >= y1/(1 - x1).
expr worse_by_tangents(const Pair& p) {
  return -p.y2 * (1 - p.x1) >= p.y1 * (1 - p.x2) && -p.y2 * (1 - p.x1) >= p.y1 * p.x2;
}

// Q strictly inside the triangle B A P (P above AB: counter-clockwise) or below (clockwise).
expr strictly_inside(const expr& qx, const expr& qy, const expr& px, const expr& py, bool above) {
  auto cross = [](const expr& ux, const expr& uy, const expr& vx, const expr& vy) { return ux * vy - uy * vx; };
  expr c1 = cross(qx.ctx().real_val(1), qx.ctx().real_val(0), qx, qy);  // (A - B) x (Q - B)
  expr c2 = cross(px - 1, py, qx - 1, qy);                              // (P - A) x (Q - A)
  expr c3 = cross(-px, -py, qx - px, qy - py);                          // (B - P) x (Q - P)
  return above ? (c1 > 0 && c2 > 0 && c3 > 0) : (c1 < 0 && c2 < 0 && c3 < 0);
}

TerminalInMesh mesh_of(const Config& c) {
  TerminalQuad q = c.quad();
  return {q, {q.A, q.B, q.C, q.D, c.P(2)}};
}
GridTriangle triangle_of(const Config& c) { return {{c.B(), c.A(), c.P(0)}}; }
Labelling labelling(bool negative) { return negative ? Labelling::AsGiven : Labelling::Fig3; }

// Rows whose hypotheses or claims are not first-order statements over the reals.
Row not_first_order(const std::string& statement, const std::string& why) {
  Row r;
  r.statement = statement;
  r.not_decided = why;
  return r;
}

std::vector<Row> make_rows() {
  std::vector<Row> rows;
  const std::string theorem1 =
      "not first-order over the reals: a closure under iterated bisection (an unbounded number of steps)";
  rows.push_back(not_first_order("Theorem1.MinAngleAtLeastHalfAlpha0", theorem1));
  rows.push_back(not_first_order("Theorem1.FinitelyManySimilarityClasses", theorem1));
  rows.push_back(not_first_order("Theorem1.QuasiEquilateralShareGrows", theorem1 + " and a limit of area shares"));

  {
    Row r;
    r.statement = "Theorem2.TerminalTrianglesLargestAngleAtMost120";
    r.qepcad_file = true;
    r.constant = "-1/2";
    r.constant_meaning = "cos of the largest angle is at least k (k = -1/2: 120 degrees)";
    r.build = [](Obligation& o, const expr& k) {
      Pair p = make_pair(o);
      p.hypotheses(false);
      Apex c = p.C();
      // cos(angle at C) >= k, k < 0: dot >= 0, or k^2 |CA|^2 |CB|^2 >= dot^2.
      o.claim = c.dot() >= 0 || k * k * c.ca2() * c.bc2() >= c.dot() * c.dot();
    };
    r.check = [](const Config& c, bool) { return check_theorem2(c.quad()); };
    r.essential = "Delaunay";
    r.note = "the angle at C; the angle at D by exchanging the triangles";
    r.known_extreme = "C on the 120-degree arc with D the equilateral apex (Theorem 2's equality case)";
    rows.push_back(r);
  }
  {
    Row r;
    r.statement = "Theorem2.EqualityCaseCocircularWithEquilateral";
    r.qepcad_file = true;
    r.build = [](Obligation& o, const expr&) {
      Pair p = make_pair(o);
      p.hypotheses(false);
      Apex c = p.C();
      o.hyp("angle at C = 120", c.dot() < 0 && 4 * c.dot() * c.dot() == c.ca2() * c.bc2());
      // Circumcentre O = (1/2, oy), oy = dot/(2 y1); |MO| = r/2 iff 3 oy^2 = 1/4 iff 3 dot^2 = y1^2.
      o.claim = p.ad2() == 1 && p.bd2() == 1 && p.in_circle() == 0 && 3 * c.dot() * c.dot() == p.y1 * p.y1;
    };
    r.essential = "angle at C = 120";
    r.note = "exact algebraic equality case; C anywhere on the 120-degree arc (the sampled row draws it)";
    rows.push_back(r);
  }
  {
    Row r;
    r.statement = "Proposition3.Alpha1AtLeastHalfAlpha0";
    r.shape = Shape::Triangle;
    r.build = [](Obligation& o, const expr&) {
      Apex c = make_triangle(o);
      expr h = o.root("ch", (1 + c.cos_alpha0()) / 2);  // cos(alpha0/2)
      o.claim = c.cos_alpha1() <= h && c.cos_beta() <= 4 * h * h * h - 3 * h;
    };
    r.check = [](const Config& c, bool neg) { return check_prop3a(triangle_of(c), labelling(neg)); };
    r.essential = "BC <= CA";
    rows.push_back(r);
  }
  {
    Row r;
    r.statement = "Proposition3.ObtuseAlpha1AtLeastAlpha0";
    r.shape = Shape::Triangle;
    r.build = [](Obligation& o, const expr&) {
      Apex c = make_triangle(o);
      o.hyp("obtuse", c.obtuse());
      expr c0 = c.cos_alpha0();
      o.claim = c.cos_alpha1() <= c0 && c.cos_beta() <= 2 * c0 * c0 - 1;
    };
    r.check = [](const Config& c, bool neg) { return check_prop3b(triangle_of(c), labelling(neg)); };
    r.essential = "obtuse";
    rows.push_back(r);
  }
  auto lemma4 = [](bool narrowed) {
    Row r;
    r.statement = narrowed ? "Lemma4.HoldsWhenBCShorterThanCA" : "Lemma4.BisectionImprovesTBLeavesObtuseTA";
    r.shape = Shape::Triangle;
    r.build = [narrowed](Obligation& o, const expr&) {
      Apex c = make_triangle(o);
      o.hyp("alpha0 < 30", c.lt30());
      if (narrowed) o.hyp("BC < CA", c.x < o.num("1/2"));
      expr c0 = c.cos_alpha0(), cb = c.cos_beta(), c1 = c.cos_alpha1();
      // t_B = BMC improved: each of its angles (at B, M, C) has cosine < cos alpha0.
      expr improved = c.x < c0 * c.bc() && cb < c0 && c.x * c.x - c.x / 2 + c.y * c.y < c0 * c.bc() * c.cm();
      // t_A = AMC bad: an angle (at A, M = pi - beta, C = alpha1) with cosine > sqrt(3)/2.
      auto below30 = [](const expr& cs) { return cs > 0 && 4 * cs * cs > 3; };
      expr bad = below30(c0) || below30(-cb) || below30(c1);
      o.claim = improved && bad && cb > 0;  // angle AMC = pi - beta > 90
    };
    r.check = [](const Config& c, bool neg) { return check_lemma4(triangle_of(c), 30, labelling(neg)); };
    if (narrowed)
      r.check = [](const Config& c, bool neg) { return check_lemma4_narrowed(triangle_of(c), 30, labelling(neg)); };
    r.essential = narrowed ? "BC < CA" : "alpha0 < 30";
    return r;
  };
  rows.push_back(lemma4(false));
  rows.push_back(lemma4(true));
  {
    Row r;
    r.statement = "Proposition6.MidpointNearestVertexOfOwnTriangle";
    r.qepcad_file = true;
    r.build = [](Obligation& o, const expr&) {
      Pair p = make_pair(o);
      p.hypotheses(true);
      Apex c = p.C();
      o.hyp("alpha0 <= 30", c.le30());
      o.hyp("not right", c.dot() != 0);
      o.claim = implies(c.acute(), o.num("1/4") <= c.cm2()) && implies(c.obtuse(), c.cm2() <= o.num("1/4"));
    };
    r.check = [](const Config& c, bool) { return check_prop6a_own_vertices(c.quad()); };
    // No hypothesis is needed (Thales: the angle at C is acute exactly when C is outside
    // the circle on diameter AB, i.e. |MC| > |MB|), so there is none to drop.
    r.note = "holds for every triangle: acute at C exactly when |MC| > |MB| (Thales)";
    rows.push_back(r);
  }
  Row sampled_mesh;
  sampled_mesh.statement = "Proposition6.MidpointNearestVertexInDelaunayMesh";
  sampled_mesh.sampled = "prop6a_mesh.txt";
  rows.push_back(sampled_mesh);
  {
    Row r;
    r.statement = "Proposition6.AcuteWorstRatioIsIsosceles";
    r.qepcad_file = true;
    r.constant = "1";
    r.constant_meaning = "d(M)/|BC| >= k times the isosceles ratio 1/(4 sin(alpha0/2))";
    r.build = [](Obligation& o, const expr& k) {
      Pair p = make_pair(o);
      p.hypotheses(true);
      Apex c = p.C();
      o.hyp("alpha0 <= 30", c.le30());
      o.hyp("acute", c.acute());
      expr f = 8 * (1 - c.cos_alpha0());  // (d/BC)^2 >= k^2 / (8 (1 - cos alpha0))
      o.claim = f / 4 >= k * k * c.bc2() && f * c.cm2() >= k * k * c.bc2();
    };
    r.check = [](const Config& c, bool) { return check_prop6b(c.quad()); };
    r.essential = "acute";
    r.known_extreme = "the isosceles triangle BA = CA (the proposition's own worst case)";
    rows.push_back(r);
  }
  {
    Row r;
    r.statement = "Proposition6.ObtuseWorstRatioIs120Triangle";
    r.qepcad_first = true;
    r.qepcad_file = true;
    r.shape = Shape::Triangle;
    r.constant = "1";
    r.constant_meaning = "d(M)/|BC| >= k times the ratio of the triangle of angles 120, alpha0, 60 - alpha0";
    r.via = {"Theorem2.TerminalTrianglesLargestAngleAtMost120"};
    r.build = [](Obligation& o, const expr& k) {
      // The pair's hypotheses enter through Theorem 2 (proved): the angle at C is at most 120.
      Apex c = make_triangle(o);
      o.hyp("angle at C <= 120 (Theorem 2)", c.dot() >= 0 || 4 * c.dot() * c.dot() <= c.ca2() * c.bc2());
      o.hyp("alpha0 <= 30", c.le30());
      o.hyp("obtuse", c.obtuse());
      // The triangle of angles 120, alpha0, 60 - alpha0 with sides sin alpha0, sin(60 - alpha0),
      // sin 120, multiplied by |CA| (cos alpha0 = (1 - x)/|CA|, sin alpha0 = y/|CA|): sides y,
      // (sqrt(3) (1 - x) - y)/2 and sqrt(3/4) |CA|; both sides of the claim times |CA|^2.
      expr s3 = o.root("s3", o.num("3"));
      expr ca = (s3 * (1 - c.x) - c.y) / 2;
      expr cm2 = (2 * ca * ca + 2 * c.y * c.y - o.num("3/4") * c.ca2()) / 4;
      expr r2 = k * k * cm2 * c.bc2();
      o.claim = o.num("1/4") * c.y * c.y >= r2 && c.cm2() * c.y * c.y >= r2;
    };
    r.essential = "angle at C <= 120 (Theorem 2)";
    r.note = "with Theorem 2 (proved) as a lemma, the pair's hypotheses reduced to the angle at C <= 120";
    r.known_extreme = "the triangle of angles 120, alpha0, 60 - alpha0 (the proposition's own worst case)";
    rows.push_back(r);
  }
  // Compare the angle alpha1 (or beta) with a decimal multiple of alpha0: transcendental.
  for (const char* s : {"Lemma7.AcuteAlpha1AtLeast079Alpha0", "Lemma7.AcuteAlpha1AtLeast0866Alpha0BelowAlphaLimit",
                        "Lemma7.Alpha1OverAlpha0TendsToOne", "Lemma7.BetaAtLeast179Alpha0"})
    rows.push_back(lemma7_transcendental(s));
  {
    Row r;
    r.statement = "Lemma7.ObtuseAlpha1AboveAlpha0";
    r.build = [](Obligation& o, const expr&) {
      Pair p = make_pair(o);
      p.hypotheses(true);
      Apex c = p.C();
      o.hyp("obtuse", c.obtuse());
      o.claim = c.cos_alpha1() < c.cos_alpha0();
    };
    r.check = [](const Config& c, bool) { return check_lemma7_II(c.quad()); };
    r.essential = "obtuse";
    rows.push_back(r);
  }
  Row l8ai;
  l8ai.statement = "Lemma8.AcuteBelowAlphaLimitDistanceAbove13";
  l8ai.sampled = "lemma8_a_i_mesh.txt";
  rows.push_back(l8ai);
  auto lemma8_own = [](bool a_i) {
    Row r;
    r.statement = a_i ? "Lemma8.AcuteBelowAlphaLimitOwnDistanceAbove129" : "Lemma8.AcuteBelow30OwnDistanceAbove096";
    r.qepcad_file = true;
    r.constant = a_i ? "129/100" : "96/100";
    r.constant_meaning = "d(M) to A, B, C > k |BC|";
    r.build = [a_i](Obligation& o, const expr& k) {
      Pair p = make_pair(o);
      p.hypotheses(true);
      Apex c = p.C();
      o.hyp("acute", c.acute());
      if (a_i)
        o.hyp("alpha0 <= alpha_limit", c.le_limit());
      else
        o.hyp("alpha0 <= 30", c.le30());
      o.claim = c.own_dM_above(k, true);
    };
    r.check = [a_i](const Config& c, bool) {
      return check_lemma8_narrowed(TerminalInMesh{c.quad(), {}},
                                   a_i ? Lemma8Narrowed::a_i_own_129 : Lemma8Narrowed::a_ii_own_096);
    };
    r.essential = a_i ? "alpha0 <= alpha_limit" : "alpha0 <= 30";
    if (a_i) r.known_extreme = "the isosceles triangle BA = CA at alpha0 = alpha_limit (1/(4 sin(alpha_limit/2)))";
    return r;
  };
  rows.push_back(lemma8_own(true));
  Row l8aii;
  l8aii.statement = "Lemma8.AcuteBelow30DistanceAbove096";
  l8aii.sampled = "lemma8_a_ii_mesh.txt";
  rows.push_back(l8aii);
  rows.push_back(lemma8_own(false));
  // (b): d(M) over every vertex of the mesh: the claim for one free vertex V outside both circumcircles.
  {
    // Not a row of the table: the lemma the rows Lemma 8 (b)(ii) and (b)(iii) use to
    // eliminate the free mesh vertex V. M = (1/2, 0) and O = (1/2, oy) lie on AB's
    // perpendicular bisector; for ABC obtuse at C, oy < 0 and the point of the circle
    // nearest M is the top of the arc through C, at distance R + oy (the arc's sagitta):
    // a vertex not strictly inside the circle is at least that far from M.
    Row r;
    r.statement = "Lemma8.MeshVertexOutsideObtuseCircumcircle";
    r.shape = Shape::Mesh;
    r.build = [](Obligation& o, const expr&) {
      expr x1 = o.ctx.real_const("x1"), y1 = o.ctx.real_const("y1"), x3 = o.ctx.real_const("x3"),
           y3 = o.ctx.real_const("y3");
      o.primary = {x1, y1, x3, y3};
      Apex c{o, x1, y1, "C"};
      o.hyp("C above AB", y1 > 0);
      o.hyp("obtuse", c.obtuse());
      o.hyp("V outside CC(ABC)", c.outside(x3, y3));
      expr s = c.R() + c.oy();
      o.claim = (x3 - o.num("1/2")) * (x3 - o.num("1/2")) + y3 * y3 >= s * s;
    };
    r.essential = "V outside CC(ABC)";
    r.note = "|MV| >= R + oy for every V not strictly inside the circumcircle of ABC, obtuse at C";
    rows.push_back(r);
  }
  {
    // (b)(i): d(M) over every vertex of the mesh, the claim for one free vertex V outside both circumcircles.
    Row r;
    r.shape = Shape::Mesh;
    r.statement = "Lemma8.ObtuseBelow14DistanceAboveBC";
    r.constant = "1";
    r.constant_meaning = "d(M) > k |BC|";
    r.build = [](Obligation& o, const expr& k) {
      Pair p = make_pair(o);
      p.hypotheses(true);
      Apex c = p.C();
      MeshVertex v = make_mesh_vertex(o, p);
      o.hyp("obtuse", c.obtuse());
      // alpha0 <= 14 strengthened to cos alpha0 >= 0.97 (alpha0 <= 14.07)
      o.hyp("cos alpha0 >= 0.97", (1 - c.x) * (1 - c.x) >= o.num("9409/10000") * c.ca2());
      expr mv2 = (v.x - o.num("1/2")) * (v.x - o.num("1/2")) + v.y * v.y;
      o.claim = mv2 > k * k * c.bc2();
    };
    r.check = [](const Config& c, bool) { return check_lemma8(mesh_of(c), Lemma8Part::b_i); };
    r.essential = "cos alpha0 >= 0.97";
    r.note = "proved for the stronger hypothesis cos alpha0 >= 0.97 (alpha0 <= 14.07 degrees), which "
             "contains alpha0 <= 14";
    rows.push_back(r);
  }
  // (b)(ii), (b)(iii) through two lemmas: the free vertex V (six variables with the pair,
  // beyond nlsat's time limit) is eliminated by Lemma8.MeshVertexOutsideObtuseCircumcircle
  // (d(M) >= R + oy, the sagitta of the arc through C; reached by the vertex C when ABC is
  // isosceles), and the pair's D by Theorem 2 (the angle at C is at most 120), leaving the
  // triangle: R + oy > k |BC| (>= for (b)(iii)); R + oy > 0 since R^2 = 1/4 + oy^2.
  auto lemma8_b_sagitta = [](Lemma8Part part) {
    Row r;
    r.shape = Shape::Triangle;
    const bool b_ii = part == Lemma8Part::b_ii;
    r.statement = b_ii ? "Lemma8.ObtuseBelowAlphaLimitDistanceAbove066" : "Lemma8.ObtuseBelow30DistanceAtLeastHalf";
    r.constant = b_ii ? "66/100" : "1/2";
    r.constant_meaning = b_ii ? "d(M) > k |BC|" : "d(M) >= k |BC|";
    r.via = {"Theorem2.TerminalTrianglesLargestAngleAtMost120", "Lemma8.MeshVertexOutsideObtuseCircumcircle"};
    r.build = [b_ii](Obligation& o, const expr& k) {
      Apex c = make_triangle(o);
      o.hyp("angle at C <= 120 (Theorem 2)", c.dot() >= 0 || 4 * c.dot() * c.dot() <= c.ca2() * c.bc2());
      o.hyp("obtuse", c.obtuse());
      if (b_ii)
        o.hyp("alpha0 <= alpha_limit", c.le_limit());
      else
        o.hyp("alpha0 <= 30", c.le30());
      expr s = c.R() + c.oy();
      o.claim = b_ii ? s * s > k * k * c.bc2() : s * s >= k * k * c.bc2();
    };
    r.essential = "angle at C <= 120 (Theorem 2)";
    // (b)(iii) in seed 3's order: 0.1 s with the z3 binary on the written file, 13 s in nlsat's own.
    if (!b_ii) r.nlsat_seeds = {3};
    r.note = "through the lemmas Theorem 2 (the angle at C is at most 120) and "
             "Lemma8.MeshVertexOutsideObtuseCircumcircle (every mesh vertex is at least R + oy from M, the "
             "sagitta of the arc through C): proved R + oy " + std::string(b_ii ? ">" : ">=") + " k |BC|";
    r.known_extreme = b_ii ? "the isosceles-apex sagitta at angle C = 120, alpha0 = alpha_limit (1/(4 sin alpha_limit) = 0.6605)"
                           : "Theorem 2's equality case with ABC isosceles: angle C = 120, D the equilateral apex (exactly 1/2)";
    return r;
  };
  rows.push_back(lemma8_b_sagitta(Lemma8Part::b_ii));
  rows.push_back(lemma8_b_sagitta(Lemma8Part::b_iii));
  {
    Row r;
    r.statement = "Lemma8.ObtuseAbove14BetaAbove28";
    r.build = [](Obligation& o, const expr&) {
      Pair p = make_pair(o);
      p.hypotheses(true);
      Apex c = p.C();
      o.hyp("obtuse", c.obtuse());
      expr c0 = c.cos_alpha0();
      o.claim = c.cos_beta() < 2 * c0 * c0 - 1;  // beta > 2 alpha0 (2 alpha0 <= 60)
    };
    r.essential = "obtuse";
    r.note = "proved in the stronger form beta > 2 alpha0 for every obtuse Delaunay terminal triangle, "
             "which gives beta > 28 when alpha0 > 14";
    rows.push_back(r);
  }
  const std::string theorem9 =
      "not first-order over the reals: a sequence of bisections of unbounded length, with theta a parameter";
  rows.push_back(not_first_order("Theorem9.BetaChainGrowsGeometrically", theorem9));
  rows.push_back(not_first_order(
      "Theorem9.MidpointNotTooCloseToMeshVertices",
      "theta is a parameter of the statement; its two claims are Lemma 8 (b)(i) and (b)(ii), decided in those rows"));
  auto lemma11 = [](bool narrowed) {
    Row r;
    r.statement = narrowed ? "Lemma11.CentroidBoundsWithCornerEquality" : "Lemma11.CentroidBoundsInLongestEdgeCoordinates";
    r.build = [narrowed](Obligation& o, const expr&) {
      Pair p = make_pair(o);
      p.hypotheses(true);
      Apex c = p.C();
      o.hyp("obtuse", c.obtuse());
      // O = (1/2, oy); U = (2 - t, 2 t oy), W = (t - 1, 2 t oy) with t = (1/2)/|O - A|^2.
      expr oy = o.quotient("oy", c.dot(), 2 * p.y1);
      expr t = o.quotient("t", o.num("1/2"), o.num("1/4") + oy * oy);
      expr aU = 2 - t, aW = t - 1, bmin = 2 * t * oy;
      expr aq = p.qx(), bq = p.qy();
      expr a_lo = aU / 4 + o.num("1/4") < aq || aW / 4 + o.num("1/4") < aq;
      expr a_hi = aq < aU / 4 + o.num("1/2") || aq < aW / 4 + o.num("1/2");
      expr b_lo = p.y2 / 4 < bq;
      expr b_hi = narrowed ? bq <= (p.y1 + bmin) / 4 : bq < (p.y1 + bmin) / 4;
      o.claim = a_lo && a_hi && b_lo && b_hi;
    };
    r.check = [narrowed](const Config& c, bool) {
      return narrowed ? check_lemma11_narrowed(c.quad()) : check_lemma11(c.quad());
    };
    r.essential = "Delaunay";
    return r;
  };
  rows.push_back(lemma11(false));
  rows.push_back(lemma11(true));
  auto corollary12 = [](bool narrowed) {
    Row r;
    r.statement = narrowed ? "Corollary12.CentroidInsideBetterTriangleWhenItIsTaller" : "Corollary12.CentroidInsideBetterTriangle";
    r.build = [narrowed](Obligation& o, const expr&) {
      Pair p = make_pair(o);
      p.hypotheses(true);
      Smallest s = smallest_angles(p);
      expr equal = !s.c_better && !s.d_better;
      if (narrowed)
        o.hyp("better is taller",
              (s.c_better && p.y1 > -p.y2) || (s.d_better && -p.y2 > p.y1) || (equal && p.y1 != -p.y2));
      expr inC = strictly_inside(p.qx(), p.qy(), p.x1, p.y1, true);
      expr inD = strictly_inside(p.qx(), p.qy(), p.x2, p.y2, false);
      o.claim = implies(s.c_better, inC) && implies(s.d_better, inD) && implies(equal, inC || inD);
    };
    r.check = [narrowed](const Config& c, bool) {
      return narrowed ? check_corollary12_narrowed(c.quad()) : check_corollary12(c.quad());
    };
    r.essential = narrowed ? "better is taller" : "Delaunay";
    return r;
  };
  rows.push_back(corollary12(false));
  rows.push_back(corollary12(true));
  // Remark 13: the worse triangle (WLOG ABC, C nearer B), d(Q) over the quad's vertices >= k |BC|.
  auto remark13 = [](int which /* -1 both, 0 obtuse, 1 non-obtuse */) {
    Row r;
    r.statement = which < 0    ? "Remark13.CentroidDistanceAtLeast075ShortestEdge"
                  : which == 0 ? "Remark13.ObtuseCaseDistanceAbove069"
                               : "Remark13.NonObtuseCaseDistanceAbove061";
    r.constant = which < 0 ? "3/4" : which == 0 ? "69/100" : "61/100";
    r.constant_meaning = "d(Q) >= k |BC|";
    r.build = [which](Obligation& o, const expr& k) {
      Pair p = make_pair(o);
      p.hypotheses(true);
      Apex c = p.C();
      if (which < 0)
        o.hyp("ABC the worse triangle", !smallest_angles(p).c_better);
      else  // through the lemma Remark13.WorseTriangleByTangents (proved first)
        o.hyp("ABC the worse triangle (by tangents)", worse_by_tangents(p));
      o.hyp("alpha0 <= 30", c.le30());
      if (which == 0) o.hyp("obtuse", c.obtuse());
      if (which == 1) o.hyp("not obtuse", !c.obtuse());
      // (1) with Theorem 2 (proved) as a lemma: the angle at C is at most 120. Implied by the
      // pair's hypotheses, so redundant for the truth of the row, but it cuts off the flat
      // obtuse triangles nlsat otherwise explores (d(Q) to C: beyond minutes without it).
      if (which == 0)
        o.hyp("angle at C <= 120 (Theorem 2)", c.dot() >= 0 || 4 * c.dot() * c.dot() <= c.ca2() * c.bc2());
      expr qx = p.qx(), qy = p.qy(), r2 = k * k * c.bc2();
      auto d2 = [&](const expr& x, const expr& y) { return (qx - x) * (qx - x) + (qy - y) * (qy - y); };
      expr zero = o.num("0"), one = o.num("1");
      o.claim = d2(zero, zero) >= r2 && d2(one, zero) >= r2 && d2(p.x1, p.y1) >= r2 && d2(p.x2, p.y2) >= r2;
    };
    r.check = [which](const Config& c, bool) {
      return which < 0 ? check_remark13(c.quad())
                       : check_remark13_case(c.quad(), which == 0 ? Remark13Case::Obtuse : Remark13Case::NonObtuse,
                                             which == 0 ? 0.69 : 0.61);
    };
    r.essential = "alpha0 <= 30";
    // The check reads alpha0 > 30 as "not applicable" and compares no distance: a negative
    // test's counterexample is Z3's exact model alone.
    if (which >= 0) r.negative_check = false;
    if (which >= 0) {
      r.via = {"Remark13.WorseTriangleByTangents"};
      if (which == 0) r.via.push_back("Theorem2.TerminalTrianglesLargestAngleAtMost120");
      r.note = "with the lemma Remark13.WorseTriangleByTangents (proved first): ABC the worse triangle gives "
               "tan(DAB) and tan(DBA) >= tan(alpha0), which stands in for it" +
               std::string(which == 0 ? "; and Theorem 2 (proved): the angle at C is at most 120" : "");
    }
    // Conjuncts d(Q) to B, A, C, D: the one to B is decided in seconds in the order of seed 4
    // and not within minutes in nlsat's own order.
    if (which == 1) r.nlsat_seeds = {4, 0, 0, 0};
    // (1): d(Q) to B and to A in seed 4's order (about 10 s and 0.1 s; beyond minutes in nlsat's
    // own), d(Q) to C and to D in four slices of x1 each (one about 10 s, the others under a
    // second; whole, beyond minutes).
    if (which == 0) r.nlsat_seeds = {4, 4, 0, 0};
    if (which == 0) r.x1_cuts = {{}, {}, {"3/10", "35/100", "4/10"}, {"3/10", "35/100", "4/10"}};
    r.known_extreme = which == 1 ? "the mirror kite of two isosceles 30-75-75 triangles (sqrt(6)/4 = 0.6124)"
                      : which == 0 ? "a right ABC with |AD| = |AB| (0.4 sqrt(3) = 0.6928)"
                                   : "";
    return r;
  };
  {
    // Not a row of the table: the lemma the narrowed Remark 13 rows use. With x1 <= 1/2 the
    // smallest angle of ABC is alpha0 (at A, opposite the shortest edge BC) and that of ABD is
    // at A or B (AB is its longest edge), all below 90 degrees: ABC is the worse triangle
    // exactly when both angles of ABD at A and B are >= alpha0, compared through tangents
    // (bilinear in the coordinates instead of the squared cosines' degree 4).
    Row r;
    r.statement = "Remark13.WorseTriangleByTangents";
    r.build = [](Obligation& o, const expr&) {
      Pair p = make_pair(o);
      p.hypotheses(true);
      o.hyp("ABC the worse triangle", !smallest_angles(p).c_better);
      o.claim = worse_by_tangents(p);
    };
    r.essential = "ABC the worse triangle";
    rows.push_back(r);
  }
  rows.push_back(remark13(-1));
  rows.push_back(remark13(0));
  rows.push_back(remark13(1));
  auto theorem14 = [](bool narrowed) {
    Row r;
    r.statement = narrowed ? "Theorem14.CentroidOnTerminalEdgeIffEqualHeights" : "Theorem14.CentroidNotCollinearExceptRightIsosceles";
    r.qepcad_file = !narrowed;
    r.build = [narrowed](Obligation& o, const expr&) {
      Pair p = make_pair(o);
      p.hypotheses(false);
      Apex c = p.C();
      expr on_ab = p.y1 + p.y2 == 0;
      if (narrowed) {
        expr between = p.qx() > 0 && p.qx() < 1;
        o.claim = (on_ab == (p.y1 == -p.y2)) && implies(on_ab, between);
      } else {
        expr ri_c = c.dot() == 0 && c.ca2() == c.bc2();
        expr ri_d = p.x2 * p.x2 - p.x2 + p.y2 * p.y2 == 0 && p.ad2() == p.bd2();
        o.claim = implies(on_ab, ri_c && ri_d);
      }
    };
    r.check = [narrowed](const Config& c, bool) {
      return narrowed ? check_theorem14_narrowed(c.quad()) : check_theorem14(c.quad());
    };
    r.essential = narrowed ? "AB longest in ABC" : "Delaunay";
    return r;
  };
  rows.push_back(theorem14(false));
  rows.push_back(theorem14(true));
  const std::string section5 = "not first-order over the reals: a measurement over meshes of generated inputs";
  rows.push_back(not_first_order("Section5.CentroidAddsFewerPoints", section5));
  rows.push_back(not_first_order("Section5.CentroidHigherAverageSmallestAngle", section5));
  rows.push_back(not_first_order("Section5.CentroidLongerShortestEdge", section5));
  rows.push_back(not_first_order("Remark15.CentroidConvergesUpTo30Degrees",
                                 "not first-order over the reals: termination of the method on generated inputs"));
  return rows;
}
}  // namespace

expr Obligation::root(const std::string& name, const expr& e) {
  if (auto it = cache.find(name); it != cache.end()) return it->second;
  expr r = ctx.real_const(name.c_str());
  defs.push_back(r >= 0);
  defs.push_back(r * r == e);
  cache.emplace(name, r);
  return r;
}

expr Obligation::quotient(const std::string& name, const expr& numerator, const expr& den) {
  if (auto it = cache.find(name); it != cache.end()) return it->second;
  expr v = ctx.real_const(name.c_str());
  defs.push_back(v * den == numerator);
  cache.emplace(name, v);
  return v;
}

std::string Config::show() const {
  auto s = [](const theorems::GridPoint& p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; };
  std::string out = "B (0, 0) A " + s(A());
  const char* names[] = {"C", "D", "V"};
  for (std::size_t i = 0; 2 * i + 1 < v.size(); ++i) out += std::string(" ") + names[i] + " " + s(P(static_cast<int>(i)));
  return out;
}

const std::vector<Row>& prover_rows() {
  static const std::vector<Row> rows = make_rows();
  return rows;
}

const Row* find_row(const std::string& statement) {
  for (const Row& r : prover_rows())
    if (r.statement == statement) return &r;
  return nullptr;
}

}  // namespace lepp::prove
