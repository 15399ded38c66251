// SPDX-License-Identifier: GPL-3.0-or-later
// The audit report three ways: markdown (stdout of `lepp audit`), JSON
// (`--json`), JUnit XML (`--junit FILE`, one testcase per row, so a CI shows
// each statement as a test).
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "lepp/audit/audit.h"

namespace lepp::audit {

std::string markdown_report(const AuditReport& report);
nlohmann::json json_report(const AuditReport& report);
std::string junit_report(const AuditReport& report);

// The conformance row's deviations, by name, and the declared reading: the
// paragraph of the markdown report under the table.
std::string deviations_text(const AuditReport& report);

// A counterexample's chain of deviations in the JSON ("deviations": [{"deviation",
// "from_step", "steps"}, ...]), and back (lepp audit merge reads shards' reports).
nlohmann::json deviations_json(const std::vector<DeviationLink>& chain);
std::vector<DeviationLink> deviations_of(const nlohmann::json& chain);

// A markdown table cell: pipes escaped, one line, at most 200 characters.
std::string md_cell(const std::string& text);

}  // namespace lepp::audit
