// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's --tie-search-states (issue 39; docs/CERTIFIER.md section 5c): the default
// is lepp's 1024 Lepp states in every entry point, and a request's bound reaches the
// built-in engine under audit, the compared lepp engines (and their points-cache keys),
// the certificate of every run and the report.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lepp/audit/audit.h"
#include "lepp/audit/report/report.h"
#include "lepp/audit/request.h"
#include "lepp/certify.h"
#include "lepp/engines/audit_setup.h"
#include "lepp/engines/builtin_engines.h"
#include "lepp/engines/refine_request.h"
#include "lepp/input.h"
#include "lepp/validate.h"

using namespace lepp;
using namespace lepp::audit;

namespace {

// tie-finding.poly: at 20 degrees lepp's default search inserts through another
// resolution of exact length ties, and leaves triangles at double precision that the
// certificate exempts only after following more than one Lepp state.
Pslg tie_finding() {
  std::vector<std::string> warnings;
  return validate(read_input(std::string(LEPP_SOURCE_DIR) + "/corpus/regressions/precision/tie-finding.poly", warnings),
                  DomainOptions{}, warnings);
}

EngineRequest at20() {
  EngineRequest r;
  r.theta = 20;
  r.timeout_seconds = 60;
  return r;
}

AuditRequest fast_request(std::size_t states) {
  AuditRequest a;
  a.engine = "fast";
  a.root = LEPP_SOURCE_DIR;
  a.compare = "fast,reference";
  a.no_isolate = true;  // in process: the test's own engines, no child
  a.no_cache = true;
  a.tie_search_states = states;
  return a;
}

TEST(TieSearchStates, DefaultIs1024LeppStatesInEveryEntryPoint) {
  EXPECT_EQ(kTieSearchStates, 1024u);
  EXPECT_EQ(RefineOptions{}.tie_search_states, 1024u);
  EXPECT_EQ(engines::refine_options(engines::RefineRequest{}).tie_search_states, 1024u);
  EXPECT_EQ(certify::Options{}.tie_search_states, 1024u);
  EXPECT_EQ(CheckOptions{}.tie_search_states, 1024u);
  EXPECT_EQ(AuditRequest{}.tie_search_states, 1024u);
  EXPECT_EQ(AuditReport{}.tie_search_states, 1024u);
  AuditRequest request;
  request.engine = "fast";
  request.root = LEPP_SOURCE_DIR;
  request.compare = "none";
  const engines::AuditSetup setup = engines::audit_setup(request);
  EXPECT_EQ(setup.options.checks.tie_search_states, 1024u);
  EXPECT_EQ(setup.options.reproduce_prefix.find("--tie-search-states"), std::string::npos) << setup.options.reproduce_prefix;
}

// The engine under audit and the compared lepp engines run with the request's bound:
// at one state lepp's engines cannot follow another Lepp, and the mesh differs.
TEST(TieSearchStates, ReachesTheEnginesTheCacheKeysAndTheReproduceLine) {
  const Pslg p = tie_finding();
  const engines::AuditSetup wide = engines::audit_setup(fast_request(kTieSearchStates));
  const engines::AuditSetup narrow = engines::audit_setup(fast_request(1));
  EXPECT_EQ(narrow.options.checks.tie_search_states, 1u);
  EXPECT_NE(narrow.options.reproduce_prefix.find(" --tie-search-states 1"), std::string::npos) << narrow.options.reproduce_prefix;
  const EngineRun a = wide.engine(p, at20()), b = narrow.engine(p, at20());
  ASSERT_EQ(a.status, RunStatus::Ok) << a.detail;
  ASSERT_EQ(b.status, RunStatus::Ok) << b.detail;
  EXPECT_TRUE(a.mesh.vertices != b.mesh.vertices) << "the engine under audit ignores --tie-search-states";
  ASSERT_EQ(wide.options.comparisons.size(), 2u);
  ASSERT_EQ(narrow.options.comparisons.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) {
    SCOPED_TRACE(narrow.options.comparisons[i].name);
    EXPECT_EQ(wide.options.comparisons[i].cache_key.find("tie-search-states"), std::string::npos);
    EXPECT_NE(narrow.options.comparisons[i].cache_key, wide.options.comparisons[i].cache_key);
    const EngineRun c = wide.options.comparisons[i].engine(p, at20()), d = narrow.options.comparisons[i].engine(p, at20());
    EXPECT_NE(c.mesh.vertices.size(), d.mesh.vertices.size()) << "a compared engine ignores --tie-search-states";
  }
}

// The certificate of each run uses the bound: lepp's mesh at the default, whose triangles
// left at double precision the rule exempts at 1024 states, fails the min-angle row when
// the audit's certificate may follow one state only (undecided: no exemption).
TEST(TieSearchStates, ReachesTheCertificateOfEachRun) {
  const Pslg p = tie_finding();
  const EngineRun run = fast_engine()(p, at20());
  ASSERT_EQ(run.status, RunStatus::Ok) << run.detail;
  CheckOptions wide, narrow;
  narrow.tie_search_states = 1;
  const CaseResult held = check_run(p, at20(), run, wide), failed = check_run(p, at20(), run, narrow);
  EXPECT_EQ(held[Row::MinAngle].verdict, Verdict::Held) << held[Row::MinAngle].detail;
  EXPECT_GT(held.precision_exempt_triangles, 0u);
  EXPECT_EQ(failed[Row::MinAngle].verdict, Verdict::Failed) << "the certificate ignores CheckOptions::tie_search_states";
  EXPECT_LT(failed.precision_exempt_triangles, held.precision_exempt_triangles);
}

// The report states a bound other than the default (markdown and JSON).
TEST(TieSearchStates, TheReportStatesTheBound) {
  AuditReport rep;
  rep.tie_search_states = 4096;
  EXPECT_NE(markdown_report(rep).find("--tie-search-states 4096"), std::string::npos);
  EXPECT_EQ(json_report(rep)["tie_search_states"], 4096);
  rep.tie_search_states = kTieSearchStates;
  EXPECT_EQ(markdown_report(rep).find("--tie-search-states"), std::string::npos);
  EXPECT_EQ(json_report(rep)["tie_search_states"], 1024);
}

}  // namespace
