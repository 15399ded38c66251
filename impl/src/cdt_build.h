// The initial constrained Delaunay triangulation of a validated PSLG, with the
// exterior and holes flooded away (ALGORITHM.md section 2), as a TriMesh.
#pragma once
#include "lepp/pslg.h"
#include "tri_mesh.h"

namespace lepp::fast {

// Vertex ids are the PSLG's. reserve_triangles: capacity to reserve for refinement.
TriMesh build_initial_cdt(const Pslg& pslg, const SegmentMembership& membership, std::size_t reserve_triangles,
                          std::size_t reserve_vertices);

}  // namespace lepp::fast
