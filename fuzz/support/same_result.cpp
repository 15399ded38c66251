// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind same_result.h.
#include "same_result.h"

namespace lepp::fuzz {

namespace {
bool claims_theta(Outcome o) { return o == Outcome::Converged || o == Outcome::Unimprovable; }

bool same_edge(const ConstrainedEdge& x, const ConstrainedEdge& y) { return x.a == y.a && x.b == y.b && x.segment == y.segment; }

bool same_left(const UnimprovableTriangle& x, const UnimprovableTriangle& y) {
  return x.triangle == y.triangle && x.apex == y.apex && x.segment1 == y.segment1 && x.segment2 == y.segment2 &&
         x.input_angle_deg == y.input_angle_deg && x.reason == y.reason && x.rule == y.rule && x.point == y.point;
}
}  // namespace

bool same_certifier_input(const RefineResult& a, const RefineResult& b) {
  const Mesh &m = a.mesh, &n = b.mesh;
  if (claims_theta(a.outcome) != claims_theta(b.outcome) || m.input_vertices != n.input_vertices ||
      m.vertices != n.vertices || m.triangles != n.triangles || m.constrained_edges.size() != n.constrained_edges.size() ||
      a.unimprovable.size() != b.unimprovable.size())
    return false;
  for (std::size_t i = 0; i < m.constrained_edges.size(); ++i)
    if (!same_edge(m.constrained_edges[i], n.constrained_edges[i])) return false;
  for (std::size_t i = 0; i < a.unimprovable.size(); ++i)
    if (!same_left(a.unimprovable[i], b.unimprovable[i])) return false;
  return true;
}

}  // namespace lepp::fuzz
