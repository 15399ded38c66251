// SPDX-License-Identifier: GPL-3.0-or-later
// Whether two runs on the same input gave the same output (private to
// lepp_audit): --repeat and the re-run of every finding ask it.
#pragma once
#include <string>

#include "lepp/audit/engine.h"

namespace lepp::audit::loop {

// Status, mesh bit for bit, trace; `why` says the first difference.
bool same_output(const EngineRun& a, const EngineRun& b, std::string& why);

}  // namespace lepp::audit::loop
