// SPDX-License-Identifier: GPL-3.0-or-later
// inexact-length at the end of its band (issue 42; audit/src/replay/tie_order.h):
// two squared lengths within 8 DBL_EPSILON of each other (relative, exactly) count
// as a tie when the variant is allowed, and one double further they do not. (The
// diagnosis of that midpoint is other-second-longest on both sides, a catalogue
// rule ranked before inexact-length.) Each test names the mutants of
// tools/mutation/mutants.txt it kills.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <string>
#include <vector>

#include <CGAL/Gmpq.h>

#include "lepp/audit/replay.h"
#include "lepp/validate.h"

namespace lepp {
namespace {

using audit::Deviation;
using audit::Replay;
using audit::ReplayChoice;
using audit::ReplayRules;

// O = (0, 0), A = (1, 0), B = (x, 0.1): |OA|^2 = 1 and |OB|^2 = x^2 + 0.01 a little
// more. The triangle has a 5.7-degree angle at O (bad at 20); O-A and O-B are
// boundary segments, so the choice is the midpoint of the longest: O-B exactly,
// and O-A's (0.5, 0) too once the two lengths count as a tie.
Pslg sliver(double x) {
  Pslg p;
  p.vertices = {{0, 0}, {1, 0}, {x, 0.1}};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

// (|OB|^2 - |OA|^2) / |OB|^2 in units of DBL_EPSILON, exactly (then rounded for the message).
double relative_gap(double x) {
  const CGAL::Gmpq b = CGAL::Gmpq(x) * CGAL::Gmpq(x) + CGAL::Gmpq(0.1) * CGAL::Gmpq(0.1);
  return CGAL::to_double((b - 1) / b / CGAL::Gmpq(DBL_EPSILON));
}

// The last double x whose gap is within 8 DBL_EPSILON, and the next one.
constexpr double kInside = 0.9949874371066207;   // 7.06 DBL_EPSILON
constexpr double kOutside = 0.9949874371066209;  // 8.06 DBL_EPSILON

TEST(InexactLengthBoundary, ThePremises) {
  ASSERT_EQ(std::nextafter(kInside, 2.0), kOutside);
  EXPECT_GT(relative_gap(kInside), 0);
  EXPECT_LE(relative_gap(kInside), 8);
  EXPECT_GT(relative_gap(kOutside), 8);
  // Both within the length prefilter's 16 DBL_EPSILON: decided exactly, not by the doubles.
  EXPECT_LT(relative_gap(kOutside), 16);
}

ReplayRules rules() {
  ReplayRules r;
  r.min_angle_deg = 20;
  r.angle_tolerance_deg = 0;
  return r;
}

// Kills audit-inexact-length-band-half (4 DBL_EPSILON: the first no tie) and
// audit-inexact-length-band-double (16: the second a tie).
TEST(InexactLengthBoundary, WithinEightEpsilonATieBeyondNot) {
  const Point shorter_midpoint{0.5, 0};
  for (const double x : {kInside, kOutside}) {
    SCOPED_TRACE("x = " + std::to_string(relative_gap(x)) + " DBL_EPSILON apart");
    const Pslg p = sliver(x);
    {  // Exactly, O-B is the longest: only its midpoint.
      Replay replay(p, rules());
      ReplayChoice c;
      EXPECT_FALSE(replay.match(shorter_midpoint, c));
      EXPECT_TRUE(replay.match({x / 2, 0.05}, c));
    }
    {  // Under the double reading (the variant allowed): a tie inside the band only.
      Replay replay(p, rules());
      replay.allow(Deviation::InexactLength);
      ReplayChoice c;
      EXPECT_EQ(replay.match(shorter_midpoint, c), x == kInside);
      if (x == kInside) EXPECT_EQ(c.deviation, Deviation::InexactLength);
    }
  }
}

}  // namespace
}  // namespace lepp
