// SPDX-License-Identifier: GPL-3.0-or-later
// lepp::audit::html_report: one row per statement with its counts, one row per
// named deviation linking to the step of the first finding that shows it, each
// finding with its directory's pictures (step.svg, the shrunk input.poly drawn)
// and its reproduce command; strings from the run (engine name, input names,
// details) escaped. The report is made by hand: the page only presents it.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "lepp/audit/report/html.h"

namespace fs = std::filesystem;

namespace lepp::audit {
namespace {

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + what.size())) ++n;
  return n;
}

struct Fixture {
  fs::path dir = fs::temp_directory_path() / ("lepp-html-test-" + std::to_string(::getpid()));
  AuditReport report;

  Fixture() {
    fs::create_directories(dir / "conformance-1");
    std::ofstream(dir / "conformance-1" / "step.svg")
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\"><defs><clipPath id=\"window\"><rect width=\"9\" "
           "height=\"9\"/></clipPath></defs><g clip-path=\"url(#window)\"><path d=\"M1 1L8 8\" stroke=\"red\"/></g></svg>\n";
    std::ofstream(dir / "conformance-1" / "input.poly") << "4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n";
    report.engine = "<script>alert('engine')</script>";
    report.thetas = {25};
    report.cases = 12;
    report.inputs = 4;
    for (std::size_t i = 0; i < kRows; ++i) report.rows[i].row = kAllRows[i], report.rows[i].run = 12, report.rows[i].held = 12;
    RowSummary& conf = report[Row::Conformance];
    conf.held = 9, conf.failed = 3;
    conf.deviations = {{"area-centroid", 3}, {"other-second-longest", 1}};
    conf.deviation_first = {{"area-centroid", "step 2 of <b>x.poly</b> at theta 25"}};
    Counterexample c;
    c.row = Row::Conformance;
    c.dir = (dir / "conformance-1").string();
    c.input = "gen/<script>alert('input')</script>";
    c.theta = 25;
    c.vertices = 4, c.segments = 4;
    c.detail = "step 2: the point is not the paper's";
    c.deviation = "area-centroid";
    c.deviations = {{"area-centroid", 2, 5}, {"other-second-longest", 4, 1}};
    c.reproduce = "lepp audit --cmd 'x {in}' --inputs " + c.dir;
    conf.counterexamples.push_back(c);
  }
  ~Fixture() { fs::remove_all(dir); }
};

TEST(AuditHtml, RowsDeviationsAndFindingsAsTheReportSays) {
  Fixture f;
  const std::string page = html_report(f.report);
  EXPECT_NE(page.find("data-holds=\"false\""), std::string::npos);
  EXPECT_EQ(count(page, "\" data-findings=\""), kRows);  // one row per statement
  EXPECT_EQ(count(page, "<tr data-row=\"conformance\" data-deviation="), 2u);
  EXPECT_NE(page.find("<tr data-row=\"conformance\" data-runs=\"12\" data-held=\"9\" data-failed=\"3\" data-findings=\"0\">"),
            std::string::npos);
  EXPECT_NE(page.find("data-deviation=\"area-centroid\" data-count=\"3\""), std::string::npos);
  EXPECT_NE(page.find("data-deviation=\"other-second-longest\" data-count=\"1\""), std::string::npos);
  // The deviation's row links to the step picture of the finding, which is on the page.
  EXPECT_NE(page.find("<a href=\"#finding-conformance-1-step\">step 2 of"), std::string::npos);
  EXPECT_NE(page.find("<div id=\"finding-conformance-1-step\">"), std::string::npos);
  EXPECT_EQ(count(page, "<section class=\"finding\""), 1u);
  // Pictures: the step (its clip path renamed for the page) and the input.
  EXPECT_EQ(count(page, "class=\"pz picture\""), 2u);
  EXPECT_NE(page.find("url(#p1-window)"), std::string::npos);
  EXPECT_NE(page.find("input.poly: 4 vertices, 4 segments"), std::string::npos);
  EXPECT_NE(page.find("<button class=\"copy\" data-copy=\"finding-conformance-1-reproduce\">"), std::string::npos);
  EXPECT_NE(page.find("<pre id=\"finding-conformance-1-reproduce\">lepp audit --cmd &#39;x {in}&#39;"), std::string::npos);
}

TEST(AuditHtml, StringsFromTheRunAreEscaped) {
  Fixture f;
  const std::string page = html_report(f.report);
  EXPECT_EQ(page.find("<script>alert"), std::string::npos);
  EXPECT_EQ(page.find("<b>x.poly"), std::string::npos);
  EXPECT_NE(page.find("&lt;script&gt;alert(&#39;engine&#39;)"), std::string::npos);
  EXPECT_NE(page.find("&lt;script&gt;alert(&#39;input&#39;)"), std::string::npos);
}

TEST(AuditHtml, FindingWithoutItsFilesHasNoPictures) {
  Fixture f;
  fs::remove_all(f.dir);
  const std::string page = html_report(f.report);
  EXPECT_EQ(count(page, "class=\"pz picture\""), 0u);
  EXPECT_EQ(count(page, "<section class=\"finding\""), 1u);
}

}  // namespace
}  // namespace lepp::audit
