// SPDX-License-Identifier: GPL-3.0-or-later
// The mesh index's input layer: the expected domain, and which mesh vertex each input vertex is.
#include <algorithm>
#include <cmath>
#include <vector>

#include "../passes.h"
#include "../point_table.h"

namespace lepp::certify::pass {
namespace {

// A crossing point another mesher rounded otherwise: the mesh vertex nearest
// to ours, if within 2^-40 of it (relative). Only a candidate: check_split_points
// then holds it to the chain tolerance of both segments. Linear: crossing
// points missing exactly are few.
int nearest_mesh_vertex(const MeshIndex& ix, const Point& p) {
  const double radius = std::ldexp(std::max({1.0, std::abs(p.x), std::abs(p.y)}), -40);
  int best = -1;
  double best_d = radius;
  for (std::size_t v = 0; v < ix.mesh.vertices.size(); ++v) {
    const double d = std::max(std::abs(ix.mesh.vertices[v].x - p.x), std::abs(ix.mesh.vertices[v].y - p.y));
    if (d <= best_d) best = static_cast<int>(v), best_d = d;
  }
  return best;
}

}  // namespace

// The expected domain, and the input outside it: vertices on no domain triangle,
// segments with the domain on neither side (the precision exemption's sliver clause).
void index_domain(Certification& cert) {
  MeshIndex& ix = cert.index;
  ix.domain = expected_domain(ix.pslg);
  for (std::size_t i = 0; i < ix.pslg.vertices.size(); ++i)
    if (!ix.domain.vertex_in_domain[i]) ix.outside.vertices.push_back(ix.pslg.vertices[i]);
  for (std::size_t s = 0; s < ix.pslg.segments.size(); ++s)
    if (ix.domain.segment_sides[s] == 0)
      ix.outside.segments.push_back({ix.pslg.vertices[static_cast<std::size_t>(ix.pslg.segments[s].a)],
                                   ix.pslg.vertices[static_cast<std::size_t>(ix.pslg.segments[s].b)]});
}

void index_input_vertices(Certification& cert) {
  MeshIndex& ix = cert.index;
  const std::size_t n = ix.pslg.vertices.size();
  ix.input_to_mesh.assign(n, -1);
  ix.mesh_to_input.assign(ix.mesh.vertices.size(), -1);
  // For the input vertices the mesh does not number as the input does (all of them in a
  // mesh read from files), the first mesh vertex at the same coordinates not merged away
  // that a triangle uses, else the first not merged away, -1 if none: one pass over the
  // mesh against a table of those input vertices only (each point's first input vertex
  // stands for it; found[k]: its mesh vertex). Copies that triangles use are reported as
  // duplicates; the input vertex is not missing too when an unused copy comes first.
  const std::size_t numbered = std::min<std::size_t>(ix.mesh.input_vertices, n);
  PointTable table(n - numbered);
  std::vector<int> found(n, -1);
  auto input = [&](int i) -> const Point& { return ix.pslg.vertices[static_cast<std::size_t>(i)]; };
  if (numbered < n) {
    for (std::size_t i = numbered; i < n; ++i)
      if (int& slot = table.slot(ix.pslg.vertices[i], input); slot < 0) slot = static_cast<int>(i);
    for (std::size_t v = 0; v < ix.mesh.vertices.size(); ++v) {
      if (ix.merged[v]) continue;
      const int k = table.find(ix.mesh.vertices[v], input);
      if (k < 0) continue;
      int& m = found[static_cast<std::size_t>(k)];
      if (m < 0 || (!ix.used[static_cast<std::size_t>(m)] && ix.used[v])) m = static_cast<int>(v);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    const Point& p = ix.pslg.vertices[i];
    if (i < ix.mesh.input_vertices) {
      // The mesh promises vertex i is input vertex i: coordinates must be bit-identical.
      if (i >= ix.mesh.vertices.size() || ix.mesh.vertices[i] != p) {
        cert.add({Reason::InputVertexMoved,
                  fmt::format("input vertex {} {} is mesh vertex {} at {}", i, pt(p), i,
                              i < ix.mesh.vertices.size() ? pt(ix.mesh.vertices[i]) : std::string("(absent)")),
                  {}, {}, {static_cast<int>(i)}, {p}, -1});
      }
      if (i < ix.mesh.vertices.size()) ix.input_to_mesh[i] = static_cast<int>(i);
    } else {
      const int k = table.find(p, input);
      if (k >= 0 && found[static_cast<std::size_t>(k)] >= 0) ix.input_to_mesh[i] = found[static_cast<std::size_t>(k)];
      else if (i + ix.pslg.crossing_vertices >= n) ix.input_to_mesh[i] = nearest_mesh_vertex(ix, p);
    }
    const int m = ix.input_to_mesh[i];
    if (m >= 0) ix.mesh_to_input[static_cast<std::size_t>(m)] = static_cast<int>(i);
    const bool moved = m >= 0 && ix.mesh.vertices[static_cast<std::size_t>(m)] != p;
    const bool present = m >= 0 && ix.used[static_cast<std::size_t>(m)];
    if (!present && (!moved || i + ix.pslg.crossing_vertices >= n) && ix.domain.vertex_in_domain[i])
      cert.add({Reason::InputVertexMissing, fmt::format("input vertex {} {} (in the domain) is not a vertex of any triangle", i, pt(p)),
                {}, {}, {static_cast<int>(i)}, {p}, -1});
  }
  if (ix.mesh.input_vertices > n)
    cert.add({Reason::InputVertexMoved,
              fmt::format("the mesh claims {} input vertices, the input has {}", ix.mesh.input_vertices, n), {}, {}, {}, {}, -1});
}

}  // namespace lepp::certify::pass
