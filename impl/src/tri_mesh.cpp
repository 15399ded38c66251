// SPDX-License-Identifier: GPL-3.0-or-later
// The cold parts of the flat mesh: segment membership and conversion to Mesh.
#include "tri_mesh.h"

#include <fmt/format.h>

#include "capacity.h"

#include <algorithm>
#include <cstdint>
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
    mesh.triangles.push_back({f.v(0), f.v(1), f.v(2)});
    for (int i = 0; i < 3; ++i) {
      if (f.seg(i) < 0) continue;
      // Each constrained edge once: from its only triangle, or from the lower id.
      if (f.nbr[i] >= 0 && nbr_tri(f.nbr[i]) < ti) continue;
      int a = f.v(next3(i)), b = f.v(prev3(i));
      mesh.constrained_edges.push_back({a, b, membership.segment_of(a, b)});
    }
  }
  return mesh;
}

IdLimits& id_limits() {
  static IdLimits limits;
  return limits;
}

void check_capacity(std::int64_t vertices, std::int64_t triangles, std::int64_t steiner) {
  const IdLimits limits = id_limits();
  if (ids_fit(vertices, triangles, limits)) return;
  if (steiner == kInputOnly)
    throw CapacityError(fmt::format(
        "the input outgrows the fast engine: {} vertices, whose triangulation may need {} triangles, where its ids "
        "number at most {} vertices and {} triangles; the reference engine (--engine reference) has no such limit",
        vertices, triangles, limits.vertices, limits.triangles));
  throw CapacityError(fmt::format(
      "the mesh outgrows the fast engine: {} vertices and {} triangles, where its ids number at most {} vertices "
      "and {} triangles; a larger --max-area, or --max-steiner {} to stop before it (exit 3)",
      vertices, triangles, limits.vertices, limits.triangles, steiner));
}

}  // namespace lepp::fast
