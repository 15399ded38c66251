// SPDX-License-Identifier: GPL-3.0-or-later
// The fast engine: same decisions as the reference (docs/ALGORITHM.md), its own
// flat-array mesh, filtered exact predicates, no point location.
#pragma once
#include "lepp/mesh.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::fast {

// The CDT of a validated PSLG with exterior and holes removed (Triangle's -p).
Mesh build_cdt(const Pslg& pslg);

// Builds the CDT and refines it as docs/ALGORITHM.md says.
RefineResult refine(const Pslg& pslg, const RefineOptions& options);

}  // namespace lepp::fast
