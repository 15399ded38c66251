// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's report written to the files asked for: its JSON (--json-file) and its JUnit XML (--junit).
#pragma once
#include <string>

#include <nlohmann/json.hpp>

#include "lepp/audit/audit.h"

namespace lepp::audit {

// Writes `json` (the report's json_report, as printed) to `json_file` and the
// report's junit_report to `junit`, each only when named, in that order. Returns
// "" or, at the first file that cannot be written, "cannot write PATH" (the
// later file is then not written): the caller reports bad usage (exit 2).
std::string write_report_files(const AuditReport& report, const nlohmann::json& json, const std::string& json_file,
                               const std::string& junit);

}  // namespace lepp::audit
