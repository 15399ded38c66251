// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind mesh_invariants.h: the fast engine's own invariants, checked
// independently of its code (CGAL's exact predicates and rationals).
#include "mesh_invariants.h"

#include <algorithm>
#include <map>
#include <set>
#include <utility>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <fmt/format.h>

#include "lepp/angle.h"

namespace lepp::impl_test {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Q = CGAL::Exact_rational;
K::Point_2 kp(const Point& p) { return {p.x, p.y}; }

// Smallest angle below theta, exactly: cross^2 < S |u|^2 |v|^2 at every vertex
// (the smallest angle is below theta iff some angle is, for theta < 60).
bool skinny(const Point& a, const Point& b, const Point& c, double s) {
  const Point* v[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i) {
    const Point &o = *v[i], &p = *v[(i + 1) % 3], &q = *v[(i + 2) % 3];
    Q ux = Q(p.x) - Q(o.x), uy = Q(p.y) - Q(o.y), wx = Q(q.x) - Q(o.x), wy = Q(q.y) - Q(o.y);
    Q cross = ux * wy - uy * wx;
    if (cross * cross < Q(s) * (ux * ux + uy * uy) * (wx * wx + wy * wy)) return true;
  }
  return false;
}
}  // namespace

std::vector<std::string> check_invariants(const Pslg& pslg, const Mesh& mesh, const InvariantOptions& options) {
  std::vector<std::string> out;
  const int nv = static_cast<int>(mesh.vertices.size());
  auto pt = [&](int v) { return mesh.vertices[static_cast<std::size_t>(v)]; };
  for (std::size_t i = 0; i < pslg.vertices.size() && i < mesh.vertices.size(); ++i)
    if (mesh.vertices[i] != pslg.vertices[i]) out.push_back(fmt::format("input vertex {} moved", i));

  std::map<std::pair<int, int>, int> directed;  // edge -> apex
  std::vector<char> used(static_cast<std::size_t>(nv), 0);
  for (const Tri& t : mesh.triangles) {
    bool ok = true;
    for (int v : t) ok = ok && v >= 0 && v < nv;
    if (!ok) {
      out.push_back("vertex id out of range");
      continue;
    }
    for (int v : t) used[static_cast<std::size_t>(v)] = 1;
    if (CGAL::orientation(kp(pt(t[0])), kp(pt(t[1])), kp(pt(t[2]))) != CGAL::LEFT_TURN)
      out.push_back(fmt::format("triangle {} {} {} not counter-clockwise", t[0], t[1], t[2]));
    for (int i = 0; i < 3; ++i)
      if (!directed.emplace(std::make_pair(t[i], t[(i + 1) % 3]), t[(i + 2) % 3]).second)
        out.push_back(fmt::format("edge {} {} used twice in the same direction", t[i], t[(i + 1) % 3]));
  }
  for (int v = static_cast<int>(pslg.vertices.size()); v < nv; ++v)
    if (!used[static_cast<std::size_t>(v)]) out.push_back(fmt::format("Steiner vertex {} in no triangle", v));

  std::map<std::pair<int, int>, int> constrained;
  for (const ConstrainedEdge& e : mesh.constrained_edges) {
    constrained[{std::min(e.a, e.b), std::max(e.a, e.b)}] = e.segment;
    if (!directed.count({e.a, e.b}) && !directed.count({e.b, e.a}))
      out.push_back(fmt::format("constrained edge {} {} is no mesh edge", e.a, e.b));
  }
  for (const auto& [edge, apex] : directed) {
    auto key = std::make_pair(std::min(edge.first, edge.second), std::max(edge.first, edge.second));
    bool is_constrained = constrained.count(key) > 0;
    auto twin = directed.find({edge.second, edge.first});
    if (twin == directed.end()) {
      if (!is_constrained) out.push_back(fmt::format("boundary edge {} {} not constrained", edge.first, edge.second));
      continue;
    }
    if (is_constrained || edge.first > edge.second) continue;
    // Locally Delaunay: the opposite apex not strictly inside the circumcircle.
    if (CGAL::side_of_oriented_circle(kp(pt(edge.first)), kp(pt(edge.second)), kp(pt(apex)), kp(pt(twin->second))) ==
        CGAL::ON_POSITIVE_SIDE)
      out.push_back(fmt::format("edge {} {} not locally Delaunay", edge.first, edge.second));
  }

  // Every segment with a constrained edge is a chain of them from end to end.
  std::map<int, std::multimap<int, int>> chains;
  for (const ConstrainedEdge& e : mesh.constrained_edges) {
    chains[e.segment].emplace(e.a, e.b);
    chains[e.segment].emplace(e.b, e.a);
  }
  for (std::size_t s = 0; s < pslg.segments.size(); ++s) {
    auto it = chains.find(static_cast<int>(s));
    if (it == chains.end()) continue;  // outside the domain (both sides removed)
    const auto& adj = it->second;
    int prev = -1, cur = pslg.segments[s].a, steps = 0;
    while (cur != pslg.segments[s].b && steps <= static_cast<int>(adj.size())) {
      int next = -1;
      for (auto r = adj.equal_range(cur); r.first != r.second; ++r.first)
        if (r.first->second != prev) next = r.first->second;
      if (next < 0) break;
      prev = cur, cur = next, ++steps;
    }
    if (cur != pslg.segments[s].b || 2 * steps != static_cast<int>(adj.size()))
      out.push_back(fmt::format("segment {} is not one chain of constrained edges", s));
  }

  std::set<std::array<int, 3>> exempt;
  for (const UnimprovableTriangle& u : options.unimprovable) {
    Tri t = u.triangle;
    std::sort(t.begin(), t.end());
    exempt.insert(t);
  }
  const double s = options.min_angle_deg > 0 ? engine_sin2_threshold(options.min_angle_deg) : 0;
  for (const Tri& t : mesh.triangles) {
    const Point &a = pt(t[0]), &b = pt(t[1]), &c = pt(t[2]);
    Tri key = t;
    std::sort(key.begin(), key.end());
    if (s > 0 && !exempt.count(key) && skinny(a, b, c, s))
      out.push_back(fmt::format("triangle {} {} {} below {} degrees", t[0], t[1], t[2], options.min_angle_deg));
    if (options.max_area > 0) {
      Q cross = (Q(b.x) - Q(a.x)) * (Q(c.y) - Q(a.y)) - (Q(b.y) - Q(a.y)) * (Q(c.x) - Q(a.x));
      if (cross > Q(2 * options.max_area))
        out.push_back(fmt::format("triangle {} {} {} larger than {}", t[0], t[1], t[2], options.max_area));
    }
  }
  return out;
}

std::vector<std::string> overlapping_triangles(const Mesh& mesh) {
  std::vector<std::string> out;
  auto pt = [&](int v) { return kp(mesh.vertices[static_cast<std::size_t>(v)]); };
  // Some edge line of t with every vertex of u on its closed outer (right) side.
  auto separates = [&](const Tri& t, const Tri& u) {
    for (int i = 0; i < 3; ++i) {
      const K::Point_2 a = pt(t[static_cast<std::size_t>(i)]), b = pt(t[static_cast<std::size_t>((i + 1) % 3)]);
      if (std::all_of(u.begin(), u.end(), [&](int v) { return CGAL::orientation(a, b, pt(v)) != CGAL::LEFT_TURN; })) return true;
    }
    return false;
  };
  const std::size_t n = mesh.triangles.size();
  std::vector<CGAL::Bbox_2> box(n);
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Tri& t = mesh.triangles[i];
    box[i] = pt(t[0]).bbox() + pt(t[1]).bbox() + pt(t[2]).bbox();
    order[i] = i;
  }
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return box[x].xmin() < box[y].xmin(); });
  for (std::size_t k = 0; k < n; ++k)  // a sweep in x: only pairs whose boxes overlap
    for (std::size_t l = k + 1; l < n && box[order[l]].xmin() <= box[order[k]].xmax(); ++l) {
      const std::size_t i = order[k], j = order[l];
      if (!CGAL::do_overlap(box[i], box[j])) continue;
      const Tri &t = mesh.triangles[i], &u = mesh.triangles[j];
      if (!separates(t, u) && !separates(u, t)) out.push_back(fmt::format("triangles {} and {} overlap", std::min(i, j), std::max(i, j)));
    }
  return out;
}

}  // namespace lepp::impl_test
