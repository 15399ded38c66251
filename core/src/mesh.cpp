// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/mesh.h: the output mesh of the domain, as written to PREFIX.node/.ele/.poly.
#include "lepp/mesh.h"

#include <algorithm>
#include <tuple>
#include <utility>

namespace lepp {

void canonicalize(Mesh& mesh) {
  for (Tri& t : mesh.triangles) {
    // Rotation keeps the orientation.
    while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
  }
  std::sort(mesh.triangles.begin(), mesh.triangles.end());
  for (ConstrainedEdge& e : mesh.constrained_edges)
    if (e.a > e.b) std::swap(e.a, e.b);
  std::sort(mesh.constrained_edges.begin(), mesh.constrained_edges.end(),
            [](const ConstrainedEdge& x, const ConstrainedEdge& y) {
              return std::tie(x.a, x.b, x.segment) < std::tie(y.a, y.b, y.segment);
            });
}

}  // namespace lepp
