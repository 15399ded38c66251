// SPDX-License-Identifier: GPL-3.0-or-later
// The conformance check on an implementation it does not share code with:
// audit/tests/mesher's lepp_test_mesher (CGAL Epick, coordinates for tie-breaking,
// a stack for the order, (A+B+C+D)/4, t2's edge when both are constrained).
// Without bugs its traces conform; with the point-selection bugs they do not.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cstdlib>
#include <iostream>
#include <map>
#include <unistd.h>
#include <string>

#include "lepp/audit/judge/conformance.h"
#include "lepp/gen.h"
#include "lepp/gen_lattice_box.h"
#include "lepp/gen_symmetry.h"
#include "lepp/io.h"
#include "lepp/trace_io.h"
#include "lepp/validate.h"

namespace lepp::audit {
namespace {

struct MesherRun {
  Pslg input;
  std::vector<Point> trace;
};

MesherRun mesh(const std::string& poly, double theta, Method m, const std::string& bug = "") {
  // One output prefix per test: ctest runs the tests of this file in parallel processes.
  std::string out = ::testing::TempDir() + "mesher_out_" + std::to_string(getpid()) + "_" +
                    ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::string cmd = std::string(LEPP_TEST_MESHER) + " " + poly + " " + out + " " + std::to_string(theta) + " " +
                    (m == Method::Centroid ? "centroid" : "midpoint") + (bug.empty() ? "" : " --bug " + bug) +
                    " 2>/dev/null";
  int status = std::system(cmd.c_str());
  EXPECT_EQ(status, 0) << cmd;
  std::vector<std::string> warnings;
  return {validate(read_poly(poly), warnings), read_trace(out + ".trace")};
}

ConformanceOptions options(Method m, double theta) {
  ConformanceOptions c;
  c.method = m;
  c.min_angle_deg = theta;
  return c;
}

std::string paper(const std::string& name) { return std::string(LEPP_SOURCE_DIR) + "/corpus/paper/" + name + ".poly"; }

TEST(ConformanceOfTestMesher, CleanTracesConform) {
  for (const char* problem : {"A", "rect162", "square400", "circles240"})
    for (Method m : {Method::Centroid, Method::Midpoint})
      for (double theta : {20.0, 25.0, 30.0}) {
        if (m == Method::Midpoint && theta > 25) continue;
        MesherRun r = mesh(paper(problem), theta, m);
        ASSERT_FALSE(r.trace.empty());
        ConformanceReport report = check_conformance(r.input, r.trace, options(m, theta));
        EXPECT_TRUE(report.conforms) << problem << " " << to_string(m) << " " << theta << ": " << describe(report);
      }
}

TEST(ConformanceOfTestMesher, CleanTracesConformOnTheAuditInputs) {
  for (const char* name : {"box-with-crack", "box-with-points", "square-with-hole", "thin-rectangle"})
    for (Method m : {Method::Centroid, Method::Midpoint})
      for (double theta : {20.0, 25.0, 30.0}) {
        MesherRun r = mesh(std::string(LEPP_SOURCE_DIR) + "/audit/tests/mesher/inputs/" + name + ".poly", theta, m);
        ConformanceReport report = check_conformance(r.input, r.trace, options(m, theta));
        EXPECT_TRUE(report.conforms) << name << " " << to_string(m) << " " << theta << ": " << describe(report);
      }
}

// Generated PSLGs (lattice families: cocircular quads, which CGAL's insertion
// in the mesher and the replay may flip differently).
RC_GTEST_PROP(ConformanceOfTestMesher, CleanTracesConformOnGeneratedPslgs, ()) {
  const Pslg p = *gen::anyPslg();
  double theta = *rc::gen::inRange(20, 31);
  Method m = *rc::gen::element(Method::Centroid, Method::Midpoint);
  std::string poly = ::testing::TempDir() + "generated_" + std::to_string(getpid()) + ".poly";
  write_poly(poly, p);
  MesherRun r = mesh(poly, theta, m);
  ConformanceReport report = check_conformance(r.input, r.trace, options(m, theta));
  RC_CLASSIFY(report.cocircular_ties > 0, "cocircular ties");
  if (!report.conforms) RC_FAIL(to_string(m) + std::string(" theta ") + std::to_string(theta) + ": " + describe(report));
}

TEST(ConformanceOfTestMesher, PointSelectionBugsAreCaught) {
  for (const char* bug : {"triangle-centroid", "no-remark10", "shortest-edge"}) {
    int caught = 0;
    for (const char* problem : {"A", "rect162", "square400"}) {
      MesherRun r = mesh(paper(problem), 25, Method::Centroid, bug);
      if (r.trace.empty()) continue;
      ConformanceReport report = check_conformance(r.input, r.trace, options(Method::Centroid, 25));
      if (!report.conforms) ++caught;
    }
    EXPECT_GT(caught, 0) << bug << " was never caught";
  }
}

// Cocircular cells of 4 to 8 points, where the replay searches the other triangulations.
using gen::lattice_box;

// With an interior segment (a crack) from a to b: constrained edges inside,
// where Remark 10 decides.
Pslg with_crack(Pslg p, Point a, Point b) {
  const int n = static_cast<int>(p.vertices.size());
  p.vertices.push_back(a);
  p.vertices.push_back(b);
  p.segments.push_back({n, n + 1, 2});
  return p;
}

// The mesher run on the input under a lattice symmetry, its trace mapped back.
MesherRun mesh_under(const Pslg& p, const gen::LatticeSymmetry& s, double theta, Method m, const std::string& bug) {
  std::string poly = ::testing::TempDir() + "cocircular_" + std::to_string(getpid()) + ".poly";
  write_poly(poly, s.apply(p));
  MesherRun r = mesh(poly, theta, m, bug);
  std::vector<std::string> warnings;
  r.input = validate(p, warnings);
  for (Point& q : r.trace) q = s.undo(q);
  return r;
}

// On cocircular lattice input under every symmetry (so that the mesher's
// triangulations of the cells differ from the replay's), with cracks where
// Remark 10 decides: the clean traces conform, and the point-selection bugs
// are still caught (today on every run where the bug changed the trace;
// asserted: three runs in four).
TEST(ConformanceOfTestMesher, PointSelectionBugsAreCaughtOnCocircularInput) {
  const std::vector<Pslg> inputs{lattice_box(4, 3, 0), lattice_box(6, 4, 2), with_crack(lattice_box(10, 7, 0), {2, 2}, {7, 5}),
                                 with_crack(lattice_box(8, 6, 0), {1, 3}, {6, 4})};
  std::map<std::string, std::pair<int, int>> caught;  // bug -> (caught, runs where the trace changed)
  for (const Pslg& p : inputs)
    for (int k = 0; k < 8; ++k) {
      const gen::LatticeSymmetry s{k % 4, k >= 4};
      MesherRun clean = mesh_under(p, s, 30, Method::Centroid, "");
      ConformanceReport ok = check_conformance(clean.input, clean.trace, options(Method::Centroid, 30));
      EXPECT_TRUE(ok.conforms) << "symmetry " << k << ": " << describe(ok);
      for (const char* bug : {"triangle-centroid", "no-remark10", "shortest-edge"}) {
        MesherRun r = mesh_under(p, s, 30, Method::Centroid, bug);
        if (r.trace == clean.trace) continue;
        ConformanceReport report = check_conformance(r.input, r.trace, options(Method::Centroid, 30));
        ++caught[bug].second;
        caught[bug].first += !report.conforms;
        EXPECT_GT(report.cocircular_ties, 0) << "not a cocircular input";
      }
    }
  for (const char* bug : {"triangle-centroid", "no-remark10", "shortest-edge"}) {
    const auto [n, runs] = caught[bug];
    std::cout << "[" << bug << "] caught on " << n << " of " << runs << " runs where it changed the trace\n";
    EXPECT_GT(runs, 0) << bug << " never changed a trace: the inputs do not exercise it";
    EXPECT_GE(4 * n, 3 * runs) << bug;
  }
}

}  // namespace
}  // namespace lepp::audit
