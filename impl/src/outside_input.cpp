// SPDX-License-Identifier: GPL-3.0-or-later
// The input outside the domain (outside_input.h): marks what the mesh has, keeps the rest.
#include "outside_input.h"

#include <vector>

namespace lepp::fast {

const OutsideInput& OutsideOfDomain::of(const TriMesh& m) {
  if (ready_) return items_;
  ready_ = true;
  const std::size_t n = pslg_.vertices.size();
  std::vector<char> vertex_in(n, 0), segment_in(pslg_.segments.size(), 0);
  for (const FTri& f : m.tris)  // every slot is a triangle of the mesh (slots are rewritten, never freed)
    for (int i = 0; i < 3; ++i) {
      if (static_cast<std::size_t>(f.v[i]) < n) vertex_in[static_cast<std::size_t>(f.v[i])] = 1;
      if (f.seg[i] < 0) continue;
      const int s = mem_.segment_of(f.v[next3(i)], f.v[prev3(i)]);
      if (s >= 0) segment_in[static_cast<std::size_t>(s)] = 1;
    }
  for (std::size_t v = 0; v < n; ++v)
    if (!vertex_in[v]) items_.vertices.push_back(pslg_.vertices[v]);
  for (std::size_t s = 0; s < pslg_.segments.size(); ++s)
    if (!segment_in[s]) {
      const Segment& g = pslg_.segments[s];
      items_.segments.push_back({pslg_.vertices[static_cast<std::size_t>(g.a)], pslg_.vertices[static_cast<std::size_t>(g.b)]});
    }
  return items_;
}

}  // namespace lepp::fast
