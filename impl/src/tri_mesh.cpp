// The cold parts of the flat mesh: segment membership and conversion to Mesh.
#include "tri_mesh.h"

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

}  // namespace lepp::fast
