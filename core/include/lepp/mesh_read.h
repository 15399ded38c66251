// SPDX-License-Identifier: GPL-3.0-or-later
// read_mesh (lepp/io.h) on several threads: for a checker reading large meshes.
#pragma once
#include <string>

#include "lepp/mesh.h"

namespace lepp {

// read_mesh(prefix), with threads other than 1 reading the .node and the .ele at once
// (and the .poly after the .node). The same mesh, and the same first error with its
// file and line: on any error the files are read again one after the other.
Mesh read_mesh(const std::string& prefix, int threads);

}  // namespace lepp
