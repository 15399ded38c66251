// SPDX-License-Identifier: GPL-3.0-or-later
// The conformance replay at the boundaries of its rules (issue 22): the
// midpoint method's rule when one second-longest edge is constrained, and the
// length prefilter's error margin at two exactly equal lengths whose doubles
// round apart. Each test names the mutants of tools/mutation/mutants.txt it kills.
#include <gtest/gtest.h>

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "lepp/input.h"
#include "lepp/validate.h"
#include "lepp/audit/replay.h"

namespace lepp {
namespace {

using audit::Replay;
using audit::ReplayChoice;
using audit::ReplayRules;

Pslg validated(Pslg p) {
  std::vector<std::string> warnings;
  return validate(p, warnings);
}

// P=(0,0), U=(5,-9), R=(10,0), S=(4,5) bound the domain; Q=(5,-5) is an input
// vertex inside. The CDT: PRS, PQR, PUQ, QUR. P-R (10) is the longest edge of
// PRS and of PQR (opposite angles 88.9 and 90 degrees: Delaunay), so it is the
// terminal edge of PRS's Lepp; PRS is bad at 42 degrees (39.8 at R). The
// second-longest edge of PRS is R-S (7.81 against P-S 6.40), a boundary
// segment; PQR's are P-Q and Q-R (7.07 each, a tie), both unconstrained.
// Select Point (the midpoint method) then splits R-S: its midpoint (7, 2.5)
// is the choice, the terminal edge's midpoint (5, 0) is not.
// Kills ref-replay-midpoint-terminal-when-constrained (the terminal midpoint
// accepted when only one second-longest edge is constrained) and, in the
// variants where the replay meets PQR first (as t1),
// ref-replay-midpoint-t2-constrained-ignored.
struct Variant {
  const char* what;
  double sx, sy;       // a reflection
  bool reversed;       // the input's vertices listed in reverse
};

Pslg quad_with_inner_vertex(const Variant& v) {
  std::vector<Point> pts = {{0, 0}, {5, -9}, {10, 0}, {4, 5}, {5, -5}};
  for (Point& p : pts) p = {v.sx * p.x, v.sy * p.y};
  Pslg p;
  p.vertices = pts;
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}};
  if (v.reversed) {
    std::reverse(p.vertices.begin(), p.vertices.end());
    for (Segment& s : p.segments) s.a = 4 - s.a, s.b = 4 - s.b;
  }
  return validated(p);
}

TEST(ReplayBoundary, MidpointMethodSplitsTheConstrainedSecondLongestEdge) {
  const std::vector<Variant> variants = {{"as is", 1, 1, false},   {"mirrored in x", -1, 1, false},
                                         {"mirrored in y", 1, -1, false}, {"turned 180 degrees", -1, -1, false},
                                         {"reversed", 1, 1, true},  {"reversed, mirrored in x", -1, 1, true},
                                         {"reversed, mirrored in y", 1, -1, true}, {"reversed, turned", -1, -1, true}};
  for (const Variant& v : variants) {
    ReplayRules rules;
    rules.method = Method::Midpoint;
    rules.min_angle_deg = 42;
    rules.angle_tolerance_deg = 0;
    const Pslg p = quad_with_inner_vertex(v);
    {
      Replay replay(p, rules);
      ReplayChoice c;
      EXPECT_FALSE(replay.match({v.sx * 5, v.sy * 0}, c))
          << v.what << ": the terminal edge's midpoint is accepted (rule " << static_cast<int>(c.rule) << ")";
    }
    {
      Replay replay(p, rules);
      ReplayChoice c;
      ASSERT_TRUE(replay.match({v.sx * 7, v.sy * 2.5}, c)) << v.what << ": the midpoint of R-S is the choice";
      EXPECT_EQ(c.rule, Rule::SecondLongestMidpoint) << v.what;
    }
  }
  // With neither second-longest edge constrained (a second inner vertex
  // (5, 5.2) above P-R, the boundary moved to (5, 9)) the midpoint method
  // takes the terminal edge's midpoint: the rejection above is the constraint's doing.
  Pslg open;
  open.vertices = {{0, 0}, {5, -9}, {10, 0}, {5, 9}, {5, -5}, {5, 5.2}};
  open.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}, {3, 0, 0}};
  ReplayRules rules;
  rules.method = Method::Midpoint;
  rules.min_angle_deg = 50;  // PQR (45, 45, 90) and P(5,5.2)R (46.1, 46.1, 87.7) are bad
  rules.angle_tolerance_deg = 0;
  Replay replay(validated(open), rules);
  ReplayChoice c;
  ASSERT_TRUE(replay.match({5, 0}, c));
  EXPECT_EQ(c.rule, Rule::TerminalMidpoint);
}

// O=(0.5,0.5), A and B below: |OA|^2 = |OB|^2 exactly (half-integers; the
// identity (x+y)^2 + (x-y)^2 = 2(x^2 + y^2) on two representations of one
// sum of two squares), but the doubles dx*dx + dy*dy differ by 1.41
// DBL_EPSILON times the larger: a tie the prefilter must leave to the exact
// comparison. The triangle OAB has a 5.44-degree angle at O: bad; its longest
// edges O-A and O-B are both boundary segments, so both midpoints are choices.
// Kills ref-replay-prefilter-no-margin (any difference of the doubles decides)
// and ref-replay-prefilter-margin-small (a margin of one DBL_EPSILON).
TEST(ReplayBoundary, EqualLengthsThatRoundApartAreATie) {
  const Point O{0.5, 0.5}, A{751852102252769, 577309298774756}, B{803192428145750, 503437715594534};
  // The premises, checked: exactly equal, rounded apart by more than one DBL_EPSILON.
  auto exact = [&](const Point& P) {
    const __int128 dx = static_cast<__int128>(2 * P.x) - 1, dy = static_cast<__int128>(2 * P.y) - 1;
    return dx * dx + dy * dy;
  };
  ASSERT_TRUE(exact(A) == exact(B));
  const double la = (A.x - O.x) * (A.x - O.x) + (A.y - O.y) * (A.y - O.y);
  const double lb = (B.x - O.x) * (B.x - O.x) + (B.y - O.y) * (B.y - O.y);
  ASSERT_GT(std::abs(la - lb), DBL_EPSILON * std::max(la, lb));
  ASSERT_LT(std::abs(la - lb), 16 * DBL_EPSILON * std::max(la, lb));

  Pslg p;
  p.vertices = {O, A, B};
  p.segments = {{0, 1, 0}, {1, 2, 0}, {2, 0, 0}};
  const Pslg v = validated(p);
  ReplayRules rules;
  rules.method = Method::Centroid;
  rules.min_angle_deg = 20;
  for (const Point& end : {A, B}) {
    Replay replay(v, rules);
    ReplayChoice c;
    const Point mid{(O.x + end.x) / 2, (O.y + end.y) / 2};
    ASSERT_TRUE(replay.match(mid, c)) << "the midpoint of O-(" << end.x << ", " << end.y << ") is a choice";
    EXPECT_EQ(c.rule, Rule::TerminalConstrainedMidpoint);
    EXPECT_EQ(c.distance, 0);
  }
}

}  // namespace
}  // namespace lepp
