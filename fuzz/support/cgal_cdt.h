// SPDX-License-Identifier: GPL-3.0-or-later
// An independent CDT for fuzz_cdt to compare against: CGAL's constrained
// Delaunay triangulation (exact predicates) of the same PSLG, with the domain
// flooded as docs/ALGORITHM.md section 2 says. Plain-double interface: CGAL
// stays inside cgal_cdt.cpp.
#pragma once
#include <cstdint>

#include "lepp/mesh.h"
#include "lepp/pslg.h"

namespace lepp::fuzz {

struct CgalCdt {
  Mesh mesh;                        // input ids, canonical
  std::int64_t cocircular_edges = 0;  // unconstrained interior edges with four cocircular points
};

// pslg must be validated.
CgalCdt cgal_cdt(const Pslg& pslg);

}  // namespace lepp::fuzz
