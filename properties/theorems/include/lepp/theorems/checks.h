// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's statements as named check functions on integer-grid inputs.
// Each check returns a Verdict: whether the statement's hypothesis holds for
// the input and whether its conclusion does, both decided exactly. The
// properties (statements.h) assert `hypothesis implies conclusion` on generated
// inputs; the negative tests feed the same functions a configuration that drops
// a hypothesis and assert the conclusion is rejected.
// Notation is the paper's Fig. 3 (see docs/THEOREMS.md for the readings chosen):
// a triangle is labelled B, A, C with BC <= CA <= BA; alpha0 is the angle at A,
// M the midpoint of BA, alpha1 the angle MCA, beta the angle BMC.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

namespace lepp::theorems {

struct GridPoint {
  std::int64_t x = 0, y = 0;
};
struct GridTriangle {
  GridPoint p[3];
};
// A pair of triangles ABC and ABD sharing the edge AB, C and D on opposite sides.
struct TerminalQuad {
  GridPoint A, B, C, D;
};
// A terminal pair inside a mesh, with every vertex of the mesh (d(M) is measured to all).
struct TerminalInMesh {
  TerminalQuad quad;
  std::vector<GridPoint> vertices;
};

struct Verdict {
  bool hypothesis = true;  // the statement's hypotheses hold for this input
  bool conclusion = true;  // its conclusion holds
  // For inputs made of several triangles (a pair, a mesh): false when the conclusion
  // fails on some triangle whatever its hypotheses, so a negative test can show a
  // violation on a triangle that drops one (see `rejected`).
  bool conclusion_everywhere = true;
  bool tie = false;        // a bracketed angle comparison met a tie within 1e-9 degrees
  std::string label;       // a short class of the input, for RC_CLASSIFY
  std::string detail;      // what was measured, for failure messages
  bool holds() const { return !hypothesis || conclusion; }
  // What a negative test asserts: the hypothesis fails and so does the conclusion.
  bool rejected() const { return !hypothesis && !(conclusion && conclusion_everywhere); }
};

std::string show(const GridTriangle& t);
std::string show(const TerminalQuad& q);

// ABC and ABD: C, D strictly on opposite sides of AB; AB a longest edge of both
// (ties allowed); D not strictly inside the circumcircle of ABC (local Delaunay).
bool is_delaunay_terminal_pair(const TerminalQuad& q, std::string* why = nullptr);

// --- Theorem 1: iterated longest-edge bisection, on exact squared-side triples.
enum class Bisection { LongestEdge, ShortestEdge /* the hypothesis dropped */ };
struct BisectionClasses {
  bool closed = false;                   // every class's children are classes already found
  std::size_t classes = 0;               // similarity classes found (mirror images identified)
  std::vector<std::size_t> cumulative;   // classes seen up to level k, k = 0..levels
  bool min_angle_bound = true;           // every class has smallest angle > alpha0/2 (strict)
  bool all_reach_quasi_equilateral = true;  // from every class a quasi-equilateral class is reachable
  std::size_t quasi_equilateral_classes = 0;
  std::vector<double> quasi_share;       // area share of quasi-equilateral triangles at level k
  std::string detail;
};
BisectionClasses bisection_classes(const GridTriangle& t0, Bisection rule, std::size_t max_classes, int levels);
Verdict check_theorem1_min_angle(const GridTriangle& t0, Bisection rule = Bisection::LongestEdge);
Verdict check_theorem1_finite_classes(const GridTriangle& t0, Bisection rule = Bisection::LongestEdge);
Verdict check_theorem1_quasi_equilateral(const GridTriangle& t0, Bisection rule = Bisection::LongestEdge);

// --- Single-triangle statements. Labelling::AsGiven reads p[0], p[1], p[2] as
// B, A, C without sorting, so a negative test can bisect a non-longest edge.
enum class Labelling { Fig3, AsGiven };
Verdict check_prop3a(const GridTriangle& t, Labelling l = Labelling::Fig3);
Verdict check_prop3b(const GridTriangle& t, Labelling l = Labelling::Fig3);
Verdict check_lemma4(const GridTriangle& t, double theta_deg = 30, Labelling l = Labelling::Fig3);
Verdict check_lemma4_narrowed(const GridTriangle& t, double theta_deg = 30, Labelling l = Labelling::Fig3);
// Theorem 9's chain: bisect t, then its son t_B, and so on: beta_j >= (3/2)^j alpha0 until t_Bj is good.
Verdict check_theorem9_chain(const GridTriangle& t, double theta_deg);

// --- Delaunay terminal triangle statements: both triangles ABC and ABD of the pair are checked.
Verdict check_theorem2(const TerminalQuad& q);
Verdict check_prop6a_own_vertices(const TerminalQuad& q);
Verdict check_prop6b(const TerminalQuad& q);
Verdict check_prop6c(const TerminalQuad& q);
Verdict check_lemma7_Ia(const TerminalQuad& q);
Verdict check_lemma7_Ib(const TerminalQuad& q);
Verdict check_lemma7_Ic(const TerminalQuad& q);
Verdict check_lemma7_Id(const TerminalQuad& q);
Verdict check_lemma7_II(const TerminalQuad& q);
Verdict check_lemma11(const TerminalQuad& q);
// Narrowed: b_Q <= (b_C + b_min)/4, equality when D is U or W; the other three bounds strict.
Verdict check_lemma11_narrowed(const TerminalQuad& q);
Verdict check_corollary12(const TerminalQuad& q);
// Narrowed to the exact condition: when the better triangle's apex is strictly farther from AB
// than the other's, Q is strictly inside the better triangle.
Verdict check_corollary12_narrowed(const TerminalQuad& q);
Verdict check_remark13(const TerminalQuad& q);
// Remark 13 restricted to one case, with the constant c: d(Q) >= c |BC|.
enum class Remark13Case { Obtuse, NonObtuse };
Verdict check_remark13_case(const TerminalQuad& q, Remark13Case which, double c);
Verdict check_theorem14(const TerminalQuad& q);
Verdict check_theorem14_narrowed(const TerminalQuad& q);

// Theorem 2's equality case, on exact points with sqrt(3): A, B on the grid, C on
// the arc where angle ACB = 120 degrees at parameter s = s_num/s_den in (-1, 1),
// D = the equilateral apex + (dx, dy)/d_den.
struct Theorem2EqualityInput {
  GridPoint A, B;
  std::int64_t s_num = 0, s_den = 1;
  std::int64_t dx = 0, dy = 0, d_den = 1;
};
Verdict check_theorem2_equality(const Theorem2EqualityInput& in);

// --- Statements measured in a Delaunay mesh: d(M) to every mesh vertex.
enum class Lemma8Part { a_i, a_ii, b_i, b_ii, b_iii, c };
// Narrowed (a)(i), (a)(ii): d(M) to the triangle's own three vertices, as in the
// proof, and (a)(i) with the constant its worst case gives, 1/(4 sin(alpha_limit/2)) = 1.29632 > 1.29.
enum class Lemma8Narrowed { a_i_own_129, a_ii_own_096 };
Verdict check_lemma8_narrowed(const TerminalInMesh& t, Lemma8Narrowed part);
Verdict check_lemma8(const TerminalInMesh& t, Lemma8Part part);
Verdict check_prop6a_mesh(const TerminalInMesh& t);
// Theorem 9 (a), (b): with theta <= alpha_limit, the midpoint M of a bad terminal
// triangle of smallest angle alpha <= 14 degrees is no closer to any vertex than
// |BC|; otherwise (obtuse) at least 0.66 |BC|.
Verdict check_theorem9_distances(const TerminalInMesh& t, double theta_deg);
// The Delaunay triangulation of the points (CGAL) and its interior terminal pairs.
std::vector<TerminalInMesh> delaunay_terminal_pairs(const std::vector<GridPoint>& points);

double alpha_limit_deg();

}  // namespace lepp::theorems
