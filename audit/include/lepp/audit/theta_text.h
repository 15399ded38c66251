// SPDX-License-Identifier: GPL-3.0-or-later
// theta as the audit writes it (reports, the command template's {theta}).
#pragma once
#include <string>

namespace lepp::audit {

// The shortest form that reads back the same ("30", "22.5").
std::string theta_text(double theta);

}  // namespace lepp::audit
