// SPDX-License-Identifier: GPL-3.0-or-later
// The small input angles of a PSLG and their regions of influence: the input side of
// the small-input-angle exemption rule (docs/CERTIFIER.md, "Small input angles: the
// exemption rule for any mesher"). Computed from the input alone, exactly.
#pragma once
#include <vector>

#include "lepp/pslg.h"

namespace lepp::certify {

// Two segments with the common endpoint `apex` whose wedge (counter-clockwise from
// segment1 to segment2) lies in the domain and measures less than 60 degrees: adjacent
// segments, or a cluster of them (every segment in between makes a smaller wedge).
// Its arms are the two segments; its disk is the closed disk around apex whose radius
// is the length of the shorter segment (apex to `near_end`).
struct SmallInputAngle {
  int apex = -1;                    // input vertex id
  int segment1 = -1, segment2 = -1;  // input segment ids; segment2 follows segment1 counter-clockwise
  int end1 = -1, end2 = -1;          // their other endpoints (input vertex ids)
  int near_end = -1;                 // end1 or end2, whichever is nearer apex (end1 on a tie)
  double angle_deg = 0;              // for display only
  double radius = 0;                 // |apex - near_end|, for display only
};

// Every small input angle of a validated PSLG (lepp::validate), sorted by apex, then
// segment1. Decided exactly: the wedge is below 60 degrees iff, with u, w the vectors
// from apex to end1 and end2, cross(u, w) > 0, dot(u, w) > 0 and
// 4 cross(u, w)^2 < 3 |u|^2 |w|^2 (sin^2 60 = 3/4).
std::vector<SmallInputAngle> small_input_angles(const Pslg& validated);

}  // namespace lepp::certify
