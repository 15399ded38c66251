// SPDX-License-Identifier: GPL-3.0-or-later
// A certificate drawn (`lepp certify --svg`, the audit's pictures of findings): the
// mesh with what each listed violation names (triangles, edges, vertices and points)
// in red, so a mesher's author sees where their program went wrong.
#pragma once
#include <string>
#include <vector>

#include "lepp/certify.h"
#include "lepp/mesh.h"
#include "lepp/render.h"

namespace lepp::certify {

// The triangles, edges and points of these violations (ids out of the mesh's range dropped).
render::Highlight highlight_of(const std::vector<Violation>& violations, const Mesh& mesh);

// The mesh, triangles coloured by smallest angle (bad ones below the report's theta outlined),
// with every listed violation highlighted and labelled by its reasons. zoom: only the window
// around the first listed violation (with context), or the whole mesh when it names nothing
// drawable. Throws std::invalid_argument when the mesh has no triangles (render_svg).
std::string report_svg(const Mesh& mesh, const Report& report, bool zoom, const std::string& title = "");

}  // namespace lepp::certify
