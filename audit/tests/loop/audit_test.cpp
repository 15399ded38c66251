// SPDX-License-Identifier: GPL-3.0-or-later
// The audit loop: lepp's own engines audit clean on a few generated inputs; a
// broken in-process engine is caught by the right row and shrunk; the reports
// are well-formed.
#include <unistd.h>

#include <filesystem>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "audit_test_support.h"
#include "lepp/audit/audit.h"
#include "lepp/engines/builtin_engines.h"
#include "lepp/audit/report/finding.h"
#include "lepp/audit/report/report.h"

namespace fs = std::filesystem;
using namespace lepp;
using namespace lepp::audit;
using lepp::audit::test::small_audit;

namespace {

TEST(Audit, FastEngineAuditsClean) {
  AuditOptions o = small_audit("lepp-audit-test-fast");
  o.comparisons.push_back({"lepp reference", reference_engine()});
  AuditReport r = run_audit(fast_engine(), o);
  EXPECT_EQ(r.cases, 12u);
  for (const RowSummary& s : r.rows) EXPECT_EQ(s.failed, 0u) << row_key(s.row) << ": " << s.first_detail;
  EXPECT_GT(r[Row::Certificate].held, 0u);
  EXPECT_EQ(exit_status(r), 0);
  ASSERT_EQ(r.ratios.size(), 1u);
  EXPECT_GT(r.ratios[0].cases, 0u);
}

TEST(Audit, ReferenceEngineAuditsCleanMidpoint) {
  AuditOptions o = small_audit("lepp-audit-test-ref");
  o.method = Method::Midpoint;
  o.thetas = {20};
  o.cases = 6;
  AuditReport r = run_audit(reference_engine(), o);
  for (const RowSummary& s : r.rows) EXPECT_EQ(s.failed, 0u) << row_key(s.row) << ": " << s.first_detail;
}

// Drops the last triangle of every mesh with more than one: the certificate row must fail, and shrink.
TEST(Audit, BrokenEngineIsCaughtAndShrunk) {
  Engine fast = fast_engine();
  Engine broken = [fast](const Pslg& p, const EngineRequest& r) {
    EngineRun run = fast(p, r);
    if (run.mesh.triangles.size() > 1) run.mesh.triangles.pop_back();
    return run;
  };
  AuditOptions o = small_audit("lepp-audit-test-broken");
  o.cases = 4;
  o.max_findings_per_row = 1;
  o.shrink_max_runs = 60;
  AuditReport r = run_audit(broken, o);
  const RowSummary& cert = r[Row::Certificate];
  EXPECT_GT(cert.failed, 0u);
  EXPECT_EQ(exit_status(r), 1);
  ASSERT_EQ(cert.counterexamples.size(), 1u);
  const Counterexample& c = cert.counterexamples[0];
  EXPECT_TRUE(fs::exists(c.dir + "/input.poly"));
  EXPECT_TRUE(fs::exists(c.dir + "/finding.svg"));
  EXPECT_TRUE(fs::exists(c.dir + "/out.node"));
  EXPECT_GT(c.shrink_runs, 0u);

  nlohmann::json j = nlohmann::json::parse(json_report(r).dump());
  EXPECT_EQ(j["rows"].size(), kRows);
  EXPECT_FALSE(j["holds"].get<bool>());
  // The size as found, next to the shrunk size.
  EXPECT_GE(c.original_vertices, c.vertices);
  EXPECT_GE(c.original_vertices, 3u);
  const auto& jc = j["rows"][0]["counterexamples"][0];
  EXPECT_EQ(jc["original_vertices"].get<std::size_t>(), c.original_vertices);
  EXPECT_EQ(jc["original_segments"].get<std::size_t>(), c.original_segments);
  EXPECT_EQ(jc["original_holes"].get<std::size_t>(), c.original_holes);
  EXPECT_NE(markdown_report(r).find(fmt::format("shrunk from {} vertices", c.original_vertices)), std::string::npos);
  std::string x = junit_report(r);
  EXPECT_NE(x.find("<failure"), std::string::npos);
  EXPECT_NE(markdown_report(r).find("FAILED"), std::string::npos);
  fs::remove_all(o.out_dir);
}

// Text into XML, the JUnit report's and the plain finding picture's alike: the
// five specials as entities, control characters (not allowed in XML) as spaces.
TEST(Report, XmlTextEscapedInJUnitAndSvg) {
  const std::string text = "a<b>&\"c'd\x01" "e";
  const std::string escaped = "a&lt;b&gt;&amp;&quot;c&apos;d e";
  AuditReport r;
  r.engine = text;
  std::string x = junit_report(r);
  EXPECT_NE(x.find("classname=\"lepp.audit." + escaped + "\""), std::string::npos) << x;
  EXPECT_EQ(x.find('\x01'), std::string::npos);
  Pslg p;
  p.vertices = {{0, 0}, {1, 0}, {0, 1}};
  std::string svg = finding_svg(p, nullptr, RowResult{}, text);
  EXPECT_NE(svg.find(">" + escaped + "</text>"), std::string::npos) << svg;
  EXPECT_EQ(svg.find('\x01'), std::string::npos);
}

}  // namespace

namespace {

// The conformance row's deviations in the report: counts by name, where each
// was first seen, and the one-consistent-variant sentence only when one name
// explains every failing run and each fits it whole.
lepp::audit::AuditReport report_with_deviations(std::size_t consistent) {
  lepp::audit::AuditReport rep;
  for (std::size_t i = 0; i < lepp::audit::kRows; ++i) rep.rows[i].row = lepp::audit::kAllRows[i];
  lepp::audit::RowSummary& c = rep[lepp::audit::Row::Conformance];
  c.run = 40, c.failed = 20, c.held = 20;
  c.deviations["area-centroid"] = 20;
  c.deviation_first["area-centroid"] = "step 2 of square400 at 25 degrees";
  if (consistent) c.deviation_consistent["area-centroid"] = consistent;
  return rep;
}

}  // namespace

TEST(Report, DeviationsByNameAndOneConsistentVariant) {
  const std::string all = lepp::audit::markdown_report(report_with_deviations(20));
  EXPECT_NE(all.find("area-centroid: 20 runs, first at step 2 of square400 at 25 degrees"), std::string::npos) << all;
  EXPECT_NE(all.find("Every traced step of the program fits one consistent variant: area-centroid"), std::string::npos) << all;
  const std::string some = lepp::audit::markdown_report(report_with_deviations(19));
  EXPECT_EQ(some.find("Every traced step of the program fits"), std::string::npos) << some;
  EXPECT_NE(some.find("every traced step of 19 of them fits area-centroid"), std::string::npos) << some;
  const nlohmann::json j = lepp::audit::json_report(report_with_deviations(20));
  for (const auto& row : j.at("rows"))
    if (row.at("check") == "conformance") EXPECT_EQ(row.at("deviations").value("area-centroid", 0), 20);
  EXPECT_EQ(j.value("centroid", ""), "vertex");
}
