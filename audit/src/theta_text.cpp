// SPDX-License-Identifier: GPL-3.0-or-later
// theta as the audit writes it.
#include "lepp/audit/theta_text.h"

#include <fmt/format.h>

namespace lepp::audit {

std::string theta_text(double theta) { return fmt::format("{}", theta); }

}  // namespace lepp::audit
