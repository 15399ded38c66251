// SPDX-License-Identifier: GPL-3.0-or-later
// A step that fits no rule of the catalogue is named `unknown` with the rules whose
// points came nearest, each with its distance and how many of its tolerances that is
// (issue 42: a reader can see which rule to widen or what to add). The numbers are
// checked against the rule's point computed apart. Kills audit-unknown-no-nearest-rules
// and audit-unknown-nearest-unsorted.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "lepp/audit/replay.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

using audit::Deviation;
using audit::Replay;
using audit::ReplayRules;

// O = (0, 0), A = (1, 0), B = (0.99, 0.1): a 5.8-degree sliver, bad at 20, whose
// longest edge O-A is a boundary segment: the paper's choice is its midpoint (0.5, 0).
Pslg sliver() {
  Pslg p;
  p.vertices = {{0, 0}, {1, 0}, {0.99, 0.1}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

TEST(UnknownNearestRules, NamedWithTheirDistancesNearestFirst) {
  ReplayRules rules;
  rules.min_angle_deg = 20;
  rules.angle_tolerance_deg = 0;
  Replay replay(sliver(), rules);
  // 0.01 above the paper's choice: no rule's point (within a thousand tolerances it
  // would be `precision`). The circumcenter of OAB, (0.5, 0.0005), is nearer in
  // distance (0.0095), but its tolerance is a thousand times smaller: the list is
  // ordered by tolerances.
  const Point p{0.5, 0.01};
  const audit::DeviationMatch m = replay.diagnose(p);
  ASSERT_EQ(m.deviation, Deviation::Unknown) << m.what;
  const std::string& w = m.what;
  const std::size_t at = w.find("; nearest rules: ");
  ASSERT_NE(at, std::string::npos) << w;
  // The paper's choice moved is the nearest in tolerances: `precision`, 0.01 away
  // (its tolerance is a thousand point tolerances, so about 6e9 of them); then the
  // circumcenter, 0.0095 away.
  EXPECT_EQ(w.find("; nearest rules: precision 0.01 away ("), at) << w;
  EXPECT_NE(w.find(", circumcenter 0.0095 away ("), std::string::npos) << w;
  // At most three, each "NAME D away (R tolerances)", the ratios ascending.
  std::vector<double> ratios;
  for (std::size_t i = w.find(" away (", at); i != std::string::npos; i = w.find(" away (", i + 1))
    ratios.push_back(std::stod(w.substr(i + 7)));
  ASSERT_GE(ratios.size(), 2u) << w;
  EXPECT_LE(ratios.size(), 3u) << w;
  for (std::size_t i = 1; i < ratios.size(); ++i) EXPECT_LE(ratios[i - 1], ratios[i]) << w;
  // A point a rule names has no such list.
  const audit::DeviationMatch named = replay.diagnose({0.5 + 1e-13, 0});
  EXPECT_EQ(named.deviation, Deviation::Precision) << named.what;
  EXPECT_EQ(named.what.find("nearest rules"), std::string::npos) << named.what;
}

}  // namespace
}  // namespace lepp
