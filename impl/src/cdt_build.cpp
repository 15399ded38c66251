// SPDX-License-Identifier: GPL-3.0-or-later
// Initial CDT: CGAL's Constrained_Delaunay_triangulation_2 on Epick (bulk point
// insertion, which sorts spatially, then the segments), copied into flat arrays
// and flooded from the outside and from hole points without crossing a segment.
// The CDT of points with no four cocircular is unique, so the reference's CDT
// (on Epeck) is the same triangulation.
#include "cdt_build.h"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "predicates.h"

namespace lepp::fast {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int, K>;
using Fb = CGAL::Triangulation_face_base_with_info_2<int, K, CGAL::Constrained_triangulation_face_base_2<K>>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::No_constraint_intersection_tag>;

// The triangles a hole or region point starts its flood from: the one it lies in, or
// both sides of the unconstrained edge it lies on; none on a constrained edge or a
// vertex (it removes or sets nothing there, as Triangle reads it).
template <class Visit>
void start_faces(const Cdt& cdt, const Point& p, Visit visit) {
  Cdt::Locate_type lt;
  int li = 0;
  auto f = cdt.locate(K::Point_2(p.x, p.y), lt, li);
  if (lt == Cdt::FACE) {
    visit(f->info());
  } else if (lt == Cdt::EDGE && !f->is_constrained(li)) {
    visit(f->info());
    visit(f->neighbor(li)->info());
  }
}

}  // namespace

TriMesh build_initial_cdt(const Pslg& pslg, const SegmentMembership& membership, std::size_t reserve_triangles,
                          std::size_t reserve_vertices, std::int64_t* cocircular_ties, bool regions) {
  Cdt cdt;
  {
    std::vector<std::pair<K::Point_2, int>> points;
    points.reserve(pslg.vertices.size());
    for (std::size_t i = 0; i < pslg.vertices.size(); ++i)
      points.emplace_back(K::Point_2(pslg.vertices[i].x, pslg.vertices[i].y), static_cast<int>(i));
    cdt.insert(points.begin(), points.end());
  }
  std::vector<Cdt::Vertex_handle> handle(pslg.vertices.size());
  for (auto v : cdt.finite_vertex_handles()) handle[static_cast<std::size_t>(v->info())] = v;
  for (const Segment& s : pslg.segments)
    cdt.insert_constraint(handle[static_cast<std::size_t>(s.a)], handle[static_cast<std::size_t>(s.b)]);

  // Number the finite faces; the infinite ones get -1.
  int count = 0;
  for (auto f : cdt.all_face_handles()) f->info() = -1;
  for (auto f : cdt.finite_face_handles()) f->info() = count++;

  TriMesh all;
  all.tris.resize(static_cast<std::size_t>(count));
  for (auto f : cdt.finite_face_handles()) {
    int v[3], nbr[3];
    std::int8_t seg[3];
    for (int i = 0; i < 3; ++i) {
      v[i] = f->vertex(i)->info();
      auto g = f->neighbor(i);
      nbr[i] = g->info() < 0 ? -1 : nbr_code(g->info(), g->index(f));
      seg[i] = f->is_constrained(i) ? 0 : -1;
      if (f->is_constrained(i) &&
          membership.segment_of(f->vertex(Cdt::cw(i))->info(), f->vertex(Cdt::ccw(i))->info()) < 0)
        throw std::logic_error("fast engine: a constrained CDT edge is no input segment");
    }
    all.t(f->info()) = FTri(v, nbr, seg);
  }

  // Flood (Triangle's -p): from hull triangles across unconstrained hull edges
  // and from triangles holding a hole point; never across a constrained edge.
  std::vector<char> removed(static_cast<std::size_t>(count), 0);
  std::vector<int> stack;
  auto seed = [&](int ti) {
    if (ti >= 0 && !removed[static_cast<std::size_t>(ti)]) removed[static_cast<std::size_t>(ti)] = 1, stack.push_back(ti);
  };
  for (int ti = 0; ti < count; ++ti)
    for (int i = 0; i < 3; ++i)
      if (all.t(ti).nbr[i] < 0 && all.t(ti).seg(i) < 0) seed(ti);
  for (const Point& h : pslg.holes) start_faces(cdt, h, seed);
  while (!stack.empty()) {
    int ti = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i)
      if (all.t(ti).seg(i) < 0 && all.t(ti).nbr[i] >= 0) seed(nbr_tri(all.t(ti).nbr[i]));
  }

  // Regions (Triangle's order): each region point, in file order, floods the
  // domain triangles around it without crossing a constrained edge, overwriting
  // what earlier regions set. A point in a removed triangle, on a constrained
  // edge or on a vertex sets nothing (as a hole point removes nothing there).
  std::vector<std::int32_t> region_of;
  if (regions) {
    region_of.assign(static_cast<std::size_t>(count), 0);
    std::vector<int> pass(static_cast<std::size_t>(count), -1);
    for (std::size_t r = 0; r < pslg.regions.size(); ++r) {
      const int mark = static_cast<int>(r);
      auto reach = [&](int ti) {
        if (ti < 0 || removed[static_cast<std::size_t>(ti)] || pass[static_cast<std::size_t>(ti)] == mark) return;
        pass[static_cast<std::size_t>(ti)] = mark;
        region_of[static_cast<std::size_t>(ti)] = mark + 1;
        stack.push_back(ti);
      };
      start_faces(cdt, pslg.regions[r].at, reach);
      while (!stack.empty()) {
        int ti = stack.back();
        stack.pop_back();
        for (int i = 0; i < 3; ++i)
          if (all.t(ti).seg(i) < 0 && all.t(ti).nbr[i] >= 0) reach(nbr_tri(all.t(ti).nbr[i]));
      }
    }
  }

  // Keep the domain, renumbered in the order CGAL listed it.
  std::vector<int> new_id(static_cast<std::size_t>(count), -1);
  int kept = 0;
  for (int ti = 0; ti < count; ++ti)
    if (!removed[static_cast<std::size_t>(ti)]) new_id[static_cast<std::size_t>(ti)] = kept++;
  TriMesh mesh;
  if (regions) mesh.region.assign(1, 0);  // non-empty, so that reserve() covers it
  mesh.reserve(std::max(reserve_vertices, pslg.vertices.size()), std::max(reserve_triangles, static_cast<std::size_t>(kept)));
  mesh.pts = pslg.vertices;
  for (int ti = 0; ti < count; ++ti) {
    if (removed[static_cast<std::size_t>(ti)]) continue;
    FTri t = all.t(ti);
    for (int i = 0; i < 3; ++i) {
      if (t.nbr[i] < 0) continue;
      int n = new_id[static_cast<std::size_t>(nbr_tri(t.nbr[i]))];
      if (n < 0) {
        if (t.seg(i) < 0) throw std::logic_error("fast engine: flooding crossed an unconstrained edge");
        t.nbr[i] = -1;
      } else {
        t.nbr[i] = nbr_code(n, nbr_edge(t.nbr[i]));
      }
    }
    mesh.tris.push_back(t);
  }
  mesh.stamp.assign(mesh.tris.size(), 0);
  if (regions) {
    mesh.region.clear();
    for (int ti = 0; ti < count; ++ti)
      if (!removed[static_cast<std::size_t>(ti)]) mesh.region.push_back(region_of[static_cast<std::size_t>(ti)]);
  }
  if (cocircular_ties) {
    *cocircular_ties = 0;
    for (int ti = 0; ti < mesh.size(); ++ti) {
      const FTri& f = mesh.t(ti);
      for (int i = 0; i < 3; ++i) {
        if (f.seg(i) >= 0 || f.nbr[i] < 0 || nbr_tri(f.nbr[i]) < ti) continue;
        const FTri& g = mesh.t(nbr_tri(f.nbr[i]));
        if (incircle(mesh.p(f.v(0)), mesh.p(f.v(1)), mesh.p(f.v(2)), mesh.p(g.v(nbr_edge(f.nbr[i])))) == 0)
          ++*cocircular_ties;
      }
    }
  }
  return mesh;
}

}  // namespace lepp::fast
