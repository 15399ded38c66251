// SPDX-License-Identifier: GPL-3.0-or-later
// The segment chains drawn as the segments are (docs/CERTIFIER.md section 1,
// "Coverage"): the coverage checks count triangles by the winding number of
// the chains, which is the domain's only if the chains cross nowhere. A chain
// vertex may lie a few ulps off its segment, so two nearly parallel segments
// can have chains that cross though the segments do not: a mesher that put a
// boundary split's rounded midpoint across the other segment (the sliver
// clause, ALGORITHM.md section 8b) meshes the outside wedge twice over.
// Private to the certifier.
#pragma once
#include <array>
#include <vector>

#include "lepp/pslg.h"

namespace lepp::certify {

// Two chain edges that meet other than at one shared endpoint (edge = -1: none),
// or a mesh vertex in a triangle that lies on a chain edge other than at its ends.
struct ChainMeet {
  int edge = -1, other = -1;  // indices into the edge list
  int vertex = -1;            // mesh vertex on `edge` (other == -1)
};

// Every such meeting, exactly (closed segments; two edges sharing an endpoint
// meet elsewhere only when they overlap along a line). `used`: the mesh
// vertices in some triangle. Edge pairs are found by CGAL's box intersection,
// vertices on edges by a grid over the edges' boxes (box intersection when the
// boxes are too large for one), so the cost is near-linear in the edges and vertices.
std::vector<ChainMeet> chain_meetings(const std::vector<Point>& points, const std::vector<std::array<int, 2>>& edges,
                                      const std::vector<char>& used);

}  // namespace lepp::certify
