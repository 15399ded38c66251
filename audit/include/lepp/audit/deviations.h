// SPDX-License-Identifier: GPL-3.0-or-later
// The deviation catalogue's vocabulary (docs/CONFORMANCE.md, "Deviations"): the
// other rules a Lepp implementation plausibly follows, their names, their
// definitions and the line that says where one matched.
#pragma once
#include <array>
#include <string>

#include "lepp/mesh.h"

namespace lepp::audit {

// Each rule is computed exactly like the paper's choices on the same mesh and
// matched with the same tolerance (the replay, lepp/audit/replay.h). The order
// is the order they are tried in: the first that matches names it.
enum class Deviation {
  AreaCentroid,         // the terminal quad's area centroid (vertex reading)
  VertexCentroid,       // the vertex average (declared area reading)
  TriangleCentroid,     // the centroid of one terminal triangle
  TerminalMidpoint,     // the terminal edge's midpoint where the paper chooses otherwise
  CentroidNotMidpoint,  // the quad centroid where the paper asks for a midpoint (not Remark 10's case)
  // Before Remark10Reversed: a centroid outside the other triangle is both
  // programs' point; only a midpoint where the centroid is inside tells
  // reversed (the conformance check merges the two then: docs/CONFORMANCE.md).
  Remark10Ignored,      // the quad centroid wherever exactly one second-longest edge is constrained
  Remark10Reversed,     // Remark 10 the wrong way round
  OtherSecondLongest,   // the midpoint of another edge of a terminal triangle
  Circumcenter,         // the bad triangle's circumcenter
  OffCenter,            // the bad triangle's off-center (Ungor)
  // The paper's choice for the Lepp of a triangle that is not bad but whose
  // smallest angle alpha is within double rounding of theta (sin^2 alpha below
  // the certified sin^2 theta's upper end + 16 DBL_EPSILON, exactly): a double
  // program's threshold. Before GoodTriangle: it is the narrower explanation.
  InexactThreshold,
  GoodTriangle,         // the paper's choice for the Lepp of a triangle that is not bad
  // The paper's choice for a Lepp reached by taking length comparisons the
  // other way where the exact squared lengths differ by no more than a double
  // computation of them may err (8 DBL_EPSILON relative): a double program's ties.
  InexactLength,
  Precision,            // within 1000 times the tolerance of a paper choice
  Unknown,              // none of these
};
constexpr int kDeviations = 15;
const char* to_string(Deviation deviation);   // "area-centroid", ..., "unknown"
const char* definition(Deviation deviation);  // one sentence, as in docs/CONFORMANCE.md

// The deviations that are a whole rule set (ReplayRules::variant): a variant of
// the algorithm with the catalogue rule put in place of the paper's where it applies.
bool has_variant(Deviation deviation);

// One line: which point of which configuration a match of deviation is, at
// terminal edge `edge` of the Lepp of triangle `lepp_start` (bad, or good for
// GoodTriangle and InexactThreshold; for Circumcenter and OffCenter, the bad triangle).
std::string match_text(Deviation deviation, const std::array<int, 2>& edge, const Tri& lepp_start);

}  // namespace lepp::audit
