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

// Pairs of counter-clockwise triangles whose interiors overlap (empty: none), exactly:
// two triangles have disjoint interiors iff the line of an edge of one of them has the
// other on its closed outer side. Not among check_invariants, whose local tests (each
// edge in two triangles, opposite ways) miss a boundary folded across another part of
// the mesh: a split at a point beyond a neighbouring boundary segment.
std::vector<std::string> overlapping_triangles(const Mesh& mesh);

}  // namespace lepp::impl_test
