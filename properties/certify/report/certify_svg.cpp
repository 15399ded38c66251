// SPDX-License-Identifier: GPL-3.0-or-later
// A certificate drawn (lepp/certify_svg.h).
#include "lepp/certify_svg.h"

#include <algorithm>
#include <set>

namespace lepp::certify {

render::Highlight highlight_of(const std::vector<Violation>& violations, const Mesh& mesh) {
  render::Highlight h;
  const std::size_t n = mesh.vertices.size();
  for (const Violation& v : violations) {
    for (int t : v.triangles)
      if (t >= 0 && static_cast<std::size_t>(t) < mesh.triangles.size()) h.triangles.push_back(t);
    for (const auto& e : v.edges)
      if (e[0] >= 0 && e[1] >= 0 && static_cast<std::size_t>(std::max(e[0], e[1])) < n) h.edges.push_back(e);
    for (const Point& p : v.points) h.points.push_back(p);
  }
  return h;
}

std::string report_svg(const Mesh& mesh, const Report& report, bool zoom, const std::string& title) {
  render::RenderOptions ro;
  ro.color = render::ColorBy::Angle;
  ro.highlight_bad = report.min_angle_deg > 0;
  if (report.min_angle_deg > 0) ro.min_angle_deg = report.min_angle_deg;
  ro.title = title;
  if (!report.violations.empty()) {
    render::Highlight h = highlight_of(report.violations, mesh);
    std::set<std::string> reasons;
    for (const Violation& v : report.violations) reasons.insert(to_string(v.reason));
    for (const std::string& r : reasons) h.label += (h.label.empty() ? "" : ", ") + r;
    ro.highlights.push_back(std::move(h));
    if (zoom) {
      const render::Highlight first = highlight_of({report.violations.front()}, mesh);
      std::vector<Point> points = first.points;
      for (const auto& e : first.edges)
        for (int v : e) points.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
      if (!first.triangles.empty() || !points.empty()) ro.window = render::window_around(mesh, first.triangles, points);
    }
  }
  return render::render_svg(mesh, ro);
}

}  // namespace lepp::certify
