// SPDX-License-Identifier: GPL-3.0-or-later
// Internal to lepp_theorems: helpers shared by the registry's translation units.
#pragma once
#include <vector>

#include "lepp/theorems/checks.h"
#include "lepp/theorems/statements.h"

namespace lepp::theorems {
// RC_CLASSIFY the verdict and RC_FAIL with its detail when the hypothesis holds and the conclusion does not.
void assert_verdict(const Verdict& v);
// Section 5 and Remark 15: statistics over generated PSLGs, run by an engine.
void add_empirical_statements(std::vector<Statement>& rows);
}  // namespace lepp::theorems
