// SPDX-License-Identifier: GPL-3.0-or-later
// The obligations written out for other tools: SMT-LIB 2 (Z3's own printer, checked
// with the same nlsat tactic) for every algebraic row, and QEPCAD B input (cylindrical
// algebraic decomposition, a second, independent procedure) for the rows it
// answers within seconds (Row::qepcad_file). Each file's first line records the answer
// lepp found, so CI can re-check it (scripts/ci.d/50-proofs.sh).
#include <gmpxx.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "lepp/prove/prove.h"
#include "lepp/theorems/statements.h"
#include "solve.h"

namespace lepp::prove {
namespace {

// A polynomial with rational coefficients, monomials keyed by variable -> exponent.
using Monomial = std::map<std::string, unsigned>;
using Poly = std::map<Monomial, mpq_class>;

Poly add(const Poly& a, const Poly& b, int sign = 1) {
  Poly r = a;
  for (const auto& [m, c] : b) {
    r[m] += sign * c;
    if (r[m] == 0) r.erase(m);
  }
  return r;
}
Poly mul(const Poly& a, const Poly& b) {
  Poly r;
  for (const auto& [ma, ca] : a)
    for (const auto& [mb, cb] : b) {
      Monomial m = ma;
      for (const auto& [v, e] : mb) m[v] += e;
      r[m] += ca * cb;
      if (r[m] == 0) r.erase(m);
    }
  return r;
}

Poly poly(const z3::expr& e) {
  if (e.is_numeral()) return Poly{{Monomial{}, mpq_class(Z3_get_numeral_string(e.ctx(), e))}};
  if (e.is_const()) return Poly{{Monomial{{e.decl().name().str(), 1}}, mpq_class(1)}};
  Z3_decl_kind k = e.decl().decl_kind();
  auto arg = [&](unsigned i) { return poly(e.arg(i)); };
  switch (k) {
    case Z3_OP_ADD: {
      Poly r;
      for (unsigned i = 0; i < e.num_args(); ++i) r = add(r, arg(i));
      return r;
    }
    case Z3_OP_SUB: {
      Poly r = arg(0);
      for (unsigned i = 1; i < e.num_args(); ++i) r = add(r, arg(i), -1);
      return r;
    }
    case Z3_OP_UMINUS: return add(Poly{}, arg(0), -1);
    case Z3_OP_MUL: {
      Poly r{{Monomial{}, mpq_class(1)}};
      for (unsigned i = 0; i < e.num_args(); ++i) r = mul(r, arg(i));
      return r;
    }
    case Z3_OP_DIV: {
      Poly d = arg(1);
      if (d.size() != 1 || !d.begin()->first.empty()) throw std::invalid_argument("division by a non-constant");
      Poly r = arg(0);
      for (auto& [m, c] : r) c /= d.begin()->second;
      return r;
    }
    case Z3_OP_POWER: {
      int n = 0;
      if (!e.arg(1).is_numeral_i(n) || n < 0) throw std::invalid_argument("non-integer power");
      Poly r{{Monomial{}, mpq_class(1)}}, b = arg(0);
      for (int i = 0; i < n; ++i) r = mul(r, b);
      return r;
    }
    case Z3_OP_TO_REAL: return arg(0);
    default: throw std::invalid_argument("not a polynomial: " + e.to_string());
  }
}

// p with integer coefficients (multiplied by the positive lcm of the denominators).
std::string qepcad_poly(Poly p) {
  mpz_class l = 1;
  for (const auto& [m, c] : p) mpz_lcm(l.get_mpz_t(), l.get_mpz_t(), c.get_den_mpz_t());
  std::ostringstream s;
  bool first = true;
  for (const auto& [m, c0] : p) {
    mpq_class c = c0 * l;
    mpz_class n = c.get_num();
    s << (n < 0 ? (first ? "-" : " - ") : (first ? "" : " + "));
    mpz_class a = abs(n);
    bool unit = a == 1 && !m.empty();
    if (!unit) s << a.get_str();
    bool sep = !unit;
    for (const auto& [v, e] : m) {
      s << (sep ? " " : "") << v;
      if (e > 1) s << "^" << e;
      sep = true;
    }
    first = false;
  }
  if (first) s << "0";
  return s.str();
}

std::string qepcad(const z3::expr& e) {
  if (e.is_true()) return "0 = 0";
  if (e.is_false()) return "1 = 0";
  Z3_decl_kind k = e.decl().decl_kind();
  auto join = [&](const char* op) {
    std::string s = "[ ";
    for (unsigned i = 0; i < e.num_args(); ++i) s += (i ? std::string(" ") + op + " " : "") + qepcad(e.arg(i));
    return s + " ]";
  };
  auto rel = [&](const char* op) {
    return qepcad_poly(add(poly(e.arg(0)), poly(e.arg(1)), -1)) + " " + op + " 0";
  };
  switch (k) {
    case Z3_OP_AND: return join("/\\");
    case Z3_OP_OR: return join("\\/");
    case Z3_OP_NOT: return "~" + qepcad(e.arg(0));
    case Z3_OP_IMPLIES: return join("==>");
    case Z3_OP_EQ: return e.arg(0).is_bool() ? join("<==>") : rel("=");
    case Z3_OP_DISTINCT: return rel("/=");
    case Z3_OP_LE: return rel("<=");
    case Z3_OP_GE: return rel(">=");
    case Z3_OP_LT: return rel("<");
    case Z3_OP_GT: return rel(">");
    default: throw std::invalid_argument("not a formula of QEPCAD B: " + e.to_string());
  }
}

}  // namespace

bool qepcad_writable(const Obligation& o) { return o.primary.size() + o.defs.size() / 2 <= kQepcadVariables; }

std::string qepcad_input(const Obligation& o, const std::string& title) {
  // Variables: the constant roots (sqrt 3, sqrt 5) first, then the coordinates, then the
  // roots and quotients defined from them; all universally quantified.
  std::vector<std::string> first, last;
  z3::expr defs = o.ctx.bool_val(true);
  for (unsigned i = 0; i < o.defs.size(); ++i) defs = defs && o.defs[i];
  for (const auto& [name, v] : o.cache) {
    bool constant = name == "s3" || name == "s5";
    (constant ? first : last).push_back(name);
  }
  std::vector<std::string> vars = first;
  for (const auto& v : o.primary) vars.push_back(v.to_string());
  vars.insert(vars.end(), last.begin(), last.end());
  std::string list, quant;
  for (const auto& v : vars) {
    list += (list.empty() ? "" : ",") + v;
    quant += "(A " + v + ")";
  }
  z3::expr hyp = defs;
  for (const auto& [n, h] : o.hyps) hyp = hyp && h;
  std::ostringstream q;
  q << "[ " << title << " ]\n(" << list << ")\n0\n" << quant << "[ " << qepcad(hyp) << " ==> "
    << qepcad(o.claim) << " ].\nfinish\n";
  return q.str();
}

namespace {

std::string stem(const std::string& statement) {
  std::string s;
  for (char c : statement) s += c == '.' ? '-' : c;
  return s;
}

}  // namespace

std::vector<ObligationFile> obligation_files(const std::vector<Decision>& decisions) {
  std::vector<ObligationFile> out;
  for (const Decision& d : decisions) {
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
    for (const z3::expr& part : parts) {
      body += "(push 1)\n(assert " + (!part).to_string() + ")\n(check-sat-using " + kTactic + ")\n(pop 1)\n";
      answers += (answers.empty() ? "" : ",") + expected;
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
