// SPDX-License-Identifier: GPL-3.0-or-later
// The prover decides, and can say no: each proved row with its essential
// hypothesis dropped is refuted, and the counterexample is rejected by the row's
// own check function; false statements are refuted; the committed obligation
// files are what the library writes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "interval_bnb.h"
#include "obligation.h"
#include "lepp/prove/prove.h"
#include "lepp/theorems/statements.h"

using namespace lepp::prove;

namespace {

Options options() {
  Options o;
  o.time_limit_s = 60;
  o.corpus_dir = std::string(LEPP_SOURCE_DIR) + "/corpus/theorems";
  return o;
}

// The rows the prover proves within seconds: each one's negative test. Proposition 6 (a)
// on the triangle's own vertices needs no hypothesis at all (Thales), so it has none to drop.
const char* kProvedRows[] = {
    "Theorem2.TerminalTrianglesLargestAngleAtMost120",
    "Theorem2.EqualityCaseCocircularWithEquilateral",
    "Proposition3.Alpha1AtLeastHalfAlpha0",
    "Proposition3.ObtuseAlpha1AtLeastAlpha0",
    "Lemma4.HoldsWhenBCShorterThanCA",
    "Proposition6.AcuteWorstRatioIsIsosceles",
    "Lemma7.ObtuseAlpha1AboveAlpha0",
    // Transcendental: the interval branch-and-bound.
    "Lemma7.AcuteAlpha1AtLeast079Alpha0",
    "Lemma7.AcuteAlpha1AtLeast0866Alpha0BelowAlphaLimit",
    "Lemma7.Alpha1OverAlpha0TendsToOne",
    "Lemma7.BetaAtLeast179Alpha0",
    "Lemma8.AcuteBelowAlphaLimitOwnDistanceAbove129",
    "Lemma8.AcuteBelow30OwnDistanceAbove096",
    "Lemma8.ObtuseBelow14DistanceAboveBC",
    "Lemma8.MeshVertexOutsideObtuseCircumcircle",
    "Lemma8.ObtuseBelowAlphaLimitDistanceAbove066",
    "Lemma8.ObtuseBelow30DistanceAtLeastHalf",
    "Lemma8.ObtuseAbove14BetaAbove28",
    "Corollary12.CentroidInsideBetterTriangleWhenItIsTaller",
    "Theorem14.CentroidOnTerminalEdgeIffEqualHeights",
    "Remark13.WorseTriangleByTangents",
    "Remark13.NonObtuseCaseDistanceAbove061",
    "Remark13.ObtuseCaseDistanceAbove069",
};

std::string test_name(const std::string& statement) {
  std::string s;
  for (char c : statement) s += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
  return s;
}

class ProvedRow : public ::testing::TestWithParam<const char*> {};

TEST_P(ProvedRow, ProvedAndRefutedWithoutItsEssentialHypothesis) {
  std::string statement = GetParam();
  Decision d = decide(statement, options());
  EXPECT_EQ(d.outcome, Outcome::Proved) << decided_cell(d);
  std::string dropped = essential_hypothesis(statement);
  ASSERT_FALSE(dropped.empty());
  Decision n = decide_without(statement, dropped, options());
  EXPECT_EQ(n.outcome, Outcome::Refuted) << "without '" << dropped << "': " << decided_cell(n);
  EXPECT_FALSE(n.counterexample.empty());
  // The counterexample is rejected by the row's check function (hypothesis and
  // conclusion both fail), except for Theorem 2's equality case and Lemma 8 (c),
  // whose obligations have no check function taking a grid configuration, and the lemma of
  // the narrowed Remark 13 rows and of Lemma 8 (b)(ii), (b)(iii) (no rows of the table); Lemma 8 (b)(ii)
  // and (b)(iii), proved on the triangle alone (Theorem 2 stands in for D, the lemma for the free vertex),
  // whose counterexample without Theorem 2's bound has no Delaunay partner D to make a mesh for the
  // check (Theorem 2 says so); Remark 13 (1)'s and (2)'s checks read alpha0 > 30
  // as "not applicable" and compares no distance (Row::negative_check), so there Z3's exact
  // model alone refutes (for (2) no other dropped hypothesis gives a point it rejects: without Delaunay or the
  // frame the claim still holds; without the others Z3's points leave the check's case).
  bool has_check = statement != "Theorem2.EqualityCaseCocircularWithEquilateral" &&
                   statement != "Lemma8.ObtuseAbove14BetaAbove28" && statement != "Remark13.WorseTriangleByTangents" &&
                   statement != "Remark13.NonObtuseCaseDistanceAbove061" &&
                   statement != "Remark13.ObtuseCaseDistanceAbove069" &&
                   statement != "Lemma8.MeshVertexOutsideObtuseCircumcircle" &&
                   statement != "Lemma8.ObtuseBelowAlphaLimitDistanceAbove066" &&
                   statement != "Lemma8.ObtuseBelow30DistanceAtLeastHalf";
  if (has_check) EXPECT_TRUE(n.confirmed) << n.counterexample << ": " << n.note;
}

INSTANTIATE_TEST_SUITE_P(Prove, ProvedRow, ::testing::ValuesIn(kProvedRows),
                         [](const auto& info) { return test_name(info.param); });

// False statements of the paper are refuted, and the row's check function rejects the point.
TEST(ProveRefutes, FindingsAreRefutedAndConfirmed) {
  for (const char* statement :
       {"Lemma4.BisectionImprovesTBLeavesObtuseTA", "Lemma11.CentroidBoundsInLongestEdgeCoordinates",
        "Corollary12.CentroidInsideBetterTriangle", "Remark13.CentroidDistanceAtLeast075ShortestEdge",
        "Theorem14.CentroidNotCollinearExceptRightIsosceles"}) {
    Decision d = decide(statement, options());
    EXPECT_EQ(d.outcome, Outcome::Refuted) << statement << ": " << decided_cell(d);
    EXPECT_TRUE(d.confirmed) << statement << ": " << d.note;
  }
}

// Rows refuted by a sampled mesh counterexample stay refuted by it.
TEST(ProveRefutes, SampledMeshCounterexamplesStay) {
  for (const char* statement : {"Proposition6.MidpointNearestVertexInDelaunayMesh",
                                "Lemma8.AcuteBelowAlphaLimitDistanceAbove13", "Lemma8.AcuteBelow30DistanceAbove096"}) {
    Decision d = decide(statement, options());
    EXPECT_EQ(d.outcome, Outcome::Refuted) << statement << ": " << decided_cell(d);
    EXPECT_TRUE(d.confirmed);
    EXPECT_EQ(d.method, "sampled counterexample");
  }
}

// A constant made too strong is refuted: Theorem 2 with 119 degrees (cos >= -0.48, 118.7 degrees)
// and Lemma 8 (a)(i)'s own-vertices bound with the paper's 1.3 instead of 1.29.
TEST(ProveRefutes, StrongerConstantsAreRefuted) {
  Options o = options();
  TightConstant t2 = tighten("Theorem2.TerminalTrianglesLargestAngleAtMost120", o, 1e-3, 12);
  EXPECT_TRUE(t2.complete);
  // cos 120 = -1/2 is the exact bound (equality case): proved at -1/2, refuted just above.
  EXPECT_NEAR(t2.proved, -0.5, 1e-3);
  EXPECT_FALSE(t2.extreme.empty());
  TightConstant l8 = tighten("Lemma8.AcuteBelowAlphaLimitOwnDistanceAbove129", o, 1e-3, 20);
  EXPECT_TRUE(l8.complete);
  // The isosceles worst case: 1/(4 sin(alpha_limit/2)) = 1.29632.
  EXPECT_NEAR(l8.proved, 1.29632, 2e-3);
  EXPECT_LT(l8.refuted, 1.3);
}

// Rows that are not first-order statements over the reals say why.
// lepp theorems fails its run on a Z3 refutation the row's check function took and did
// not confirm; a confirmed one, one no check function takes (re-checked by Z3), one
// found otherwise (a sampled counterexample) or any other outcome does not.
TEST(ProveRefutes, UnconfirmedRefutationFailsTheRun) {
  Decision d;
  d.outcome = Outcome::Refuted;
  d.method = "Z3 nlsat";
  d.note = "the row's check function reads a configuration without this hypothesis as not applicable";
  EXPECT_TRUE(unconfirmed_refutation(d));
  Decision confirmed = d;
  confirmed.confirmed = true;
  EXPECT_FALSE(unconfirmed_refutation(confirmed));
  Decision no_check = d;
  no_check.note = "no check function takes this configuration; the point was re-checked exactly by Z3";
  EXPECT_FALSE(unconfirmed_refutation(no_check));
  Decision sampled = d;
  sampled.method = "sampled counterexample";
  EXPECT_FALSE(unconfirmed_refutation(sampled));
  Decision proved = d;
  proved.outcome = Outcome::Proved;
  EXPECT_FALSE(unconfirmed_refutation(proved));
}

TEST(ProveNotDecided, NamesTheReason) {
  Decision d = decide("Theorem1.FinitelyManySimilarityClasses", options());
  EXPECT_EQ(d.outcome, Outcome::NotDecided);
  EXPECT_NE(d.note.find("not first-order"), std::string::npos);
}

// A solver that runs out of time proves nothing.
TEST(ProveNotDecided, TimeLimitIsNotAProof) {
  Options o = options();
  o.time_limit_s = 0.001;
  Decision d = decide("Theorem2.TerminalTrianglesLargestAngleAtMost120", o);
  EXPECT_EQ(d.outcome, Outcome::NotDecided) << decided_cell(d);
  EXPECT_NE(d.note.find("time limit"), std::string::npos) << d.note;
}

// Every statement of the table is a row of the prover, and a row's essential hypothesis is one of its own.
TEST(ProveRows, EveryStatementOfTheTableIsARow) {
  EXPECT_EQ(row_statements().size(), lepp::theorems::statements().size());
  for (const std::string& s : row_statements()) {
    EXPECT_FALSE(row_kind(s).empty()) << s;
    std::string e = essential_hypothesis(s);
    if (e.empty()) continue;
    auto h = hypotheses(s);
    EXPECT_NE(std::find(h.begin(), h.end(), e), h.end()) << s << ": " << e;
  }
  EXPECT_EQ(row_kind("Theorem2.TerminalTrianglesLargestAngleAtMost120"), "algebraic");
  EXPECT_EQ(row_kind("Lemma8.AcuteBelow30DistanceAbove096"), "sampled");
  EXPECT_EQ(row_kind("Section5.CentroidAddsFewerPoints"), "not first-order");
  EXPECT_EQ(row_kind("No.Such"), "");
}

// corpus/theorems/proofs/ holds exactly what the library writes for the recorded answers.
TEST(ProveFiles, CommittedObligationsAreCurrent) {
  namespace fs = std::filesystem;
  fs::path dir = fs::path(LEPP_SOURCE_DIR) / "corpus/theorems/proofs";
  std::ifstream index(dir / "expected.txt");
  ASSERT_TRUE(index) << dir / "expected.txt";
  std::vector<Decision> decisions;
  std::map<std::string, std::string> expected;
  for (std::string line; std::getline(index, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ss(line);
    std::string file, answer;
    ss >> file >> answer;
    expected[file] = answer;
    auto dot = file.rfind('.');
    std::string statement = file.substr(0, dot), kind = file.substr(dot + 1);
    statement[statement.find('-')] = '.';
    bool proved = answer.rfind("unsat", 0) == 0 || answer == "TRUE";
    auto it = std::find_if(decisions.begin(), decisions.end(), [&](const Decision& d) { return d.statement == statement; });
    if (it == decisions.end()) {
      Decision d;
      d.statement = statement;
      d.method = kind == "smt2" ? "Z3" : "QEPCAD B";
      d.outcome = proved ? Outcome::Proved : Outcome::Refuted;
      decisions.push_back(d);
    } else if (kind == "smt2") {
      it->method = "Z3";
    }
  }
  auto files = obligation_files(decisions);
  EXPECT_EQ(files.size(), expected.size());
  for (const ObligationFile& f : files) {
    std::ifstream in(dir / f.name);
    ASSERT_TRUE(in) << f.name << " is not committed: run lepp theorems --prove --write-proofs";
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text, f.contents) << f.name << " is stale: run lepp theorems --prove --write-proofs";
    EXPECT_EQ(expected[f.name], f.expected) << f.name;
  }
}

}  // namespace

// The table links its pictures relative to its own directory (stdout: the current one).
TEST(ProvePictures, LinkIsRelativeToTheTable) {
  EXPECT_EQ(picture_link_dir("docs/theorems", "docs/THEOREMS.md"), "theorems");
  EXPECT_EQ(picture_link_dir("docs/theorems", ""), "docs/theorems");
  EXPECT_EQ(picture_link_dir("pics", "out/deep/T.md"), "../../pics");
  EXPECT_EQ(picture_link_dir("docs/./theorems", "docs/THEOREMS.md"), "theorems");
}

// A refuted row's picture is written, linked from its cell, and names the counterexample's
// exact points (Lemma 4's isosceles counterexample and a sampled mesh's pair).
TEST(ProvePictures, WrittenLinkedAndNameTheCounterexamplesPoints) {
  namespace fs = std::filesystem;
  fs::path dir = fs::temp_directory_path() / "lepp_prove_pictures_test";
  fs::remove_all(dir);
  std::vector<Decision> decisions = {decide("Lemma4.BisectionImprovesTBLeavesObtuseTA", options()),
                                     decide("Lemma8.AcuteBelow30DistanceAbove096", options()),
                                     decide("Lemma7.ObtuseAlpha1AboveAlpha0", options())};
  ASSERT_EQ(decisions[0].outcome, Outcome::Refuted);
  ASSERT_EQ(decisions[1].outcome, Outcome::Refuted);
  ASSERT_EQ(decisions[2].outcome, Outcome::Proved);
  std::string error;
  ASSERT_TRUE(write_counterexample_pictures(dir.string(), "theorems", decisions, &error)) << error;
  for (std::size_t i = 0; i < 2; ++i) {
    const Decision& d = decisions[i];
    EXPECT_EQ(d.picture, "theorems/" + picture_name(d.statement));
    EXPECT_NE(decided_cell(d).find("[picture](theorems/" + picture_name(d.statement) + ")"), std::string::npos);
    std::ifstream in(dir / picture_name(d.statement));
    ASSERT_TRUE(in) << picture_name(d.statement);
    std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(svg.find("<svg"), std::string::npos);
    ASSERT_GE(d.points.size(), 3u);
    for (const NamedPoint& p : d.points)
      EXPECT_NE(svg.find(p.name + " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"), std::string::npos)
          << d.statement << ": " << p.name;
    // The points are those of the counterexample the table prints.
    for (const NamedPoint& p : d.points)
      if (p.name != "mesh vertex")
        EXPECT_NE(d.counterexample.find(std::to_string(p.x) + ", " + std::to_string(p.y)), std::string::npos)
            << d.counterexample << " vs " << p.name;
  }
  // A proved row has no picture.
  EXPECT_TRUE(decisions[2].picture.empty());
  EXPECT_FALSE(fs::exists(dir / picture_name(decisions[2].statement)));
  Decision none;
  EXPECT_THROW(counterexample_svg(none), std::invalid_argument);
  fs::remove_all(dir);
}

// A conjunct decided in slices of x1 is proved only if the slices cover every x1: each
// row's cuts are checked (increasing rationals, their slices' disjunction valid), and a
// list that leaves a gap or is out of order is rejected.
TEST(ProveRows, SlicesCoverEveryX1) {
  int split = 0;
  for (const std::string& s : row_statements())
    for (const auto& cuts : x1_cuts(s)) {
      if (cuts.empty()) continue;
      ++split;
      EXPECT_EQ(slice_gap(cuts), "") << s;
    }
  EXPECT_GE(split, 2);  // Remark 13 (1): d(Q) to C and to D
  EXPECT_EQ(slice_gap({"3/10"}), "");
  EXPECT_NE(slice_gap({"4/10", "3/10"}), "");
  EXPECT_NE(slice_gap({"3/10", "3/10"}), "");
  EXPECT_NE(slice_gap({"x"}), "");
}

// --- The interval branch-and-bound on its own (interval_bnb.h).
namespace {
namespace bnb = lepp::prove::bnb;
using bnb::Interval;

// On the unit disk, acos x + acos y >= k: true for k = 3/2 (the least value is pi/2,
// on the arc x, y >= 0), false for k = 8/5 (x = y = 0.7 gives 1.59).
bnb::Problem disk(long k_num, long k_den) {
  bnb::Problem p;
  p.vars = {{"x", -1, 1}, {"y", -1, 1}};
  p.hyps = {{"in the disk", [](const bnb::Point& v) { return Interval(1) - bnb::sqr(v[0]) - bnb::sqr(v[1]); }, false}};
  Interval k = Interval::rational(k_num, k_den);
  p.claim = [k](const bnb::Point& v) { return bnb::acos(v[0]) + bnb::acos(v[1]) - k; };
  return p;
}
}  // namespace

TEST(ProveBoxes, ProvesATrueTranscendentalStatement) {
  bnb::Outcome r = bnb::run(disk(3, 2), 60);
  EXPECT_EQ(r.result, bnb::Result::Proved) << r.why;
  EXPECT_TRUE(r.left.empty());
  EXPECT_GT(r.boxes, 1u);
}

TEST(ProveBoxes, RefutesAFalseOneWithACheckedGridPoint) {
  bnb::Problem p = disk(8, 5);
  bnb::Outcome r = bnb::run(p, 60);
  ASSERT_EQ(r.result, bnb::Result::Refuted) << r.why;
  ASSERT_EQ(r.point.size(), 2u);
  // On the grid, in the disk, and below the constant: checked independently in long double.
  const long double x = r.point[0], y = r.point[1];
  EXPECT_EQ(std::fmod(static_cast<double>(x * p.grid), 1.0), 0.0);
  EXPECT_LE(x * x + y * y, 1.0L);
  EXPECT_LT(std::acos(x) + std::acos(y), 1.6L);
}

// (x - sin x)^2 >= 0, written expanded so that intervals never see it certain around its
// equality case x = 0, which lies on the boundary of the hypothesis x >= 0: the boxes
// there are left (no closer), and the statement is "not decided", never "proved".
bnb::Problem dependent_square() {
  bnb::Problem p;
  p.vars = {{"x", -1, 2}};  // 0 is never a cut point: it stays inside a box at every width
  p.hyps = {{"x >= 0", [](const bnb::Point& v) { return v[0]; }, false}};
  p.claim = [](const bnb::Point& v) {
    Interval s = bnb::sin(v[0]);
    return bnb::sqr(v[0]) - Interval(2) * v[0] * s + bnb::sqr(s);
  };
  return p;
}

TEST(ProveBoxes, AnEqualityCaseItCannotCloseIsNotDecided) {
  bnb::Problem p = dependent_square();
  bnb::Outcome r = bnb::run(p, 60);
  EXPECT_EQ(r.result, bnb::Result::NotDecided);
  ASSERT_FALSE(r.left.empty());
  EXPECT_LE(r.left.front()[0].first, 0.0);
  EXPECT_GE(r.left.front()[0].second, 0.0);
  EXPECT_NE(r.why.find("boxes left near x in"), std::string::npos) << r.why;
  // A closer that refuses leaves them too; one that proves the box (here: (x - sin x)^2 is
  // a square) closes them: proved.
  p.close = [](const bnb::Box&) { return false; };
  EXPECT_EQ(bnb::run(p, 60).result, bnb::Result::NotDecided);
  p.close = [](const bnb::Box&) { return true; };
  EXPECT_EQ(bnb::run(p, 60).result, bnb::Result::Proved);
}

TEST(ProveBoxes, ATimeLimitIsNotAProof) {
  bnb::Outcome r = bnb::run(dependent_square(), 0);
  EXPECT_EQ(r.result, bnb::Result::NotDecided);
  EXPECT_TRUE(r.timed_out);
  EXPECT_NE(r.why.find("time limit"), std::string::npos) << r.why;
}

// The Lemma 7 (I) rows are decided by the boxes (ProvedRow above: proved, and refuted with a
// counterexample their check functions reject once the bound on alpha0 is dropped).
TEST(ProveBoxes, Lemma7RowsAreTranscendental) {
  // The corner C -> B: Z3 closes it for 0.79 (alpha1/alpha0 -> 1 there) and refuses for
  // 1.01, where the closing condition 2 k CM <= 1 - u^2/6 fails (2 CM >= 1 when acute).
  bnb::Box corner = {{0, 1.0 / (1 << 17)}, {0, 1.0 / (1 << 16)}};
  EXPECT_TRUE(lepp::prove::lemma7_problem("Lemma7.AcuteAlpha1AtLeast079Alpha0", "").close(corner));
  EXPECT_FALSE(lepp::prove::lemma7_problem("Lemma7.AcuteAlpha1AtLeast079Alpha0", "", 101, 100).close(corner));
  // beta >= 1.79 alpha0 closes as alpha1 >= 0.79 alpha0 (beta = alpha0 + alpha1); beta >= 2.01 alpha0 does not.
  EXPECT_TRUE(lepp::prove::lemma7_problem("Lemma7.BetaAtLeast179Alpha0", "").close(corner));
  EXPECT_FALSE(lepp::prove::lemma7_problem("Lemma7.BetaAtLeast179Alpha0", "", 201, 100).close(corner));
  // The closing condition is a sufficient one, not the claim: at the worst triangle (alpha0 = 30,
  // CA = BA: C = (1 - cos 30, 1/2)) it fails (2 0.79 CM = 0.979 > 1 - tan^2(30)/6 = 0.944).
  bnb::Box worst = {{0.1339, 0.1340}, {0.4999, 0.5}};
  EXPECT_FALSE(lepp::prove::lemma7_problem("Lemma7.AcuteAlpha1AtLeast079Alpha0", "").close(worst));
  // Just above the true worst ratio at alpha0 = 30 (0.79313, the isosceles triangle): refuted.
  bnb::Outcome above = bnb::run(lepp::prove::lemma7_problem("Lemma7.AcuteAlpha1AtLeast079Alpha0", "", 7935, 10000), 60);
  EXPECT_EQ(above.result, bnb::Result::Refuted) << above.why;
  EXPECT_EQ(row_kind("Lemma7.AcuteAlpha1AtLeast079Alpha0"), "transcendental");
  auto h = hypotheses("Lemma7.BetaAtLeast179Alpha0");
  EXPECT_NE(std::find(h.begin(), h.end(), "acute"), h.end());
}

TEST(ProveBoxes, Lemma7aJustBelowItsWorstRatioIsProved) {
  bnb::Outcome below = bnb::run(lepp::prove::lemma7_problem("Lemma7.AcuteAlpha1AtLeast079Alpha0", "", 7930, 10000), 60);
  EXPECT_EQ(below.result, bnb::Result::Proved) << below.why;
}

// The tight-constant bisection covers the Lemma 7 (I) rows with the boxes: (a) brackets its
// worst ratio, the isosceles triangle at alpha0 = 30 (alpha1/alpha0 = 0.7931326), proved
// below and refuted above by a grid point its check function, given k, rejects.
TEST(ProveTight, Lemma7aBracketsTheIsoscelesWorstRatio) {
  auto rows = tight_statements();
  for (const char* s : {"Lemma7.AcuteAlpha1AtLeast079Alpha0", "Lemma7.AcuteAlpha1AtLeast0866Alpha0BelowAlphaLimit",
                        "Lemma7.Alpha1OverAlpha0TendsToOne", "Lemma7.BetaAtLeast179Alpha0"})
    EXPECT_NE(std::find(rows.begin(), rows.end(), s), rows.end()) << s;
  TightConstant t = tighten("Lemma7.AcuteAlpha1AtLeast079Alpha0", options(), 1e-3, 20);
  EXPECT_TRUE(t.complete) << t.stopped;
  EXPECT_LT(t.proved, 0.7931326);
  EXPECT_GT(t.refuted, 0.7931325);
  EXPECT_LE(t.refuted - t.proved, 1e-3);
  EXPECT_EQ(t.witnessed, t.refuted);
  EXPECT_FALSE(t.extreme.empty());
  EXPECT_EQ(t.paper, "79/100");
}

// The check function given k: near the worst triangle (C just below alpha0 = 30 on CA = BA,
// alpha1/alpha0 = 0.79313) it rejects k = 0.7935 and accepts k = 0.7930.
TEST(ProveTight, Lemma7CheckFunctionTakesTheConstant) {
  Config c;
  c.L = std::int64_t(1) << 32;
  c.v = {575415628, 2147482120};
  auto above = lemma7_check_at("Lemma7.AcuteAlpha1AtLeast079Alpha0", c, 0.7935);
  EXPECT_TRUE(above.hypothesis && !above.conclusion && !above.tie) << above.detail;
  auto below = lemma7_check_at("Lemma7.AcuteAlpha1AtLeast079Alpha0", c, 0.7930);
  EXPECT_TRUE(below.hypothesis && below.conclusion) << below.detail;
  // beta = alpha0 + alpha1: the same triangle, 1.7935 rejected, 1.7930 accepted.
  EXPECT_FALSE(lemma7_check_at("Lemma7.BetaAtLeast179Alpha0", c, 1.7935).conclusion);
  EXPECT_TRUE(lemma7_check_at("Lemma7.BetaAtLeast179Alpha0", c, 1.7930).conclusion);
}
