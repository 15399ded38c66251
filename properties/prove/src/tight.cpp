// SPDX-License-Identifier: GPL-3.0-or-later
// Tight constants: a row's constant k moved by bisection between the largest value
// proved and the smallest refuted (every claim with a constant gets stronger as k
// grows). An algebraic row is decided at k by Z3: a refuted value comes with a rational
// configuration on which Z3, with every coordinate fixed, re-checks "hypotheses and not
// claim" exactly. A transcendental row (Lemma 7 (I)) is decided at k by the interval
// branch-and-bound: a refuted value is its grid counterexample, which the row's check
// function, given k, must reject.
#include <chrono>
#include <cmath>
#include <cstdio>

#include "lepp/prove/prove.h"
#include "lepp/theorems/statements.h"
#include "obligation.h"
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

// The bisection's boxes are finer than a row's decision's: near the extreme the claim
// fails on a region about (k - k*) wide, which boxes and grid points must resolve.
constexpr double kTightMinWidth = 1.0 / (1 << 28);
constexpr std::int64_t kTightGrid = std::int64_t(1) << 32;
// Where the claim's zero curve meets a hypothesis's boundary (Lemma 7 (I)(c) at k in
// (0.9925, 1): on BA = CA) hundreds of boxes are left while a counterexample lies
// further on: the search goes on past them (its time limit bounds it).
constexpr std::size_t kTightMaxLeft = 4096;
constexpr long kTightDen = 1000000000L;  // k is decided as the rational round(k 10^9) / 10^9

bool tightenable(const Row* r) { return r && (r->build || r->boxes) && !r->constant.empty(); }

}  // namespace

std::vector<std::string> tight_statements() {
  std::vector<std::string> out;
  for (const std::string& s : row_statements())
    if (tightenable(find_row(s))) out.push_back(s);
  return out;
}

TightConstant tighten(const std::string& statement, const Options& opt, double tolerance, int max_steps) {
  auto t0 = std::chrono::steady_clock::now();
  TightConstant t;
  t.statement = statement;
  if (const auto* s = theorems::find_statement(statement)) t.where = s->where;
  const Row* row = find_row(statement);
  if (!tightenable(row)) return t;
  t.paper = row->constant;
  t.meaning = row->constant_meaning;
  t.known = row->known_extreme;
  // Decides the row at k: Unsat (proved), Sat (refuted, with its configuration) or Unknown.
  // Sat without a grid point (the solutions Z3 found have no small rational point
  // near them) still refutes k exactly; the configuration shown stays the last one with a point.
  std::string why;
  auto algebraic = [&](double k, std::string* config) {
    z3::context ctx;
    Obligation o(ctx);
    build(*row, o, decimal(k));
    Solved s = solve(o, opt.time_limit_s);
    if (s.answer == Answer::Sat && config) *config = s.config ? s.config->show() : "";
    if (s.answer == Answer::Sat && s.config && (t.witnessed == 0 || k < t.witnessed)) t.witnessed = k;
    why = s.reason;
    return s.answer;
  };
  // The boxes at k = round(k 10^9)/10^9 (the value reported): proved when the search
  // proves it, refuted when its grid counterexample is rejected by the row's check
  // function given k, else Unknown with the search's reason.
  std::string side;  // the row's algebraic part (k-free), proved once
  if (row->boxes && row->side) side = row->side(opt.time_limit_s);
  auto boxes = [&](double& k, std::string* config) {
    long num = std::lround(k * static_cast<double>(kTightDen));
    k = static_cast<double>(num) / static_cast<double>(kTightDen);
    if (!side.empty()) {
      why = side;
      return Answer::Unknown;
    }
    bnb::Problem p = lemma7_problem(statement, "", num, kTightDen);
    p.min_width = kTightMinWidth;
    p.grid = kTightGrid;
    p.max_left = kTightMaxLeft;
    bnb::Outcome r = bnb::run(p, opt.time_limit_s);
    if (r.result == bnb::Result::Proved) {
      // Row (c)'s right triangles (the side) have alpha1 = alpha0: they meet the claim for k <= 1 only.
      if (row->side && k > 1) {
        why = "right triangles have alpha1 = alpha0 < k alpha0 (no grid point taken)";
        return Answer::Unknown;
      }
      return Answer::Unsat;
    }
    if (r.result == bnb::Result::NotDecided) {
      why = r.why;
      return Answer::Unknown;
    }
    Config c;
    c.L = p.grid;
    for (double v : r.point) c.v.push_back(std::llround(v * static_cast<double>(p.grid)));
    theorems::Verdict v = lemma7_check_at(statement, c, k);
    if (!(v.hypothesis && !v.conclusion && !v.tie)) {
      why = "the boxes found " + c.show() + " but the row's check function does not reject it (" + v.detail + ")";
      return Answer::Unknown;
    }
    Config m = c;  // shown as the pair the check function was given: D mirrors C in AB
    m.v = {c.v[0], c.v[1], c.v[0], -c.v[1]};
    if (config) *config = m.show();
    if (t.witnessed == 0 || k < t.witnessed) t.witnessed = k;
    return Answer::Sat;
  };
  auto at = [&](double& k, std::string* config) {
    ++t.steps;
    return row->boxes ? boxes(k, config) : algebraic(k, config);
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
  // The boxes walk in 0.1% steps: Lemma 7 (I)(c)'s ratio tends to 1 at the corner C -> B,
  // so a 1% step from 0.99 would probe k = 1, where the corner's closer (it needs k < 1)
  // leaves boxes; a smaller step brackets the extreme 0.9925 first.
  double step = row->boxes ? std::max(0.001, std::abs(k) * 0.001) : std::max(0.01, std::abs(k) * 0.01);
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
