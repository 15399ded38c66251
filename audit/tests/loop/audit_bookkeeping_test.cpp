// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's counts and its record of a finding at their boundaries (issue 30,
// item 7): rows held count as run, `--repeat` names the runs that differ, and a
// flaky program's shrunk input is not saved once it no longer fails. Each test
// names the mutants of tools/mutation/mutants.txt it kills.
#include <filesystem>
#include <functional>
#include <memory>
#include <map>
#include <mutex>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "audit_test_support.h"
#include "lepp/audit/audit.h"
#include "lepp/engines/builtin_engines.h"
#include "lepp/audit/report/report.h"
#include "lepp/io.h"

namespace fs = std::filesystem;
using namespace lepp;
using namespace lepp::audit;
using lepp::audit::test::small_audit;

namespace {

std::string key_of(const Pslg& p) {
  std::string k;
  for (const Point& v : p.vertices) k += fmt::format("{:a},{:a};", v.x, v.y);
  return k;
}

// lepp's fast engine, with its last triangle dropped (a certificate failure) on
// the calls for one input that `broken(n)` picks, n counting that input's calls from 1.
Engine broken_on_calls(std::function<bool(std::size_t)> broken) {
  auto calls = std::make_shared<std::map<std::string, std::size_t>>();
  auto lock = std::make_shared<std::mutex>();
  Engine fast = fast_engine();
  return [=](const Pslg& p, const EngineRequest& r) {
    std::size_t n;
    {
      std::lock_guard<std::mutex> g(*lock);
      n = ++(*calls)[key_of(p)];
    }
    EngineRun run = fast(p, r);
    if (broken(n) && run.mesh.triangles.size() > 1) run.mesh.triangles.pop_back();
    return run;
  };
}

// A clean engine: every row's runs are its held + failed + findings, and a
// run's row is counted once whatever its verdict (held ones included).
// Kills audit-held-not-counted-as-run.
TEST(AuditBookkeeping, RowsHeldCountAsRun) {
  AuditOptions o = small_audit("lepp-audit-bookkeeping-held");
  o.cases = 4;
  o.repeat = 2;
  o.compare_orders = false;
  const AuditReport r = run_audit(fast_engine(), o);
  ASSERT_EQ(r.cases, 4u);
  for (const RowSummary& s : r.rows) {
    EXPECT_EQ(s.run, s.held + s.failed + s.findings) << row_key(s.row);
    EXPECT_EQ(s.run + s.not_applicable + s.not_checked + s.internal_errors, r.cases * o.repeat) << row_key(s.row);
  }
  EXPECT_EQ(r[Row::Certificate].held, r.cases * o.repeat);
  EXPECT_EQ(r[Row::Certificate].run, r.cases * o.repeat);
  fs::remove_all(o.out_dir);
}

// Runs 1 and 2 agree, run 3 differs: the report says which two runs differ.
// Kills audit-repeat-names-wrong-run.
TEST(AuditBookkeeping, RepeatNamesTheRunsThatDiffer) {
  for (std::size_t differs : {3u, 4u}) {
    AuditOptions o = small_audit("lepp-audit-bookkeeping-repeat");
    o.cases = 2;
    o.repeat = 4;
    o.shrink = false;
    o.compare_orders = false;
    const AuditReport r = run_audit(broken_on_calls([differs](std::size_t n) { return n == differs; }), o);
    EXPECT_EQ(r.nondeterministic_cases, r.cases);
    ASSERT_FALSE(r.nondeterministic_first.empty());
    const std::string want = fmt::format("runs 1 and {} differ", differs);
    for (const std::string& line : r.nondeterministic_first) EXPECT_NE(line.find(want), std::string::npos) << line;
    EXPECT_NE(markdown_report(r).find(want), std::string::npos);
    fs::remove_all(o.out_dir);
  }
}

// A flaky program: each input fails on its first run only. Every shrink
// candidate fails when tried, the smallest passes when run again: the finding
// keeps the input as found, not the shrunk one that no longer fails.
// Kills audit-flaky-shrunk-input-saved.
TEST(AuditBookkeeping, FlakyProgramKeepsTheInputAsFound) {
  AuditOptions o = small_audit("lepp-audit-bookkeeping-flaky");
  o.cases = 3;
  o.max_findings_per_row = 1;
  o.shrink_max_runs = 40;
  o.compare_orders = false;
  const AuditReport r = run_audit(broken_on_calls([](std::size_t n) { return n == 1; }), o);
  const RowSummary& cert = r[Row::Certificate];
  ASSERT_EQ(cert.counterexamples.size(), 1u);
  const Counterexample& c = cert.counterexamples[0];
  EXPECT_GT(c.shrink_runs, 0u);
  EXPECT_FALSE(c.deterministic);
  EXPECT_EQ(c.shrink_steps, 0u);
  EXPECT_EQ(c.vertices, c.original_vertices);
  EXPECT_EQ(c.segments, c.original_segments);
  EXPECT_EQ(read_poly(c.dir + "/input.poly").vertices.size(), c.original_vertices);
  fs::remove_all(o.out_dir);
}

}  // namespace
