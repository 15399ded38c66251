// SPDX-License-Identifier: GPL-3.0-or-later
// Boundary markers and regions of an output mesh, from its input PSLG.
#include "lepp/mesh_labels.h"

#include <cstdint>
#include <unordered_set>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace lepp {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

std::uint64_t edge_key(int a, int b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

int sign(const Point& a, const Point& b, const Point& c) {
  return static_cast<int>(CGAL::orientation(K::Point_2(a.x, a.y), K::Point_2(b.x, b.y), K::Point_2(c.x, c.y)));
}

// The triangle a region point floods from, or -1 (the rule in lepp/mesh_labels.h).
// A Steiner vertex off every segment was inside a face or an unconstrained edge
// of the input's triangulation, where the engines flood; an input vertex or a
// point on a segment marks nothing.
int start_triangle(const Mesh& mesh, const Point& p, const std::unordered_set<std::uint64_t>& constrained,
                   const std::vector<char>& on_segment) {
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Tri& tri = mesh.triangles[t];
    const Point* v[3];
    for (int k = 0; k < 3; ++k) v[k] = &mesh.vertices[static_cast<std::size_t>(tri[static_cast<std::size_t>(k)])];
    const int s = sign(*v[0], *v[1], *v[2]);
    if (s == 0) continue;  // a degenerate triangle contains nothing
    int o[3], zeros = 0;
    bool outside = false;
    for (int k = 0; k < 3; ++k) {
      o[k] = s * sign(*v[k], *v[(k + 1) % 3], p);
      if (o[k] < 0) outside = true;
      zeros += o[k] == 0;
    }
    if (outside) continue;
    if (zeros == 0) return static_cast<int>(t);
    if (zeros == 1) {
      for (int k = 0; k < 3; ++k)
        if (o[k] == 0)
          return constrained.count(edge_key(tri[static_cast<std::size_t>(k)], tri[static_cast<std::size_t>((k + 1) % 3)]))
                     ? -1
                     : static_cast<int>(t);
    }
    // On a vertex: the corner where the two sides p lies on meet.
    for (int k = 0; k < 3; ++k)
      if (o[k] == 0 && o[(k + 2) % 3] == 0) {
        const auto w = static_cast<std::size_t>(tri[static_cast<std::size_t>(k)]);
        return w < mesh.input_vertices || on_segment[w] ? -1 : static_cast<int>(t);
      }
    return -1;
  }
  return -1;
}

}  // namespace

std::vector<int> triangle_regions(const Mesh& mesh, const std::vector<Region>& regions) {
  const std::size_t n = mesh.vertices.size(), m = mesh.triangles.size();
  std::vector<int> region(m, 0);
  if (regions.empty() || m == 0) return region;

  std::unordered_set<std::uint64_t> constrained;
  std::vector<char> on_segment(n, 0);
  for (const ConstrainedEdge& e : mesh.constrained_edges) {
    constrained.insert(edge_key(e.a, e.b));
    on_segment[static_cast<std::size_t>(e.a)] = on_segment[static_cast<std::size_t>(e.b)] = 1;
  }
  // Triangles around each vertex (compressed rows), to find the neighbour across an edge.
  std::vector<std::size_t> first(n + 1, 0);
  for (const Tri& t : mesh.triangles)
    for (int v : t) ++first[static_cast<std::size_t>(v) + 1];
  for (std::size_t v = 0; v < n; ++v) first[v + 1] += first[v];
  std::vector<int> around(first[n]);
  {
    std::vector<std::size_t> fill(first.begin(), first.end() - 1);
    for (std::size_t t = 0; t < m; ++t)
      for (int v : mesh.triangles[t]) around[fill[static_cast<std::size_t>(v)]++] = static_cast<int>(t);
  }
  auto has = [](const Tri& t, int v) { return t[0] == v || t[1] == v || t[2] == v; };

  std::vector<int> seen(m, -1);  // the last region whose flood reached the triangle
  std::vector<int> stack;
  for (std::size_t r = 0; r < regions.size(); ++r) {
    const int start = start_triangle(mesh, regions[r].at, constrained, on_segment);
    if (start < 0) continue;
    stack.assign(1, start);
    seen[static_cast<std::size_t>(start)] = static_cast<int>(r);
    while (!stack.empty()) {
      const auto t = static_cast<std::size_t>(stack.back());
      stack.pop_back();
      region[t] = static_cast<int>(r) + 1;
      const Tri& tri = mesh.triangles[t];
      for (int k = 0; k < 3; ++k) {
        const int a = tri[static_cast<std::size_t>(k)], b = tri[static_cast<std::size_t>((k + 1) % 3)];
        if (constrained.count(edge_key(a, b))) continue;
        for (std::size_t i = first[static_cast<std::size_t>(a)]; i < first[static_cast<std::size_t>(a) + 1]; ++i) {
          const int u = around[i];
          if (static_cast<std::size_t>(u) == t || !has(mesh.triangles[static_cast<std::size_t>(u)], b)) continue;
          if (seen[static_cast<std::size_t>(u)] != static_cast<int>(r)) {
            seen[static_cast<std::size_t>(u)] = static_cast<int>(r);
            stack.push_back(u);
          }
        }
      }
    }
  }
  return region;
}

MeshLabels mesh_labels(const Mesh& mesh, const Pslg& input) {
  MeshLabels labels;
  labels.edge_markers.reserve(mesh.constrained_edges.size());
  for (const ConstrainedEdge& e : mesh.constrained_edges)
    labels.edge_markers.push_back(e.segment >= 0 && static_cast<std::size_t>(e.segment) < input.segments.size()
                                      ? input.segments[static_cast<std::size_t>(e.segment)].marker
                                      : 0);
  if (!input.regions.empty()) labels.triangle_regions = triangle_regions(mesh, input.regions);
  labels.region_count = static_cast<int>(input.regions.size());
  return labels;
}

}  // namespace lepp
