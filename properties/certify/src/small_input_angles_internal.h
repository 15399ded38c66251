// SPDX-License-Identifier: GPL-3.0-or-later
// The certifier's entry to small_input_angles with the domain it has already computed.
#pragma once
#include <vector>

#include "expected_domain.h"
#include "lepp/small_input_angles.h"

namespace lepp::certify {

std::vector<SmallInputAngle> small_input_angles(const Pslg& validated, const ExpectedDomain& domain);

}  // namespace lepp::certify
