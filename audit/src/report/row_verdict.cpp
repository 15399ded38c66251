// SPDX-License-Identifier: GPL-3.0-or-later
// A row's verdict in words (row_verdict.h).
#include "row_verdict.h"

#include <fmt/format.h>

namespace lepp::audit::detail {

std::string row_verdict(const RowSummary& r) {
  if (r.failed > 0) return "FAILED";
  if (r.internal_errors > 0) return fmt::format("undecided on {} runs (internal error of the audit)", r.internal_errors);
  if (r.run == 0) return r.not_checked > 0 ? "not checked" : "not applicable";
  if (r.findings > 0) return "holds (findings outside the claim)";
  return "holds";
}

}  // namespace lepp::audit::detail
