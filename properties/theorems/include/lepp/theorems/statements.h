// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's statements, one row each: where the paper states it, the
// RapidCheck property that checks it (Suite.Name, as the gtest is named), the
// reading chosen, and, for a statement that fails as written, the finding and
// the narrowed statement that holds. Both the gtest binary (ctest label
// `theorems`) and `lepp theorems` run these same properties.
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace lepp::theorems {

struct Statement {
  std::string where;           // "Theorem 2", "Lemma 8 (a)(i)"
  std::string suite, name;     // the property: Suite.Name
  std::string interpretation;  // the reading chosen, in a sentence or two
  // Empty when the statement holds as written. Otherwise the finding: why it
  // fails, the corpus file with the shrunk counterexample, and `narrowed`,
  // the Suite.Name of the narrowed statement (a row of its own).
  std::string finding;
  std::string corpus;
  std::string narrowed;
  std::function<void()> property;  // a RapidCheck property body: uses *gen and RC_ASSERT
  // A statistical row (Section 5): runs its own N inputs and reports a share.
  std::function<std::string(int inputs, bool* holds)> statistic;
};

const std::vector<Statement>& statements();
const Statement* find_statement(const std::string& suite_dot_name);

// Fixed seed of the default and long runs (the gtests use it through RC_PARAMS).
constexpr std::uint64_t kSeed = 20260522;
constexpr int kDefaultCases = 100;
constexpr int kLongCases = 3000;
constexpr int kDefaultInputs = 24;  // Section 5 statistics
constexpr int kLongInputs = 200;

struct RunOutcome {
  bool passed = false;      // the property found no counterexample
  bool gave_up = false;     // too many discarded cases
  int cases = 0;            // cases run
  int applicable = 0;       // cases where the statement's hypothesis held
  std::map<std::string, int> classes;  // RC_CLASSIFY distribution
  std::string counterexample;          // the shrunk failing input and message
  std::string statistic;               // Section 5 rows: the measured share
  double seconds = 0;
};
RunOutcome run_statement(const Statement& s, int cases, int inputs, std::uint64_t seed);

// Markdown certificate: one row per statement. Returns true when every row holds
// or is a documented finding whose counterexample reproduced (its narrowed row holds).
struct CertificateRow {
  const Statement* statement;
  RunOutcome outcome;
};
bool certificate_ok(const std::vector<CertificateRow>& rows);
std::string certificate_markdown(const std::vector<CertificateRow>& rows, bool long_run, int cases, int inputs);

}  // namespace lepp::theorems
