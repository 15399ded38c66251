// SPDX-License-Identifier: GPL-3.0-or-later
// A .node file read once for both what read_node returns and its numbering (0 or 1),
// which the .ele and .poly beside it use too (read_mesh).
#pragma once
#include <string>
#include <vector>

#include "lepp/pslg.h"

namespace lepp::detail {

// read_node(path, warnings), and `first` set to the first vertex's number (1 when there is none).
// vertices_only: the vertices without their lines and markers (a mesh's .node, read_mesh:
// at 10^7 vertices those are 80 MB written and never read).
Pslg read_node_numbered(const std::string& path, std::vector<std::string>& warnings, int& first,
                        bool vertices_only = false);

}  // namespace lepp::detail
