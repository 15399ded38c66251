// SPDX-License-Identifier: GPL-3.0-or-later
// What the output formats say beyond the triangles: the boundary marker of each
// constrained edge and the region of each triangle, taken from the input PSLG.
// They become Gmsh's physical groups and the .vtu's `region` array.
#pragma once
#include <vector>

#include "lepp/mesh.h"
#include "lepp/pslg.h"

namespace lepp {

struct MeshLabels {
  // One per Mesh::constrained_edges: the Triangle boundary marker of the input
  // segment the edge lies on (0 when unknown). Empty: no markers.
  std::vector<int> edge_markers;
  // One per Mesh::triangles: k + 1 for the PSLG's region k (Pslg::regions, file
  // order), 0 for a triangle no region reaches. Empty: no regions.
  std::vector<int> triangle_regions;
  // How many regions the input has (Pslg::regions.size()): the .msh's group of
  // triangles no region reaches is numbered after them.
  int region_count = 0;
};

// Labels of a mesh of the validated PSLG `input` (what lepp::validate returns;
// each ConstrainedEdge::segment numbers its segments, as the engines write
// them). Regions follow the engines' rule (docs/ALGORITHM.md section 2): each
// region point, in file order, floods the triangles it lies in (strictly inside
// a triangle, or on an unconstrained edge: both sides) across unconstrained
// edges, overwriting earlier regions; a point on a constrained edge, on an input
// vertex or outside the mesh marks nothing. Exact predicates.
MeshLabels mesh_labels(const Mesh& mesh, const Pslg& input);

// The regions alone (mesh_labels' triangle_regions), for any mesh and region list.
std::vector<int> triangle_regions(const Mesh& mesh, const std::vector<Region>& regions);

}  // namespace lepp
