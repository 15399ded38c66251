// SPDX-License-Identifier: GPL-3.0-or-later
// The obligations written out for other tools: SMT-LIB 2 (Z3's own printer, checked
// with the same nlsat tactic) for every row a solver decided, and QEPCAD B input
// (qepcad.cpp) for the rows it answers within seconds (Row::qepcad_file). Each
// file's first line records the answer lepp found, so CI can re-check it
// (scripts/ci.d/50-proofs.sh).
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "lepp/prove/prove.h"
#include "lepp/theorems/statements.h"
#include "solve.h"

namespace lepp::prove {
namespace {

std::string stem(const std::string& statement) {
  std::string s;
  for (char c : statement) s += c == '.' ? '-' : c;
  return s;
}

}  // namespace

std::vector<ObligationFile> obligation_files(const std::vector<Decision>& decisions) {
  std::vector<ObligationFile> out;
  // A proved row's lemma that is no row of the table (Row::via) is proved first, by Z3:
  // its file goes before the row's, once.
  std::vector<Decision> all;
  auto listed = [&all](const std::string& st) {
    for (const Decision& d : all)
      if (d.statement == st) return true;
    return false;
  };
  for (const Decision& d : decisions) {
    const Row* row = find_row(d.statement);
    if (row && d.outcome == Outcome::Proved)
      for (const std::string& via : row->via) {
        if (theorems::find_statement(via) || listed(via)) continue;
        Decision lemma;
        lemma.statement = via;
        lemma.outcome = Outcome::Proved;
        lemma.method = "Z3";
        all.push_back(lemma);
      }
    if (!listed(d.statement)) all.push_back(d);
  }
  for (const Decision& d : all) {
    const std::string& statement = d.statement;
    const Row* row = find_row(statement);
    // Only the rows a solver decided: a file records the answer lepp found. A row only
    // QEPCAD B decided gets its QEPCAD B file alone (Z3 runs out of time on it).
    bool by_z3 = d.method.rfind("Z3", 0) == 0, by_qepcad = d.method.rfind("QEPCAD", 0) == 0;
    if (!row || !row->build || d.outcome == Outcome::NotDecided || !(by_z3 || by_qepcad)) continue;
    std::string expected = d.outcome == Outcome::Proved ? "unsat" : "sat";
    const bool proved = d.outcome == Outcome::Proved;
    z3::context ctx;
    Obligation o(ctx);
    build(*row, o);
    const theorems::Statement* st = theorems::find_statement(statement);
    std::string where = st ? st->where : statement;
    // The premises, then one check per conjunct of the claim for a proved row (as the
    // library decides it), one check of the whole claim for a refuted one.
    z3::solver s(ctx);
    s.add(premises(o));
    std::string body = s.to_smt2();
    if (auto at = body.rfind("(check-sat)"); at != std::string::npos) body.erase(at);
    std::vector<z3::expr> parts = expected == "unsat" ? conjuncts(o.claim) : std::vector<z3::expr>{o.claim};
    std::string answers;
    for (std::size_t i = 0; i < parts.size(); ++i) {
      // A refuted row's one check of the whole claim runs nlsat in its own order.
      std::string tactic = expected == "unsat" ? nlsat_tactic_smt2(o, i) : std::string(kTactic);
      // A proved conjunct split into slices of x1 (Row::x1_cuts): one check per slice.
      for (const z3::expr& slice : expected == "unsat" ? slices(o, i) : std::vector<z3::expr>{ctx.bool_val(true)}) {
        body += "(push 1)\n";
        if (!slice.is_true()) body += "(assert " + slice.to_string() + ")\n";
        body += "(assert " + (!parts[i]).to_string() + ")\n(check-sat-using " + tactic + ")\n(pop 1)\n";
        answers += (answers.empty() ? "" : ",") + expected;
      }
    }
    expected = answers;
    std::ostringstream smt;
    smt << "; expected: " << expected << "\n"
        << "; " << where << " (" << statement << "), written by `lepp theorems --prove`.\n"
        << "; Frame B = (0, 0), A = (1, 0), C = (x1, y1), D = (x2, y2); unsat = the statement holds.\n"
        << "(set-logic QF_NRA)\n"
        << body;
    if (by_z3) out.push_back({stem(statement) + ".smt2", smt.str(), expected});
    if (row->qepcad_file && qepcad_writable(o))
      out.push_back({stem(statement) + ".qepcad", qepcad_input(o, statement), proved ? "TRUE" : "FALSE"});
  }
  return out;
}

bool write_obligation_files(const std::string& dir, const std::vector<Decision>& decisions, std::string* error) {
  std::ostringstream index;
  index << "# file expected-answer (written by `lepp theorems --prove --write-proofs`)\n";
  for (const ObligationFile& f : obligation_files(decisions)) {
    std::ofstream out(dir + "/" + f.name);
    if (!out || !(out << f.contents)) {
      if (error) *error = "cannot write " + dir + "/" + f.name;
      return false;
    }
    index << f.name << " " << f.expected << "\n";
  }
  // Files of rows no longer decided (or renamed) go: the directory is what the library writes.
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    std::string ext = entry.path().extension().string();
    if (ext != ".smt2" && ext != ".qepcad") continue;
    if (index.str().find("\n" + entry.path().filename().string() + " ") == std::string::npos)
      std::filesystem::remove(entry.path(), ec);
  }
  std::ofstream out(dir + "/expected.txt");
  if (!out || !(out << index.str())) {
    if (error) *error = "cannot write " + dir + "/expected.txt";
    return false;
  }
  return true;
}

}  // namespace lepp::prove
