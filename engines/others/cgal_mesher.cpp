// SPDX-License-Identifier: GPL-3.0-or-later
// CGAL::refine_Delaunay_mesh_2 on a lepp::Pslg, with a point budget and a time limit.
#include "cgal_mesher.h"

#include <chrono>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace lepp::others {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
// The input id of a vertex; Steiner points keep -1.
struct VertexId {
  int id = -1;
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexId, K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Mesher = CGAL::Delaunay_mesher_2<Cdt, Criteria>;

// Input vertices keep their ids; Steiner points follow in CGAL's vertex order.
Mesh to_mesh(const Cdt& cdt, std::size_t input_vertices) {
  Mesh mesh;
  mesh.input_vertices = input_vertices;
  mesh.vertices.resize(input_vertices);
  std::vector<std::pair<Cdt::Vertex_handle, int>> ids;
  std::map<Cdt::Vertex_handle, int> id_of;
  int next = static_cast<int>(input_vertices);
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    int id = v->info().id;
    if (id < 0) {
      id = next++;
      mesh.vertices.push_back({});
    }
    mesh.vertices[static_cast<std::size_t>(id)] = {v->point().x(), v->point().y()};
    id_of[v] = id;
  }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    // CGAL's faces are counter-clockwise.
    mesh.triangles.push_back({id_of[f->vertex(0)], id_of[f->vertex(1)], id_of[f->vertex(2)]});
  }
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    if (!cdt.is_constrained(*e)) continue;
    Cdt::Face_handle f = e->first, g = f->neighbor(e->second);
    bool in_domain = (!cdt.is_infinite(f) && f->is_in_domain()) || (!cdt.is_infinite(g) && g->is_in_domain());
    if (!in_domain) continue;
    int a = id_of[f->vertex(Cdt::cw(e->second))], b = id_of[f->vertex(Cdt::ccw(e->second))];
    mesh.constrained_edges.push_back({a, b, -1});
  }
  return mesh;
}

}  // namespace

CgalMeshResult cgal_mesh(const Pslg& pslg, double min_angle_deg, double max_edge_size, const CgalMeshLimits& limits) {
  auto start = std::chrono::steady_clock::now();
  auto elapsed = [&start] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };

  Cdt cdt;
  // Bulk insertion (spatially sorted): one at a time, 10^5 collinear boundary
  // points take tens of seconds.
  std::vector<std::pair<K::Point_2, VertexId>> points;
  points.reserve(pslg.vertices.size());
  for (std::size_t i = 0; i < pslg.vertices.size(); ++i)
    points.push_back({K::Point_2(pslg.vertices[i].x, pslg.vertices[i].y), VertexId{static_cast<int>(i)}});
  cdt.insert(points.begin(), points.end());
  std::vector<Cdt::Vertex_handle> handle(pslg.vertices.size());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) handle[static_cast<std::size_t>(v->info().id)] = v;
  for (const Segment& s : pslg.segments) cdt.insert_constraint(handle[static_cast<std::size_t>(s.a)], handle[static_cast<std::size_t>(s.b)]);
  const auto input_count = static_cast<std::int64_t>(cdt.number_of_vertices());

  double s = std::sin(min_angle_deg * M_PI / 180.0);
  Mesher mesher(cdt, Criteria(s * s, max_edge_size));
  std::vector<K::Point_2> seeds;
  for (const Point& h : pslg.holes) seeds.emplace_back(h.x, h.y);
  mesher.set_seeds(seeds.begin(), seeds.end(), /*mark=*/false);
  mesher.init();

  CgalMeshResult result;
  result.finished = true;
  std::int64_t steps = 0;
  while (!mesher.is_refinement_done()) {
    mesher.step_by_step_refine_mesh();
    if (++steps % 256 != 0) continue;
    std::int64_t added = static_cast<std::int64_t>(cdt.number_of_vertices()) - input_count;
    if ((limits.max_steiner > 0 && added >= limits.max_steiner) ||
        (limits.time_limit_seconds > 0 && elapsed() >= limits.time_limit_seconds)) {
      result.finished = false;
      break;
    }
  }
  result.steiner_points = static_cast<std::int64_t>(cdt.number_of_vertices()) - input_count;
  result.mesh = to_mesh(cdt, pslg.vertices.size());
  result.seconds = elapsed();
  return result;
}

}  // namespace lepp::others
