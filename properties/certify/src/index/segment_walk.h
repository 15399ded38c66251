// SPDX-License-Identifier: GPL-3.0-or-later
// A segment's chain of mesh edges: the walk from one endpoint to the other (docs/CERTIFIER.md section 3).
#pragma once
#include <vector>

#include "../certification.h"

namespace lepp::certify {

// The chain of mesh vertices from a to b along segment AB (a, b mesh vertex ids), or
// {-1, v} when there is none, v where the first choices stopped (segment_walk.cpp).
std::vector<int> walk(const MeshIndex& ix, int a, int b);

}  // namespace lepp::certify
