// SPDX-License-Identifier: GPL-3.0-or-later
// Issue 19's audit behaviour on in-process engines with known bugs: shrinking
// keeps the failure's signature (a candidate failing the same row another way
// is not kept), termination candidates get a timeout derived from the program's
// own time, every finding is run again and a program whose output changes is
// called not deterministic, -j gives the same report as one thread, the
// comparison points come from the disk cache the second time, and the fast
// engine gives the reference's points where the comparison asks for them.
#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <mutex>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "audit_test_support.h"
#include "lepp/audit/audit.h"
#include "lepp/engines/builtin_engines.h"
#include "lepp/audit/report/report.h"
#include "lepp/audit/judge/signature.h"
#include "lepp/gen.h"

namespace fs = std::filesystem;
using namespace lepp;
using namespace lepp::audit;
using lepp::audit::test::slurp;
using lepp::audit::test::small_audit;

namespace {

// The reason name a certificate detail starts with ("not-locally-delaunay: ...").
std::string reason_of(const std::string& detail) { return detail.substr(0, detail.find(':')); }

// Flips one unconstrained interior edge of a convex quad: the mesh stays a
// triangulation with its segments, and is no longer Delaunay there.
bool flip_one_edge(Mesh& m) {
  std::set<std::pair<int, int>> constrained;
  for (const ConstrainedEdge& e : m.constrained_edges) constrained.insert(std::minmax(e.a, e.b));
  std::map<std::pair<int, int>, std::pair<std::size_t, int>> half;  // directed edge -> (triangle, apex)
  for (std::size_t t = 0; t < m.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i)
      half[{m.triangles[t][i], m.triangles[t][(i + 1) % 3]}] = {t, m.triangles[t][(i + 2) % 3]};
  auto orient = [&](int a, int b, int c) {
    const Point &p = m.vertices[a], &q = m.vertices[b], &r = m.vertices[c];
    return (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
  };
  for (const auto& [edge, tc] : half) {
    const auto [a, b] = edge;
    auto other = half.find({b, a});
    if (other == half.end() || constrained.count(std::minmax(a, b))) continue;
    const int c = tc.second, d = other->second.second;
    if (orient(a, d, c) <= 0 || orient(d, b, c) <= 0) continue;
    m.triangles[tc.first] = {{a, d, c}};
    m.triangles[other->second.first] = {{d, b, c}};
    return true;
  }
  return false;
}

// A program with two bugs: on inputs of 6 or more vertices it flips one edge
// (not-locally-delaunay); on smaller ones it drops its last triangle (a gap: a
// topology failure). Without signatures the shrinker would trade the first bug
// for the second.
Engine two_bugs() {
  Engine fast = fast_engine();
  return [fast](const Pslg& p, const EngineRequest& r) {
    EngineRun run = fast(p, r);
    if (run.status != RunStatus::Ok || run.mesh.triangles.size() < 2) return run;
    if (p.vertices.size() >= 6) flip_one_edge(run.mesh);
    else run.mesh.triangles.pop_back();
    return run;
  };
}

TEST(AuditFindings, ShrinkingKeepsTheViolationKind) {
  AuditOptions o = small_audit("lepp-audit-signature");
  o.max_findings_per_row = 12;
  o.shrink_max_runs = 120;
  AuditReport r = run_audit(two_bugs(), o);
  const RowSummary& cert = r[Row::Certificate];
  std::size_t flipped = 0;
  for (const Counterexample& c : cert.counterexamples) {
    // Each keeps the kind it was found with: the flip's never shrinks into the gap's.
    EXPECT_EQ(reason_of(c.detail), reason_of(c.original_detail)) << c.detail;
    EXPECT_EQ(c.signature, reason_of(c.original_detail));
    if (c.signature != "not-locally-delaunay") continue;
    ++flipped;
    EXPECT_GE(c.vertices, 6u) << "shrunk into the other bug: " << c.detail;
    if (c.shrink_steps > 0) {
      EXPECT_LE(c.vertices + c.segments + c.holes, c.original_vertices + c.original_segments + c.original_holes);
      EXPECT_TRUE(fs::exists(c.original_input)) << c.original_input;  // the input as found, kept beside the shrunk one
    }
    const std::string md = slurp(fs::path(c.dir) / "finding.md");
    EXPECT_NE(md.find("failing with not-locally-delaunay"), std::string::npos) << md;
  }
  EXPECT_GT(flipped, 0u);
  const nlohmann::json j = json_report(r);
  EXPECT_FALSE(j["rows"][0]["counterexamples"][0]["signature"].get<std::string>().empty());
  EXPECT_FALSE(j["rows"][0]["counterexamples"][0]["original_detail"].get<std::string>().empty());
  fs::remove_all(o.out_dir);
}

TEST(AuditFindings, SignaturesOfTheRows) {
  Pslg square;
  square.vertices = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  square.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  Pslg wedge;  // a 10-degree input angle: outside the well-shaped class
  wedge.vertices = {{0, 0}, {1, 0}, {std::cos(0.1745), std::sin(0.1745)}};
  wedge.segments = {{0, 1}, {1, 2}, {2, 0}};
  RowResult angle;
  angle.verdict = Verdict::Failed;
  angle.violations.push_back({certify::Reason::AngleBelowTheta, "x", {}, {}, {}, {}, -1});
  EngineRun ok;
  const FailureSignature inside = failure_signature(Row::MinAngle, square, ok, angle);
  const FailureSignature outside = failure_signature(Row::MinAngle, wedge, ok, angle);
  EXPECT_TRUE(inside.well_shaped);
  EXPECT_FALSE(outside.well_shaped);
  EXPECT_EQ(inside.kind, "angle-below-theta");
  // A failure inside every claim does not shrink into one at a small input angle (Rectangle162's, issue 19)...
  EXPECT_FALSE(keeps(inside, outside));
  // ...one outside may shrink into one inside.
  EXPECT_TRUE(keeps(outside, inside));
  RowResult other = angle;
  other.violations.front().reason = certify::Reason::AngleNotCertified;
  EXPECT_FALSE(keeps(inside, failure_signature(Row::MinAngle, square, ok, other)));
  // Certificate rows of runs without a mesh: how they ended.
  EngineRun crashed;
  crashed.status = RunStatus::Crashed;
  crashed.signal = 11;
  EngineRun aborted = crashed;
  aborted.signal = 6;
  RowResult failed;
  failed.verdict = Verdict::Failed;
  EXPECT_FALSE(keeps(failure_signature(Row::Certificate, square, crashed, failed), failure_signature(Row::Certificate, square, aborted, failed)));
  EXPECT_TRUE(keeps(failure_signature(Row::Certificate, square, crashed, failed), failure_signature(Row::Certificate, wedge, crashed, failed)));
  // Termination: failed (inside the claim) is not a finding (outside), timed out is not stopped.
  EngineRun timed_out;
  timed_out.status = RunStatus::TimedOut;
  EngineRun stopped;
  stopped.status = RunStatus::Stopped;
  RowResult finding;
  finding.verdict = Verdict::Finding;
  const FailureSignature t = failure_signature(Row::Termination, square, timed_out, failed);
  EXPECT_FALSE(keeps(t, failure_signature(Row::Termination, square, timed_out, finding)));
  EXPECT_FALSE(keeps(t, failure_signature(Row::Termination, square, stopped, failed)));
  EXPECT_TRUE(keeps(t, failure_signature(Row::Termination, wedge, timed_out, failed)));
}

// "Does not end" at theta 30 on well-shaped inputs of 4 or more vertices (the run
// returns at once, as if killed); the timeouts the shrink's candidates get are recorded.
TEST(AuditFindings, TerminationCandidatesGetATimeoutFromTheProgramsOwnTime) {
  std::mutex m;
  std::vector<double> timeouts;
  Engine fast = fast_engine();
  Engine loops = [&](const Pslg& p, const EngineRequest& r) {
    {
      std::lock_guard<std::mutex> lock(m);
      timeouts.push_back(r.timeout_seconds);
    }
    if (r.theta == 30 && p.vertices.size() >= 4 && gen::min_input_angle_deg(p) >= 60) {
      EngineRun run;
      run.status = RunStatus::TimedOut;
      run.detail = "killed";
      run.seconds = r.timeout_seconds;
      return run;
    }
    return fast(p, r);
  };
  AuditOptions o = small_audit("lepp-audit-termination");
  o.thetas = {20, 30};
  o.timeout_seconds = 10;
  o.max_findings_per_row = 1;
  o.shrink_max_runs = 40;
  AuditReport r = run_audit(loops, o);
  const RowSummary& term = r[Row::Termination];
  ASSERT_GT(term.failed, 0u);
  ASSERT_EQ(term.counterexamples.size(), 1u);
  const Counterexample& c = term.counterexamples[0];
  // The program ends in milliseconds elsewhere on the same input: 20 times that, at least a second.
  EXPECT_EQ(c.shrink_timeout, 1.0);
  EXPECT_GT(c.shrink_runs, 0u);
  EXPECT_NE(std::find(timeouts.begin(), timeouts.end(), 1.0), timeouts.end());
  EXPECT_NE(std::find(timeouts.begin(), timeouts.end(), 10.0), timeouts.end());  // cases and the final run: the full timeout
  EXPECT_GE(c.vertices, 4u);
  fs::remove_all(o.out_dir);
}

// An engine whose output depends on a seed it reads from its environment, else
// on a fresh one per run: an unused vertex at a seed-dependent place (the
// certificate fails every time, its output differs every time).
Engine seeded() {
  static std::atomic<int> calls{0};
  Engine fast = fast_engine();
  return [fast](const Pslg& p, const EngineRequest& r) {
    EngineRun run = fast(p, r);
    const char* env = std::getenv("LEPP_TEST_ENGINE_SEED");
    const int seed = env ? std::atoi(env) : ++calls;
    if (run.status == RunStatus::Ok) run.mesh.vertices.push_back({1e6 + seed, 1e6});
    return run;
  };
}

TEST(AuditFindings, ANonDeterministicProgramIsSaidToBe) {
  AuditOptions o = small_audit("lepp-audit-flaky");
  o.cases = 3;
  o.shrink = false;
  unsetenv("LEPP_TEST_ENGINE_SEED");
  AuditReport r = run_audit(seeded(), o);
  const RowSummary& cert = r[Row::Certificate];
  ASSERT_FALSE(cert.counterexamples.empty());
  for (const Counterexample& c : cert.counterexamples) {
    EXPECT_FALSE(c.deterministic);
    EXPECT_NE(c.nondeterminism.find("differ"), std::string::npos) << c.nondeterminism;
  }
  EXPECT_NE(markdown_report(r).find("**not deterministic**"), std::string::npos);
  // --repeat 2: every case run twice, each run checked, the difference counted.
  o.repeat = 2;
  AuditReport twice = run_audit(seeded(), o);
  EXPECT_EQ(twice.cases, 3u);
  EXPECT_EQ(twice[Row::Certificate].run, 6u);
  EXPECT_EQ(twice.nondeterministic_cases, 3u);
  // With the seed fixed the same program is deterministic.
  setenv("LEPP_TEST_ENGINE_SEED", "5", 1);
  o.repeat = 2;
  AuditReport fixed = run_audit(seeded(), o);
  unsetenv("LEPP_TEST_ENGINE_SEED");
  EXPECT_EQ(fixed.nondeterministic_cases, 0u);
  for (const Counterexample& c : fixed[Row::Certificate].counterexamples) EXPECT_TRUE(c.deterministic) << c.nondeterminism;
  fs::remove_all(o.out_dir);
}

// The same report, counterexamples and all, with one thread and with four.
TEST(AuditFindings, ParallelAuditGivesTheSameReport) {
  AuditOptions o = small_audit("lepp-audit-jobs");
  o.max_findings_per_row = 2;
  o.shrink_max_runs = 60;
  o.comparisons.push_back({"lepp fast", fast_engine(), ""});
  o.jobs = 1;
  const AuditReport one = run_audit(two_bugs(), o);
  o.jobs = 4;
  const AuditReport four = run_audit(two_bugs(), o);
  EXPECT_EQ(four.jobs, 4u);
  for (Row row : kAllRows) {
    const RowSummary &a = one[row], &b = four[row];
    EXPECT_EQ(a.run, b.run) << row_key(row);
    EXPECT_EQ(a.failed, b.failed) << row_key(row);
    EXPECT_EQ(a.first_detail, b.first_detail) << row_key(row);
    ASSERT_EQ(a.counterexamples.size(), b.counterexamples.size()) << row_key(row);
    for (std::size_t i = 0; i < a.counterexamples.size(); ++i) {
      EXPECT_EQ(a.counterexamples[i].dir, b.counterexamples[i].dir);
      EXPECT_EQ(a.counterexamples[i].vertices, b.counterexamples[i].vertices);
      EXPECT_EQ(a.counterexamples[i].detail, b.counterexamples[i].detail);
    }
  }
  ASSERT_EQ(one.ratios.size(), 1u);
  EXPECT_EQ(one.ratios[0].total, four.ratios[0].total);
  fs::remove_all(o.out_dir);
}

TEST(AuditFindings, ComparisonPointsComeFromTheCacheTheSecondTime) {
  AuditOptions o = small_audit("lepp-audit-cache");
  o.points_cache_dir = o.out_dir + "-cache";
  fs::remove_all(o.points_cache_dir);
  std::atomic<int> runs{0};
  Engine fast = fast_engine();
  Engine counted = [&](const Pslg& p, const EngineRequest& r) {
    ++runs;
    return fast(p, r);
  };
  o.comparisons.push_back({"lepp fast", counted, "lepp-fast test"});
  const AuditReport first = run_audit(fast_engine(), o);
  const int first_runs = runs.load();
  EXPECT_GT(first_runs, 0);
  EXPECT_EQ(first.comparison_cache_hits, 0u);
  const AuditReport second = run_audit(fast_engine(), o);
  EXPECT_EQ(runs.load(), first_runs) << "the second audit ran comparisons";
  EXPECT_EQ(second.comparison_runs, 0u);
  EXPECT_EQ(second.comparison_cache_hits, static_cast<std::size_t>(first_runs));
  ASSERT_EQ(second.ratios.size(), 1u);
  EXPECT_EQ(second.ratios[0].total, first.ratios[0].total);
  EXPECT_EQ(second.ratios[0].cases, first.ratios[0].cases);
  // Another theta, method or engine key is another entry.
  o.thetas = {30};
  run_audit(fast_engine(), o);
  EXPECT_GT(runs.load(), first_runs);
  fs::remove_all(o.points_cache_dir);
  fs::remove_all(o.out_dir);
}

// `--compare reference` is computed by the fast engine where the two give the same
// mesh: the points are the reference's on the audit's inputs, both methods.
TEST(AuditFindings, ReferencePointsEngineGivesTheReferencesPoints) {
  Engine quick = reference_points_engine(), reference = reference_engine();
  std::size_t compared = 0;
  for (std::size_t i = 0; i < 24; ++i) {
    auto in = generated_input(1, i, static_cast<int>(i));
    if (!in) continue;
    for (Method m : {Method::Centroid, Method::Midpoint})
      for (double theta : {20.0, 25.0, 30.0}) {
        if (m == Method::Midpoint && theta > 22) continue;
        EngineRequest r;
        r.method = m;
        r.theta = theta;
        r.timeout_seconds = 20;
        const EngineRun a = quick(in->pslg, r), b = reference(in->pslg, r);
        ASSERT_EQ(a.status, b.status) << in->name;
        EXPECT_EQ(a.mesh.vertices.size(), b.mesh.vertices.size()) << in->name << " theta " << theta;
        ++compared;
      }
  }
  EXPECT_GT(compared, 40u);
}

}  // namespace
