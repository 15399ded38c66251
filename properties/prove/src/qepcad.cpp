// SPDX-License-Identifier: GPL-3.0-or-later
// QEPCAD B, the second decision procedure (cylindrical algebraic decomposition):
// an obligation printed as its input (polynomials with integer coefficients, the
// universal closure of "definitions and hypotheses imply claim"), and run with a
// time limit where Z3's nlsat runs out.
#include <gmpxx.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

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

Solved solve_qepcad(const Obligation& o, double time_limit_s) {
  auto t0 = std::chrono::steady_clock::now();
  Solved out;
  out.reason = "QEPCAD B did not answer";
  char path[] = "/tmp/lepp-prove-XXXXXX";
  int fd = mkstemp(path);
  if (fd < 0) return out;
  std::string input = qepcad_input(o, "lepp");
  bool written = write(fd, input.data(), input.size()) == static_cast<ssize_t>(input.size());
  close(fd);
  if (written) {
    // GNU timeout takes fractions of a second: a limit below one second is kept, not
    // rounded up to one (in which QEPCAD B answers Theorem 2 on an idle machine).
    char limit[32];
    std::snprintf(limit, sizeof limit, "%.3f", std::max(time_limit_s, 0.001));
    std::string cmd = std::string("timeout ") + limit + " qepcad +N200000000 < " + path + " 2>&1";
    std::string text;
    if (FILE* p = popen(cmd.c_str(), "r")) {
      char buf[4096];
      for (std::size_t n; (n = fread(buf, 1, sizeof buf, p)) > 0;) text.append(buf, n);
      int status = pclose(p);
      (void)status;
    }
    // The answer follows "An equivalent quantifier-free formula:".
    auto at = text.find("An equivalent quantifier-free formula:");
    if (at != std::string::npos) {
      std::istringstream rest(text.substr(at + 38));
      std::string word;
      rest >> word;
      if (word == "TRUE") out.answer = Answer::Unsat;
      if (word == "FALSE") out.answer = Answer::Sat;
    } else if (text.find("Failure occurred") != std::string::npos) {
      out.reason = "QEPCAD B failed (" + text.substr(text.find("Reason for the failure:") == std::string::npos
                                                          ? text.find("Failure occurred")
                                                          : text.find("Reason for the failure:") + 24,
                                                      40) + ")";
      for (char& c : out.reason)
        if (c == '\n') c = ' ';
    } else if (text.empty() || text.find("The End") == std::string::npos) {
      out.reason = "QEPCAD B: time limit (" + std::to_string(static_cast<int>(time_limit_s)) + " s) or not installed";
    }
  }
  std::remove(path);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

}  // namespace lepp::prove
