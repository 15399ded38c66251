// SPDX-License-Identifier: GPL-3.0-or-later
// The cases planned and run: the engine, the rows, the comparisons (loop/cases.h).
#include "loop/cases.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "lepp/audit/report/shard.h"
#include "lepp/audit/run/parallel.h"
#include "loop/same_output.h"

namespace lepp::audit::loop {
namespace {

bool ended(RunStatus s) { return s != RunStatus::TimedOut && s != RunStatus::Stopped; }

// The engine on the case `repeat` times, each run checked; whether some row failed.
bool run_repeats(AuditSession& session, const AuditInput& input, const Case& c, CaseOutcome& out) {
  const AuditOptions& opt = session.options;
  std::optional<EngineRun> first;
  bool any_failed = false;
  for (std::size_t k = 0; k < opt.repeat; ++k) {
    EngineRequest req = session.request_for(c.theta, opt.timeout_seconds);
    const auto t0 = Clock::now();
    EngineRun run = session.engine(input.pslg, req);
    const double own = run.seconds > 0 ? run.seconds : since(t0);
    out.engine_seconds += own;
    if (ended(run.status)) out.finished_seconds = std::max(out.finished_seconds, own);
    CaseResult result = check_run(input.pslg, req, run, opt.checks);
    std::string why;
    if (first && out.nondeterminism.empty() && !same_output(*first, run, why))
      out.nondeterminism = fmt::format("runs 1 and {} differ: {}", k + 1, why);
    bool keep = false;
    for (Row row : kAllRows) {
      const Verdict v = result[row].verdict;
      keep = keep || v == Verdict::Failed || v == Verdict::Finding;
      any_failed = any_failed || v == Verdict::Failed;
    }
    out.statuses.push_back(run.status);
    out.results.push_back(std::move(result));
    if (!first) first = run;
    out.runs.push_back(keep ? std::move(run) : EngineRun{});
  }
  return any_failed;
}

// Points added against the comparison engines, where both finished.
void compare_points(AuditSession& session, const AuditInput& input, const Case& c, CaseOutcome& out) {
  const AuditOptions& opt = session.options;
  const CaseResult& r0 = out.results.front();
  out.theirs.assign(opt.comparisons.size(), std::nullopt);
  if (!(out.statuses.front() == RunStatus::Ok && r0.steiner_points >= 0)) return;
  // A comparison only feeds the points ratio: it gets 50 times the audited
  // program's own time on this case rounded up to a power of two seconds, at
  // least a second, at most --timeout: a peer that hangs on an input (Triangle on
  // some of the hostile corpus) does not cost the whole timeout; a run cut short
  // drops out of the ratio.
  const double own = out.engine_seconds / static_cast<double>(opt.repeat);
  const double compare_timeout =
      opt.timeout_seconds > 0 ? std::min(opt.timeout_seconds, std::exp2(std::ceil(std::log2(std::max(1.0, 50 * own))))) : 0;
  for (std::size_t e = 0; e < opt.comparisons.size(); ++e) {
    const NamedEngine& other = opt.comparisons[e];
    // An entry of a run that did not finish (within at least a second, where the
    // audited program took 1/50 of its limit) is reused as it is: --no-cache reruns it.
    if (auto hit = session.cache.get(other.cache_key, input.pslg, c.theta, opt.method)) {
      ++out.cache_hits;
      if (hit->finished) out.theirs[e] = hit->points_added;
      continue;
    }
    const auto tc = Clock::now();
    EngineRun theirs = other.engine(input.pslg, session.request_for(c.theta, compare_timeout));
    out.comparison_seconds += since(tc);
    ++out.comparison_runs;
    CachedPoints value;
    value.finished = theirs.status == RunStatus::Ok;
    value.points_added = static_cast<double>(theirs.mesh.vertices.size()) - static_cast<double>(input.pslg.vertices.size());
    value.timeout_seconds = compare_timeout;
    session.cache.put(other.cache_key, input.pslg, c.theta, opt.method, value);
    if (value.finished) out.theirs[e] = value.points_added;
  }
}

// A termination difference with lepp's default order: which lepp orders end there.
void compare_orders(AuditSession& session, const AuditInput& input, const Case& c, CaseOutcome& out) {
  const AuditOptions& opt = session.options;
  if (!termination_comparable(out.statuses.front())) return;
  const auto tc = Clock::now();
  out.order_termination = compare_termination(input.pslg, input.name, opt.method, c.theta,
                                              out.statuses.front() == RunStatus::Ok, opt.timeout_seconds, 10,
                                              opt.checks.tie_search_states);
  out.comparison_seconds += since(tc);
}

}  // namespace

CasePlan plan_cases(const AuditOptions& opt, std::size_t inputs) {
  const bool sharded = opt.shard_count > 0;
  CasePlan plan;
  for (std::size_t ii = 0; ii < inputs && plan.all_cases < opt.cases; ++ii)
    for (double theta : opt.thetas)
      if (plan.all_cases < opt.cases) {
        if (!sharded || in_shard(plan.all_cases, opt.shard_index, opt.shard_count))
          plan.cases.push_back({ii, theta, plan.all_cases});
        ++plan.all_cases;
      }
  return plan;
}

std::vector<CaseOutcome> run_cases(AuditSession& session, const std::vector<AuditInput>& inputs, const std::vector<Case>& cases) {
  std::vector<CaseOutcome> outcomes(cases.size());
  parallel_for(cases.size(), session.jobs, [&](std::size_t ci) {
    const Case& c = cases[ci];
    const AuditInput& input = inputs[c.input];
    CaseOutcome& out = outcomes[ci];
    session.progress(input.name);
    const bool any_failed = run_repeats(session, input, c, out);
    compare_points(session, input, c, out);
    if (session.options.compare_orders) compare_orders(session, input, c, out);
    session.case_done(any_failed);
  });
  return outcomes;
}

}  // namespace lepp::audit::loop
