// SPDX-License-Identifier: GPL-3.0-or-later
// One violation's picture on a certificate's page: the window around what it names
// (triangles, edges, points), drawn by lepp::render with the violation in red.
#include "certify_pictures.h"
#include "lepp/certify_svg.h"
#include "lepp/render.h"

namespace lepp::certify::detail {

std::optional<std::string> violation_zoom_svg(const Mesh& mesh, const Report& report, const Violation& violation) {
  render::Highlight h = highlight_of({violation}, mesh);
  std::vector<Point> points = h.points;
  for (const auto& e : h.edges)
    for (int v : e) points.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
  if (h.triangles.empty() && points.empty()) return std::nullopt;
  h.label = to_string(violation.reason);
  render::RenderOptions ro;
  ro.color = render::ColorBy::Angle;
  ro.highlight_bad = report.min_angle_deg > 0;
  if (report.min_angle_deg > 0) ro.min_angle_deg = report.min_angle_deg;
  ro.width = 340;
  ro.window = render::window_around(mesh, h.triangles, points);
  ro.highlights.push_back(std::move(h));
  return render::render_svg(mesh, ro);
}

}  // namespace lepp::certify::detail
