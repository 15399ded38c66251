// SPDX-License-Identifier: GPL-3.0-or-later
// theta as the audit writes it (reports, the command template's {theta}).
#pragma once
#include <string>
#include <vector>

namespace lepp::audit {

// The shortest form that reads back the same ("30", "22.5").
std::string theta_text(double theta);
// A list of thetas so, comma-separated ("20, 25, 30").
std::string thetas_text(const std::vector<double>& thetas);

}  // namespace lepp::audit
