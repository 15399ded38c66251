// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind expected_domain.h: the domain a correct mesh of a PSLG must cover,
// computed independently of any engine.
#include "expected_domain.h"

#include <cmath>
#include <queue>
#include <stdexcept>
#include <utility>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace lepp::certify {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fbb = CGAL::Triangulation_face_base_with_info_2<char, K>;  // 1: removed, exterior; 2: removed, hole
using Fb = CGAL::Constrained_triangulation_face_base_2<K, Fbb>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag>;

void flood(Cdt& cdt, std::queue<Cdt::Face_handle>& queue, char mark) {
  while (!queue.empty()) {
    Cdt::Face_handle f = queue.front();
    queue.pop();
    for (int i = 0; i < 3; ++i) {
      Cdt::Face_handle n = f->neighbor(i);
      if (n->info() == 0 && !cdt.is_constrained(Cdt::Edge(f, i))) {
        n->info() = mark;
        queue.push(n);
      }
    }
  }
}

// The engines' rule for a region point (ALGORITHM.md section 2), on this CDT.
RegionPlace region_place(const Cdt& cdt, const Point& at) {
  if (!std::isfinite(at.x) || !std::isfinite(at.y)) return RegionPlace::Outside;
  Cdt::Locate_type type;
  int li = 0;
  Cdt::Face_handle f = cdt.locate(K::Point_2(at.x, at.y), type, li);
  if (type == Cdt::VERTEX) return RegionPlace::OnVertex;
  if (type == Cdt::EDGE && cdt.is_constrained(Cdt::Edge(f, li))) return RegionPlace::OnSegment;
  if (type != Cdt::FACE && type != Cdt::EDGE) return RegionPlace::Outside;
  if (cdt.is_infinite(f) || f->info() == 1) return RegionPlace::Outside;
  return f->info() == 2 ? RegionPlace::InHole : RegionPlace::Floods;
}

}  // namespace

ExpectedDomain expected_domain(const Pslg& pslg) {
  Cdt cdt;
  std::vector<std::pair<K::Point_2, int>> points;
  points.reserve(pslg.vertices.size());
  for (std::size_t i = 0; i < pslg.vertices.size(); ++i)
    points.emplace_back(K::Point_2(pslg.vertices[i].x, pslg.vertices[i].y), static_cast<int>(i));
  cdt.insert(points.begin(), points.end());
  std::vector<Cdt::Vertex_handle> handle(pslg.vertices.size());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v)
    handle[static_cast<std::size_t>(v->info())] = v;
  for (const Segment& s : pslg.segments)
    cdt.insert_constraint(handle[static_cast<std::size_t>(s.a)], handle[static_cast<std::size_t>(s.b)]);

  ExpectedDomain d;
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = 0;
  std::queue<Cdt::Face_handle> queue;
  for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f)
    if (cdt.is_infinite(f)) {
      f->info() = 1;
      queue.push(f);
    }
  flood(cdt, queue, 1);
  for (const Point& h : pslg.holes) {
    Cdt::Locate_type type;
    int li = 0;
    Cdt::Face_handle f = cdt.locate(K::Point_2(h.x, h.y), type, li);
    // Inside a triangle, or on an unconstrained edge; on a vertex or a segment it removes nothing.
    bool removes = type == Cdt::FACE || (type == Cdt::EDGE && !cdt.is_constrained(Cdt::Edge(f, li)));
    if (removes && f->info() == 0) {
      f->info() = 2;
      queue.push(f);
      flood(cdt, queue, 2);
    }
  }
  for (const Region& r : pslg.regions) d.region_places.push_back(region_place(cdt, r.at));

  d.vertex_in_domain.assign(pslg.vertices.size(), 0);
  long faces = 0, edges = 0, vertices = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (f->info() != 0) continue;
    ++faces;
    for (int i = 0; i < 3; ++i) d.vertex_in_domain[static_cast<std::size_t>(f->vertex(i)->info())] = 1;
  }
  for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
    Cdt::Face_handle f = e->first, n = f->neighbor(e->second);
    if ((!cdt.is_infinite(f) && f->info() == 0) || (!cdt.is_infinite(n) && n->info() == 0)) ++edges;
  }
  for (char in : d.vertex_in_domain) vertices += in;
  d.euler = vertices - edges + faces;

  d.segment_sides.assign(pslg.segments.size(), 0);
  for (std::size_t s = 0; s < pslg.segments.size(); ++s) {
    Cdt::Vertex_handle va = handle[static_cast<std::size_t>(pslg.segments[s].a)];
    Cdt::Vertex_handle vb = handle[static_cast<std::size_t>(pslg.segments[s].b)];
    Cdt::Face_handle f;
    int i = 0;
    if (!cdt.is_edge(va, vb, f, i)) throw std::logic_error("certify: segment is not a CDT edge (PSLG not validated?)");
    Cdt::Face_handle n = f->neighbor(i);
    // Edge i of the CCW face f runs from vertex ccw(i) to vertex cw(i), f on its left.
    Cdt::Face_handle left = f->vertex(Cdt::ccw(i)) == va ? f : n;
    Cdt::Face_handle right = left == f ? n : f;
    unsigned char sides = 0;
    if (!cdt.is_infinite(left) && left->info() == 0) sides |= ExpectedDomain::Left;
    if (!cdt.is_infinite(right) && right->info() == 0) sides |= ExpectedDomain::Right;
    d.segment_sides[s] = sides;
  }
  return d;
}

}  // namespace lepp::certify
