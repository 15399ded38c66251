// SPDX-License-Identifier: GPL-3.0-or-later
// The exact engine: CGAL's constrained Delaunay triangulation on the Epeck
// kernel, refined by the paper's Lepp-centroid or Lepp-midpoint method.
// Written for clarity, not speed: the oracle the fast engine is checked against.
#pragma once
#include "lepp/mesh.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::reference {

// The CDT of a validated PSLG with exterior and holes removed (Triangle's -p).
Mesh build_cdt(const Pslg& pslg);

// Builds the CDT and refines it as docs/ALGORITHM.md says.
RefineResult refine(const Pslg& pslg, const RefineOptions& options);

}  // namespace lepp::reference
