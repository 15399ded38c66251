// SPDX-License-Identifier: GPL-3.0-or-later
// Two engine results the certifier cannot tell apart (fuzz_differential: the
// reference's run takes the fast run's verdict instead of certifying the same
// mesh again; the certifier is a function of its input).
#pragma once
#include "lepp/refine.h"

namespace lepp::fuzz {

// Everything of a result certify_result reads besides the PSLG and the options: the mesh
// in engine order (vertices, input vertex count, triangles, constrained edges), whether it
// claims theta (converged or unimprovable), and the unimprovable list, field by field.
bool same_certifier_input(const RefineResult& a, const RefineResult& b);

}  // namespace lepp::fuzz
