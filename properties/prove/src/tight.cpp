// SPDX-License-Identifier: GPL-3.0-or-later
// Tight constants: a row's constant k moved by bisection between the largest value
// proved and the smallest refuted (every claim with a constant gets stronger as k
// grows). A refuted value comes with a rational configuration on which Z3, with
// every coordinate fixed, re-checks "hypotheses and not claim" exactly.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "lepp/prove/prove.h"
#include "lepp/theorems/statements.h"
#include "solve.h"

namespace lepp::prove {
namespace {

std::string decimal(double k) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10f", k);
  return buf;
}

double value_of(const std::string& rational) {
  auto slash = rational.find('/');
  if (slash == std::string::npos) return std::stod(rational);
  return std::stod(rational.substr(0, slash)) / std::stod(rational.substr(slash + 1));
}

}  // namespace

std::vector<std::string> tight_statements() {
  std::vector<std::string> out;
  for (const std::string& s : row_statements())
    if (const Row* r = find_row(s); r && r->build && !r->constant.empty()) out.push_back(s);
  return out;
}

TightConstant tighten(const std::string& statement, const Options& opt, double tolerance, int max_steps) {
  auto t0 = std::chrono::steady_clock::now();
  TightConstant t;
  t.statement = statement;
  if (const auto* s = theorems::find_statement(statement)) t.where = s->where;
  const Row* row = find_row(statement);
  if (!row || !row->build || row->constant.empty()) return t;
  t.paper = row->constant;
  t.meaning = row->constant_meaning;
  t.known = row->known_extreme;
  // Decides the row at k: Unsat (proved), Sat (refuted, with its configuration) or Unknown.
  // Sat without a grid point (the solutions Z3 found have no small rational point
  // near them) still refutes k exactly; the configuration shown stays the last one with a point.
  std::string why;
  auto at = [&](double k, std::string* config) {
    ++t.steps;
    z3::context ctx;
    Obligation o(ctx);
    build(*row, o, decimal(k));
    Solved s = solve(o, opt.time_limit_s);
    if (s.answer == Answer::Sat && config) *config = s.config ? s.config->show() : "";
    if (s.answer == Answer::Sat && s.config && (t.witnessed == 0 || k < t.witnessed)) t.witnessed = k;
    why = s.reason;
    return s.answer;
  };
  double k = value_of(row->constant);
  std::string config;
  Answer first = at(k, &config);
  if (first == Answer::Unknown) {
    t.stopped = "the row's own constant is not decided: " + why;
    t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return t;
  }
  double lo = k, hi = k;
  bool have_lo = first == Answer::Unsat, have_hi = first == Answer::Sat;
  double step = std::max(0.01, std::abs(k) * 0.01);
  // Bracket: walk away from k, doubling the step, until the other answer appears.
  while (!(have_lo && have_hi) && t.steps < max_steps) {
    double probe = have_lo ? lo + step : hi - step;
    Answer a = at(probe, &config);
    if (a == Answer::Unknown) {
      t.stopped = why + " at k = " + decimal(probe);
      break;
    }
    if (a == Answer::Unsat) {
      lo = probe;
      have_lo = true;
    } else {
      hi = probe;
      have_hi = true;
      if (!config.empty()) t.extreme = config;
    }
    step *= 2;
  }
  if (have_hi && t.extreme.empty()) t.extreme = config;
  while (have_lo && have_hi && hi - lo > tolerance && t.steps < max_steps) {
    double mid = (lo + hi) / 2;
    std::string c;
    Answer a = at(mid, &c);
    if (a == Answer::Unknown) {
      t.stopped = why + " at k = " + decimal(mid);
      break;
    }
    if (a == Answer::Unsat) {
      lo = mid;
    } else {
      hi = mid;
      if (!c.empty()) t.extreme = c;
    }
  }
  t.proved = lo;
  t.refuted = hi;
  t.complete = have_lo && have_hi && hi - lo <= tolerance;
  if (!t.complete && t.stopped.empty()) t.stopped = "step limit";
  if (!have_lo) t.proved = 0;
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return t;
}

}  // namespace lepp::prove
