// SPDX-License-Identifier: GPL-3.0-or-later
// The second step of run_audit (private to lepp_audit): the cases' outcomes
// counted into the report in case order (the same report for any -j), and the
// failures chosen to be shrunk and saved.
#pragma once
#include <cstddef>
#include <map>
#include <utility>
#include <vector>

#include "lepp/audit/audit.h"
#include "loop/cases.h"

namespace lepp::audit::loop {

// A failure chosen to be shrunk and saved.
struct FindingJob {
  std::size_t case_index = 0, repetition = 0;
  Row row = Row::Certificate;
  std::size_t number = 0;  // OUT/ROW-N
  bool internal = false;   // an internal error of the audit: OUT/internal-error-N
};

struct Tally {
  std::vector<std::vector<std::pair<double, double>>> points;  // (ours, theirs) per comparison, for the ratios
  std::vector<FindingJob> finding_jobs;
  double longest_finished = -1;                    // the engine's longest finished run: the termination shrink's fallback clock
  std::map<std::size_t, double> finished_on_input;  // and its longest on each input
};

// Adds every case's counts to `report` (rows, statuses, times, shard data).
Tally tally_cases(AuditReport& report, const AuditOptions& options, const std::vector<AuditInput>& inputs,
                  const std::vector<Case>& cases, const std::vector<CaseOutcome>& outcomes);

}  // namespace lepp::audit::loop
