// SPDX-License-Identifier: GPL-3.0-or-later
// The cold parts of the flat mesh: segment membership and conversion to Mesh.
#include "tri_mesh.h"

#include <algorithm>
#include <cstdint>
#include <tuple>
#include <utility>

namespace lepp::fast {

SegmentMembership make_membership(const Pslg& pslg) {
  SegmentMembership m;
  m.input_vertices = static_cast<int>(pslg.vertices.size());
  m.segments = &pslg.segments;
  m.start.assign(pslg.vertices.size() + 1, 0);
  for (const Segment& s : pslg.segments) {
    ++m.start[static_cast<std::size_t>(s.a) + 1];
    ++m.start[static_cast<std::size_t>(s.b) + 1];
  }
  for (std::size_t v = 0; v < pslg.vertices.size(); ++v) m.start[v + 1] += m.start[v];
  m.list.resize(2 * pslg.segments.size());
  std::vector<int> fill(m.start.begin(), m.start.end() - 1);
  // Segment ids ascend within each vertex's list.
  for (std::size_t k = 0; k < pslg.segments.size(); ++k) {
    const Segment& s = pslg.segments[k];
    m.list[static_cast<std::size_t>(fill[static_cast<std::size_t>(s.a)]++)] = static_cast<int>(k);
    m.list[static_cast<std::size_t>(fill[static_cast<std::size_t>(s.b)]++)] = static_cast<int>(k);
  }
  return m;
}

void TriMesh::reserve(std::size_t vertices, std::size_t triangles) {
  pts.reserve(vertices);
  tris.reserve(triangles);
  stamp.reserve(triangles);
  if (!region.empty()) region.reserve(triangles);
}

Mesh TriMesh::to_mesh(const SegmentMembership& membership) const {
  Mesh mesh;
  mesh.vertices = pts;
  mesh.input_vertices = static_cast<std::size_t>(membership.input_vertices);
  mesh.triangles.reserve(tris.size());
  for (int ti = 0; ti < size(); ++ti) {
    const FTri& f = t(ti);
    mesh.triangles.push_back({f.v[0], f.v[1], f.v[2]});
    for (int i = 0; i < 3; ++i) {
      if (f.seg[i] < 0) continue;
      // Each constrained edge once: from its only triangle, or from the lower id.
      if (f.nbr[i] >= 0 && nbr_tri(f.nbr[i]) < ti) continue;
      int a = f.v[next3(i)], b = f.v[prev3(i)];
      mesh.constrained_edges.push_back({a, b, membership.segment_of(a, b)});
    }
  }
  return mesh;
}

Mesh TriMesh::take_canonical_mesh(const SegmentMembership& membership) {
  Mesh mesh;
  mesh.input_vertices = static_cast<std::size_t>(membership.input_vertices);
  const std::size_t nv = pts.size();
  mesh.vertices = std::move(pts);
  pts = {};
  // Freed before the output's arrays are made: the peak memory is here.
  stamp = {};
  region = {};
  auto rotated = [](const FTri& f) {
    Tri t{f.v[0], f.v[1], f.v[2]};
    while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
    return t;
  };
  // Triangles: bucket by the smallest id (counting sort), then order each small bucket.
  std::vector<std::uint32_t> start(nv + 1, 0);
  for (const FTri& f : tris) ++start[static_cast<std::size_t>(std::min({f.v[0], f.v[1], f.v[2]})) + 1];
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  mesh.triangles.resize(tris.size());
  std::vector<ConstrainedEdge> edges;
  {
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (int ti = 0; ti < size(); ++ti) {
      const FTri& f = t(ti);
      Tri r = rotated(f);
      mesh.triangles[fill[static_cast<std::size_t>(r[0])]++] = r;
      for (int i = 0; i < 3; ++i) {
        if (f.seg[i] < 0 || (f.nbr[i] >= 0 && nbr_tri(f.nbr[i]) < ti)) continue;
        int a = f.v[next3(i)], b = f.v[prev3(i)];
        edges.push_back({std::min(a, b), std::max(a, b), membership.segment_of(a, b)});
      }
    }
  }
  tris = {};
  for (std::size_t v = 0; v < nv; ++v)
    std::sort(mesh.triangles.begin() + start[v], mesh.triangles.begin() + start[v + 1]);
  // Constrained edges: few; a plain sort in canonicalize's order.
  std::sort(edges.begin(), edges.end(), [](const ConstrainedEdge& x, const ConstrainedEdge& y) {
    return std::tie(x.a, x.b, x.segment) < std::tie(y.a, y.b, y.segment);
  });
  mesh.constrained_edges = std::move(edges);
  return mesh;
}

}  // namespace lepp::fast
