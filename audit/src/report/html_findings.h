// SPDX-License-Identifier: GPL-3.0-or-later
// One finding of an audit's HTML page (html_findings.cpp): private to lepp_audit.
#pragma once
#include <string>

#include "lepp/audit/audit.h"
#include "lepp/html/page.h"

namespace lepp::audit::detail {

// The anchor of a finding's section: "finding-" and its directory's last part.
std::string finding_anchor(const Counterexample& c);

// Its section: what failed, the deviations of its trace, the pictures of its directory
// (step.svg, finding-zoom.svg, finding.svg; the shrunk input.poly drawn), and the
// reproduce command with a copy button. `internal`: an internal error of the audit.
std::string finding_section(html::Page& page, const Counterexample& c, bool internal);

}  // namespace lepp::audit::detail
