// SPDX-License-Identifier: GPL-3.0-or-later
// The chains drawn as the segments are (chain_embedding.h): box intersection
// for candidate pairs, then exact signs.
#include "chain_embedding.h"

#include <algorithm>

#include <CGAL/Bbox_2.h>
#include <CGAL/box_intersection_d.h>

#include "exact.h"
#include "lepp/boundary_sliver.h"

namespace lepp::certify {
namespace {

using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 2, int>;

Box box_of(const Point& u, const Point& w, int info) {
  return Box(CGAL::Bbox_2(std::min(u.x, w.x), std::min(u.y, w.y), std::max(u.x, w.x), std::max(u.y, w.y)), info);
}

}  // namespace

std::vector<ChainMeet> chain_meetings(const std::vector<Point>& points, const std::vector<std::array<int, 2>>& edges,
                                      const std::vector<char>& used) {
  auto P = [&](int v) -> const Point& { return points[static_cast<std::size_t>(v)]; };
  std::vector<Box> edge_boxes;
  edge_boxes.reserve(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) edge_boxes.push_back(box_of(P(edges[i][0]), P(edges[i][1]), static_cast<int>(i)));
  std::vector<ChainMeet> found;

  // Edge against edge. Sharing an endpoint u, edges u-x and u-y meet elsewhere
  // iff they run along one line the same way from u (collinear, dot product > 0);
  // sharing none, iff the closed segments share a point.
  auto pair = [&](const Box& b1, const Box& b2) {
    const std::array<int, 2>&e = edges[static_cast<std::size_t>(b1.info())], &f = edges[static_cast<std::size_t>(b2.info())];
    int u = -1, x = -1, y = -1;
    for (int i = 0; i < 2; ++i)
      for (int j = 0; j < 2; ++j)
        if (e[i] == f[j]) u = e[i], x = e[1 - i], y = f[1 - j];
    bool meet = false;
    if (u >= 0) {
      // Collinear from U, X - U and Y - U point the same way iff their coordinates'
      // signs agree (comparisons of doubles: exact).
      const Point &U = P(u), &X = P(x), &Y = P(y);
      auto sgn = [](double s, double t) { return (s > t) - (s < t); };
      meet = exact::orient(U, X, Y) == 0 && sgn(X.x, U.x) == sgn(Y.x, U.x) && sgn(X.y, U.y) == sgn(Y.y, U.y);
    } else {
      meet = closed_segments_meet(P(e[0]), P(e[1]), P(f[0]), P(f[1]), exact::orient);
    }
    if (meet) found.push_back({b1.info(), b2.info(), -1});
  };
  CGAL::box_self_intersection_d(edge_boxes.begin(), edge_boxes.end(), pair);

  // Vertex against edge: a mesh vertex (in a triangle) on an edge's interior. The
  // closed boxes meet, so the vertex is in the edge's box: on the closed segment iff
  // collinear.
  std::vector<Box> vertex_boxes;
  for (std::size_t v = 0; v < points.size(); ++v)
    if (used[v]) vertex_boxes.push_back(box_of(points[v], points[v], static_cast<int>(v)));
  auto on_edge = [&](const Box& vb, const Box& eb) {
    const int v = vb.info();
    const std::array<int, 2>& e = edges[static_cast<std::size_t>(eb.info())];
    if (v != e[0] && v != e[1] && exact::orient(P(e[0]), P(e[1]), P(v)) == 0) found.push_back({eb.info(), -1, v});
  };
  CGAL::box_intersection_d(vertex_boxes.begin(), vertex_boxes.end(), edge_boxes.begin(), edge_boxes.end(), on_edge, std::ptrdiff_t(10),
                           CGAL::Box_intersection_d::CLOSED, CGAL::Box_intersection_d::BIPARTITE);
  return found;
}

}  // namespace lepp::certify
