// SPDX-License-Identifier: GPL-3.0-or-later
// The output: a triangle mesh of the domain, as written to PREFIX.node/.ele/.poly.
#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "lepp/pslg.h"

namespace lepp {

using Tri = std::array<int, 3>;  // vertex ids, counter-clockwise

// A mesh edge lying on an input segment. segment is the 0-based id of that
// segment in the (validated) Pslg, or -1 when unknown (a mesh read from a
// program that does not say).
struct ConstrainedEdge {
  int a = 0, b = 0;
  int segment = -1;
};

struct Mesh {
  // Input vertices first, in input order (ids equal to the Pslg's), then the
  // Steiner points in insertion order. Input vertices outside the domain (in a
  // hole, say) stay in the list but belong to no triangle.
  std::vector<Point> vertices;
  std::size_t input_vertices = 0;  // how many leading vertices are input vertices
  std::vector<Tri> triangles;
  std::vector<ConstrainedEdge> constrained_edges;
};

// Rotate each triangle so its smallest id comes first, sort the triangles, and
// sort constrained edges with a < b: two meshes with the same triangles then
// compare equal element by element, whatever engine made them.
void canonicalize(Mesh& mesh);

}  // namespace lepp
