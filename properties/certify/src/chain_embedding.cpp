// SPDX-License-Identifier: GPL-3.0-or-later
// The chains drawn as the segments are (chain_embedding.h): box intersection
// for candidate pairs, then exact signs.
#include "chain_embedding.h"

#include <algorithm>
#include <cmath>

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

// Calls f(v, i) for every used point v in the closed box of edge i, each pair once, by a
// uniform grid over the edges' boxes: a point is looked up in its one cell, an edge is
// listed in every cell its box covers. The cell of a coordinate is a monotone function
// of it (a subtraction, a product by a positive factor, a floor: each rounds monotonely),
// so a point inside a box has its cell inside the box's cells. False, with nothing
// called, when the edges' boxes would fill too many cells (long edges across the
// domain): box intersection then does it.
template <class F>
bool vertices_on_edges_by_grid(const std::vector<Point>& points, const std::vector<Box>& edge_boxes, const std::vector<char>& used, const F& f) {
  if (edge_boxes.empty()) return true;
  double x0 = edge_boxes[0].min_coord(0), y0 = edge_boxes[0].min_coord(1), x1 = edge_boxes[0].max_coord(0), y1 = edge_boxes[0].max_coord(1);
  for (const Box& b : edge_boxes) {
    x0 = std::min(x0, b.min_coord(0)), y0 = std::min(y0, b.min_coord(1));
    x1 = std::max(x1, b.max_coord(0)), y1 = std::max(y1, b.max_coord(1));
  }
  if (!(std::isfinite(x1 - x0) && std::isfinite(y1 - y0))) return false;
  // About as many cells as edges along each side of a square domain's boundary squared.
  const std::size_t side = std::clamp<std::size_t>(static_cast<std::size_t>(std::sqrt(static_cast<double>(edge_boxes.size()))) * 4, 1, 4096);
  const double fx = x1 > x0 ? static_cast<double>(side) / (x1 - x0) : 0, fy = y1 > y0 ? static_cast<double>(side) / (y1 - y0) : 0;
  if (!(std::isfinite(fx) && std::isfinite(fy))) return false;
  auto cell = [side](double c, double c0, double f) {
    const double k = std::floor((c - c0) * f);
    return k <= 0 ? std::size_t{0} : k >= static_cast<double>(side - 1) ? side - 1 : static_cast<std::size_t>(k);
  };
  std::size_t listed = 0;
  for (const Box& b : edge_boxes)
    listed += (cell(b.max_coord(0), x0, fx) - cell(b.min_coord(0), x0, fx) + 1) * (cell(b.max_coord(1), y0, fy) - cell(b.min_coord(1), y0, fy) + 1);
  if (listed > 8 * edge_boxes.size() + points.size()) return false;
  std::vector<int> begin(side * side + 1, 0), in_cell(listed);
  auto each_cell = [&](const Box& b, auto&& g) {
    for (std::size_t i = cell(b.min_coord(0), x0, fx); i <= cell(b.max_coord(0), x0, fx); ++i)
      for (std::size_t j = cell(b.min_coord(1), y0, fy); j <= cell(b.max_coord(1), y0, fy); ++j) g(i * side + j);
  };
  for (const Box& b : edge_boxes) each_cell(b, [&](std::size_t c) { ++begin[c + 1]; });
  for (std::size_t c = 0; c < side * side; ++c) begin[c + 1] += begin[c];
  // The pairs the grid would test: a cluster (many vertices and edges in one cell,
  // the rest of the domain far away) makes them quadratic; box intersection's
  // sweep, which reports only the pairs whose boxes meet, is the caller's then.
  std::size_t pairs = 0;
  for (std::size_t v = 0; v < points.size(); ++v) {
    const Point& p = points[v];
    if (!used[v] || !(p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1)) continue;
    const std::size_t c = cell(p.x, x0, fx) * side + cell(p.y, y0, fy);
    pairs += static_cast<std::size_t>(begin[c + 1] - begin[c]);
  }
  if (pairs > 16 * (edge_boxes.size() + points.size())) return false;
  std::vector<int> next(begin.begin(), begin.end() - 1);
  // Positions in edge_boxes (box intersection may have reordered them; info() is the edge).
  for (std::size_t i = 0; i < edge_boxes.size(); ++i)
    each_cell(edge_boxes[i], [&](std::size_t c) { in_cell[static_cast<std::size_t>(next[c]++)] = static_cast<int>(i); });
  for (std::size_t v = 0; v < points.size(); ++v) {
    const Point& p = points[v];
    if (!used[v] || !(p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1)) continue;  // in no box (NaN: none either)
    const std::size_t c = cell(p.x, x0, fx) * side + cell(p.y, y0, fy);
    for (int k = begin[c]; k < begin[c + 1]; ++k) {
      const Box& b = edge_boxes[static_cast<std::size_t>(in_cell[static_cast<std::size_t>(k)])];
      if (p.x >= b.min_coord(0) && p.x <= b.max_coord(0) && p.y >= b.min_coord(1) && p.y <= b.max_coord(1)) f(static_cast<int>(v), b.info());
    }
  }
  return true;
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
  auto on_edge_at = [&](int v, int i) {
    const std::array<int, 2>& e = edges[static_cast<std::size_t>(i)];
    if (v != e[0] && v != e[1] && exact::orient(P(e[0]), P(e[1]), P(v)) == 0) found.push_back({i, -1, v});
  };
  if (vertices_on_edges_by_grid(points, edge_boxes, used, on_edge_at)) return found;
  std::vector<Box> vertex_boxes;
  for (std::size_t v = 0; v < points.size(); ++v)
    if (used[v]) vertex_boxes.push_back(box_of(points[v], points[v], static_cast<int>(v)));
  auto on_edge = [&](const Box& vb, const Box& eb) { on_edge_at(vb.info(), eb.info()); };
  CGAL::box_intersection_d(vertex_boxes.begin(), vertex_boxes.end(), edge_boxes.begin(), edge_boxes.end(), on_edge, std::ptrdiff_t(10),
                           CGAL::Box_intersection_d::CLOSED, CGAL::Box_intersection_d::BIPARTITE);
  return found;
}

}  // namespace lepp::certify
