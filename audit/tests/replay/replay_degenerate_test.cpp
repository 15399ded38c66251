// SPDX-License-Identifier: GPL-3.0-or-later
// The conformance replay on degenerate output and options (issue 30): a
// program's recorded run whose deviation diagnosis used to end the audit with
// SIGFPE (a flat triangle in the replay's mesh after a point that could not be
// inserted, whose circumcenter the catalogue computed), a circumcenter beyond
// the doubles, and rules that cannot be exact numbers.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "lepp/audit/judge/conformance.h"
#include "lepp/io.h"
#include "lepp/audit/replay.h"
#include "lepp/trace_io.h"
#include "lepp/validate.h"

namespace {

using lepp::Point;
using lepp::audit::Deviation;
using lepp::audit::Replay;
using lepp::audit::ReplayRules;

const std::string kRecorded = std::string(LEPP_SOURCE_DIR) + "/audit/tests/inputs/audit-fpe/";

lepp::Pslg valid(const lepp::Pslg& p) {
  std::vector<std::string> warnings;
  return lepp::validate(p, warnings);
}

// The recorded run (a mesher with a deliberate point-choice bug, on a triangle):
// the replay stops at a point that is a choice but cannot be inserted, and the
// diagnosis of that step walked the mesh the failed insertion left, with a flat
// triangle. Now a named (or unknown) deviation, on the mesh before the step.
TEST(ReplayDegenerate, RecordedRunIsDiagnosedNotASignal) {
  const lepp::Pslg pslg = valid(lepp::read_poly(kRecorded + "tri.poly"));
  const std::vector<Point> trace = lepp::read_trace(kRecorded + "rec.trace");
  ASSERT_GT(trace.size(), 100u);
  std::set<std::string> names;
  for (int k = 0; k < lepp::audit::kDeviations; ++k) names.insert(lepp::audit::to_string(static_cast<Deviation>(k)));
  int not_insertable = 0;
  for (double theta : {20.0, 25.0, 30.0}) {
    lepp::audit::ConformanceOptions o;
    o.min_angle_deg = theta;
    const lepp::audit::ConformanceReport r = lepp::audit::check_conformance(pslg, trace, o);
    ASSERT_FALSE(r.conforms) << theta;
    ASSERT_TRUE(r.failure);
    EXPECT_TRUE(names.count(r.failure->deviation)) << r.failure->deviation;
    EXPECT_FALSE(r.failure->reason.empty());
    // The point is a choice the replay cannot insert; its insertion stopped half
    // way, so the report's mesh is the one just before the step, replayed again:
    // one vertex per input vertex and earlier step, the failed point not among them.
    if (r.failure->reason.find("cannot be inserted") == std::string::npos) continue;
    ++not_insertable;
    EXPECT_EQ(r.failure->mesh.vertices.size(), pslg.vertices.size() + r.failure->step);
    for (const Point& v : r.failure->mesh.vertices) EXPECT_FALSE(v == r.failure->point);
  }
  EXPECT_GT(not_insertable, 0);  // the path of issue 30 is taken
}

// A triangle so flat at huge coordinates that its circumcenter is beyond the
// largest double: its scale, and so its tolerance, would be infinite and every
// point the catalogue is asked about would be named "circumcenter" (and its
// rounding for the report made an infinity into a rational: SIGFPE).
TEST(ReplayDegenerate, ACircumcenterBeyondTheDoublesMatchesNothing) {
  lepp::Pslg p;
  p.vertices = {{-1e200, 0}, {1e200, 0}, {0, 1e-200}};
  p.segments = {{0, 1}, {1, 2}, {2, 0}};
  ReplayRules rules;
  rules.min_angle_deg = 20;
  Replay replay(valid(p), rules);
  // Far from every other rule's point (their tolerance is about 1e185 here).
  const Point far{5e199, 3e199};
  lepp::audit::ReplayChoice choice;
  EXPECT_FALSE(replay.match(far, choice));
  EXPECT_EQ(replay.diagnose(far).deviation, Deviation::Unknown);
}

// Rules become exact numbers: a tolerance or an angle that is not a finite
// number is refused when the replay is made, not met inside a step.
TEST(ReplayDegenerate, RulesThatAreNotNumbersAreRefused) {
  lepp::Pslg p;
  p.vertices = {{0, 0}, {4, 0}, {4, 1}, {0, 1}};
  p.segments = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  const lepp::Pslg pslg = valid(p);
  ReplayRules rules;
  rules.min_angle_deg = 25;
  for (double bad : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    ReplayRules r = rules;
    r.point_tolerance_ulps = bad;
    EXPECT_THROW(Replay(pslg, r), std::invalid_argument);
    r = rules;
    r.angle_tolerance_deg = bad;
    EXPECT_THROW(Replay(pslg, r), std::invalid_argument);
  }
  ReplayRules r = rules;
  r.min_angle_deg = std::nan("");
  EXPECT_THROW(Replay(pslg, r), std::invalid_argument);

}

}  // namespace
