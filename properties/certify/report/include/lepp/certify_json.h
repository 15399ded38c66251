// SPDX-License-Identifier: GPL-3.0-or-later
// The certifier's report as JSON: what `lepp certify --json` prints and what
// the Python package's lepp.certify() returns (docs/CERTIFIER.md).
#pragma once
#include <cstddef>

#include <nlohmann/json.hpp>

#include "lepp/certify.h"

namespace lepp::certify {

// The verdict, statistics, violation counts by reason, the violations (at most
// Options::max_listed_per_reason of each reason, as certify() kept them), the
// unimprovable and exempt triangles (at most max_listed of the latter) and the
// size bounds checked. Violation ids are 0-based.
nlohmann::json json_report(const Report& report, std::size_t max_listed);

}  // namespace lepp::certify
