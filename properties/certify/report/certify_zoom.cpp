// SPDX-License-Identifier: GPL-3.0-or-later
// One violation's picture on a certificate's page: the window around what it names
// (triangles, edges, points), drawn by lepp::render with the violation in red. Only
// the triangles meeting the window are handed to the renderer (a copy with its ids
// renumbered): a page lists up to 50 violations of each kind, and drawing each from
// a mesh of 10^6 triangles would take the renderer a whole pass per picture.
#include <algorithm>
#include <unordered_map>

#include "certify_pictures.h"
#include "lepp/certify_svg.h"
#include "lepp/render.h"

namespace lepp::certify::detail {
namespace {

bool meets(const render::Window& w, double x0, double y0, double x1, double y1) {
  return x1 >= w.min_x && x0 <= w.max_x && y1 >= w.min_y && y0 <= w.max_y;
}

// The part of the mesh a window shows: its triangles meeting the window and the
// constrained edges meeting it, vertices renumbered; `vertex` and `triangle` map the
// mesh's ids to the part's (vertices named by the highlight are added even when no
// kept triangle uses them).
struct Part {
  Mesh mesh;
  std::unordered_map<int, int> vertex, triangle;

  int add_vertex(const Mesh& from, int v) {
    auto [it, added] = vertex.emplace(v, static_cast<int>(mesh.vertices.size()));
    if (added) mesh.vertices.push_back(from.vertices[static_cast<std::size_t>(v)]);
    return it->second;
  }
};

Part part_in(const Mesh& mesh, const render::Window& w) {
  Part part;
  const auto& p = mesh.vertices;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Tri& x = mesh.triangles[t];
    const Point &a = p[static_cast<std::size_t>(x[0])], &b = p[static_cast<std::size_t>(x[1])], &c = p[static_cast<std::size_t>(x[2])];
    if (!meets(w, std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}), std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}))) continue;
    part.triangle.emplace(static_cast<int>(t), static_cast<int>(part.mesh.triangles.size()));
    part.mesh.triangles.push_back({part.add_vertex(mesh, x[0]), part.add_vertex(mesh, x[1]), part.add_vertex(mesh, x[2])});
  }
  for (const ConstrainedEdge& e : mesh.constrained_edges) {
    const Point &a = p[static_cast<std::size_t>(e.a)], &b = p[static_cast<std::size_t>(e.b)];
    if (!meets(w, std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y))) continue;
    part.mesh.constrained_edges.push_back({part.add_vertex(mesh, e.a), part.add_vertex(mesh, e.b), e.segment});
  }
  return part;
}

}  // namespace

std::optional<std::string> violation_zoom_svg(const Mesh& mesh, const Report& report, const Violation& violation) {
  const render::Highlight whole = highlight_of({violation}, mesh);
  std::vector<Point> points = whole.points;
  for (const auto& e : whole.edges)
    for (int v : e) points.push_back(mesh.vertices[static_cast<std::size_t>(v)]);
  if (whole.triangles.empty() && points.empty()) return std::nullopt;
  // Ids out of range anywhere in the mesh: the renderer refuses the mesh, as for the overview.
  auto bad = [&](int v) { return v < 0 || static_cast<std::size_t>(v) >= mesh.vertices.size(); };
  for (const Tri& t : mesh.triangles)
    if (bad(t[0]) || bad(t[1]) || bad(t[2])) return render::render_svg(mesh);  // throws, naming the id
  for (const ConstrainedEdge& e : mesh.constrained_edges)
    if (bad(e.a) || bad(e.b)) return render::render_svg(mesh);
  render::RenderOptions ro;
  ro.color = render::ColorBy::Angle;
  ro.highlight_bad = report.min_angle_deg > 0;
  if (report.min_angle_deg > 0) ro.min_angle_deg = report.min_angle_deg;
  ro.width = 340;
  ro.window = render::window_around(mesh, whole.triangles, points);
  ro.title = "the triangles meeting the window";
  Part part = part_in(mesh, *ro.window);
  render::Highlight h;
  h.label = to_string(violation.reason);
  for (int t : whole.triangles) h.triangles.push_back(part.triangle.at(t));  // each meets the window around it
  for (const auto& e : whole.edges) h.edges.push_back({part.add_vertex(mesh, e[0]), part.add_vertex(mesh, e[1])});
  h.points = whole.points;
  ro.highlights.push_back(std::move(h));
  if (part.mesh.triangles.empty()) return std::nullopt;  // nothing of the mesh there to draw it on
  return render::render_svg(part.mesh, ro);
}

}  // namespace lepp::certify::detail
