// SPDX-License-Identifier: GPL-3.0-or-later
// What a conformance failure's chain says as a whole (private to lepp_audit):
// whether every traced step fits one consistent variant, the line the finding,
// the rows' counts and the report build on (docs/CONFORMANCE.md, "Every
// deviation of a trace"). Apart from the replay so that its decision table is
// tested alone (audit/tests/judge/chain_summary_test.cpp).
#pragma once
#include <string>

#include "lepp/audit/deviations.h"
#include "lepp/audit/judge/conformance.h"

namespace lepp::audit {

// The catalogue's deviation of that name; Unknown for any other text.
Deviation deviation_named(const std::string& name);

// Every step of the trace is the paper's choice or one deviation's: the replay
// reached the trace's end (chain_complete) with that one name allowed, and the
// name is a rule set the replay can follow (has_variant). A chain that stopped
// before the trace's end says nothing of the steps after it.
bool fits_one_variant(const ConformanceFailure& failure);

}  // namespace lepp::audit
