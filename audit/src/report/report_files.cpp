// SPDX-License-Identifier: GPL-3.0-or-later
// The audit's report written to the files asked for: its JSON (--json-file) and its JUnit XML (--junit).
#include "lepp/audit/report/report_files.h"

#include <fstream>
#include <string>

#include "lepp/audit/report/report.h"

namespace lepp::audit {

std::string write_report_files(const AuditReport& report, const nlohmann::json& json, const std::string& json_file,
                               const std::string& junit) {
  if (!json_file.empty()) {
    std::ofstream out(json_file);
    out << json.dump(2) << "\n";
    if (!out) return "cannot write " + json_file;
  }
  if (!junit.empty()) {
    std::ofstream out(junit);
    out << junit_report(report);
    if (!out) return "cannot write " + junit;
  }
  return "";
}

}  // namespace lepp::audit
