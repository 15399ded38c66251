// SPDX-License-Identifier: GPL-3.0-or-later
// A row's verdict in words, as the markdown report and the HTML page both write it.
#pragma once
#include <string>

#include "lepp/audit/report/report.h"

namespace lepp::audit::detail {

// "FAILED", "holds", "holds (findings outside the claim)", "not checked", ...
std::string row_verdict(const RowSummary& r);

}  // namespace lepp::audit::detail
