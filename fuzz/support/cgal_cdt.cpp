// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind cgal_cdt.h: an independent CDT for fuzz_cdt to compare against.
#include "cgal_cdt.h"

#include <vector>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace lepp::fuzz {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fbi = CGAL::Triangulation_face_base_with_info_2<bool, K>;  // true: removed from the domain
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbi>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
}  // namespace

CgalCdt cgal_cdt(const Pslg& pslg) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  for (std::size_t i = 0; i < pslg.vertices.size(); ++i) {
    handles.push_back(cdt.insert(K::Point_2(pslg.vertices[i].x, pslg.vertices[i].y)));
    handles.back()->info() = static_cast<int>(i);
  }
  for (const Segment& s : pslg.segments)
    cdt.insert_constraint(handles[static_cast<std::size_t>(s.a)], handles[static_cast<std::size_t>(s.b)]);

  // Flood from outside the hull and from hole points, never across a constraint.
  std::vector<Cdt::Face_handle> stack;
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) {
    f->info() = false;
    if (cdt.is_infinite(f)) stack.push_back(f);
  }
  for (const Point& h : pslg.holes) {
    Cdt::Locate_type type;
    int li = 0;
    Cdt::Face_handle f = cdt.locate(K::Point_2(h.x, h.y), type, li);
    if (type == Cdt::FACE) stack.push_back(f);
    if (type == Cdt::EDGE && !cdt.is_constrained({f, li})) stack.push_back(f), stack.push_back(f->neighbor(li));
  }
  while (!stack.empty()) {
    Cdt::Face_handle f = stack.back();
    stack.pop_back();
    if (f->info()) continue;
    f->info() = true;
    for (int i = 0; i < 3; ++i)
      if (!cdt.is_constrained({f, i}) && !f->neighbor(i)->info()) stack.push_back(f->neighbor(i));
  }

  CgalCdt out;
  out.mesh.vertices = pslg.vertices;
  out.mesh.input_vertices = pslg.vertices.size();
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info()) continue;
    out.mesh.triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  }
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    Cdt::Face_handle f = e->first, g = f->neighbor(e->second);
    const bool inside_f = !cdt.is_infinite(f) && !f->info(), inside_g = !cdt.is_infinite(g) && !g->info();
    const int a = f->vertex(Cdt::ccw(e->second))->info(), b = f->vertex(Cdt::cw(e->second))->info();
    if (cdt.is_constrained(*e)) {
      if (inside_f || inside_g) out.mesh.constrained_edges.push_back({a, b, -1});
      continue;
    }
    if (inside_f && inside_g &&
        cdt.side_of_oriented_circle(f, g->vertex(g->index(f))->point()) == CGAL::ON_ORIENTED_BOUNDARY)
      ++out.cocircular_edges;
  }
  canonicalize(out.mesh);
  return out;
}

}  // namespace lepp::fuzz
