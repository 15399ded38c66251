// SPDX-License-Identifier: GPL-3.0-or-later
// The audit report as one self-contained HTML page (`lepp audit --html FILE`,
// `lepp audit merge --html FILE`, the Python report's _repr_html_): the rows,
// the deviations by name with their counts and a link to the finding that shows
// each first, and every finding with the picture of its step (the mesh just
// before it, the paper's choice and the program's point), the shrunk input's
// picture, the mesh with the violation and the reproduce command with a copy
// button. The pictures are the finding directories' SVG files (lepp::render's),
// read when the page is written.
#pragma once
#include <string>

#include "lepp/audit/audit.h"

namespace lepp::audit {

std::string html_report(const AuditReport& report);

// Writes html_report(report) to `path`. Returns "" or "cannot write PATH" (bad usage, exit 2).
std::string write_html_report(const AuditReport& report, const std::string& path);

}  // namespace lepp::audit
