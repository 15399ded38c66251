// SPDX-License-Identifier: GPL-3.0-or-later
// The CDT of the input and its domain (ALGORITHM.md, Sections 1 and 2), and
// the conversion back to the plain Mesh.
#include <algorithm>
#include <deque>
#include <set>
#include <stdexcept>

#include "lepp/reference.h"
#include "triangulation.h"

namespace lepp::reference::detail {

namespace {

// Triangle's -p: remove every triangle reachable, without crossing a
// constrained edge, from outside the input's convex hull or from a hole point.
// All triangles outside the hull have a bounding-box corner, so seeding the
// flood there reaches exactly the triangles behind unconstrained hull edges.
// The faces a hole or region point starts its flood from: the one it lies in, or
// both sides of the unconstrained edge it lies on; none on a constrained edge or a
// vertex (it removes or sets nothing there; validation warns).
void push_start_faces(const Cdt& cdt, const Point& p, std::deque<FH>& todo) {
  Cdt::Locate_type lt;
  int li;
  FH f = cdt.locate(CPoint(p.x, p.y), lt, li);
  if (lt == Cdt::FACE) {
    todo.push_back(f);
  } else if (lt == Cdt::EDGE && !f->is_constrained(li)) {
    todo.push_back(f);
    todo.push_back(f->neighbor(li));
  }
}

void mark_domain(Triangulation& tr) {
  Cdt& cdt = tr.cdt;
  std::deque<FH> todo;
  for (FH f : cdt.finite_face_handles()) {
    f->info().in_domain = true;
    if (id(f->vertex(0)) < 0 || id(f->vertex(1)) < 0 || id(f->vertex(2)) < 0) todo.push_back(f);
  }
  for (const Point& h : tr.input->holes) push_start_faces(cdt, h, todo);
  while (!todo.empty()) {
    FH f = todo.front();
    todo.pop_front();
    if (cdt.is_infinite(f) || !f->info().in_domain) continue;
    f->info().in_domain = false;
    for (int i = 0; i < 3; ++i)
      if (!f->is_constrained(i)) todo.push_back(f->neighbor(i));
  }
}

}  // namespace

void build_triangulation(const Pslg& pslg, Triangulation& tr) {
  tr.input = &pslg;
  tr.input_vertices = pslg.vertices.size();
  if (pslg.vertices.size() < 3) throw std::invalid_argument("reference: fewer than three vertices");

  double x0 = pslg.vertices[0].x, x1 = x0, y0 = pslg.vertices[0].y, y1 = y0;
  for (const Point& p : pslg.vertices) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  // Far corners: the box keeps every input segment off the convex hull, so a
  // rounded midpoint half an ulp outside a boundary segment still has a
  // finite triangle on each side. They cannot see into the domain (which is
  // enclosed by constrained edges), so the domain's CDT is unchanged.
  double pad = std::max({x1 - x0, y1 - y0, 1.0});
  const CPoint corners[4] = {{x0 - pad, y0 - pad}, {x1 + pad, y0 - pad}, {x1 + pad, y1 + pad}, {x0 - pad, y1 + pad}};
  for (const CPoint& c : corners) tr.cdt.insert(c)->info().id = -1;

  FH hint;
  for (std::size_t i = 0; i < pslg.vertices.size(); ++i) {
    const Point& p = pslg.vertices[i];
    VH v = tr.cdt.insert(CPoint(p.x, p.y), hint);
    if (v->info().id != -1)
      throw std::invalid_argument("reference: duplicate vertex (the input must be validated)");
    v->info().id = static_cast<int>(i);
    hint = v->face();
    tr.vertex.push_back(v);
    tr.coords.push_back(p);
  }
  for (std::size_t s = 0; s < pslg.segments.size(); ++s) {
    const Segment& seg = pslg.segments[s];
    VH a = tr.vertex.at(static_cast<std::size_t>(seg.a)), b = tr.vertex.at(static_cast<std::size_t>(seg.b));
    std::size_t before = tr.cdt.number_of_vertices();
    tr.cdt.insert_constraint(a, b);
    if (tr.cdt.number_of_vertices() != before)
      throw std::invalid_argument("reference: segments cross or touch (the input must be validated)");
    a->info().segments.push_back(static_cast<int>(s));
    b->info().segments.push_back(static_cast<int>(s));
    tr.segment_of_edge[edge_key(seg.a, seg.b)] = static_cast<int>(s);
  }
  // A vertex inside a segment would have split the constraint into pieces
  // that are not edges a-b: validation forbids it; check.
  for (const auto& [edge, s] : tr.segment_of_edge) {
    FH f;
    int i;
    if (!tr.cdt.is_edge(tr.vertex[static_cast<std::size_t>(edge.first)], tr.vertex[static_cast<std::size_t>(edge.second)], f, i))
      throw std::invalid_argument("reference: a vertex lies inside a segment (the input must be validated)");
  }
  mark_domain(tr);
}

void assign_regions(Triangulation& tr) {
  Cdt& cdt = tr.cdt;
  const auto& regions = tr.input->regions;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const int region = static_cast<int>(r) + 1;
    std::set<FH> seen;
    std::deque<FH> todo;
    push_start_faces(cdt, regions[r].at, todo);
    while (!todo.empty()) {
      FH g = todo.front();
      todo.pop_front();
      if (cdt.is_infinite(g) || !g->info().in_domain || !seen.insert(g).second) continue;
      g->info().region = region;
      for (int i = 0; i < 3; ++i)
        if (!g->is_constrained(i)) todo.push_back(g->neighbor(i));
    }
  }
}

Mesh extract_mesh(const Triangulation& tr) {
  Mesh mesh;
  mesh.vertices = tr.coords;
  mesh.input_vertices = tr.input_vertices;
  std::set<std::pair<int, int>> edges;
  for (FH f : tr.cdt.finite_face_handles()) {
    if (!f->info().in_domain) continue;
    mesh.triangles.push_back({id(f->vertex(0)), id(f->vertex(1)), id(f->vertex(2))});
    for (int i = 0; i < 3; ++i) {
      if (!f->is_constrained(i)) continue;
      edges.insert(edge_key(id(f->vertex(Cdt::ccw(i))), id(f->vertex(Cdt::cw(i)))));
    }
  }
  for (const auto& e : edges) mesh.constrained_edges.push_back({e.first, e.second, tr.segment_of_edge.at(e)});
  canonicalize(mesh);
  return mesh;
}

std::int64_t count_cocircular_edges(const Triangulation& tr) {
  std::int64_t ties = 0;
  for (FH f : tr.cdt.finite_face_handles()) {
    if (!f->info().in_domain) continue;
    for (int i = 0; i < 3; ++i) {
      FH n = f->neighbor(i);
      if (f->is_constrained(i) || !n->info().in_domain || f.operator->() > n.operator->()) continue;  // each edge once
      if (tr.cdt.side_of_oriented_circle(n, f->vertex(i)->point(), false) == CGAL::ON_ORIENTED_BOUNDARY) ++ties;
    }
  }
  return ties;
}

}  // namespace lepp::reference::detail

namespace lepp::reference {

Mesh build_cdt(const Pslg& pslg) {
  detail::Triangulation tr;
  detail::build_triangulation(pslg, tr);
  return detail::extract_mesh(tr);
}

}  // namespace lepp::reference
