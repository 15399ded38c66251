// SPDX-License-Identifier: GPL-3.0-or-later
// The initial constrained Delaunay triangulation of a validated PSLG, with the
// exterior and holes flooded away (ALGORITHM.md section 2), as a TriMesh.
#pragma once
#include <cstdint>

#include "lepp/pslg.h"
#include "tri_mesh.h"

namespace lepp::fast {

// Vertex ids are the PSLG's. reserve_*: capacity to reserve for refinement.
// cocircular_ties: set to the unconstrained domain edges whose two triangles
// are cocircular (in-circle exactly zero): there the CDT is not unique.
// regions: also fill TriMesh::region by flooding from the PSLG's region points
// (ALGORITHM.md section 2).
TriMesh build_initial_cdt(const Pslg& pslg, const SegmentMembership& membership, std::size_t reserve_triangles,
                          std::size_t reserve_vertices, std::int64_t* cocircular_ties = nullptr, bool regions = false);

}  // namespace lepp::fast
