// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's counts of internal errors (issue 42; loop/tally.h): one exception inside
// the checks of a run makes every row that stage was deciding `internal-error` (the
// certifier: three rows), and the run counts once, as one internal-error run with one
// saved finding, not once per row. Each row still counts its own. Kills
// audit-internal-error-counted-per-row.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "loop/tally.h"

namespace {

using namespace lepp::audit;

CaseResult run_where(std::initializer_list<Row> internal) {
  CaseResult r;
  for (Row row : kAllRows) r[row].verdict = Verdict::Held;
  for (Row row : internal) {
    r[row].verdict = Verdict::InternalError;
    r[row].internal_error = row == Row::Conformance ? "conformance replay" : "certifier";
  }
  r.steiner_points = 10;
  return r;
}

// Three cases, each with the runs given (--repeat: one outcome, several runs).
struct Audit {
  AuditReport report;
  loop::Tally tally;
};
Audit tally(const std::vector<std::vector<CaseResult>>& cases, std::size_t max_findings = 3) {
  AuditOptions o;
  o.max_findings_per_row = max_findings;
  std::vector<AuditInput> inputs;
  std::vector<loop::Case> plan;
  std::vector<loop::CaseOutcome> outcomes;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    AuditInput in;
    in.name = "input-" + std::to_string(i);
    inputs.push_back(in);
    plan.push_back({i, 25, i});
    loop::CaseOutcome out;
    out.results = cases[i];
    out.statuses.assign(cases[i].size(), RunStatus::Ok);
    outcomes.push_back(out);
  }
  Audit a;
  a.tally = loop::tally_cases(a.report, o, inputs, plan, outcomes);
  return a;
}

TEST(InternalErrorTally, TheCertifiersExceptionCountsOnceForItsThreeRows) {
  const Audit a = tally({{run_where({Row::Certificate, Row::MinAngle, Row::Theorem2})}});
  EXPECT_EQ(a.report.internal_error_runs, 1u);
  for (Row row : {Row::Certificate, Row::MinAngle, Row::Theorem2}) EXPECT_EQ(a.report[row].internal_errors, 1u) << row_key(row);
  EXPECT_EQ(a.report[Row::Conformance].held, 1u);
  ASSERT_EQ(a.tally.finding_jobs.size(), 1u);  // one internal-error finding for the run
  EXPECT_TRUE(a.tally.finding_jobs[0].internal);
  EXPECT_EQ(a.tally.finding_jobs[0].row, Row::Certificate);  // the row whose code stopped first
  EXPECT_EQ(exit_status(a.report), 3);
}

TEST(InternalErrorTally, BothStagesInOneRunCountOnce) {
  const Audit a = tally({{run_where({Row::Certificate, Row::MinAngle, Row::Theorem2, Row::Conformance})}});
  EXPECT_EQ(a.report.internal_error_runs, 1u);
  EXPECT_EQ(a.tally.finding_jobs.size(), 1u);
}

TEST(InternalErrorTally, EveryRunCountsItsOwn) {
  // Three cases: the certifier stops on the first, nothing on the second, the replay
  // on the third; and a case of two repeated runs, both stopping: four runs in all.
  const Audit a = tally({{run_where({Row::Certificate, Row::MinAngle, Row::Theorem2})},
                         {run_where({})},
                         {run_where({Row::Conformance})},
                         {run_where({Row::Conformance}), run_where({Row::Certificate, Row::MinAngle, Row::Theorem2})}});
  EXPECT_EQ(a.report.internal_error_runs, 4u);
  EXPECT_EQ(a.report[Row::Certificate].internal_errors, 2u);
  EXPECT_EQ(a.report[Row::Conformance].internal_errors, 2u);
  EXPECT_EQ(a.report[Row::Certificate].held, 3u);
  // Saved: the first max_findings (3), one per input.
  std::size_t internal = 0;
  for (const loop::FindingJob& j : a.tally.finding_jobs) internal += j.internal;
  EXPECT_EQ(internal, 3u);
}

}  // namespace
