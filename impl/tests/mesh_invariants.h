// SPDX-License-Identifier: GPL-3.0-or-later
// The fast engine's own invariants, checked independently of its code (CGAL's
// exact predicates and rationals): used by impl's tests next to the certifier.
#pragma once
#include <string>
#include <vector>

#include "lepp/mesh.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::impl_test {

struct InvariantOptions {
  double min_angle_deg = 0;  // 0: no angle check
  double max_area = 0;       // 0: no size check
  std::vector<UnimprovableTriangle> unimprovable;  // exempt from the angle check
};

// Problems found (empty: all hold): counter-clockwise triangles, each edge in at
// most two triangles with opposite directions, mesh boundary edges constrained,
// every segment covered by a chain of its constrained edges, every Steiner
// vertex used, every unconstrained interior edge locally Delaunay, every
// triangle not listed unimprovable of smallest angle >= theta (exact, with the
// engines' sin^2 threshold) and area <= max_area.
std::vector<std::string> check_invariants(const Pslg& pslg, const Mesh& mesh, const InvariantOptions& options);

}  // namespace lepp::impl_test
