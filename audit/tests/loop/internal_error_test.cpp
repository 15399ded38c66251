// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 30: the audit never dies of its own verdict code. An exception inside
// the certifier or the conformance replay makes the rows it was deciding
// `internal-error` (check_run never throws); the audit saves such a run as an
// internal-error finding (input, the program's output, reproduce line), goes
// on with the other cases, writes its reports, and exits 3. A shrink whose
// check throws on a candidate keeps the best input so far.
#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "audit_test_support.h"
#include "lepp/audit/audit.h"
#include "lepp/engines/builtin_engines.h"
#include "lepp/audit/report/report.h"
#include "lepp/audit/shrink/shrink.h"
#include "lepp/audit/judge/signature.h"
#include "lepp/validate.h"

namespace fs = std::filesystem;
using namespace lepp;
using namespace lepp::audit;
using lepp::audit::test::slurp;
using lepp::audit::test::small_audit;

namespace {

Pslg valid(const Pslg& p) {
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

Pslg rectangle() {
  Pslg p;
  p.vertices = {{0, 0}, {6, 0}, {6, 1}, {0, 1}};
  p.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  return valid(p);
}

EngineRequest request(double theta) {
  EngineRequest r;
  r.theta = theta;
  r.timeout_seconds = 20;
  return r;
}

// The certifier throws on a PSLG that was not validated (two crossing segments
// cannot both be edges of its constrained triangulation): check_run's contract
// is broken, but the rows it was deciding say so instead of the exception
// escaping the audit's worker thread (std::terminate: no report at all).
TEST(InternalError, AnExceptionInTheCertifierIsAnInternalErrorOfItsRows) {
  const Pslg pslg = rectangle();
  const EngineRun run = fast_engine()(pslg, request(25));
  ASSERT_EQ(run.status, RunStatus::Ok);
  Pslg crossing = pslg;
  crossing.segments.push_back({0, 2});
  crossing.segments.push_back({1, 3});
  CaseResult c;
  ASSERT_NO_THROW(c = check_run(crossing, request(25), run, CheckOptions{}));
  for (Row r : {Row::Certificate, Row::MinAngle, Row::Theorem2}) {
    EXPECT_EQ(c[r].verdict, Verdict::InternalError) << row_key(r);
    EXPECT_EQ(c[r].internal_error, "certifier");
    EXPECT_NE(c[r].detail.find("internal error of the audit"), std::string::npos) << c[r].detail;
  }
  EXPECT_EQ(c[Row::Termination].verdict, Verdict::Held);  // decided before, by how the run ended
  EXPECT_EQ(failure_signature(Row::Certificate, crossing, run, c[Row::Certificate]).text(), "internal-error in the certifier");
}

// The replay refuses rules that cannot be exact numbers (a NaN tolerance):
// the conformance row is an internal error, the certifier's rows are decided.
TEST(InternalError, AnExceptionInTheReplayIsAnInternalErrorOfConformance) {
  const Pslg pslg = rectangle();
  const EngineRun run = fast_engine()(pslg, request(25));
  ASSERT_TRUE(run.trace && !run.trace->empty());
  CheckOptions o;
  o.point_tolerance_ulps = std::nan("");
  CaseResult c;
  ASSERT_NO_THROW(c = check_run(pslg, request(25), run, o));
  EXPECT_EQ(c[Row::Conformance].verdict, Verdict::InternalError);
  EXPECT_EQ(c[Row::Conformance].internal_error, "conformance replay");
  for (Row r : {Row::Certificate, Row::MinAngle, Row::Theorem2, Row::Termination}) EXPECT_EQ(c[r].verdict, Verdict::Held) << row_key(r);
  // The same run with a number is decided: the internal error came from the option alone.
  EXPECT_EQ(check_run(pslg, request(25), run, CheckOptions{})[Row::Conformance].verdict, Verdict::Held);
}

// A whole audit where every run's replay stops: each case is counted as an
// internal error of the conformance row, the first ones saved as findings like
// any other (shrunk with their own signature), every other row decided, the
// reports written, exit status 3.
TEST(InternalError, TheAuditSavesItGoesOnAndExitsThree) {
  AuditOptions o = small_audit("lepp-audit-test-internal");
  o.cases = 4;
  o.max_findings_per_row = 2;
  o.shrink_max_runs = 30;
  o.reproduce_prefix = "lepp audit --engine fast";
  o.checks.point_tolerance_ulps = std::nan("");
  fs::remove_all(o.out_dir);
  const AuditReport r = run_audit(fast_engine(), o);
  EXPECT_EQ(r.cases, 4u);
  EXPECT_EQ(r.internal_error_runs, 4u);
  EXPECT_EQ(r[Row::Conformance].internal_errors, 4u);
  EXPECT_EQ(r[Row::Conformance].failed, 0u);  // not the program's failure
  EXPECT_EQ(r[Row::Certificate].held, 4u);     // the other rows decided on every case
  EXPECT_EQ(r[Row::MinAngle].held, 4u);
  EXPECT_FALSE(r.holds());
  EXPECT_EQ(exit_status(r), 3);
  ASSERT_EQ(r.internal_errors.size(), 2u);
  for (const Counterexample& c : r.internal_errors) {
    EXPECT_EQ(c.row, Row::Conformance);
    EXPECT_NE(c.dir.find("internal-error-"), std::string::npos) << c.dir;
    EXPECT_EQ(c.signature, "internal-error in the conformance replay");
    for (const char* f : {"input.poly", "out.node", "out.ele", "out.trace", "finding.md", "reproduce.sh"})
      EXPECT_TRUE(fs::exists(fs::path(c.dir) / f)) << c.dir << "/" << f;
    EXPECT_NE(slurp(fs::path(c.dir) / "finding.md").find("internal error of lepp audit, not a failure of the program"),
              std::string::npos);
    EXPECT_NE(c.reproduce.find("lepp audit --engine fast"), std::string::npos) << c.reproduce;
  }
  const std::string md = markdown_report(r);
  EXPECT_NE(md.find("## Internal errors of the audit"), std::string::npos) << md;
  EXPECT_NE(md.find("Verdict: the audit itself FAILED on 4 runs"), std::string::npos) << md;
  const nlohmann::json j = json_report(r);
  EXPECT_EQ(j["internal_error_runs"], 4);
  EXPECT_EQ(j["internal_errors"].size(), 2u);
  EXPECT_EQ(j["internal_errors"][0]["check"], "conformance");
  EXPECT_EQ(j["rows"][4]["internal_errors"], 4);
  EXPECT_FALSE(j["holds"].get<bool>());
  EXPECT_NE(junit_report(r).find("<error message=\"internal error of lepp audit\">"), std::string::npos);
  fs::remove_all(o.out_dir);
}

// A shrink whose check throws on some candidates (here: on every input of
// fewer than 6 vertices) keeps the best input so far, with one job and with
// several (where an exception in a worker thread would end the process).
TEST(InternalError, AShrinkWhoseCheckThrowsKeepsTheBestInputSoFar) {
  Pslg p;
  for (int i = 0; i < 12; ++i) p.vertices.push_back({std::round(80 * std::cos(i * M_PI / 6)) / 8, std::round(80 * std::sin(i * M_PI / 6)) / 8});
  for (int i = 0; i < 12; ++i) p.segments.push_back({i, (i + 1) % 12});
  const Pslg start = valid(p);
  auto still_fails = [](const Pslg& q) {
    if (q.vertices.size() < 6) throw std::runtime_error("the check broke");
    return true;
  };
  for (std::size_t jobs : {1u, 3u}) {
    ShrinkLimits limits;
    limits.jobs = jobs;
    ShrinkResult r;
    ASSERT_NO_THROW(r = shrink_pslg(start, still_fails, limits)) << jobs;
    // Smaller than 12 (some edit kept), never a candidate that threw.
    EXPECT_GE(r.pslg.vertices.size(), 6u) << jobs;
    EXPECT_LT(r.pslg.vertices.size(), 12u) << jobs;
    EXPECT_GT(r.steps, 0u);
  }
}

}  // namespace
