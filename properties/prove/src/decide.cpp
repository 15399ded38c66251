// SPDX-License-Identifier: GPL-3.0-or-later
// A row decided: proved (Z3: no configuration meets the hypotheses and misses the
// claim), refuted (an exact counterexample that the row's own check function
// rejects), or not decided (why). Rows already refuted by a sampled counterexample
// (corpus/theorems/) stay refuted by it, re-checked here.
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

#include "lepp/prove/prove.h"
#include "lepp/theorems/statements.h"
#include "solve.h"

namespace lepp::prove {
namespace {

// The note of a Z3 refutation no check function could confirm (unconfirmed_refutation reads it).
constexpr const char* kNoCheckFunction = "no check function takes this configuration";

bool same(const theorems::GridPoint& a, const theorems::GridPoint& b) { return a.x == b.x && a.y == b.y; }

double since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// A sampled mesh counterexample (`mesh x y x y ...`) checked again: some terminal pair violates the row.
Decision sampled(const Row& row, Decision d, const Options& opt) {
  d.method = "sampled counterexample";
  std::string path = opt.corpus_dir + "/" + row.sampled;
  std::ifstream in(path);
  if (!in) {
    d.note = "cannot read " + path;
    return d;
  }
  std::vector<theorems::GridPoint> pts;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    std::string kind;
    ss >> kind;
    for (std::int64_t x, y; ss >> x >> y;) pts.push_back({x, y});
  }
  for (const auto& pair : theorems::delaunay_terminal_pairs(pts)) {
    theorems::Verdict v = row.statement == "Proposition6.MidpointNearestVertexInDelaunayMesh"
                              ? theorems::check_prop6a_mesh(pair)
                          : row.statement == "Lemma8.AcuteBelowAlphaLimitDistanceAbove13"
                              ? theorems::check_lemma8(pair, theorems::Lemma8Part::a_i)
                              : theorems::check_lemma8(pair, theorems::Lemma8Part::a_ii);
    if (v.hypothesis && !v.conclusion) {
      d.outcome = Outcome::Refuted;
      d.confirmed = true;
      d.counterexample = "`" + path.substr(path.rfind('/') + 1) + "`: " + theorems::show(pair.quad) + " in a mesh of " +
                         std::to_string(pts.size()) + " points";
      const theorems::TerminalQuad& q = pair.quad;
      d.points = {{"A", q.A.x, q.A.y}, {"B", q.B.x, q.B.y}, {"C", q.C.x, q.C.y}, {"D", q.D.x, q.D.y}};
      for (const theorems::GridPoint& p : pts)
        if (!(same(p, q.A) || same(p, q.B) || same(p, q.C) || same(p, q.D))) d.points.push_back({"mesh vertex", p.x, p.y});
      return d;
    }
  }
  d.note = "the sampled counterexample " + path + " no longer violates the row";
  return d;
}

// A transcendental row: its algebraic side (Z3), then its boxes. A refutation is the
// counterexample point on the grid, confirmed by the row's check function.
Decision decide_boxes(const Row& row, Decision d, const std::string& dropped, const Options& opt) {
  auto t0 = std::chrono::steady_clock::now();
  d.method = "interval branch-and-bound (MPFI)";
  if (row.side && dropped.empty()) {
    std::string why = row.side(opt.time_limit_s);
    d.seconds = since(t0);
    if (!why.empty()) {
      d.note = why;
      return d;
    }
  }
  bnb::Problem p = row.boxes(dropped);
  bnb::Outcome r = bnb::run(p, opt.time_limit_s);
  d.seconds = since(t0);
  d.method += ", " + std::to_string(r.boxes) + " boxes";
  if (r.closed) d.method += ", " + std::to_string(r.closed) + " closed by Z3 " + kTactic;
  if (row.side && dropped.empty()) d.method += ", and Z3 " + std::string(kTactic);
  if (r.result == bnb::Result::Proved) {
    d.outcome = Outcome::Proved;
    return d;
  }
  if (r.result == bnb::Result::NotDecided) {
    d.note = r.why;
    return d;
  }
  Config c;
  c.L = p.grid;
  for (double v : r.point) c.v.push_back(static_cast<std::int64_t>(std::llround(v * static_cast<double>(p.grid))));
  d.outcome = Outcome::Refuted;
  d.counterexample = c.show();
  d.points = {{"B", 0, 0}, {"A", c.L, 0}, {"C", c.v[0], c.v[1]}};
  theorems::Verdict v = row.check(c, !dropped.empty());
  d.confirmed = dropped.empty() ? v.hypothesis && !v.conclusion && !v.tie : v.rejected();
  if (!d.confirmed) {
    d.outcome = Outcome::NotDecided;
    d.note = "the boxes found " + d.counterexample + " but the row's check function does not reject it (" + v.detail +
             ")";
  }
  return d;
}

}  // namespace

const char* name(Outcome o) {
  switch (o) {
    case Outcome::Proved: return "proved";
    case Outcome::Refuted: return "refuted";
    case Outcome::NotDecided: return "not decided";
  }
  return "?";
}

std::vector<std::string> row_statements() {
  std::vector<std::string> out;
  for (const auto& s : theorems::statements()) out.push_back(s.suite + "." + s.name);
  return out;
}

Decision decide_without(const std::string& statement, const std::string& dropped, const Options& opt) {
  auto t0 = std::chrono::steady_clock::now();
  const Row* row = find_row(statement);
  Decision d;
  d.statement = statement;
  if (const auto* s = theorems::find_statement(statement)) d.where = s->where;
  if (!row) {
    d.note = "no prover row for this statement";
    return d;
  }
  d.note = row->note;
  if (!row->not_decided.empty()) {
    d.note = row->not_decided;
    return d;
  }
  if (!row->sampled.empty() && dropped.empty()) return sampled(*row, d, opt);
  if (row->boxes) return decide_boxes(*row, d, dropped, opt);
  for (const std::string& via : row->via) {
    Decision lemma = decide(via, opt);
    if (lemma.outcome != Outcome::Proved) {
      d.note = "its lemma " + via + " is not proved: " + decided_cell(lemma);
      return d;
    }
  }
  z3::context ctx;
  Obligation o(ctx);
  build(*row, o, "", dropped);
  Solved s;
  if (row->qepcad_first && qepcad_writable(o)) {
    s = solve_qepcad(o, opt.time_limit_s);
    if (s.answer == Answer::Unsat) d.method = "QEPCAD B";
  }
  if (s.answer != Answer::Unsat) {
    s = solve(o, opt.time_limit_s);
    d.method = std::string("Z3 ") + kTactic;
  }
  if (s.answer == Answer::Unknown && qepcad_writable(o) && !row->qepcad_first) {
    // The second procedure, cylindrical algebraic decomposition, where nlsat ran out of time.
    Solved q = solve_qepcad(o, opt.time_limit_s);
    if (q.answer == Answer::Unsat) {
      d.method = "QEPCAD B (Z3 nlsat: " + s.reason + ")";
      s = q;
    } else {
      s.reason += "; " + (q.answer == Answer::Sat ? std::string("QEPCAD B: FALSE (no point given)") : q.reason);
    }
  }
  d.seconds = since(t0);
  if (s.answer == Answer::Unsat) {
    d.outcome = Outcome::Proved;
    return d;
  }
  if (s.answer == Answer::Unknown) {
    d.note = s.reason;
    return d;
  }
  if (!s.config) {
    d.note = s.reason;
    return d;
  }
  d.outcome = Outcome::Refuted;
  d.counterexample = s.config->show();
  d.points = {{"B", 0, 0}, {"A", s.config->L, 0}};
  const char* names[] = {"C", "D", "V"};
  for (std::size_t i = 0; 2 * i + 1 < s.config->v.size() && i < 3; ++i)
    d.points.push_back({names[i], s.config->v[2 * i], s.config->v[2 * i + 1]});
  if (row->check && (dropped.empty() || row->negative_check)) {
    theorems::Verdict v = row->check(*s.config, !dropped.empty());
    // The row's own check must reject the point: as written (hypothesis met, conclusion
    // fails) or, with a hypothesis dropped, as a negative test does (both fail).
    d.confirmed = dropped.empty() ? v.hypothesis && !v.conclusion && !v.tie : v.rejected();
    if (!d.confirmed) {
      d.outcome = Outcome::NotDecided;
      d.note = "Z3 found " + d.counterexample + " but the row's check function does not reject it (" + v.detail +
               "); " + (row->note.empty() ? "" : row->note);
    }
  } else {
    d.note = row->check ? "the row's check function reads a configuration without this hypothesis as not "
                          "applicable; the point was re-checked exactly by Z3"
                        : std::string(kNoCheckFunction) + "; the point was re-checked exactly by Z3";
    d.confirmed = false;
  }
  d.seconds = since(t0);
  return d;
}

Decision decide(const std::string& statement, const Options& opt) { return decide_without(statement, "", opt); }

bool unconfirmed_refutation(const Decision& d) {
  return d.outcome == Outcome::Refuted && !d.confirmed && d.method.rfind("Z3", 0) == 0 &&
         d.note.find(kNoCheckFunction) == std::string::npos;
}

std::vector<Decision> decide_all(const Options& opt, const std::function<void(const Decision&)>& progress) {
  std::vector<Decision> out;
  for (const std::string& s : row_statements()) {
    out.push_back(decide(s, opt));
    if (progress) progress(out.back());
  }
  return out;
}

std::string row_kind(const std::string& statement) {
  const Row* row = find_row(statement);
  if (!row) return "";
  return row->build    ? "algebraic"
         : row->boxes  ? "transcendental"
         : !row->sampled.empty() ? "sampled"
                                 : "not first-order";
}

std::vector<std::string> hypotheses(const std::string& statement) {
  const Row* row = find_row(statement);
  std::vector<std::string> out;
  if (row && row->boxes) {
    for (const bnb::Hypothesis& h : row->boxes("").hyps) out.push_back(h.name);
    return out;
  }
  if (!row || !row->build) return out;
  z3::context ctx;
  Obligation o(ctx);
  build(*row, o);
  for (const auto& [n, h] : o.hyps) out.push_back(n);
  return out;
}

std::vector<std::vector<std::string>> x1_cuts(const std::string& statement) {
  const Row* row = find_row(statement);
  return row ? row->x1_cuts : std::vector<std::vector<std::string>>{};
}

std::string slice_gap(const std::vector<std::string>& cuts) {
  z3::context ctx;
  Obligation o(ctx);
  o.x1_cuts = {cuts};
  try {
    for (std::size_t j = 0; j + 1 < cuts.size(); ++j) {
      z3::solver s(ctx);
      s.add(ctx.real_val(cuts[j].c_str()) >= ctx.real_val(cuts[j + 1].c_str()));
      if (s.check() != z3::unsat) return "cuts not increasing: " + cuts[j] + ", " + cuts[j + 1];
    }
    z3::expr any = ctx.bool_val(false);
    for (const z3::expr& slice : slices(o, 0)) any = any || slice;
    z3::solver s(ctx);
    s.add(!any);
    if (s.check() != z3::unsat) return "some x1 is in no slice: " + s.get_model().to_string();
  } catch (const z3::exception& e) {
    return std::string("not a rational cut: ") + e.msg();
  }
  return "";
}

std::string essential_hypothesis(const std::string& statement) {
  const Row* row = find_row(statement);
  return row ? row->essential : "";
}

}  // namespace lepp::prove
