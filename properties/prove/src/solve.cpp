// SPDX-License-Identifier: GPL-3.0-or-later
// Z3's nlsat on an obligation, one conjunct of the claim at a time, and a model
// made an exact integer-grid configuration.
#include "solve.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <optional>

namespace lepp::prove {
namespace {

// A numeral of the model as a double (rational or algebraic).
double approx(const z3::expr& v) { return std::strtod(v.get_decimal_string(30).c_str(), nullptr); }

struct Rational {
  std::int64_t num = 0, den = 1;
};

// The model's own value when it is a rational with a small denominator.
std::optional<Rational> small_rational(const z3::expr& v) {
  if (!v.is_numeral() || v.is_algebraic()) return std::nullopt;
  std::int64_t n = 0, d = 0;
  if (!v.numerator().is_numeral_i64(n) || !v.denominator().is_numeral_i64(d)) return std::nullopt;
  if (d <= 0 || d > (std::int64_t(1) << 24) || std::llabs(n) > (std::int64_t(1) << 40)) return std::nullopt;
  return Rational{n, d};
}

}  // namespace

namespace {
unsigned seed_of(const Obligation& o, std::size_t i) { return i < o.seeds.size() ? o.seeds[i] : 0; }
}  // namespace

z3::tactic nlsat_tactic(const Obligation& o, std::size_t i) {
  z3::tactic t(o.ctx, kTactic);
  unsigned seed = seed_of(o, i);
  if (seed == 0) return t;
  z3::params p(o.ctx);
  p.set("shuffle_vars", true);
  p.set("seed", seed);
  return z3::with(t, p);
}

std::string nlsat_tactic_smt2(const Obligation& o, std::size_t i) {
  unsigned seed = seed_of(o, i);
  if (seed == 0) return kTactic;
  return std::string("(using-params ") + kTactic + " :shuffle_vars true :seed " + std::to_string(seed) + ")";
}

void build(const Row& row, Obligation& o, const std::string& k, const std::string& dropped) {
  o.seeds = row.nlsat_seeds;
  o.x1_cuts = row.x1_cuts;
  row.build(o, o.num(k.empty() ? (row.constant.empty() ? "0" : row.constant) : k));
  if (!dropped.empty()) {
    for (auto it = o.hyps.begin(); it != o.hyps.end(); ++it)
      if (it->first == dropped) {
        o.hyps.erase(it);
        return;
      }
    throw std::invalid_argument("no hypothesis named '" + dropped + "' in " + row.statement);
  }
}

std::vector<z3::expr> conjuncts(const z3::expr& claim) {
  if (!claim.is_app() || claim.decl().decl_kind() != Z3_OP_AND) return {claim};
  std::vector<z3::expr> out;
  for (unsigned i = 0; i < claim.num_args(); ++i)
    for (const z3::expr& c : conjuncts(claim.arg(i))) out.push_back(c);
  return out;
}

std::vector<z3::expr> slices(const Obligation& o, std::size_t i) {
  if (i >= o.x1_cuts.size() || o.x1_cuts[i].empty()) return {o.ctx.bool_val(true)};
  z3::expr x1 = o.ctx.real_const("x1");
  std::vector<z3::expr> out;
  const std::vector<std::string>& cuts = o.x1_cuts[i];
  out.push_back(x1 <= o.ctx.real_val(cuts.front().c_str()));
  for (std::size_t j = 0; j + 1 < cuts.size(); ++j)
    out.push_back(o.ctx.real_val(cuts[j].c_str()) <= x1 && x1 <= o.ctx.real_val(cuts[j + 1].c_str()));
  out.push_back(x1 >= o.ctx.real_val(cuts.back().c_str()));
  return out;
}

z3::expr_vector premises(const Obligation& o) {
  z3::expr_vector all(o.ctx);
  for (unsigned i = 0; i < o.defs.size(); ++i) all.push_back(o.defs[i]);
  for (const auto& [name, h] : o.hyps) all.push_back(h);
  return all;
}

Solved solve(Obligation& o, double time_limit_s) {
  auto t0 = std::chrono::steady_clock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(); };
  auto limit_ms = [&](double s) { return static_cast<unsigned>(std::max(1.0, s * 1000)); };
  Solved out;
  // A conjunctive claim is decided one conjunct at a time (nlsat is much faster on
  // each than on their disjunction of negations): proved when every one is.
  std::optional<z3::solver> found;
  out.answer = Answer::Unsat;
  std::vector<z3::expr> parts = conjuncts(o.claim);
  for (std::size_t i = 0; i < parts.size() && !found; ++i) {
    const z3::expr& part = parts[i];
    for (const z3::expr& slice : slices(o, i)) {
      z3::solver s = z3::try_for(nlsat_tactic(o, i), limit_ms(time_limit_s)).mk_solver();
      s.add(premises(o));
      if (!slice.is_true()) s.add(slice);
      s.add(!part);
      z3::check_result r = z3::unknown;
      try {
        r = s.check();
      } catch (const z3::exception& e) {
        out.reason = std::string("Z3: ") + e.msg();
      }
      if (r == z3::sat) {
        found.emplace(s);
        break;
      }
      if (r == z3::unknown) {
        out.answer = Answer::Unknown;
        if (out.reason.empty()) out.reason = "time limit (" + std::to_string(static_cast<int>(time_limit_s)) + " s)";
      }
    }
  }
  if (!found) {
    out.seconds = elapsed();
    return out;
  }
  out.answer = Answer::Sat;
  out.reason.clear();
  z3::solver& s = *found;
  // A rational point near the model: fix the coordinates one at a time to the
  // nearest fractions with denominators 4, 16, ..., 2^20, keeping the rest solvable;
  // fall back on the model's own value when it is a small rational.
  std::vector<Rational> point;
  z3::model m = s.get_model();
  for (const z3::expr& v : o.primary) {
    z3::expr value = m.eval(v, true);
    double a = approx(value);
    bool fixed = false;
    for (int bits = 2; bits <= 32 && !fixed; bits += bits < 20 ? 2 : 4) {
      std::int64_t den = std::int64_t(1) << bits;
      Rational q{static_cast<std::int64_t>(std::llround(a * static_cast<double>(den))), den};
      std::int64_t g = std::gcd(q.num, q.den);
      q = {q.num / g, q.den / g};
      s.push();
      s.add(v == o.ctx.real_val(std::to_string(q.num).c_str()) / o.ctx.real_val(std::to_string(q.den).c_str()));
      z3::check_result fixed_result = z3::unknown;
      try {
        fixed_result = s.check();
      } catch (const z3::exception&) {
      }
      if (fixed_result == z3::sat) {
        point.push_back(q);
        m = s.get_model();
        fixed = true;
      } else {
        s.pop();
      }
    }
    if (!fixed) {
      auto q = small_rational(value);
      if (!q) {  // still Sat: Z3 decided it exactly, but there is no grid point to show
        out.reason = "satisfiable (a counterexample exists), but no rational point with small denominators found near "
                     "Z3's algebraic model";
        out.seconds = elapsed();
        return out;
      }
      s.push();
      s.add(v == value);
      point.push_back(*q);
    }
  }
  // The grid: L = lcm of the denominators; B = (0, 0), A = (L, 0).
  Config c;
  for (const Rational& q : point) c.L = std::lcm(c.L, q.den);
  for (const Rational& q : point) c.v.push_back(q.num * (c.L / q.den));
  out.config = c;
  out.seconds = elapsed();
  return out;
}

}  // namespace lepp::prove
