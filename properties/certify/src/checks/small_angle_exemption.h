// SPDX-License-Identifier: GPL-3.0-or-later
// The small-input-angle exemption rule on the mesh: the mesh side of docs/CERTIFIER.md's rule.
#pragma once
#include <cstddef>
#include <vector>

#include "../certification.h"
#include "lepp/small_input_angles.h"

namespace lepp::certify {

// The first angle of `angles` (the input's small input angles, Report::small_angles)
// that exempts triangle t of the indexed mesh, or -1 (small_angle_exemption.cpp).
int exempting_angle(const MeshIndex& ix, const std::vector<SmallInputAngle>& angles, std::size_t t);

}  // namespace lepp::certify
