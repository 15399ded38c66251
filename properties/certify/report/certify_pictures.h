// SPDX-License-Identifier: GPL-3.0-or-later
// The pictures of a certificate's HTML page (certify_html.cpp): private to lepp_certify_report.
#pragma once
#include <cstddef>
#include <optional>
#include <string>

#include "lepp/certify.h"
#include "lepp/mesh.h"

namespace lepp::certify::detail {

// The whole mesh with every listed violation marked (outline only above `outline_above`
// triangles, lepp::render's outline_only). Throws std::invalid_argument when it cannot be drawn.
std::string overview_svg(const Mesh& mesh, const Report& report, std::size_t outline_above);

// The window around one violation with it marked; nullopt when it names nothing drawable
// (a count, an Euler characteristic). Throws std::invalid_argument when it cannot be drawn.
std::optional<std::string> violation_zoom_svg(const Mesh& mesh, const Report& report, const Violation& violation);

}  // namespace lepp::certify::detail
