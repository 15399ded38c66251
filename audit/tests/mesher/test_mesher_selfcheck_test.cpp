// SPDX-License-Identifier: GPL-3.0-or-later
// The premise of the audit tests, checked without `lepp audit`: lepp_test_mesher
// without bugs is right on the hand-made inputs (exact certificate with the angle
// under the small-input-angle exemption rule, conformance of its trace), and each seeded bug really shows on at least one of
// them (the certifier or the conformance checker names it directly). So when an
// audit test fails, the audit missed a bug that is there, or flagged a program
// that is right.
#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "lepp/audit/judge/conformance.h"
#include "lepp/certify.h"
#include "lepp/io.h"
#include "lepp/trace_io.h"
#include "lepp/validate.h"

namespace {

namespace fs = std::filesystem;

const std::string kMesher = LEPP_TEST_MESHER;
const std::string kInputs = LEPP_AUDIT_INPUTS;
// Inputs on which the program without bugs once left a triangle it must refine.
const std::string kRegressions = LEPP_AUDIT_REGRESSIONS;

struct Case {
  std::string input;
  double theta;
  lepp::Method method;
};

std::vector<Case> cases(std::vector<double> thetas = {20, 25, 30}, const std::string& dir = kInputs) {
  std::vector<Case> out;
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".poly") files.push_back(e.path().string());
  std::sort(files.begin(), files.end());
  for (const std::string& f : files)
    for (double t : thetas)
      for (lepp::Method m : {lepp::Method::Centroid, lepp::Method::Midpoint})
        if (m == lepp::Method::Centroid || t <= 22) out.push_back({f, t, m});
  return out;
}

// The paper's four problems (corpus/paper), centroid at 20, 25 and 30 degrees:
// large enough for a program's two deviations to meet in one trace.
std::vector<Case> paper_cases() {
  std::vector<Case> out;
  for (const Case& c : cases({20, 25, 30}, LEPP_PAPER_INPUTS))
    if (c.method == lepp::Method::Centroid) out.push_back(c);
  return out;
}

std::string fmt_step(const lepp::audit::DeviationLink& l) { return l.deviation + " from step " + std::to_string(l.first_step); }

std::string name(const Case& c) {
  return fs::path(c.input).filename().string() + " theta " + std::to_string(c.theta) +
         (c.method == lepp::Method::Centroid ? " centroid" : " midpoint");
}

struct MesherRun {
  int status = -1;  // exit status, or 128 + signal
  std::string prefix;
};

MesherRun run_mesher(const Case& c, const std::string& extra, const std::string& wrapper = "") {
  static int counter = 0;
  const fs::path dir = fs::temp_directory_path() / ("lepp_test_mesher_selfcheck_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  MesherRun r;
  r.prefix = (dir / ("run" + std::to_string(counter++))).string();
  const std::string cmd = wrapper + kMesher + " " + c.input + " " + r.prefix + " " + std::to_string(c.theta) + " " +
                          (c.method == lepp::Method::Centroid ? "centroid" : "midpoint") + " " + extra + " 2>/dev/null";
  const int raw = std::system(cmd.c_str());
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : 128 + WTERMSIG(raw);
  return r;
}

lepp::Pslg validated(const std::string& path) {
  std::vector<std::string> warnings;
  return lepp::validate(lepp::read_poly(path), warnings);
}

lepp::certify::Report certify(const Case& c, const MesherRun& r) {
  lepp::certify::Options o;
  o.min_angle_deg = c.theta;
  o.exempt_small_input_angles = true;  // inputs/small-angle-corner.poly: its wedge triangle stays
  return lepp::certify::certify(validated(c.input), lepp::read_mesh(r.prefix), o);
}

lepp::audit::ConformanceReport conformance(const Case& c, const MesherRun& r) {
  lepp::audit::ConformanceOptions o;
  o.method = c.method;
  o.min_angle_deg = c.theta;
  return lepp::audit::check_conformance(validated(c.input), lepp::read_trace(r.prefix + ".trace"), o);
}

TEST(TestMesherSelfCheck, WithoutBugsCertifiedAndConforms) {
  for (const std::string& extra : {std::string(), std::string("--zero-based")})
    for (const Case& c : cases()) {
      const MesherRun r = run_mesher(c, extra);
      ASSERT_EQ(r.status, 0) << name(c);
      const lepp::certify::Report cert = certify(c, r);
      EXPECT_TRUE(cert.certified()) << name(c) << " " << extra << "\n" << lepp::certify::format_report(cert);
      const lepp::audit::ConformanceReport conf = conformance(c, r);
      EXPECT_TRUE(conf.conforms) << name(c) << "\n" << lepp::audit::describe(conf);
    }
}

// regressions/beyond-wedge-mouth.poly: a 4.57-degree triangle beyond the mouth of a
// 26.57-degree wedge was once left as a small-input-angle triangle at theta 30.
TEST(TestMesherSelfCheck, RegressionsCertifiedAndConform) {
  const std::vector<Case> all = cases({20, 25, 30}, kRegressions);
  ASSERT_FALSE(all.empty());
  for (const Case& c : all) {
    const MesherRun r = run_mesher(c, "");
    ASSERT_EQ(r.status, 0) << name(c);
    const lepp::certify::Report cert = certify(c, r);
    EXPECT_TRUE(cert.certified()) << name(c) << "\n" << lepp::certify::format_report(cert);
    const lepp::audit::ConformanceReport conf = conformance(c, r);
    EXPECT_TRUE(conf.conforms) << name(c) << "\n" << lepp::audit::describe(conf);
  }
}

// How many cases show a certificate violation of `reason` under --bug.
std::size_t shows_reason(const std::string& bug, lepp::certify::Reason reason) {
  std::size_t n = 0;
  for (const Case& c : cases()) {
    const MesherRun r = run_mesher(c, "--bug " + bug);
    if (r.status == 0 && certify(c, r).has(reason)) ++n;
  }
  return n;
}

// How many cases end normally but do not conform under --bug.
std::size_t shows_nonconformance(const std::string& bug) {
  std::size_t n = 0;
  for (const Case& c : cases()) {
    const MesherRun r = run_mesher(c, "--bug " + bug);
    if (r.status == 0 && !conformance(c, r).conforms) ++n;
  }
  return n;
}

TEST(TestMesherSelfCheck, NonDelaunayBugShows) {
  EXPECT_GT(shows_reason("non-delaunay", lepp::certify::Reason::NotLocallyDelaunay), 0u);
}
TEST(TestMesherSelfCheck, DropSegmentBugShows) {
  EXPECT_GT(shows_reason("drop-segment", lepp::certify::Reason::SegmentMissing), 0u);
}
TEST(TestMesherSelfCheck, SkinnyBugShows) {
  EXPECT_GT(shows_reason("skinny", lepp::certify::Reason::AngleBelowTheta), 0u);
}
TEST(TestMesherSelfCheck, TriangleCentroidBugShows) { EXPECT_GT(shows_nonconformance("triangle-centroid"), 0u); }
TEST(TestMesherSelfCheck, NoRemark10BugShows) { EXPECT_GT(shows_nonconformance("no-remark10"), 0u); }
TEST(TestMesherSelfCheck, ShortestEdgeBugShows) { EXPECT_GT(shows_nonconformance("shortest-edge"), 0u); }

// Each deviation bug of the test mesher is caught by conformance and named by
// the catalogue (docs/CONFORMANCE.md, "Deviations"): every failing run's first
// failing step is that deviation, with the mesh before the step and the place
// where it matched; for the deviations that are a whole rule set, some run's
// every step fits that one variant.
struct DeviationBug {
  std::string bug, deviation;
};
void PrintTo(const DeviationBug& d, std::ostream* os) { *os << "--bug " << d.bug << " -> " << d.deviation; }
class DeviationNamed : public ::testing::TestWithParam<DeviationBug> {};

TEST_P(DeviationNamed, EveryFailureNamed) {
  const DeviationBug& d = GetParam();
  std::size_t failed = 0, consistent = 0, undecided_remark10 = 0;
  for (const Case& c : cases()) {
    if (c.method != lepp::Method::Centroid) continue;
    const MesherRun r = run_mesher(c, "--bug " + d.bug);
    if (r.status != 0) continue;
    const lepp::audit::ConformanceReport conf = conformance(c, r);
    if (conf.conforms) continue;
    ++failed;
    ASSERT_TRUE(conf.failure);
    // A Remark 10 reversed program whose trace never has the centroid inside the
    // other triangle shows only points an ignoring one takes too: named
    // remark10-ignored, and said that remark10-reversed fits as well.
    if (d.deviation == "remark10-reversed" && conf.failure->deviation == "remark10-ignored" &&
        conf.failure->remark10_centroid_inside_steps == 0) {
      ++undecided_remark10;
      EXPECT_NE(lepp::audit::describe(conf).find("remark10-reversed fits the trace as well"), std::string::npos);
      continue;
    }
    EXPECT_EQ(conf.failure->deviation, d.deviation) << name(c) << "\n" << lepp::audit::describe(conf);
    // One bug, one name: the continued replay finds no second deviation.
    ASSERT_FALSE(conf.failure->chain.empty()) << name(c);
    EXPECT_EQ(conf.failure->chain.front().deviation, conf.failure->deviation) << name(c);
    if (conf.failure->consistent_variant) {
      EXPECT_EQ(conf.failure->chain.size(), 1u) << name(c) << "\n" << lepp::audit::describe(conf);
      EXPECT_TRUE(conf.failure->chain_complete) << name(c);
      EXPECT_EQ(conf.failure->chain.front().steps, conf.failure->variant_steps) << name(c);
    }
    EXPECT_FALSE(conf.failure->mesh.triangles.empty()) << name(c);
    if (conf.failure->deviation == d.deviation) {
      ASSERT_TRUE(conf.failure->deviation_at) << name(c);
      EXPECT_LE(conf.failure->deviation_at->distance, conf.failure->deviation_at->tolerance);
      EXPECT_NE(lepp::audit::describe(conf).find("deviation: " + d.deviation), std::string::npos);
    }
    consistent += conf.failure->consistent_variant;
  }
  EXPECT_GT(failed, 0u) << "--bug " << d.bug << " never caught";
  EXPECT_LT(undecided_remark10, failed) << "--bug " << d.bug << ": no run named " << d.deviation;
  if (d.deviation != "good-triangle") EXPECT_GT(consistent, 0u) << "--bug " << d.bug << ": no run fits one variant";
  std::cout << "--bug " << d.bug << ": " << failed << " failing runs named " << d.deviation << ", " << consistent
            << " fit one consistent variant\n";
}

INSTANTIATE_TEST_SUITE_P(Catalogue, DeviationNamed,
                         ::testing::Values(DeviationBug{"area-centroid", "area-centroid"},
                                           DeviationBug{"triangle-centroid", "triangle-centroid"},
                                           DeviationBug{"terminal-midpoint", "terminal-midpoint"},
                                           DeviationBug{"centroid-not-midpoint", "centroid-not-midpoint"},
                                           DeviationBug{"remark10-reversed", "remark10-reversed"},
                                           DeviationBug{"no-remark10", "remark10-ignored"},
                                           DeviationBug{"other-second-longest", "other-second-longest"},
                                           DeviationBug{"good-triangle", "good-triangle"}),
                         [](const ::testing::TestParamInfo<DeviationBug>& info) {
                           std::string n = info.param.bug;
                           for (char& ch : n)
                             if (ch == '-') ch = '_';
                           return n;
                         });

// A program that ignores Remark 10 is told from one that reverses it by its
// trace: some run of the ignoring program took the centroid inside the other
// triangle (which a reversed program never does), and none of its runs is named
// remark10-reversed; some run of the reversed program took a midpoint where the
// centroid is inside (which an ignoring program never does).
TEST(TestMesherSelfCheck, Remark10IgnoredToldFromReversed) {
  std::size_t ignored_evidence = 0, reversed_named = 0, reversed_from_shared_step = 0;
  for (const Case& c : paper_cases()) {
    for (const char* bug : {"no-remark10", "remark10-reversed"}) {
      const MesherRun r = run_mesher(c, std::string("--bug ") + bug);
      ASSERT_EQ(r.status, 0);
      const lepp::audit::ConformanceReport conf = conformance(c, r);
      if (conf.conforms) continue;
      const std::string named = conf.failure->deviation;
      if (std::string(bug) == "no-remark10") {
        EXPECT_EQ(named, "remark10-ignored") << name(c) << "\n" << lepp::audit::describe(conf);
        if (conf.failure->remark10_centroid_inside_steps > 0) {
          ++ignored_evidence;
          EXPECT_NE(lepp::audit::describe(conf).find("remark10-ignored, not remark10-reversed"), std::string::npos);
        }
      } else {
        reversed_named += named == "remark10-reversed";
        EXPECT_TRUE(named == "remark10-reversed" || named == "remark10-ignored") << name(c);
        // A first step both programs take (the centroid outside the other
        // triangle), then one only reversing takes: remark10-reversed from the first.
        bool both_in_chain = false;
        for (const auto& l : conf.failure->chain) both_in_chain = both_in_chain || l.deviation == "remark10-ignored";
        EXPECT_FALSE(both_in_chain && named == "remark10-reversed") << name(c) << "\n" << lepp::audit::describe(conf);
        reversed_from_shared_step += named == "remark10-reversed" &&
                                     conf.failure->deviation_what.find("outside the triangle across") != std::string::npos;
      }
    }
  }
  EXPECT_GT(ignored_evidence, 0u);
  EXPECT_GT(reversed_named, 0u);
  EXPECT_GT(reversed_from_shared_step, 0u) << "no run of the reversed program began with a step the ignoring one takes too";
}

// Two deviations at once (--bug given twice: the area centroid, and another
// edge's midpoint where Remark 10 asks for the constrained one's): one check
// names both, in the order the trace shows them, and the trace does not fit
// either one variant. Each bug alone gives a chain of its one name.
TEST(TestMesherSelfCheck, TwoDeviationsNamedInOneCheck) {
  std::size_t both = 0;
  for (const Case& c : paper_cases()) {
    const MesherRun r = run_mesher(c, "--bug area-centroid --bug other-second-longest");
    ASSERT_EQ(r.status, 0);
    const lepp::audit::ConformanceReport conf = conformance(c, r);
    ASSERT_FALSE(conf.conforms) << name(c);
    const lepp::audit::ConformanceFailure& f = *conf.failure;
    ASSERT_FALSE(f.chain.empty());
    EXPECT_EQ(f.chain.front().deviation, f.deviation);
    EXPECT_EQ(f.chain.front().first_step, f.step + 1);
    std::set<std::string> names;
    for (std::size_t i = 0; i < f.chain.size(); ++i) {
      names.insert(f.chain[i].deviation);
      EXPECT_GE(f.chain[i].steps, 1u) << name(c) << "\n" << lepp::audit::describe(conf);
      if (i) EXPECT_GT(f.chain[i].first_step, f.chain[i - 1].first_step) << name(c);
    }
    EXPECT_EQ(names.size(), f.chain.size()) << "a name twice: " << name(c);
    for (const std::string& n : names) EXPECT_TRUE(n == "area-centroid" || n == "other-second-longest") << n << " " << name(c);
    if (names.size() < 2) continue;
    ++both;
    EXPECT_TRUE(f.chain_complete) << name(c) << "\n" << lepp::audit::describe(conf);
    EXPECT_FALSE(f.consistent_variant) << name(c);
    const std::string text = lepp::audit::describe(conf);
    EXPECT_NE(text.find(lepp::audit::chain_text(f.chain)), std::string::npos) << text;
    EXPECT_NE(text.find(fmt_step(f.chain[0]) + "; then " + fmt_step(f.chain[1])), std::string::npos) << text;
    for (const char* bug : {"area-centroid", "other-second-longest"}) {
      const lepp::audit::ConformanceReport alone = conformance(c, run_mesher(c, std::string("--bug ") + bug));
      if (alone.conforms) continue;
      EXPECT_EQ(alone.failure->chain.size(), 1u) << bug << " " << name(c) << "\n" << lepp::audit::describe(alone);
      EXPECT_EQ(alone.failure->deviation, bug) << name(c);
    }
  }
  EXPECT_GT(both, 0u) << "no run showed both deviations";
}

// The midpoint method: a quad centroid anywhere is centroid-not-midpoint.
TEST(TestMesherSelfCheck, MidpointMethodCentroidNamed) {
  std::size_t failed = 0;
  for (const Case& c : cases()) {
    if (c.method != lepp::Method::Midpoint) continue;
    const MesherRun r = run_mesher(c, "--bug centroid-not-midpoint");
    ASSERT_EQ(r.status, 0);
    const lepp::audit::ConformanceReport conf = conformance(c, r);
    if (conf.conforms) continue;
    ++failed;
    EXPECT_EQ(conf.failure->deviation, "centroid-not-midpoint") << name(c) << "\n" << lepp::audit::describe(conf);
    EXPECT_TRUE(conf.failure->consistent_variant) << name(c) << "\n" << lepp::audit::describe(conf);
  }
  EXPECT_GT(failed, 0u);
}

// The declared reading: the area-centroid program conforms when its reading
// is declared, and the program without bugs does not (where the two differ).
TEST(TestMesherSelfCheck, DeclaredAreaReading) {
  std::size_t area_conforms = 0, vertex_rejected = 0, runs = 0;
  for (const Case& c : cases()) {
    if (c.method != lepp::Method::Centroid) continue;
    ++runs;
    lepp::audit::ConformanceOptions o;
    o.method = c.method;
    o.min_angle_deg = c.theta;
    o.area_centroid = true;
    const MesherRun bugged = run_mesher(c, "--bug area-centroid");
    ASSERT_EQ(bugged.status, 0);
    const auto with_area = lepp::audit::check_conformance(validated(c.input), lepp::read_trace(bugged.prefix + ".trace"), o);
    area_conforms += with_area.conforms;
    EXPECT_TRUE(with_area.area_centroid);
    const MesherRun plain = run_mesher(c, "");
    const auto vertex_under_area = lepp::audit::check_conformance(validated(c.input), lepp::read_trace(plain.prefix + ".trace"), o);
    if (!vertex_under_area.conforms) {
      ++vertex_rejected;
      EXPECT_EQ(vertex_under_area.failure->deviation, "vertex-centroid") << name(c) << "\n" << lepp::audit::describe(vertex_under_area);
    }
  }
  EXPECT_EQ(area_conforms, runs);
  EXPECT_GT(vertex_rejected, 0u);
}

TEST(TestMesherSelfCheck, CrashGarbageLoopBugsShow) {
  const Case c = cases().back();
  // Dies by a signal: SIGSEGV, or SIGABRT under ASan (its SEGV handler reports, then aborts).
  const int crash = run_mesher(c, "--bug crash").status;
  EXPECT_TRUE(crash == 128 + SIGSEGV || crash == 128 + SIGABRT) << crash;
  const MesherRun g = run_mesher(c, "--bug garbage");
  EXPECT_EQ(g.status, 0);
  EXPECT_THROW(lepp::read_mesh(g.prefix), lepp::InputError);
  // A run that needs points never ends: `timeout` stops it (status 124).
  EXPECT_EQ(run_mesher(c, "--bug loop", "timeout 1 ").status, 124);
}

}  // namespace
