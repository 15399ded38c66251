// The cold parts of the flat mesh: segment membership and conversion to Mesh.
#include "tri_mesh.h"

#include <algorithm>
#include <utility>

namespace lepp::fast {

SegmentMembership make_membership(const Pslg& pslg) {
  SegmentMembership m;
  m.input_vertices = static_cast<int>(pslg.vertices.size());
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

Mesh TriMesh::to_mesh(std::size_t input_vertices) const {
  Mesh mesh;
  mesh.vertices = pts;
  mesh.input_vertices = input_vertices;
  mesh.triangles.reserve(tris.size());
  for (int ti = 0; ti < size(); ++ti) {
    const FTri& f = t(ti);
    mesh.triangles.push_back({f.v[0], f.v[1], f.v[2]});
    for (int i = 0; i < 3; ++i) {
      if (f.seg[i] < 0) continue;
      // Each constrained edge once: from its only triangle, or from the lower id.
      if (f.nbr[i] >= 0 && nbr_tri(f.nbr[i]) < ti) continue;
      mesh.constrained_edges.push_back({f.v[next3(i)], f.v[prev3(i)], f.seg[i]});
    }
  }
  return mesh;
}

Mesh TriMesh::to_canonical_mesh(std::size_t input_vertices) const {
  Mesh raw = to_mesh(input_vertices);
  Mesh mesh;
  mesh.input_vertices = input_vertices;
  mesh.vertices = std::move(raw.vertices);
  const std::size_t nv = mesh.vertices.size();
  // Triangles: rotate to the smallest id, bucket by it, then order each (small) bucket.
  for (Tri& t : raw.triangles)
    while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
  std::vector<std::size_t> start(nv + 1, 0);
  for (const Tri& t : raw.triangles) ++start[static_cast<std::size_t>(t[0]) + 1];
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  mesh.triangles.resize(raw.triangles.size());
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (const Tri& t : raw.triangles) mesh.triangles[fill[static_cast<std::size_t>(t[0])]++] = t;
  }
  raw.triangles = {};
  for (std::size_t v = 0; v < nv; ++v)
    std::sort(mesh.triangles.begin() + static_cast<std::ptrdiff_t>(start[v]),
              mesh.triangles.begin() + static_cast<std::ptrdiff_t>(start[v + 1]));
  // Constrained edges: a < b, then the same bucket order by a.
  for (ConstrainedEdge& e : raw.constrained_edges)
    if (e.a > e.b) std::swap(e.a, e.b);
  std::fill(start.begin(), start.end(), 0);
  for (const ConstrainedEdge& e : raw.constrained_edges) ++start[static_cast<std::size_t>(e.a) + 1];
  for (std::size_t v = 0; v < nv; ++v) start[v + 1] += start[v];
  mesh.constrained_edges.resize(raw.constrained_edges.size());
  {
    std::vector<std::size_t> fill(start.begin(), start.end() - 1);
    for (const ConstrainedEdge& e : raw.constrained_edges) mesh.constrained_edges[fill[static_cast<std::size_t>(e.a)]++] = e;
  }
  for (std::size_t v = 0; v < nv; ++v)
    std::sort(mesh.constrained_edges.begin() + static_cast<std::ptrdiff_t>(start[v]),
              mesh.constrained_edges.begin() + static_cast<std::ptrdiff_t>(start[v + 1]),
              [](const ConstrainedEdge& x, const ConstrainedEdge& y) {
                return x.b != y.b ? x.b < y.b : x.segment < y.segment;
              });
  return mesh;
}

}  // namespace lepp::fast
