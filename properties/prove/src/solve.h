// SPDX-License-Identifier: GPL-3.0-or-later
// Deciding an obligation with Z3 (nlsat) and turning a model into an exact
// integer-grid configuration. Internal to lepp_prove.
#pragma once
#include <optional>
#include <string>

#include "obligation.h"

namespace lepp::prove {

// The solver every decision uses: Z3's nlsat procedure for nonlinear real arithmetic.
constexpr const char* kTactic = "qfnra-nlsat";

// The tactic for conjunct `i` of `o`'s claim: nlsat in its own variable order, or with
// the order shuffled by the seed the row fixed (Row::nlsat_seeds); and its SMT-LIB text.
z3::tactic nlsat_tactic(const Obligation& o, std::size_t i);
std::string nlsat_tactic_smt2(const Obligation& o, std::size_t i);

enum class Answer { Unsat, Sat, Unknown };
struct Solved {
  Answer answer = Answer::Unknown;
  // Sat: a rational point of "hypotheses and not claim", scaled to the grid (none when
  // the solutions found have no rational point with small denominators near them).
  std::optional<Config> config;
  std::string reason;            // Unknown: why (time limit, no rational point found)
  double seconds = 0;
};

// Builds the row's obligation in `o` with constant k (the row's own when empty),
// without the hypothesis `dropped` (none when empty).
void build(const Row& row, Obligation& o, const std::string& k = "", const std::string& dropped = "");
Solved solve(Obligation& o, double time_limit_s);
// The claim's top-level conjuncts (solve decides them one at a time), and the premises
// (definitions and hypotheses).
std::vector<z3::expr> conjuncts(const z3::expr& claim);
// The slices of conjunct `i` (Row::x1_cuts): x1 <= c1, c1 <= x1 <= c2, ..., x1 >= cn, or
// the one piece `true` when it has no cuts. Their disjunction is valid.
std::vector<z3::expr> slices(const Obligation& o, std::size_t i);
z3::expr_vector premises(const Obligation& o);

// QEPCAD B (cylindrical algebraic decomposition), the second procedure: its input for
// the universal closure of "definitions and hypotheses imply claim", when the
// obligation has at most kQepcadVariables variables.
constexpr std::size_t kQepcadVariables = 5;
bool qepcad_writable(const Obligation& o);
std::string qepcad_input(const Obligation& o, const std::string& title);
// Runs `qepcad +N200000000` on it with a time limit: Unsat (TRUE, proved), Sat
// (FALSE, no point given) or Unknown with the reason (time, failure, not installed).
Solved solve_qepcad(const Obligation& o, double time_limit_s);

}  // namespace lepp::prove
