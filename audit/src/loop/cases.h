// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's cases (private to lepp_audit): which inputs run at which theta
// (plan_cases), and each case run, checked and compared (run_cases), the first
// step of run_audit.
#pragma once
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "lepp/audit/audit.h"
#include "loop/session.h"

namespace lepp::audit::loop {

// One case: an input at one theta. `index` is its place in the whole audit
// (with --shard, every shard lists the same cases and keeps its own slice).
struct Case {
  std::size_t input;
  double theta;
  std::size_t index;
};

struct CasePlan {
  std::vector<Case> cases;     // this audit's (this shard's) cases, in order
  std::size_t all_cases = 0;   // cases of the whole audit
};

// The cases, input by input, each at every theta, up to --cases.
CasePlan plan_cases(const AuditOptions& options, std::size_t inputs);

// A run's ordinal in the whole audit: case index x repeat + repetition, the order run_audit sums in.
inline std::size_t run_ordinal(const Case& c, std::size_t repetition, std::size_t repeat) {
  return c.index * repeat + repetition;
}

// One case run `repeat` times, each run checked, and the comparison engines' points (from the cache when there).
struct CaseOutcome {
  std::vector<EngineRun> runs;       // kept only for runs some row failed or found on (for the findings)
  std::vector<CaseResult> results;   // one per repetition
  std::vector<RunStatus> statuses;
  std::string nondeterminism;        // the repeated runs differed: how
  std::vector<std::optional<double>> theirs;  // per comparison: its points added, when it finished
  double engine_seconds = 0, comparison_seconds = 0;
  double finished_seconds = -1;      // the engine's time on a run that ended (for the termination shrink's timeout)
  std::size_t comparison_runs = 0, cache_hits = 0;
  std::optional<OrderTermination> order_termination;  // lepp's orders where its fifo ends differently
};

// Every case, `jobs` at a time: the program, the rows, the comparisons; in case order.
std::vector<CaseOutcome> run_cases(AuditSession& session, const std::vector<AuditInput>& inputs, const std::vector<Case>& cases);

}  // namespace lepp::audit::loop
