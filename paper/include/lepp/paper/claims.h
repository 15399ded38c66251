// SPDX-License-Identifier: GPL-3.0-or-later
// The paper's claims of Sections 5.2 and 6, checked against our runs: the angle
// up to which each method works, fewer points than Lepp-midpoint and than
// Triangle above 25 degrees, a higher average smallest angle, the Lepp size.
#pragma once
#include <string>
#include <vector>

#include "lepp/paper/run.h"

namespace lepp::paper {

// PAPER.md's section "The paper's claims, checked" (markdown), over the runs on
// the corpus problems at `angles` (ascending).
std::string claims_section(const Results& res, const std::vector<double>& angles);

}  // namespace lepp::paper
