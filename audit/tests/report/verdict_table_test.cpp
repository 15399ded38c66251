// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's verdicts as a decision table (docs/AUDIT.md, "The verdicts, row
// by row"): the table below is the specification, the doc's table must say the
// same, and every combination it covers (method x theta against the claimed
// band x input class x run outcome) goes through the row logic (check_run) and
// through the whole audit (run_audit, exit_status) with the expected verdicts.
// Mutants killed here (tools/mutation/mutants.txt): the bands moved by one
// (audit-centroid-band-open, audit-midpoint-band-open), swapped or merged
// (audit-bands-swapped, audit-midpoint-band-is-centroids), the input class
// ignored (audit-input-class-ignored), a guard's stop or a timeout taken as an
// end (audit-stopped-counts-as-ended, audit-timeout-counts-as-ended), the two
// non-ending verdicts swapped, a crash or unreadable output not failing the
// certificate, the exemption off, findings counted as failures or not saved,
// a row with findings only failing the exit status.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "lepp/audit/audit.h"
#include "lepp/engines/builtin_engines.h"
#include "lepp/audit/report/report.h"
#include "lepp/io.h"
#include "lepp/validate.h"

namespace fs = std::filesystem;
using namespace lepp;
using namespace lepp::audit;

namespace {

// One row of the decision table, every cell as written in docs/AUDIT.md.
struct TableRow {
  std::vector<std::string> cells;  // outcome, method, theta, input, certificate, min-angle, theorem-2, termination, conformance, exit
};

const std::vector<std::string> kHeader = {"run outcome", "method", "θ against the band", "input angles", "certificate",
                                          "min-angle", "theorem-2", "termination", "conformance", "exit"};

// The specification. docs/AUDIT.md must hold the same table.
const std::vector<TableRow> kTable = {
    {{"converged", "any", "any", "any", "held", "held", "held", "held", "held", "0"}},
    {{"converged, no trace", "any", "any", "any", "held", "held", "held", "held", "not checked", "0"}},
    {{"converged, exit status 3", "any", "any", "any", "held", "held", "held", "held", "held", "0"}},
    {{"converged, a triangle below θ left", "any", "any", "any", "held", "failed", "held", "held", "not checked", "1"}},
    {{"converged, a trace point no choice", "any", "any", "any", "held", "held", "held", "held", "failed", "1"}},
    {{"stopped by a guard or timed out", "any", "below or at", "none below 60°", "n/a", "n/a", "n/a", "failed", "n/a", "1"}},
    {{"stopped by a guard or timed out", "any", "below or at", "one below 60°", "n/a", "n/a", "n/a", "finding", "n/a", "0"}},
    {{"stopped by a guard or timed out", "any", "above", "any", "n/a", "n/a", "n/a", "finding", "n/a", "0"}},
    {{"crashed or unreadable output or exited non-zero, no mesh", "any", "any", "any", "failed", "n/a", "n/a", "held", "n/a",
      "1"}},
};

const std::vector<std::string> kOutcomes = {"converged",
                                            "converged, no trace",
                                            "converged, exit status 3",
                                            "converged, a triangle below θ left",
                                            "converged, a trace point no choice",
                                            "stopped by a guard",
                                            "timed out",
                                            "crashed",
                                            "unreadable output",
                                            "exited non-zero, no mesh"};
const std::vector<std::string> kMethods = {"centroid", "midpoint"};
const std::vector<std::string> kThetas = {"below", "at", "above"};
const std::vector<std::string> kInputs = {"none below 60°", "one below 60°"};

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t"), e = s.find_last_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::string cur;
  for (std::size_t i = 1; i < line.size(); ++i) {
    if (line[i] == '|') {
      cells.push_back(trim(cur));
      cur.clear();
    } else {
      cur += line[i];
    }
  }
  return cells;
}

// The table under the heading "The verdicts, row by row" of docs/AUDIT.md.
std::vector<std::vector<std::string>> doc_table() {
  std::ifstream in(std::string(LEPP_SOURCE_DIR) + "/docs/AUDIT.md");
  std::string line;
  bool in_section = false;
  std::vector<std::vector<std::string>> rows;
  while (std::getline(in, line)) {
    if (line.rfind("### The verdicts, row by row", 0) == 0) in_section = true;
    else if (in_section && line.rfind("#", 0) == 0) break;
    else if (in_section && line.rfind("|", 0) == 0) rows.push_back(split_cells(line));
    else if (in_section && !rows.empty()) break;  // the table ended
  }
  return rows;
}

// "a or b or c" -> {a, b, c}; "any" -> every value.
bool covers(const std::string& cell, const std::string& value) {
  if (cell == "any") return true;
  std::size_t at = 0;
  while (true) {
    std::size_t next = cell.find(" or ", at);
    if (cell.substr(at, next == std::string::npos ? std::string::npos : next - at) == value) return true;
    if (next == std::string::npos) return false;
    at = next + 4;
  }
}

Method method_of(const std::string& method) { return method == "centroid" ? Method::Centroid : Method::Midpoint; }

double theta_of(const std::string& method, const std::string& band) {
  const bool centroid = method == "centroid";
  if (band == "below") return centroid ? 25 : 20;
  if (band == "at") return centroid ? 30 : 22;
  return centroid ? 33 : 25;
}

Pslg polygon(std::vector<Point> pts) {
  Pslg p;
  p.vertices = std::move(pts);
  for (int i = 0; i < static_cast<int>(p.vertices.size()); ++i)
    p.segments.push_back({i, (i + 1) % static_cast<int>(p.vertices.size()), 1});
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

// No input angle below 60 degrees: a 16 x 2 rectangle (its unrefined CDT has 7-degree angles).
// One below: a quadrilateral with a 14-degree corner at the origin; its unrefined CDT's
// triangle (1,0.25) (16,0) (16,2) has an 8-degree angle outside the exemption's disk (radius 1.03).
Pslg input_of(const std::string& cls) {
  if (cls == "none below 60°") return polygon({{0, 0}, {16, 0}, {16, 2}, {0, 2}});
  return polygon({{0, 0}, {16, 0}, {16, 2}, {1, 0.25}});
}

struct Case {
  std::string outcome, method, band, input;
};

class Fixture {
 public:
  // lepp's own engine's run (in process), computed once per method, theta and input.
  const EngineRun& converged(const std::string& method, double theta, const std::string& input) {
    auto key = std::make_tuple(method, theta, input);
    auto it = cache_.find(key);
    if (it != cache_.end()) return it->second;
    EngineRequest req;
    req.method = method_of(method);
    req.theta = theta;
    req.timeout_seconds = 60;
    EngineRun run = engine_(input_of(input), req);
    return cache_.emplace(key, std::move(run)).first->second;
  }

  EngineRun make(const Case& c, const Pslg& pslg, double theta) {
    EngineRun run;
    if (c.outcome.rfind("converged", 0) == 0) {
      if (c.outcome == "converged, a triangle below θ left") {
        // The input's constrained Delaunay triangulation, unrefined: lepp at 0.1 degree adds no point here.
        run = converged(c.method, 0.1, c.input);
        EXPECT_EQ(run.mesh.vertices.size(), pslg.vertices.size()) << "the unrefined mesh has no Steiner point";
        run.trace.reset();
        return run;
      }
      run = converged(c.method, theta, c.input);
      EXPECT_EQ(run.status, RunStatus::Ok) << "lepp's engine must converge for this row: " << run.detail;
      EXPECT_TRUE(run.trace && !run.trace->empty());
      if (c.outcome == "converged, no trace") run.trace.reset();
      if (c.outcome == "converged, exit status 3") run.exit_code = 3;
      if (c.outcome == "converged, a trace point no choice" && run.trace && !run.trace->empty()) {
        Point& p = run.trace->front();
        p = {p.x + 0.3125, p.y + 0.0625};  // off every choice: a choice is a midpoint or centroid of the mesh's vertices
      }
      return run;
    }
    if (c.outcome == "stopped by a guard") run.status = RunStatus::Stopped, run.detail = "stopped by a guard: Steiner budget";
    if (c.outcome == "timed out") run.status = RunStatus::TimedOut, run.detail = "killed at the timeout";
    if (c.outcome == "crashed") run.status = RunStatus::Crashed, run.signal = 11, run.detail = "signal 11";
    if (c.outcome == "unreadable output") run.status = RunStatus::UnreadableOutput, run.detail = "out.node:1: expected a number";
    if (c.outcome == "exited non-zero, no mesh") run.status = RunStatus::ExitCode, run.exit_code = 1, run.detail = "exit status 1";
    return run;
  }

 private:
  Engine engine_ = fast_engine();
  std::map<std::tuple<std::string, double, std::string>, EngineRun> cache_;
};

const TableRow* row_for(const Case& c) {
  const TableRow* found = nullptr;
  for (const TableRow& r : kTable) {
    if (!covers(r.cells[0], c.outcome) || !covers(r.cells[1], c.method) || !covers(r.cells[2], c.band) ||
        !covers(r.cells[3], c.input))
      continue;
    EXPECT_EQ(found, nullptr) << "two rows of the table cover " << c.outcome << ", " << c.method << ", " << c.band << ", " << c.input;
    found = &r;
  }
  return found;
}

std::string out_dir(const std::string& name) {
  return (fs::temp_directory_path() / fmt::format("lepp-verdict-table-{}-{}", name, getpid())).string();
}

std::string where_of(const Case& c, double theta) {
  return fmt::format("{}, {} at theta {} ({}), input {}", c.outcome, c.method, theta, c.band, c.input);
}

// Each combination of the table's columns with the row that covers it; a
// combination no row covers fails the test and is skipped.
template <class Visit>
void for_each_case(Visit&& visit) {
  for (const auto& o : kOutcomes)
    for (const auto& m : kMethods)
      for (const auto& t : kThetas)
        for (const auto& in : kInputs) {
          const Case c{o, m, t, in};
          const TableRow* row = row_for(c);
          EXPECT_NE(row, nullptr) << "no row covers " << o << ", " << m << ", " << t << ", " << in;
          if (row) visit(c, *row);
        }
}

}  // namespace

TEST(VerdictTable, DocumentSaysTheSame) {
  const auto doc = doc_table();
  ASSERT_GE(doc.size(), 2u) << "docs/AUDIT.md has no table under \"The verdicts, row by row\"";
  EXPECT_EQ(doc[0], kHeader);
  ASSERT_EQ(doc.size(), kTable.size() + 2) << "the doc's table and the test's have different numbers of rows";
  for (std::size_t i = 0; i < kTable.size(); ++i) EXPECT_EQ(doc[i + 2], kTable[i].cells) << "row " << i + 1;
}

TEST(VerdictTable, EveryCombinationIsCoveredOnce) {
  std::size_t covered = 0;
  for_each_case([&](const Case&, const TableRow&) { ++covered; });
  EXPECT_EQ(covered, kOutcomes.size() * kMethods.size() * kThetas.size() * kInputs.size());
}

// Every combination through check_run: each row's verdict as the table says.
TEST(VerdictTable, RowLogic) {
  Fixture fx;
  for_each_case([&](const Case& c, const TableRow& row) {
    const Pslg pslg = input_of(c.input);
    EngineRequest req;
    req.method = method_of(c.method);
    req.theta = theta_of(c.method, c.band);
    const EngineRun run = fx.make(c, pslg, req.theta);
    const CaseResult result = check_run(pslg, req, run, CheckOptions{});
    const std::string where = where_of(c, req.theta);
    for (std::size_t r = 0; r < kRows; ++r)
      EXPECT_EQ(to_string(result.rows[r].verdict), row.cells[4 + r])
          << where << ": row " << row_key(kAllRows[r]) << ": " << result.rows[r].detail;
    // The small-angle input's converged meshes hold min-angle through the exemption, not by luck.
    if (c.outcome == "converged" && c.input == "one below 60°") EXPECT_GT(result.exempt_triangles, 0u) << where;
  });
}

// Every combination as a one-run audit: the row counts, the saved findings and the exit status.
TEST(VerdictTable, AuditAndExitStatus) {
  Fixture fx;
  const std::string dir = out_dir("inputs");
  fs::create_directories(dir);
  std::map<std::string, std::string> files;
  for (const auto& in : kInputs) {
    const std::string f = fmt::format("{}/{}.poly", dir, in == kInputs[0] ? "well-shaped" : "small-angle");
    write_poly(f, input_of(in));
    files[in] = f;
  }
  int n = 0;
  for_each_case([&](const Case& c, const TableRow& row) {
    const double theta = theta_of(c.method, c.band);
    const EngineRun canned = fx.make(c, input_of(c.input), theta);
    AuditOptions opt;
    opt.method = method_of(c.method);
    opt.thetas = {theta};
    opt.cases = 1;
    opt.inputs.dirs = {files[c.input]};
    opt.shrink = false;
    opt.out_dir = out_dir(std::to_string(n++));
    const AuditReport rep = run_audit([&](const Pslg&, const EngineRequest&) { return canned; }, opt);
    const std::string where = where_of(c, theta);
    ASSERT_EQ(rep.cases, 1u) << where;
    for (std::size_t r = 0; r < kRows; ++r) {
      const RowSummary& s = rep.rows[r];
      const std::string& want = row.cells[4 + r];
      EXPECT_EQ(s.failed, want == "failed" ? 1u : 0u) << where << ": " << row_key(s.row);
      EXPECT_EQ(s.findings, want == "finding" ? 1u : 0u) << where << ": " << row_key(s.row);
      EXPECT_EQ(s.held, want == "held" ? 1u : 0u) << where << ": " << row_key(s.row);
      // Every failure and every finding is saved (shrinking off: the input as found).
      if (want == "failed" || want == "finding") {
        EXPECT_EQ(s.counterexamples.size(), 1u) << where << ": " << row_key(s.row);
        if (!s.counterexamples.empty()) EXPECT_TRUE(fs::exists(s.counterexamples[0].dir + "/input.poly")) << where;
      }
    }
    EXPECT_EQ(std::to_string(exit_status(rep)), row.cells[9]) << where;
    fs::remove_all(opt.out_dir);
  });
  fs::remove_all(dir);
}

// The report's verdict column: failures win over findings, findings alone hold.
TEST(VerdictTable, ReportVerdictColumn) {
  AuditReport rep;
  for (std::size_t i = 0; i < kRows; ++i) rep.rows[i].row = kAllRows[i], rep.rows[i].run = 2, rep.rows[i].held = 2;
  RowSummary& term = rep[Row::Termination];
  term.held = 0, term.failed = 1, term.findings = 1;
  RowSummary& conf = rep[Row::Conformance];
  conf.held = 1, conf.findings = 1;
  const std::string md = markdown_report(rep);
  std::istringstream lines(md);
  std::string line;
  std::map<std::string, std::string> verdict;
  while (std::getline(lines, line))
    for (Row r : kAllRows)
      if (line.find(fmt::format("| {} |", row_key(r))) != std::string::npos) {
        auto cells = split_cells(line);
        if (cells.size() > 6) verdict[row_key(r)] = cells[6];
      }
  EXPECT_EQ(verdict["termination"], "FAILED");
  EXPECT_EQ(verdict["conformance"], "holds (findings outside the claim)");
  EXPECT_EQ(verdict["certificate"], "holds");
  EXPECT_FALSE(rep.holds());
  EXPECT_EQ(exit_status(rep), 1);
  term.failed = 0;
  EXPECT_TRUE(rep.holds());
  EXPECT_EQ(exit_status(rep), 0);
}

// A converged run whose mesh is not Delaunay at a terminal edge: the
// certificate row fails for the Delaunay check and theorem-2 for the angle
// over 120 degrees (kills audit-certificate-no-delaunay and audit-no-theorem2;
// the table's outcomes all come from Delaunay meshes, where Theorem 2 holds).
// The mesh: v (0,0), a (10,0), b (8,6), c (5,-1), d (-6,8); triangles vab, vca,
// vbd; v-a is the longest edge of vab (the tie with v-b goes to the older
// vertex) and of vca, whose angle at c is 157 degrees (certify_boundary_test.cpp).
TEST(VerdictTable, ConvergedMeshNotDelaunayAtATerminalEdge) {
  Pslg p;
  p.vertices = {{0, 0}, {10, 0}, {8, 6}, {5, -1}, {-6, 8}};
  p.segments = {{3, 1, 0}, {1, 2, 0}, {2, 4, 0}, {4, 0, 0}, {0, 3, 0}};
  std::vector<std::string> warnings;
  p = validate(p, warnings);
  EngineRun run;
  run.mesh.vertices = p.vertices;
  run.mesh.input_vertices = 5;
  run.mesh.triangles = {{0, 1, 2}, {0, 3, 1}, {0, 2, 4}};
  EngineRequest req;
  req.theta = 20;
  const CaseResult r = check_run(p, req, run, CheckOptions{});
  EXPECT_EQ(r[Row::Certificate].verdict, Verdict::Failed);
  EXPECT_NE(r[Row::Certificate].detail.find("Delaunay"), std::string::npos) << r[Row::Certificate].detail;
  EXPECT_EQ(r[Row::Theorem2].verdict, Verdict::Failed);
  EXPECT_NE(r[Row::Theorem2].detail.find("120"), std::string::npos) << r[Row::Theorem2].detail;
  EXPECT_EQ(r[Row::Termination].verdict, Verdict::Held);
  EXPECT_EQ(r[Row::Conformance].verdict, Verdict::NotChecked);
}
