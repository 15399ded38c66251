// SPDX-License-Identifier: GPL-3.0-or-later
// The third step of run_audit (private to lepp_audit): each chosen failure run
// again on the input as found (is the program deterministic?), shrunk keeping
// its signature, run on the smallest input and saved under the output directory.
#pragma once
#include <vector>

#include "lepp/audit/audit.h"
#include "loop/cases.h"
#include "loop/session.h"
#include "loop/tally.h"

namespace lepp::audit::loop {

// Adds each saved counterexample (and internal error) to `report`, with its shrinking time.
void save_findings(AuditReport& report, AuditSession& session, const std::vector<AuditInput>& inputs,
                   const std::vector<Case>& cases, const std::vector<CaseOutcome>& outcomes, const Tally& tally);

}  // namespace lepp::audit::loop
