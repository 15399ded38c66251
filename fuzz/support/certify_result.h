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

// The prefix of certify_problems' text when every violation is a claim of double
// precision the certifier's search of tie resolutions could not decide within its
// bound, or one it rejects on a triangle the engine left with its own search cut at
// its bound (UnimprovableTriangle::search_cut; docs/THEOREMS.md, "The precision stop
// and exact length ties"): a known, documented class, kept once and gone past
// (precision_undecided below).
inline constexpr const char* kPrecisionUndecided = "precision-undecided: ";
inline bool precision_undecided(const std::string& problems) { return problems.rfind(kPrecisionUndecided, 0) == 0; }

}  // namespace lepp::fuzz
