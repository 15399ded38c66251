// SPDX-License-Identifier: GPL-3.0-or-later
// The Delaunay triangulation of grid points (CGAL, exact predicates: integer
// coordinates are exact in double) and its interior terminal pairs, for the
// statements that measure d(M) to every vertex of a Delaunay mesh.
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <set>

#include "lepp/theorems/checks.h"

namespace lepp::theorems {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using DT = CGAL::Delaunay_triangulation_2<K>;

std::int64_t d2(const GridPoint& a, const GridPoint& b) {
  return (a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y);
}
GridPoint grid(const DT::Vertex_handle& v) {
  return {static_cast<std::int64_t>(v->point().x()), static_cast<std::int64_t>(v->point().y())};
}
}  // namespace

std::vector<TerminalInMesh> delaunay_terminal_pairs(const std::vector<GridPoint>& points) {
  std::set<std::pair<std::int64_t, std::int64_t>> unique;
  std::vector<K::Point_2> pts;
  std::vector<GridPoint> vertices;
  for (auto& p : points)
    if (unique.emplace(p.x, p.y).second) {
      pts.emplace_back(static_cast<double>(p.x), static_cast<double>(p.y));
      vertices.push_back(p);
    }
  DT dt(pts.begin(), pts.end());
  std::vector<TerminalInMesh> out;
  if (dt.dimension() < 2) return out;  // all points collinear: no triangles
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    DT::Face_handle f = e->first, g = f->neighbor(e->second);
    if (dt.is_infinite(f) || dt.is_infinite(g)) continue;
    GridPoint a = grid(f->vertex(DT::cw(e->second))), b = grid(f->vertex(DT::ccw(e->second)));
    GridPoint c = grid(f->vertex(e->second)), d = grid(g->vertex(g->index(f)));
    std::int64_t ab = d2(a, b);
    // AB a longest edge of both triangles (ties allowed): a terminal edge.
    if (d2(a, c) > ab || d2(b, c) > ab || d2(a, d) > ab || d2(b, d) > ab) continue;
    out.push_back({{a, b, c, d}, vertices});
  }
  return out;
}

}  // namespace lepp::theorems
