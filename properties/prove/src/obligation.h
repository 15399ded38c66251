// SPDX-License-Identifier: GPL-3.0-or-later
// A statement's proof obligation as Z3 expressions, in the frame B = (0, 0),
// A = (1, 0) (a similarity puts the terminal edge there): the primary variables
// (C = (x1, y1), D = (x2, y2), and a mesh vertex V = (x3, y3) where the claim
// ranges over every vertex of a mesh), square roots as defined variables, the
// named hypotheses and the claim. Internal to lepp_prove.
#pragma once
#include <z3++.h>

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "interval_bnb.h"
#include "lepp/theorems/checks.h"

namespace lepp::prove {

struct Obligation {
  explicit Obligation(z3::context& c) : ctx(c), defs(c), claim(c.bool_val(true)) {}
  z3::context& ctx;
  std::vector<z3::expr> primary;  // the coordinates, in order: x1 y1 [x2 y2 [x3 y3]]
  z3::expr_vector defs;           // r >= 0, r^2 = E for each square root r
  std::vector<std::pair<std::string, z3::expr>> hyps;
  z3::expr claim;
  std::map<std::string, z3::expr> cache;  // square roots and cosines made once
  // nlsat's variable order per conjunct of the claim (Row::nlsat_seeds; 0: its own order).
  std::vector<unsigned> seeds;
  // Per conjunct, the cut points on x1 that split it into slices (Row::x1_cuts).
  std::vector<std::vector<std::string>> x1_cuts;

  z3::expr num(const std::string& rational) { return ctx.real_val(rational.c_str()); }
  // A defined variable r with r >= 0 and r^2 = e.
  z3::expr root(const std::string& name, const z3::expr& e);
  // A defined variable v with v * den = numerator (den > 0 by the hypotheses).
  z3::expr quotient(const std::string& name, const z3::expr& numerator, const z3::expr& den);
  void hyp(const std::string& name, const z3::expr& e) { hyps.emplace_back(name, e); }
};

// Exact integer-grid configuration: B = (0, 0), A = (L, 0), then C, D, V scaled by L.
struct Config {
  std::int64_t L = 1;
  std::vector<std::int64_t> v;  // x1 y1 [x2 y2 [x3 y3]], already scaled
  theorems::GridPoint B() const { return {0, 0}; }
  theorems::GridPoint A() const { return {L, 0}; }
  theorems::GridPoint P(int i) const { return {v[2 * i], v[2 * i + 1]}; }
  theorems::TerminalQuad quad() const { return {A(), B(), P(0), P(1)}; }
  std::string show() const;
};

enum class Shape { Triangle, Pair, Mesh };

// One row of the table, as the prover sees it.
struct Row {
  std::string statement;  // Suite.Name
  Shape shape = Shape::Pair;
  // Builds hypotheses and claim; `k` is the row's constant (paper's value when default).
  std::function<void(Obligation&, const z3::expr& k)> build;
  std::string constant;   // the row's constant as a rational ("-1/2", "129/100"); empty: none
  std::string constant_meaning;  // how the constant reads ("cos of the angle at C")
  // The row's exact check function on a configuration; `negative`: a hypothesis was
  // dropped, read the triangle as given (Labelling::AsGiven) where that matters.
  std::function<theorems::Verdict(const Config&, bool negative)> check;
  std::string essential;  // the hypothesis a negative test drops
  // false: the check function cannot judge a configuration outside the row's hypotheses
  // (it reports "not applicable" without a conclusion), so a negative test's refutation
  // is Z3's exact model alone, not confirmed by it.
  bool negative_check = true;
  std::string note;       // how the proof reads the statement (a strengthening, the frame)
  std::string not_decided;  // non-empty: not first-order over the reals, why
  std::string sampled;      // corpus file of the sampled counterexample that refutes the row
  std::string known_extreme;  // the configuration the tight constant approaches, if known
  // Proved rows (lemmas) whose claims stand in for some hypotheses here (the proof is the
  // composition: the lemma's hypotheses give its claim, which with the rest gives ours).
  std::vector<std::string> via;
  // QEPCAD B: write its input file for CI (the rows it answers within seconds, measured:
  // a four-variable CAD of the other rows runs for minutes), and try it before Z3
  // (the rows nlsat does not decide in minutes).
  bool qepcad_file = false;
  bool qepcad_first = false;
  // nlsat's variable order for each conjunct of the claim, in order: 0 keeps its own
  // order, s > 0 shuffles the variables with seed s (`shuffle_vars`, `seed`). Any order
  // is a complete procedure, so an unsat answer is a proof whichever order found it; the
  // order only decides how long it takes (seconds or beyond the time limit). Found by
  // trying seeds 1, 2, ... with the z3 binary on the written file, and fixed here so the
  // library and the file CI re-checks run the same procedure.
  std::vector<unsigned> nlsat_seeds;
  // Per conjunct of the claim, in order: cut points c1 < ... < cn on x1 (rationals) that
  // split its obligation into the slices x1 <= c1, c1 <= x1 <= c2, ..., x1 >= cn, each
  // decided (and written) on its own; the slices cover every x1, so the conjunct is
  // proved when every slice is. Empty: one piece. For the conjuncts nlsat decides in
  // each slice within a second and not within minutes whole.
  std::vector<std::vector<std::string>> x1_cuts;
  // A transcendental row (its claim compares angles with a decimal multiple of angles):
  // its box problem without the hypothesis `dropped` (none when empty), decided by the
  // interval branch-and-bound (interval_bnb.h) instead of `build`.
  std::function<bnb::Problem(const std::string& dropped)> boxes;
  // An algebraic part of such a row, proved by Z3 before the boxes: "" when proved, else why not.
  std::function<std::string(double time_limit_s)> side;
};

// The Lemma 7 (I) rows (transcendental.cpp), and a row's box problem with its constant
// replaced by k_num/k_den (k_den = 0: the row's own constant).
Row lemma7_transcendental(const std::string& statement);
bnb::Problem lemma7_problem(const std::string& statement, const std::string& dropped, long k_num = 0, long k_den = 0);
// Its check function with the constant k (the row's own check at the paper's k), on the
// configuration's triangle B A C with D its mirror image in AB.
theorems::Verdict lemma7_check_at(const std::string& statement, const Config& c, double k);

const std::vector<Row>& prover_rows();
const Row* find_row(const std::string& statement);

}  // namespace lepp::prove
