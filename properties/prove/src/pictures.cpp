// SPDX-License-Identifier: GPL-3.0-or-later
// A refuted row's counterexample as a picture: the terminal pair (ABC above the
// terminal edge, ABD below) or the triangle drawn by the project's renderer
// (lepp::render), every point of the counterexample ringed and labelled with its
// exact grid coordinates, so the picture and the table's text name the same points.
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "lepp/prove/prove.h"
#include "lepp/render.h"
#include "lepp/theorems/statements.h"

namespace lepp::prove {
namespace {

int find(const std::vector<NamedPoint>& pts, const std::string& name) {
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (pts[i].name == name) return static_cast<int>(i);
  return -1;
}

std::string coordinates(const NamedPoint& p) {
  return p.name + " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
}

}  // namespace

std::string picture_name(const std::string& statement) {
  std::string s;
  for (char c : statement) s += c == '.' ? '-' : c;
  return s + ".svg";
}

std::string counterexample_svg(const Decision& d) {
  const std::vector<NamedPoint>& pts = d.points;
  int a = find(pts, "A"), b = find(pts, "B"), c = find(pts, "C"), dd = find(pts, "D");
  if (a < 0 || b < 0 || c < 0) throw std::invalid_argument("prove: no counterexample points for " + d.statement);
  Mesh mesh;
  for (const NamedPoint& p : pts) mesh.vertices.push_back({static_cast<double>(p.x), static_cast<double>(p.y)});
  mesh.input_vertices = mesh.vertices.size();
  // Counter-clockwise: the apex on the left of B -> A is C's side in the prover's frame,
  // but a sampled mesh's pair may lie either way round.
  auto ccw = [&](int i, int j, int k) -> Tri {
    const Point &p = mesh.vertices[i], &q = mesh.vertices[j], &r = mesh.vertices[k];
    double o = (q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x);
    return o >= 0 ? Tri{i, j, k} : Tri{j, i, k};
  };
  mesh.triangles.push_back(ccw(b, a, c));
  if (dd >= 0) mesh.triangles.push_back(ccw(b, a, dd));
  render::RenderOptions opt;
  opt.color = render::ColorBy::Angle;
  opt.width = 640;
  const theorems::Statement* st = theorems::find_statement(d.statement);
  opt.title = (st ? st->where : d.statement) + " refuted";
  render::Highlight edge;
  edge.edges.push_back({b, a});
  edge.colour = "black";
  edge.label = "terminal edge " + coordinates(pts[b]) + " - " + coordinates(pts[a]);
  opt.highlights.push_back(edge);
  std::vector<Point> all;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (static_cast<int>(i) == a || static_cast<int>(i) == b) continue;
    render::Highlight h;
    h.points.push_back(mesh.vertices[i]);
    h.colour = pts[i].name == "C" ? "red" : pts[i].name == "D" ? "blue" : pts[i].name == "V" ? "darkorange" : "gray";
    h.label = coordinates(pts[i]);
    opt.highlights.push_back(h);
  }
  for (const Point& p : mesh.vertices) all.push_back(p);
  std::vector<int> tris;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) tris.push_back(static_cast<int>(i));
  opt.window = render::window_around(mesh, tris, all, 0.1);
  return render::render_svg(mesh, opt);
}

std::string picture_link_dir(const std::string& dir, const std::string& table_path) {
  namespace fs = std::filesystem;
  const fs::path base = table_path.empty() ? fs::current_path() : fs::absolute(table_path).parent_path();
  return fs::absolute(dir).lexically_normal().lexically_relative(base).generic_string();
}

bool write_counterexample_pictures(const std::string& dir, const std::string& link_dir, std::vector<Decision>& decisions,
                                   std::string* error) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  for (Decision& d : decisions) {
    if (d.outcome != Outcome::Refuted || d.points.empty()) continue;
    std::string name = picture_name(d.statement);
    std::string svg;
    try {
      svg = counterexample_svg(d);
    } catch (const std::exception& e) {  // a drawing the renderer refuses: name the row
      if (error) *error = name + ": " + e.what();
      return false;
    }
    std::ofstream out(dir + "/" + name);
    if (!out || !(out << svg)) {
      if (error) *error = "cannot write " + dir + "/" + name;
      return false;
    }
    d.picture = (link_dir.empty() ? std::string() : link_dir + "/") + name;
  }
  return true;
}

}  // namespace lepp::prove
