// SPDX-License-Identifier: GPL-3.0-or-later
// CGAL's own quality mesher (CGAL::refine_Delaunay_mesh_2), wrapped for comparisons.
#pragma once
#include <cstdint>

#include "lepp/mesh.h"
#include "lepp/pslg.h"

namespace lepp::others {

struct CgalMeshResult {
  Mesh mesh;                  // domain triangles only, input vertices first
  std::int64_t steiner_points = 0;
  double seconds = 0;         // meshing time (CDT build + refinement)
  bool finished = false;      // false: stopped by the point budget or the time limit
};

// Limits of one run: CGAL's refinement is only proven to stop up to about 20.7
// degrees, so a comparison run above that needs a guard. 0 or less: no limit.
struct CgalMeshLimits {
  std::int64_t max_steiner = 0;
  double time_limit_seconds = 0;
};

// Builds the CDT of a validated PSLG (points inserted in bulk), marks holes as
// seeds, and refines with Delaunay_mesh_size_criteria_2(B = sin^2(theta),
// max_edge_size; 0 = no size bound), the step-by-step loop of
// CGAL::refine_Delaunay_mesh_2 so that `limits` can stop it. CGAL guarantees
// termination for theta up to about 20.7 degrees; above that it may not stop.
// Constrained edges of the output carry segment = -1 (CGAL does not say).
CgalMeshResult cgal_mesh(const Pslg& pslg, double min_angle_deg, double max_edge_size = 0,
                         const CgalMeshLimits& limits = {});

}  // namespace lepp::others
