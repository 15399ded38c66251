// SPDX-License-Identifier: GPL-3.0-or-later
// theta as the audit writes it.
#include "lepp/audit/theta_text.h"

#include <fmt/format.h>

namespace lepp::audit {

std::string theta_text(double theta) { return fmt::format("{}", theta); }

std::string thetas_text(const std::vector<double>& thetas) {
  std::string s;
  for (double t : thetas) s += (s.empty() ? "" : ", ") + theta_text(t);
  return s;
}

}  // namespace lepp::audit
