// SPDX-License-Identifier: GPL-3.0-or-later
// Meshes made by CGAL, independently of our engines, for the certifier's tests:
// the constrained Delaunay triangulation of a PSLG, and CGAL's Mesh_2 refinement
// of it (Steiner points on segments, rounded by CGAL's own formulas).
#pragma once
#include "lepp/mesh.h"
#include "lepp/pslg.h"

namespace lepp::test {

// A mesh as read_mesh gives it: no vertex promised to be an input vertex.
inline Mesh as_read(Mesh m) {
  m.input_vertices = 0;
  return m;
}

// The CDT of a validated PSLG, exterior and holes removed (Triangle's -p).
// Vertices keep the input ids; constrained edges list the segments (ids -1).
Mesh cgal_cdt(const Pslg& pslg);

// CGAL's Delaunay refinement (Mesh_2) with shape bound B = 1/(4 sin^2 alpha):
// B = 0.125 gives alpha >= 20.7 degrees. Steiner vertices follow the input vertices.
Mesh cgal_refined(const Pslg& pslg, double shape_bound = 0.125);

}  // namespace lepp::test
