// SPDX-License-Identifier: GPL-3.0-or-later
// The pure parts of lepp::paper: the paper's numbers, the distance to them, the
// angle up to which a method works, the table cells, the quality histogram.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "lepp/paper/cells.h"
#include "lepp/paper/figures.h"
#include "lepp/paper/html_page.h"
#include "lepp/paper/measures.h"
#include "lepp/paper/numbers.h"
#include "lepp/paper/runner.h"
#include "lepp/paper/summary_table.h"

namespace lepp::paper {
namespace {

// (Inside a TEST body, Run is testing::Test::Run: runs are paper::Run there.)
Run finished_run(const std::string& problem, const std::string& method, double theta, std::int64_t steiner,
                 const std::string& reading = "") {
  Run r = keyed_run(problem, reading, method, theta);
  r.steiner = steiner;
  r.finished = true;
  r.outcome = "converged";
  r.stats.triangles = 100;
  r.stats.min_angle_deg = theta + 0.5;
  return r;
}

TEST(PaperNumbers, TableOneAndFig12) {
  EXPECT_EQ(paper_number("A", "triangle", 30), 47);        // Table 1 (the Triangle runner smoke test's 47)
  EXPECT_EQ(paper_number("rect162", "centroid", 36), 5473);
  EXPECT_EQ(paper_number("square400", "centroid", 10), 185);  // Fig. 12's caption, not in Table 1
  EXPECT_EQ(paper_number("square400", "midpoint", 25), 668);
  EXPECT_EQ(paper_number("square400", "centroid", 25), 491);  // both say so
  EXPECT_FALSE(paper_number("square400", "triangle", 36));  // "-" in Table 1
  EXPECT_FALSE(paper_number("circles240", "midpoint", 25));
  EXPECT_FALSE(paper_number("A", "centroid", 33));
  EXPECT_FALSE(paper_number("nosuch", "centroid", 30));
  for (const auto& p : paper_problems()) {
    EXPECT_EQ(p.centroid.size(), table_angles().size()) << p.name;
    EXPECT_EQ(p.triangle.size(), table_angles().size()) << p.name;
  }
}

// A's centroid column: 30, 43, 44, 49, 57 at 20, 25, 28, 30, 32 degrees.
TEST(MedianRelativeGap, OddAndEvenCountsOnlyFinishedRunsOfTheReading) {
  Results res;
  res.add(finished_run("A", "centroid", 20, 33));  // gap 0.1
  res.add(finished_run("A", "centroid", 25, 43));  // 0
  res.add(finished_run("A", "centroid", 28, 55));  // 0.25
  paper::Run unfinished = finished_run("A", "centroid", 30, 4900);
  unfinished.finished = false;
  res.add(unfinished);                                       // not counted
  res.add(finished_run("A", "centroid", 15, 1000));          // no paper number: not counted
  res.add(finished_run("A", "centroid", 32, 5700, "A-other"));  // another reading
  res.add(finished_run("A", "midpoint", 32, 5700));          // another method

  auto g = median_relative_gap(res, "A", "centroid", "");
  ASSERT_TRUE(g);
  EXPECT_EQ(g->angles, 3);
  EXPECT_DOUBLE_EQ(g->median, 0.1);

  res.add(finished_run("A", "centroid", 32, 57 + 57 / 2));  // gap 28/57, the largest: median of 4 is (0.1 + 0.25) / 2
  g = median_relative_gap(res, "A", "centroid", "");
  ASSERT_TRUE(g);
  EXPECT_EQ(g->angles, 4);
  EXPECT_DOUBLE_EQ(g->median, (0.1 + 0.25) / 2);

  auto other = median_relative_gap(res, "A", "centroid", "A-other");
  ASSERT_TRUE(other);
  EXPECT_EQ(other->angles, 1);
  EXPECT_DOUBLE_EQ(other->median, (5700.0 - 57) / 57);

  EXPECT_FALSE(median_relative_gap(res, "A", "midpoint", ""));  // no paper column for midpoint
  EXPECT_FALSE(median_relative_gap(res, "A", "triangle", ""));  // no run
}

TEST(ConvergesUpTo, StopsAtTheFirstRunThatFailsOrLeavesAnAngleBelowTheta) {
  const std::vector<double> angles = {10, 15, 20, 25, 28, 30};
  Results res;
  EXPECT_FALSE(converges_up_to(res, "A", "centroid", angles));
  res.add(finished_run("A", "centroid", 10, 5));
  res.add(finished_run("A", "centroid", 20, 9));  // 15 missing: skipped
  EXPECT_EQ(converges_up_to(res, "A", "centroid", angles), 20.0);

  paper::Run below = finished_run("A", "centroid", 25, 12);
  below.stats.min_angle_deg = 25 - 2 * kAngleSlack;  // finished by its own rule, an angle left below theta
  res.add(below);
  res.add(finished_run("A", "centroid", 28, 14));  // after the failure: not counted
  EXPECT_EQ(converges_up_to(res, "A", "centroid", angles), 20.0);

  Results slack;
  paper::Run within = finished_run("A", "cgal", 10, 5);
  within.stats.min_angle_deg = 10 - kAngleSlack / 2;  // within the slack: meets theta
  slack.add(within);
  paper::Run unfinished = finished_run("A", "cgal", 15, 5000);
  unfinished.finished = false;
  slack.add(unfinished);
  slack.add(finished_run("A", "cgal", 20, 50));
  EXPECT_EQ(converges_up_to(slack, "A", "cgal", angles), 10.0);
  EXPECT_FALSE(converges_up_to(slack, "A", "centroid", angles));
}

TEST(Cells, PointsAddedAndWhyARunStopped) {
  EXPECT_EQ(points_cell(nullptr), "");
  paper::Run r = finished_run("A", "centroid", 30, 49);
  EXPECT_EQ(points_cell(&r), "49");
  r.stats.min_angle_deg = 29;
  EXPECT_EQ(points_cell(&r), "49 †");

  paper::Run stopped = finished_run("A", "centroid", 36, 5000);
  stopped.finished = false;
  for (auto [outcome, cell] : std::vector<std::pair<std::string, std::string>>{{"steiner-budget", "> 5000 (budget)"},
                                                                             {"edge-floor", "> 5000 (edge floor)"},
                                                                             {"time-limit", "> 5000 (time)"},
                                                                             {"did-not-finish", "> 5000 (dnf)"}}) {
    stopped.outcome = outcome;
    EXPECT_EQ(points_cell(&stopped), cell) << outcome;
  }
  stopped.outcome = "engine error: boom";
  EXPECT_EQ(points_cell(&stopped), "n/a");
  paper::Run failed;
  failed.outcome = "triangle failed (1): no";
  EXPECT_EQ(points_cell(&failed), "failed");
}

TEST(Cells, DifferenceToThePaper) {
  paper::Run r = finished_run("A", "centroid", 30, 55);
  EXPECT_EQ(difference_cell(&r, 50), "+5 (+10%)");
  r.steiner = 40;
  EXPECT_EQ(difference_cell(&r, 50), "-10 (-20%)");
  r.steiner = 50;
  EXPECT_EQ(difference_cell(&r, 50), "+0 (+0%)");
  EXPECT_EQ(difference_cell(&r, std::nullopt), "");
  EXPECT_EQ(difference_cell(nullptr, 50), "");
  r.finished = false;
  EXPECT_EQ(difference_cell(&r, 50), "");
}

TEST(SummaryTable, OneLinePerRunInProblemMethodAngleOrder) {
  Results res;
  res.add(finished_run("A", "triangle", 30, 47));
  res.add(finished_run("square400", "centroid", 10, 204));
  res.add(finished_run("A", "centroid", 15, 20, "A-other"));  // a reading: not in the table
  std::string table = summary_table(res, {10, 15, 30});
  EXPECT_EQ(table,
            "problem      method    theta   steiner   paper  min_angle outcome\n"
            "square400    centroid     10       204     185     10.500 converged\n"
            "A            triangle     30        47      47     30.500 converged\n");
}

TEST(QualityHistogram, EquilateralInTheTopBinNeedleInTheBottom) {
  Mesh m;
  m.vertices = {{0, 0}, {1, 0}, {0.5, 0.8660254037844386}, {2, 0}, {1.5, 1e-6}};
  m.triangles = {{0, 1, 2}, {1, 3, 4}};
  std::vector<int> h = quality_histogram(m);
  ASSERT_EQ(h.size(), 20u);
  EXPECT_EQ(h[19], 1);
  EXPECT_EQ(h[0], 1);
  int total = 0;
  for (int n : h) total += n;
  EXPECT_EQ(total, 2);
}

}  // namespace
}  // namespace lepp::paper

// ---- the processing-order study's page (lepp/paper/orders.h) ----
#include "lepp/paper/orders.h"

namespace lepp::paper {
namespace {

OrderRun order_run(const std::string& problem, const std::string& order, std::uint64_t seed, double theta,
                   std::int64_t steiner, bool converged) {
  OrderRun r;
  r.problem = problem, r.method = "centroid", r.order = order, r.seed = seed, r.theta = theta;
  r.steiner = steiner, r.budget = 100000, r.converged = converged;
  r.outcome = converged ? "converged" : "steiner-budget";
  r.min_angle = converged ? theta + 0.1 : theta - 3;
  return r;
}

TEST(OrderStudy, BudgetIsTheFactorTimesTheNextTableCount) {
  EXPECT_EQ(order_budget("square400", 30, 20), 20 * 595);
  EXPECT_EQ(order_budget("square400", 29, 20), 20 * 595);   // the next Table 1 angle, 30
  EXPECT_EQ(order_budget("square400", 38, 20), 20 * 1843);  // above 36: 36's count
  EXPECT_EQ(order_budget("A", 36, 10), 10 * 239);
}

TEST(OrderStudy, AnswersComeFromTheRuns) {
  OrderStudy s;
  s.options.problems = {"square400", "A"};
  s.options.methods = {"centroid"};
  s.options.angles = {30, 36};
  s.options.random_orders = 1;
  for (const std::string& p : s.options.problems)
    for (double t : s.options.angles) {
      const bool square = p == "square400";
      const int paper = *paper_number(p, "centroid", t);
      s.runs.push_back(order_run(p, "fifo", 0, t, square && t == 36 ? 100000 : paper * 2, !(square && t == 36)));
      s.runs.push_back(order_run(p, "lifo", 0, t, paper * 3, true));
      s.runs.push_back(order_run(p, "flip", 0, t, paper, true));  // the paper's counts exactly
      s.runs.push_back(order_run(p, "smallest-angle", 0, t, paper * 4, true));
      s.runs.push_back(order_run(p, "random", 1, t, paper * 5, t == 30));
    }
  const std::string md = order_section(s, "lepp paper --orders --test");
  EXPECT_NE(md.find("Named orders within 5 % everywhere: flip."), std::string::npos) << md;
  EXPECT_NE(md.find("Lepp-centroid: named orders lifo, flip, smallest-angle; random seeds 0 of 1"), std::string::npos) << md;
  // At 30 on Square400 the best is flip (595), the worst random 1 (5 x 595).
  EXPECT_NE(md.find("| Square400 | centroid | flip | 595 | random 1 | 2975 | 5.00 |"), std::string::npos) << md;
  EXPECT_NE(md.find("**flip** converges in more cells than fifo"), std::string::npos) << md;
  // The section replaces itself in a page, and is found again.
  const std::string page = "# Title\n\ntext\n";
  const std::string once = splice_order_section(page, md);
  EXPECT_EQ(once.find("# Title"), 0u);
  EXPECT_EQ(order_section_of(once), md);
  EXPECT_EQ(splice_order_section(once, md), once);
  EXPECT_EQ(order_section_of(page), "");
  // JSON round trip.
  OrderStudy back = order_study_from_json(to_json(s));
  EXPECT_EQ(order_section(back, "lepp paper --orders --test"), md);
}

// docs/paper/index.html on a small fixture (the whole `lepp paper` takes minutes): Table 1
// with a row per table angle, ours beside the paper's; a table per problem run; the
// figures found inlined (a PNG as a data: URI, Fig. 13's SVG inline), the others named missing.
TEST(PaperHtml, TablesAndFiguresOfASmallStudy) {
  namespace fs = std::filesystem;
  const fs::path figdir = fs::temp_directory_path() / ("lepp-paper-html-" + std::to_string(::getpid()));
  fs::create_directories(figdir);
  std::ofstream(figdir / plot_figures()[0].first, std::ios::binary) << std::string("\x89PNG\r\n\x1a\n", 8) << "fake";
  std::ofstream(figdir / fig13_files()[0]) << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 4 4\"><path d=\"M0 0L4 4\"/></svg>\n";
  Study study;
  study.engine = "fast";
  study.angles = {20, 30};
  study.results.add(finished_run("A", "centroid", 20, 33));
  study.results.add(finished_run("A", "centroid", 30, 52));
  study.results.add(finished_run("A", "triangle", 30, 47));
  Options options;
  const std::string page = paper_html(options, study, figdir.string(), 12);
  fs::remove_all(figdir);
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  std::size_t rows = 0;
  for (std::size_t at = page.find("<tr data-theta="); at != std::string::npos && at < page.find("</table>"); at = page.find("<tr data-theta=", at + 1)) ++rows;
  EXPECT_EQ(rows, table_angles().size());
  // A at 30: ours 52 beside the paper's 49, Triangle's 47 beside 47 (Table 1).
  const std::size_t row30 = page.find("<tr data-theta=\"30\">");
  ASSERT_NE(row30, std::string::npos);
  const std::string row = page.substr(row30, page.find("</tr>", row30) - row30);
  EXPECT_NE(row.find("<td class=\"n\">52</td><td class=\"n\">49</td><td class=\"n\">47</td><td class=\"n\">47</td>"), std::string::npos) << row;
  EXPECT_NE(page.find("<table class=\"problem\" id=\"problem-A\">"), std::string::npos);
  EXPECT_EQ(page.find("id=\"problem-square400\""), std::string::npos);  // no run of it: no table
  EXPECT_NE(page.find("src=\"data:image/png;base64,iVBORw0KGgpmYWtl\""), std::string::npos);
  EXPECT_NE(page.find("<path d=\"M0 0L4 4\"/>"), std::string::npos);
  EXPECT_NE(page.find(plot_figures()[1].first + " is missing"), std::string::npos);
  EXPECT_NE(page.find(fig13_files()[1] + " is missing"), std::string::npos);
}

}  // namespace
}  // namespace lepp::paper
