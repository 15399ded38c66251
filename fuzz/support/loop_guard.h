// SPDX-License-Identifier: GPL-3.0-or-later
// What counts as a loop in a fuzzed refinement, and what kind of loop it is.
//
// A run is a loop when it needs more Steiner points than the input's size and
// local feature size justify, or makes an edge far shorter than the input's
// shortest feature. Both bounds come from the good-grading argument: a
// terminating quality mesher adds O(area / lfs_min^2) points and keeps edges
// above a constant fraction of lfs_min.
#pragma once
#include <cstdint>
#include <string>

#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::fuzz {

struct InputFeatures {
  double lfs_min = 0;              // shortest distance between disjoint features (vertex-vertex, vertex-segment)
  double bbox_area = 0;
  double min_input_angle_deg = 180;  // smallest angle between two segments sharing a vertex
};
InputFeatures input_features(const Pslg& pslg);

struct LoopGuard {
  std::int64_t steiner_budget = 0;
  double edge_floor = 0;
};
// budget = 64 * (vertices + segments) + 16 * bbox_area / lfs_min^2, capped at
// `cap`; floor = lfs_min / 1024.
LoopGuard loop_guard(const Pslg& pslg, std::int64_t cap);

// alpha_limit of Section 3: the midpoint method's special loop needs theta above it.
double alpha_limit_deg();

// The class of a loop (a run that stopped on the guard), from the input, the
// options and a traced re-run's result:
//  - "small-angle-cascade": the mesh's shortest edge sits at an input vertex
//    where two segments meet at less than 60 degrees;
//  - "midpoint-special-loop": midpoint method, theta > alpha_limit, and the
//    last bad triangles processed repeat one shape at shrinking sizes
//    (Section 3's self-similar triangle M A M1);
//  - "self-similar-loop": the same repetition with the centroid method or
//    theta <= alpha_limit (Theorem 14 says the centroid method has none);
//  - "other".
std::string classify_loop(const Pslg& pslg, const RefineOptions& options, const RefineResult& traced);

// The theta band a finding belongs to, for the findings table.
const char* theta_band(double theta_deg);

}  // namespace lepp::fuzz
