// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's choice at a terminal pair as one table (Select Point, New Select
// Point, Remark 10): which points, in which order, under which condition. The
// one definition the reference engine's Select Point (select_point.cpp) and the
// replay of other meshers' traces (audit/src/replay/paper_points.cpp) share.
//
// Why sharing it weakens no test: the reference engine is the fast engine's
// oracle, and the fast engine's Select Point (impl/) stays its own code, so a
// wrong row here still makes the two engines differ (the differential tests)
// and makes the fast engine's and the test mesher's traces fail the replay
// (the replay's tests). Only the table is shared: each side evaluates it on
// its own geometry and its own edge order. The engine computes the double
// formula and tests Remark 10 strictly, with ties broken by vertex ids; the
// replay computes the exact rational points, branches on every tie and allows
// both branches of Remark 10 within its point tolerance.
#pragma once
#include <array>

#include "lepp/refine.h"

namespace lepp::reference::detail {

// Where a point of the table lies.
enum class PaperPoint {
  TerminalEdgeMidpoint,   // the midpoint of the terminal edge
  SecondLongestMidpoint,  // the midpoint of the second-longest edge of PaperOption::triangle
  QuadCentroid,           // the centroid of the terminal quad
};

// When a point is the choice: always, or by Remark 10 as the quad centroid lies
// (strictly) inside the terminal triangle other than PaperOption::triangle.
enum class PaperCondition { Always, CentroidInsideOther, CentroidNotInsideOther };

struct PaperOption {
  Rule rule = Rule::QuadCentroid;
  PaperPoint point = PaperPoint::QuadCentroid;
  int triangle = 1;  // 1: t1, 2: t2; whose second-longest edge (Remark 10: the triangle t* with the constrained one)
  PaperCondition when = PaperCondition::Always;
};

// At most two rows apply to a configuration; room for three.
struct PaperOptions {
  std::array<PaperOption, 3> option;
  int count = 0;
  const PaperOption* begin() const { return option.data(); }
  const PaperOption* end() const { return option.data() + count; }
};

// The rows for a terminal pair: has_t2 false for a constrained terminal edge;
// c1, c2: the second-longest edges of t1, t2 (as the caller's edge order
// chose them) are constrained. In the engine's order: Select Point takes the
// first whose condition holds; the replay allows every one whose condition may.
inline PaperOptions paper_options(Method method, bool has_t2, bool c1, bool c2) {
  using P = PaperPoint;
  using W = PaperCondition;
  PaperOptions o;
  auto add = [&o](Rule rule, P point, int triangle, W when) { o.option[static_cast<std::size_t>(o.count++)] = {rule, point, triangle, when}; };
  if (!has_t2) {
    add(Rule::TerminalConstrainedMidpoint, P::TerminalEdgeMidpoint, 1, W::Always);
    return o;
  }
  if (method == Method::Midpoint) {
    // Select Point: a constrained second-longest edge (either when both are: t1's
    // first), else the terminal edge.
    if (c1) add(Rule::SecondLongestMidpoint, P::SecondLongestMidpoint, 1, W::Always);
    if (c2) add(Rule::SecondLongestMidpoint, P::SecondLongestMidpoint, 2, W::Always);
    if (!c1 && !c2) add(Rule::TerminalMidpoint, P::TerminalEdgeMidpoint, 1, W::Always);
    return o;
  }
  // New Select Point.
  if (!c1 && !c2) {
    add(Rule::QuadCentroid, P::QuadCentroid, 1, W::Always);
  } else if (c1 && c2) {
    // The paper leaves either constrained edge; the engine splits t1's first.
    add(Rule::BothSecondLongestMidpoint, P::SecondLongestMidpoint, 1, W::Always);
    add(Rule::BothSecondLongestMidpoint, P::SecondLongestMidpoint, 2, W::Always);
  } else {
    // Remark 10: exactly one, t*, has a constrained second-longest edge: the
    // centroid if it is inside the other triangle, else the midpoint of t*'s edge.
    const int star = c1 ? 1 : 2;
    add(Rule::CentroidInOther, P::QuadCentroid, star, W::CentroidInsideOther);
    add(Rule::SecondLongestMidpoint, P::SecondLongestMidpoint, star, W::CentroidNotInsideOther);
  }
  return o;
}

}  // namespace lepp::reference::detail
