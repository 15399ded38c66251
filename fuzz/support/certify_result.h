// SPDX-License-Identifier: GPL-3.0-or-later
// The certifier as the fuzz targets use it: an empty string when the mesh is
// certified, else the first violations, one line. When the certifier library is
// not built (LEPP_FUZZ_HAVE_CERTIFIER undefined) only cheap structural checks run.
#pragma once
#include <string>

#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::fuzz {

// theta_deg = 0: no angle check (a guard outcome's mesh is only a CDT).
std::string certify_problems(const Pslg& pslg, const Mesh& mesh, double theta_deg,
                             const std::vector<UnimprovableTriangle>& unimprovable,
                             Method method = Method::Centroid);

// Checks a refinement result: the certificate, with theta only when converged.
std::string certify_result(const Pslg& pslg, const RefineOptions& options, const RefineResult& result);

bool have_certifier();

}  // namespace lepp::fuzz
