// SPDX-License-Identifier: GPL-3.0-or-later
// The chain followed on the program's mesh (lepp/audit/judge/program_mesh.h,
// docs/CONFORMANCE.md "The program's mesh"): after missing-flips, inexact-incircle
// or single-precision, the replay rebuilds the mesh the program had and names
// every later step there. On audit/tests/mesher's lepp_test_mesher with those bugs
// (and catalogue rules beside them): the chain reaches the trace's end on the
// program's mesh, names every rule the exact replay named, and a wrong reading of
// the mesh (or none) does not get there.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <set>
#include <string>
#include <unistd.h>
#include <vector>

#include "lepp/audit/judge/conformance.h"
#include "lepp/audit/judge/diagnosis.h"
#include "lepp/audit/judge/program_mesh.h"
#include "lepp/audit/replay.h"
#include "lepp/io.h"
#include "lepp/trace_io.h"
#include "lepp/validate.h"

namespace lepp::audit {
namespace {

struct MesherRun {
  std::string name;
  Pslg input;
  std::vector<Point> trace;
  double theta = 0;
};

MesherRun mesh(const std::string& poly, double theta, const std::string& bugs) {
  const std::string out = ::testing::TempDir() + "program_mesh_" + std::to_string(getpid()) + "_" +
                          ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::string cmd = std::string(LEPP_TEST_MESHER) + " " + poly + " " + out + " " + std::to_string(theta) +
                          " centroid " + bugs + " 2>/dev/null";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  std::vector<std::string> warnings;
  return {poly.substr(poly.rfind('/') + 1) + " at " + std::to_string(int(theta)), validate(read_poly(poly), warnings),
          read_trace(out + ".trace"), theta};
}

std::vector<std::string> inputs() {
  std::vector<std::string> out;
  for (const char* p : {"A", "rect162"}) out.push_back(std::string(LEPP_SOURCE_DIR) + "/corpus/paper/" + p + ".poly");
  for (const char* p : {"box-with-crack", "box-with-points", "square-with-hole", "thin-rectangle"})
    out.push_back(std::string(LEPP_SOURCE_DIR) + "/audit/tests/mesher/inputs/" + p + ".poly");
  return out;
}

ConformanceOptions options(double theta) {
  ConformanceOptions c;
  c.min_angle_deg = theta;
  return c;
}

std::set<std::string> names(const ConformanceFailure& f) {
  std::set<std::string> out;
  for (const DeviationLink& l : f.chain) out.insert(l.deviation);
  return out;
}

// The exact check's failure, renamed as checks.cpp names it from the final mesh.
ConformanceFailure named(const MesherRun& r, const std::string& name) {
  ConformanceReport report = check_conformance(r.input, r.trace, options(r.theta));
  EXPECT_TRUE(report.failure) << r.name;
  ConformanceFailure f = report.failure ? *report.failure : ConformanceFailure{};
  f.deviation = name;
  if (!f.chain.empty()) f.chain.front().deviation = name;
  return f;
}

// Each arithmetic name of the mesh reads its own mesh; any other name the exact one.
TEST(ProgramMesh, ReadingChosenByTheArithmeticName) {
  EXPECT_EQ(mesh_reading_for("missing-flips"), MeshReading::NoFlips);
  EXPECT_EQ(mesh_reading_for("inexact-incircle"), MeshReading::DoubleIncircle);
  EXPECT_EQ(mesh_reading_for("single-precision"), MeshReading::FloatPoints);
  EXPECT_EQ(mesh_reading_for("float-input"), MeshReading::FloatInput);
  for (const char* other : {"printed-digits", "area-centroid", "terminal-midpoint", "unknown", "inexact-length", ""})
    EXPECT_EQ(mesh_reading_for(other), MeshReading::Exact) << other;
  // A name that reads the exact mesh, its chain ended at a step no rule fits
  // (no-rule): the program's final mesh is Delaunay here, but it had none of the
  // replay's meshes. The fallback's meshes are tried and the one that follows past
  // that step is kept, with the mesh's name there: without flips, missing-flips.
  const MesherRun r = mesh(inputs()[0], 30, "--bug terminal-midpoint --bug no-flips");
  ConformanceFailure f = named(r, "area-centroid");
  ASSERT_EQ(f.chain_end_reason, "no-rule") << f.chain_end;
  const std::size_t lost_at = f.chain_end_step;
  follow_program_mesh(r.input, r.trace, options(r.theta), f);
  EXPECT_TRUE(f.mesh_reading == "no-flips" || f.mesh_reading == "no-flips-but-splits") << f.mesh_reading;
  EXPECT_TRUE(f.chain_complete || f.chain_end_step > lost_at) << chain_text(f.chain) << "; " << f.chain_end;
  std::size_t missing_at = 0;
  for (const DeviationLink& l : f.chain)
    if (l.deviation == "missing-flips") missing_at = l.first_step;
  EXPECT_EQ(missing_at, lost_at) << chain_text(f.chain);
  // In step order, the mesh's name first among the names of its step.
  for (std::size_t i = 1; i < f.chain.size(); ++i) {
    EXPECT_LE(f.chain[i - 1].first_step, f.chain[i].first_step) << chain_text(f.chain);
    if (f.chain[i].deviation == "missing-flips") EXPECT_LT(f.chain[i - 1].first_step, lost_at) << chain_text(f.chain);
  }
  EXPECT_EQ(names(f).count("terminal-midpoint"), 1u) << chain_text(f.chain);
  EXPECT_EQ(names(f).count("unknown"), 0u) << chain_text(f.chain);
}

// The mesh's name comes first among the names of the step the exact chain lost:
// on a generated cloud (integer coordinates) the midpoint mesher without flips
// leaves a Delaunay final mesh; the exact replay loses its first failing step (no
// bad triangle there), and without flips that step is also a terminal midpoint.
TEST(ProgramMesh, FallbackNameFirstAtItsStep) {
  const MesherRun r = mesh(std::string(LEPP_SOURCE_DIR) + "/audit/tests/replay/inputs/cloud-no-flips.poly", 30,
                           "--bug terminal-midpoint --bug no-flips");
  ConformanceReport exact = check_conformance(r.input, r.trace, options(r.theta));
  ASSERT_TRUE(exact.failure);
  ConformanceFailure f = *exact.failure;
  ASSERT_EQ(f.deviation, "unknown") << chain_text(f.chain);
  follow_program_mesh(r.input, r.trace, options(r.theta), f);
  ASSERT_GE(f.chain.size(), 2u) << chain_text(f.chain);
  EXPECT_EQ(f.deviation, "missing-flips") << chain_text(f.chain);
  EXPECT_EQ(f.chain[0].deviation, "missing-flips") << chain_text(f.chain);
  EXPECT_EQ(f.chain[0].first_step, exact.failure->step + 1) << chain_text(f.chain);
  EXPECT_EQ(f.chain[1].deviation, "terminal-midpoint") << chain_text(f.chain);
  EXPECT_EQ(f.chain[1].first_step, f.chain[0].first_step) << chain_text(f.chain);
  EXPECT_TRUE(f.chain_complete) << chain_text(f.chain) << "; " << f.chain_end;
  // That step is no choice without flips either (a terminal midpoint): the finding
  // shows its picture and choices on the mesh followed.
  EXPECT_EQ(f.step_mesh_reading, f.mesh_reading);
}

// The fallback is kept only when it goes past the step the exact chain lost: the
// area-centroid mesher's trace with its last point moved off every choice names
// area-centroid, then a step no rule fits on the exact mesh and on every mesh of
// the fallback: the exact chain stays, ending no-rule at that step.
TEST(ProgramMesh, FallbackNotKeptWhereEveryMeshLosesTheStep) {
  MesherRun r = mesh(inputs()[0], 30, "--bug area-centroid");
  ASSERT_GT(r.trace.size(), 6u);
  Point& last = r.trace.back();
  last.x += 1e-6 * (1 + std::abs(last.x));
  last.y -= 2e-6 * (1 + std::abs(last.y));  // off in both: the Euclidean and the larger difference differ
  ConformanceReport exact = check_conformance(r.input, r.trace, options(r.theta));
  ASSERT_TRUE(exact.failure);
  ConformanceFailure f = *exact.failure;
  ASSERT_EQ(f.deviation, "area-centroid") << chain_text(f.chain);
  ASSERT_EQ(f.chain_end_reason, "no-rule") << chain_text(f.chain) << "; " << f.chain_end;
  ASSERT_EQ(f.chain_end_step, r.trace.size());
  // The reason's nearest distance is the table's first (Euclidean), not another measure.
  ASSERT_FALSE(exact.failure->candidates.empty());
  const std::string first = fmt::format("nearest choice {:.3g} away;", exact.failure->candidates.front().euclidean);
  EXPECT_NE(exact.failure->reason.find(first), std::string::npos) << exact.failure->reason << " / " << first;
  const std::vector<DeviationLink> before = f.chain;
  follow_program_mesh(r.input, r.trace, options(r.theta), f);
  EXPECT_TRUE(f.mesh_reading.empty()) << f.mesh_reading << ": " << chain_text(f.chain);
  EXPECT_EQ(f.chain_end_reason, "no-rule");
  EXPECT_EQ(chain_text(f.chain), chain_text(before));
}

// A program that keeps an exactly cocircular quad's diagonal as its insertion made
// it (a strict Lawson test), where CGAL's insertion breaks the tie the other way:
// on the audit's generated box with a hole (integer coordinates) the exact replay
// loses the double-flips mesher's chain at its first failing step (unknown); the
// mesh with ties kept follows it to the end, naming the seeded rules and no
// arithmetic, since every in-circle test of this run is exact in double too.
TEST(ProgramMesh, ChainLostAtACocircularTieFollowedWithTiesKept) {
  const MesherRun r = mesh(std::string(LEPP_SOURCE_DIR) + "/audit/tests/replay/inputs/cocircular-box-hole.poly", 30,
                           "--bug double-flips --bug area-centroid --bug remark10-reversed");
  ConformanceReport exact = check_conformance(r.input, r.trace, options(r.theta));
  ASSERT_TRUE(exact.failure);
  ConformanceFailure f = *exact.failure;
  ASSERT_EQ(f.deviation, "unknown") << chain_text(f.chain);
  follow_program_mesh(r.input, r.trace, options(r.theta), f);
  EXPECT_EQ(f.mesh_reading, "ties-kept");
  EXPECT_TRUE(f.chain_complete) << chain_text(f.chain) << "; " << f.chain_end;
  EXPECT_EQ(f.deviation, "area-centroid") << chain_text(f.chain);
  EXPECT_EQ(f.chain.front().first_step, exact.failure->step + 1) << chain_text(f.chain);
  for (const char* arithmetic : {"unknown", "inexact-incircle", "missing-flips"})
    EXPECT_EQ(names(f).count(arithmetic), 0u) << arithmetic << ": " << chain_text(f.chain);
  // finding.md says which mesh, and that the final mesh did not name it.
  ConformanceReport followed = exact;
  followed.failure = f;
  const std::string md = diagnosis_markdown(conformance_diagnosis(followed, r.theta, false));
  EXPECT_NE(md.find("(`ties-kept`), not the exact one: on the exact mesh the chain lost a step no rule fits"), std::string::npos) << md;
  EXPECT_EQ(md.find("of the final mesh), not the exact one"), std::string::npos) << md;
  // The step's table and picture are of that mesh too, where its deviation is: the
  // program's point is the area centroid of a quad whose vertex centroid is the
  // nearest choice listed; the exact mesh's table listed other choices.
  EXPECT_EQ(f.step_mesh_reading, "ties-kept");
  ASSERT_TRUE(f.deviation_at) << f.deviation_what;
  ASSERT_FALSE(f.candidates.empty());
  ASSERT_FALSE(f.deviation_paper.empty());
  EXPECT_EQ(f.candidates.front().point, f.deviation_paper.front().point);
  EXPECT_NE(f.candidates.front().point, exact.failure->candidates.front().point);
  EXPECT_EQ(f.mesh.vertices.size(), exact.failure->mesh.vertices.size());
  EXPECT_NE(f.reason.find(fmt::format("nearest choice {:.3g} away", f.candidates.front().euclidean)), std::string::npos) << f.reason;
  EXPECT_NE(md.find("choices at this step on the program's mesh as the replay rebuilds it (`ties-kept`)"), std::string::npos) << md;
  // Where the chain would have stopped, the same mesh draws the step (chain_end_failure).
  EXPECT_FALSE(chain_end_failure(r.input, r.trace, options(r.theta), f)) << "a complete chain has no end to draw";
}

// The seeded midpoint mesher without flips (issue 42: "missing-flips from step 3;
// then unknown from step 8"): followed without flips, every run's chain reaches
// the trace's end and names terminal-midpoint; on the exact mesh some end unknown,
// and under the wrong reading (flips decided in double) some stop early.
TEST(ProgramMesh, MissingFlipsFollowedWithoutFlips) {
  int runs = 0, exact_unknown = 0, wrong_reading_stops = 0;
  for (const std::string& in : inputs())
    for (double theta : {20.0, 25.0, 30.0}) {
      const MesherRun r = mesh(in, theta, "--bug terminal-midpoint --bug no-flips");
      ConformanceReport exact = check_conformance(r.input, r.trace, options(theta));
      if (!exact.failure) continue;
      ++runs;
      const std::set<std::string> exact_names = names(*exact.failure);
      exact_unknown += exact_names.count("unknown") > 0;
      ConformanceFailure f = named(r, "missing-flips");
      follow_program_mesh(r.input, r.trace, options(theta), f);
      EXPECT_TRUE(f.chain_complete) << r.name << ": " << chain_text(f.chain) << "; " << f.chain_end;
      EXPECT_TRUE(f.mesh_reading == "no-flips" || f.mesh_reading == "no-flips-but-splits") << f.mesh_reading;
      EXPECT_EQ(f.chain.front().deviation, "missing-flips");
      EXPECT_EQ(names(f).count("unknown"), 0u) << r.name;
      // The seeded rule wherever the exact replay named it; nothing else but the mesh's name
      // (the exact mesh's good-triangle or precision were its own mesh's artifacts).
      if (exact_names.count("terminal-midpoint")) EXPECT_EQ(names(f).count("terminal-midpoint"), 1u) << r.name;
      for (const std::string& n : names(f)) EXPECT_TRUE(n == "missing-flips" || n == "terminal-midpoint") << r.name << " " << n;
      if (getenv("LEPP_PROGRAM_MESH_VERBOSE"))
        std::printf("%s: exact %s; %s%s; program's mesh (%s) %s%s\n", r.name.c_str(), chain_text(exact.failure->chain).c_str(),
                    exact.failure->chain_complete ? "complete" : "stopped: ", exact.failure->chain_end.c_str(),
                    f.mesh_reading.c_str(), chain_text(f.chain).c_str(), f.chain_complete ? " (complete)" : "");
      ConformanceFailure wrong = named(r, "inexact-incircle");
      follow_program_mesh(r.input, r.trace, options(theta), wrong);
      wrong_reading_stops += !wrong.chain_complete;
      // Lost there, the chain ends with a named reason, not an unknown link.
      EXPECT_EQ(names(wrong).count("unknown"), 0u) << r.name;
      if (!wrong.chain_complete) EXPECT_FALSE(wrong.chain_end_reason.empty()) << r.name << ": " << wrong.chain_end;
    }
  EXPECT_GT(runs, 6);
  EXPECT_GT(exact_unknown, 0) << "the exact replay no longer loses this mesher: the test shows nothing";
  EXPECT_GT(wrong_reading_stops, 0);
}


// Flips decided in double (lepp_test_mesher --bug double-flips, with the area
// centroid and Remark 10 reversed beside it): on huge, tiny and subnormal
// coordinates the double in-circle overflows or underflows, the final mesh misses
// flips beyond rounding (missing-flips), and the meshes without flips or with
// flips decided in double follow it; named inexact-incircle, the latter directly.
// Every run's chain reaches the trace's end there (the exact replay's stop at an
// unknown or good-triangle step) with no name but the seeded ones.
TEST(ProgramMesh, FlipsDecidedInDoubleFollowed) {
  int runs = 0, exact_stopped = 0;
  for (const char* in : {"huge-coordinates", "tiny-coordinates", "subnormal-coordinates"})
    for (double theta : {20.0, 25.0, 30.0}) {
      const MesherRun r = mesh(std::string(LEPP_SOURCE_DIR) + "/corpus/hostile/" + in + ".poly", theta,
                               "--bug double-flips --bug area-centroid --bug remark10-reversed");
      ConformanceReport exact = check_conformance(r.input, r.trace, options(theta));
      if (!exact.failure) continue;
      ++runs;
      exact_stopped += !exact.failure->chain_complete;
      for (const char* name : {"missing-flips", "inexact-incircle"}) {
        ConformanceFailure f = named(r, name);
        follow_program_mesh(r.input, r.trace, options(theta), f);
        EXPECT_TRUE(f.chain_complete) << r.name << " " << name << ": " << chain_text(f.chain) << "; " << f.chain_end;
        // Named missing-flips, a mesh without any flip follows as far (the overflowed
        // test flips nothing): the first reading tried is kept on a tie.
        if (std::string(name) == "inexact-incircle") EXPECT_EQ(f.mesh_reading, "double-incircle") << r.name;
        else EXPECT_TRUE(f.mesh_reading == "no-flips" || f.mesh_reading == "double-incircle") << r.name << " " << f.mesh_reading;
        EXPECT_EQ(names(f).count("unknown"), 0u) << r.name;
        if (names(*exact.failure).count("area-centroid")) EXPECT_EQ(names(f).count("area-centroid"), 1u) << r.name;
        for (const std::string& n : names(f))
          EXPECT_TRUE(n == name || n == "area-centroid" || n == "remark10-reversed" || n == "remark10-ignored") << r.name << " " << n;
        if (getenv("LEPP_PROGRAM_MESH_VERBOSE"))
          std::printf("%s: exact %s%s; program's mesh (%s) %s%s\n", r.name.c_str(), chain_text(exact.failure->chain).c_str(),
                      exact.failure->chain_complete ? " (complete)" : "", f.mesh_reading.c_str(), chain_text(f.chain).c_str(),
                      f.chain_complete ? " (complete)" : "");
      }
    }
  EXPECT_GE(runs, 6);
  EXPECT_GT(exact_stopped, 0) << "the exact replay no longer loses this mesher: the test shows nothing";
}

// A program that holds floats (--bug single-precision): its points are the
// choices at float rounding; followed with the float tolerance and each point
// kept where the program computed it, the chain reaches the trace's end with no
// other name. On the exact mesh it stops at the first step.
TEST(ProgramMesh, SinglePrecisionFollowedAtFloatRounding) {
  int runs = 0;
  for (const std::string& in : inputs())
    for (double theta : {20.0, 30.0}) {
      const MesherRun r = mesh(in, theta, "--bug single-precision");
      ConformanceReport exact = check_conformance(r.input, r.trace, options(theta));
      if (!exact.failure) continue;
      ++runs;
      EXPECT_FALSE(exact.failure->chain_complete && exact.failure->chain.size() == 1 &&
                   exact.failure->chain.front().deviation == "single-precision");
      ConformanceFailure f = named(r, "single-precision");
      follow_program_mesh(r.input, r.trace, options(theta), f);
      EXPECT_TRUE(f.chain_complete) << r.name << ": " << chain_text(f.chain) << "; " << f.chain_end;
      EXPECT_EQ(f.mesh_reading, "float-points");
      EXPECT_EQ(names(f), std::set<std::string>{"single-precision"}) << r.name << ": " << chain_text(f.chain);
    }
  EXPECT_GE(runs, 4);
}

// A program that reads its input as float meshes another input: on its rounding,
// the chain of the float-input mesher reaches the trace's end with that one name.
// Where the rounding makes two input vertices one, there is no such mesh: the
// replay says so, and the chain stays as the exact replay found it.
TEST(ProgramMesh, FloatInputFollowedOnTheInputAtFloatRounding) {
  const MesherRun r = mesh(std::string(LEPP_SOURCE_DIR) + "/audit/tests/mesher/arithmetic/poly2tri-polygon-01.poly", 25,
                           "--bug float-input");
  ConformanceFailure f = named(r, "float-input");
  EXPECT_FALSE(f.chain_complete) << chain_text(f.chain);  // the exact input's replay cannot follow it
  follow_program_mesh(r.input, r.trace, options(r.theta), f);
  EXPECT_TRUE(f.chain_complete) << chain_text(f.chain) << "; " << f.chain_end;
  EXPECT_EQ(f.mesh_reading, "float-input");
  EXPECT_EQ(names(f), std::set<std::string>{"float-input"}) << chain_text(f.chain);
  // The step's table stays the exact input's (how far the float rounding put the
  // point from the paper's choice there), and says so.
  EXPECT_EQ(f.step_mesh_reading, "");
  ConformanceReport followed;
  followed.steps = r.trace.size();
  followed.failure = f;
  const std::string md = diagnosis_markdown(conformance_diagnosis(followed, r.theta, false));
  EXPECT_NE(md.find("choices at this step on the exact mesh (Euclidean distances)"), std::string::npos) << md;

  Pslg merged = r.input;
  merged.vertices.push_back({merged.vertices[0].x * (1 + 0x1p-40), merged.vertices[0].y});
  ReplayRules rules;
  rules.min_angle_deg = 25;
  rules.mesh = MeshReading::FloatInput;
  // Said by the rounding's own check, naming the two vertices, not by whatever a
  // triangulation with one point twice would do further on.
  try {
    Replay replay(merged, rules);
    ADD_FAILURE() << "a replay of an input whose float rounding merges two vertices";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(fmt::format("input vertices 0 and {} are one point", merged.vertices.size() - 1)),
              std::string::npos)
        << e.what();
  }
  ConformanceFailure g = named(r, "float-input");
  const std::string before = chain_text(g.chain);
  follow_program_mesh(merged, r.trace, options(r.theta), g);
  EXPECT_EQ(chain_text(g.chain), before);
  EXPECT_EQ(g.mesh_reading, "");
}

// A double program's final mesh can be Delaunay again (later insertions flipped a
// near tie back) and name nothing: on corpus/hostile/near-touching at 20 degrees
// the exact chain of the double-flips mesher ends at a step no rule fits; the mesh
// with flips decided in double takes it to the trace's end with the seeded names.
TEST(ProgramMesh, ChainLostOnTheExactMeshFollowedWithFlipsDecidedInDouble) {
  const MesherRun r = mesh(std::string(LEPP_SOURCE_DIR) + "/corpus/hostile/near-touching.poly", 20,
                           "--bug double-flips --bug area-centroid --bug remark10-reversed");
  ConformanceReport exact = check_conformance(r.input, r.trace, options(r.theta));
  ASSERT_TRUE(exact.failure);
  ConformanceFailure f = *exact.failure;
  EXPECT_EQ(f.chain_end_reason, "no-rule") << chain_text(f.chain) << "; " << f.chain_end;
  EXPECT_EQ(names(f).count("unknown"), 1u) << chain_text(f.chain);
  follow_program_mesh(r.input, r.trace, options(r.theta), f);
  EXPECT_TRUE(f.chain_complete) << chain_text(f.chain) << "; " << f.chain_end;
  EXPECT_EQ(f.mesh_reading, "double-incircle");
  // The flips decided in double named where the exact mesh lost the chain.
  EXPECT_EQ(names(f), (std::set<std::string>{"inexact-incircle", "remark10-reversed", "area-centroid"})) << chain_text(f.chain);
  for (const DeviationLink& l : f.chain)
    if (l.deviation == "inexact-incircle") EXPECT_EQ(l.first_step, exact.failure->chain_end_step);
  // The mesher with flips decided in double alone: every step is the paper's choice
  // on the mesh with flips decided in double, and its chain is that mesh's name
  // alone, from the step the exact mesh lost; that step's picture and choices stay
  // the exact mesh's, where it is none.
  const MesherRun alone = mesh(std::string(LEPP_SOURCE_DIR) + "/corpus/hostile/near-touching.poly", 20, "--bug double-flips");
  ConformanceReport exact_alone = check_conformance(alone.input, alone.trace, options(alone.theta));
  ASSERT_TRUE(exact_alone.failure);
  ConformanceFailure g = *exact_alone.failure;
  follow_program_mesh(alone.input, alone.trace, options(alone.theta), g);
  EXPECT_TRUE(g.mesh_reading_fallback) << g.mesh_reading << ": " << chain_text(g.chain);
  EXPECT_EQ(g.deviation, "inexact-incircle") << chain_text(g.chain);
  EXPECT_EQ(names(g), std::set<std::string>{"inexact-incircle"}) << chain_text(g.chain);
  EXPECT_EQ(g.chain.front().first_step, exact_alone.failure->step + 1) << chain_text(g.chain);
  EXPECT_TRUE(g.chain_complete) << chain_text(g.chain) << "; " << g.chain_end;
  EXPECT_EQ(g.step_mesh_reading, "") << chain_text(g.chain);
  EXPECT_EQ(g.reason, exact_alone.failure->reason);
}

}  // namespace
}  // namespace lepp::audit
