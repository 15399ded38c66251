// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's statements decided for all configurations, not sampled. With the
// terminal edge put at B = (0, 0), A = (1, 0) by similarity, a terminal pair is
// two points C, D; the hypotheses and the claims of an algebraic statement are
// polynomial inequalities (cosines and squared lengths for angles and lengths, a
// square root as a variable r with r^2 = E, r >= 0). Z3's nlsat procedure, which
// is complete for nonlinear real arithmetic, proves a statement by showing that
// "hypotheses and not claim" has no solution, or finds a solution, which becomes
// an exact integer-grid counterexample that the row's own check function in
// properties/theorems (the one its sampling property calls) must then reject.
#pragma once
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace lepp::prove {

enum class Outcome { Proved, Refuted, NotDecided };
const char* name(Outcome o);

// A point of a counterexample, exact on the integer grid ("B", "A", "C", "D", "V", or
// "mesh vertex" for the other vertices of a sampled mesh).
struct NamedPoint {
  std::string name;
  std::int64_t x = 0, y = 0;
};

// One statement of docs/THEOREMS.md's table, decided.
struct Decision {
  std::string where;      // "Theorem 2", as in the table
  std::string statement;  // the row's property, Suite.Name
  Outcome outcome = Outcome::NotDecided;
  std::string method;     // "Z3 nlsat", "interval branch-and-bound (MPFI), ...", "sampled counterexample", ...
  double seconds = 0;
  // Refuted: the exact counterexample (integer coordinates) and whether the
  // row's check function rejected it (a refutation it does not confirm is a bug).
  std::string counterexample;
  std::vector<NamedPoint> points;  // the counterexample's points, for its picture
  bool confirmed = false;
  // The picture's link as the table gives it (write_counterexample_pictures sets it).
  std::string picture;
  std::string note;  // why not decided, or what the proof assumed (a strengthening)
};

struct Options {
  double time_limit_s = 30;  // per solver call (Z3, then QEPCAD B where Z3 ran out)
  std::string corpus_dir = "corpus/theorems";  // the sampled counterexamples
};

// The rows, in the table's order: every statement of lepp::theorems::statements().
std::vector<std::string> row_statements();
// "algebraic" (an obligation for the solvers), "transcendental" (a box problem for the
// interval branch-and-bound, MPFI), "sampled" (refuted by a kept sampled
// counterexample), "not first-order", or "" when the prover has no such row.
std::string row_kind(const std::string& statement);
// Decide one row (by Suite.Name), or all; `progress` hears each row as it ends.
Decision decide(const std::string& statement, const Options& opt);
std::vector<Decision> decide_all(const Options& opt, const std::function<void(const Decision&)>& progress = {});
// A refutation lepp theorems cannot stand behind (its run fails): Z3's counterexample,
// not confirmed, where a check function took the configuration (decide re-checks a
// point no check function takes exactly by Z3 and says so in the note).
bool unconfirmed_refutation(const Decision& d);

// --- The prover can say no: the row's obligation with one hypothesis dropped.
// Returns the hypotheses a row has (by name) and decides the obligation without
// `dropped`; a refutation is confirmed when the row's check function rejects the
// counterexample (its hypothesis fails and so does its conclusion).
std::vector<std::string> hypotheses(const std::string& statement);
Decision decide_without(const std::string& statement, const std::string& dropped, const Options& opt);
// The hypothesis a negative test drops (the row's essential one).
std::string essential_hypothesis(const std::string& statement);

// --- Slices: a conjunct may be decided in slices of x1 (x1 <= c1, c1 <= x1 <= c2, ...,
// x1 >= cn). The row's cut points per conjunct of its claim (empty: not split), and why a
// list of cuts would not cover every x1 ("" when it does: the cuts are rationals in
// increasing order and Z3 proves the slices' disjunction valid).
std::vector<std::vector<std::string>> x1_cuts(const std::string& statement);
std::string slice_gap(const std::vector<std::string>& cuts);

// --- Obligation files (corpus/theorems/proofs/): SMT-LIB 2 for every algebraic
// row, QEPCAD B input for the rows with few enough variables. Each file names the
// answer lepp recorded (unsat = proved, sat = refuted).
struct ObligationFile {
  std::string name;      // file name, e.g. "theorem2.smt2"
  std::string contents;
  std::string expected;  // "unsat"/"sat" for SMT-LIB, "TRUE"/"FALSE" for QEPCAD B
};
// The files of the rows Z3 decided in `decisions` (proved: unsat, refuted: sat).
std::vector<ObligationFile> obligation_files(const std::vector<Decision>& decisions);
// Writes them (and an index, expected.txt) into `dir`; false when a file cannot be written.
bool write_obligation_files(const std::string& dir, const std::vector<Decision>& decisions, std::string* error = nullptr);

// --- Tight constants: for a statement with a numeric constant, the largest value
// proved and a value at most `tolerance` above it refuted by an exact counterexample.
struct TightConstant {
  std::string where, statement;
  std::string paper;        // the paper's (or the narrowed row's) constant
  std::string meaning;      // how the constant k reads in the claim
  double proved = 0;        // largest value proved
  double refuted = 0;       // smallest value refuted (Z3: satisfiable, exactly; Lemma 7 (I): a grid point
                            // of the boxes that the row's check function, given k, rejects)
  double witnessed = 0;     // smallest value refuted with a grid configuration (`extreme`)
  bool complete = false;    // refuted - proved <= tolerance, both decided
  std::string extreme;      // the configuration near the extreme (counterexample at `refuted`)
  std::string known;        // the known configuration it approaches, where there is one
  std::string stopped;      // when not complete: why the bisection stopped
  int steps = 0;
  double seconds = 0;
};
std::vector<std::string> tight_statements();
TightConstant tighten(const std::string& statement, const Options& opt, double tolerance = 1e-6, int max_steps = 40);

// --- Counterexample pictures: the terminal pair (or triangle) of a refuted row drawn
// with the project's renderer, each point ringed and labelled with its exact coordinates.
// Throws std::invalid_argument when the decision has no counterexample points.
std::string counterexample_svg(const Decision& d);
// The picture's file name for a row: "Lemma4-BisectionImprovesTBLeavesObtuseTA.svg".
std::string picture_name(const std::string& statement);
// Writes one SVG per refuted decision with points into `dir` and sets its `picture` to
// `link_dir` + "/" + the file name (the path the table links, relative to the table).
bool write_counterexample_pictures(const std::string& dir, const std::string& link_dir, std::vector<Decision>& decisions,
                                   std::string* error = nullptr);
// The `link_dir` for a table written to `table_path` ("" when it goes to stdout: the
// current directory): `dir` relative to the table's directory, with '/' separators.
std::string picture_link_dir(const std::string& dir, const std::string& table_path);

// --- Markdown. The cell of the "decided" column for one row.
std::string decided_cell(const Decision& d);
// The certificate table of `lepp theorems` with its "result" column renamed
// "sampled" and a "decided" column added (rows matched by their property).
std::string add_decided_column(const std::string& table, const std::vector<Decision>& decisions);
std::string tight_markdown(const std::vector<TightConstant>& rows);

}  // namespace lepp::prove
