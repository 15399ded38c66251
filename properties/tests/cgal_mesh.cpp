// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind cgal_mesh.h: meshes made by CGAL, independently of our engines, for
// the certifier's tests.
#include "cgal_mesh.h"

#include <map>
#include <vector>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace lepp::test {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_2<K>;
using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Mesher = CGAL::Delaunay_mesher_2<Cdt, Criteria>;

Mesh mesh_of(const Pslg& pslg, bool refine, double shape_bound) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handle;
  for (const Point& p : pslg.vertices) handle.push_back(cdt.insert(K::Point_2(p.x, p.y)));
  for (const Segment& s : pslg.segments)
    cdt.insert_constraint(handle[static_cast<std::size_t>(s.a)], handle[static_cast<std::size_t>(s.b)]);
  std::vector<K::Point_2> seeds;
  for (const Point& h : pslg.holes) seeds.emplace_back(h.x, h.y);
  Mesher mesher(cdt, Criteria(shape_bound, 0));
  mesher.set_seeds(seeds.begin(), seeds.end(), /*mark=*/false, /*do_it_now=*/true);
  if (refine) mesher.refine_mesh();

  Mesh mesh;
  std::map<Cdt::Vertex_handle, int> id;
  for (std::size_t i = 0; i < handle.size(); ++i) {
    id[handle[i]] = static_cast<int>(i);
    mesh.vertices.push_back(pslg.vertices[i]);
  }
  mesh.input_vertices = pslg.vertices.size();
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    if (!id.count(v)) {
      id[v] = static_cast<int>(mesh.vertices.size());
      mesh.vertices.push_back({v->point().x(), v->point().y()});
    }
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    if (f->is_in_domain()) mesh.triangles.push_back({id[f->vertex(0)], id[f->vertex(1)], id[f->vertex(2)]});
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    if (!cdt.is_constrained(*e)) continue;
    Cdt::Face_handle f = e->first, n = f->neighbor(e->second);
    if (!(f->is_in_domain() || (!cdt.is_infinite(n) && n->is_in_domain()))) continue;
    mesh.constrained_edges.push_back({id[f->vertex(Cdt::ccw(e->second))], id[f->vertex(Cdt::cw(e->second))], -1});
  }
  canonicalize(mesh);
  return mesh;
}

}  // namespace

Mesh cgal_cdt(const Pslg& pslg) { return mesh_of(pslg, false, 0.125); }
Mesh cgal_refined(const Pslg& pslg, double shape_bound) { return mesh_of(pslg, true, shape_bound); }

}  // namespace lepp::test
