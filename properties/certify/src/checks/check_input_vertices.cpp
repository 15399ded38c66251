// SPDX-License-Identifier: GPL-3.0-or-later
// The input-vertex check on the built index: no triangle covers an input vertex outside the domain.
#include <algorithm>

#include "../exact.h"
#include "../passes.h"
#include "lepp/certify/checks.h"

namespace lepp::certify {
namespace pass {

// An input vertex outside the domain may be in no triangle, but then must lie in
// none: a triangle covering it (on its closed area, not at a corner) makes the
// mesh no triangulation of its vertices there. The coverage checks count sides
// of segments and the Euler characteristic, which a vertex in no triangle does
// not enter, so they do not see it (a boundary split whose rounded midpoint,
// half an ulp outside, takes such a vertex into its sliver: ALGORITHM.md
// section 8b). Sweep by x: such vertices are few, usually none.
void check_outside_vertices_uncovered(Certification& cert) {
  const MeshIndex& ix = cert.index;
  std::vector<int> loose;  // input ids: outside the domain, a vertex of no triangle
  for (std::size_t i = 0; i < ix.pslg.vertices.size(); ++i) {
    const int m = ix.input_to_mesh[i];
    if (!ix.domain.vertex_in_domain[i] && (m < 0 || !ix.used[static_cast<std::size_t>(m)])) loose.push_back(static_cast<int>(i));
  }
  if (loose.empty()) return;
  auto X = [&](int i) { return ix.pslg.vertices[static_cast<std::size_t>(i)].x; };
  std::sort(loose.begin(), loose.end(), [&](int i, int j) { return X(i) < X(j); });
  for (std::size_t t = 0; t < ix.mesh.triangles.size(); ++t) {
    if (!ix.tri_ok[t]) continue;
    const Point &a = ix.P(ix.T(t)[0]), &b = ix.P(ix.T(t)[1]), &c = ix.P(ix.T(t)[2]);
    if (!finite(a) || !finite(b) || !finite(c) || exact::orient(a, b, c) <= 0) continue;  // reported in section 1
    const double x0 = std::min({a.x, b.x, c.x}), x1 = std::max({a.x, b.x, c.x});
    const double y0 = std::min({a.y, b.y, c.y}), y1 = std::max({a.y, b.y, c.y});
    auto it = std::lower_bound(loose.begin(), loose.end(), x0, [&](int i, double x) { return X(i) < x; });
    for (; it != loose.end() && X(*it) <= x1; ++it) {
      const Point& q = ix.pslg.vertices[static_cast<std::size_t>(*it)];
      if (q.y < y0 || q.y > y1 || q == a || q == b || q == c) continue;
      if (exact::orient(a, b, q) < 0 || exact::orient(b, c, q) < 0 || exact::orient(c, a, q) < 0) continue;
      cert.add({Reason::InputVertexMissing,
                fmt::format("input vertex {} {} (outside the domain) lies on {} but is not one of its vertices", *it, pt(q), ix.tri_text(t)),
                {static_cast<int>(t)}, {}, {*it}, {q}, -1});
    }
  }
}

void input_vertices(Certification& cert) { check_outside_vertices_uncovered(cert); }

}  // namespace pass

Report check_input_vertices(const Pslg& pslg, const Mesh& mesh, const Options& options) {
  return pass::run_alone(Check::InputVertices, pass::input_vertices, pslg, mesh, options);
}

}  // namespace lepp::certify
