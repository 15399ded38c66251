// SPDX-License-Identifier: GPL-3.0-or-later
// The overview picture of a certificate's page: lepp::render's drawing of the whole
// mesh, every listed violation in red; a large mesh drawn as its outline and markers.
#include <set>

#include "certify_pictures.h"
#include "lepp/certify_svg.h"
#include "lepp/render.h"

namespace lepp::certify::detail {

std::string overview_svg(const Mesh& mesh, const Report& report, std::size_t outline_above) {
  render::RenderOptions ro;
  ro.color = render::ColorBy::Angle;
  ro.outline_only = mesh.triangles.size() > outline_above;
  ro.highlight_bad = report.min_angle_deg > 0;
  if (report.min_angle_deg > 0) ro.min_angle_deg = report.min_angle_deg;
  ro.width = 900;
  if (ro.outline_only) ro.title = "outline (boundary, constrained edges, violations)";
  if (!report.violations.empty()) {
    render::Highlight h = highlight_of(report.violations, mesh);
    std::set<std::string> reasons;
    for (const Violation& v : report.violations) reasons.insert(to_string(v.reason));
    for (const std::string& r : reasons) h.label += (h.label.empty() ? "" : ", ") + r;
    ro.highlights.push_back(std::move(h));
  }
  return render::render_svg(mesh, ro);
}

}  // namespace lepp::certify::detail
