// SPDX-License-Identifier: GPL-3.0-or-later
// How many vertices and triangles the fast engine can number: a vertex id takes
// the low 29 bits of a triangle's vertex word, and a neighbour code holds a
// triangle id shifted by 2 in an int (tri_mesh.h). A refinement that would go
// past either stops with CapacityError before the insertion that would overflow,
// instead of writing ids that alias others (about 5.4e8 triangles, 13 GB).
#pragma once
#include <cstdint>
#include <limits>

#include "lepp/capacity_error.h"
#include "tri_mesh.h"

namespace lepp::fast {

// Ids 0 .. 2^29 - 1 of each kind.
constexpr std::int64_t kMaxVertices = std::int64_t{1} << FTri::kIdBits;
constexpr std::int64_t kMaxTriangles = std::int64_t{1} << 29;
static_assert((kMaxTriangles - 1) * 4 + 3 <= std::numeric_limits<int>::max(), "a neighbour code (nbr_code) is an int");

struct IdLimits {
  std::int64_t vertices = kMaxVertices, triangles = kMaxTriangles;
};

// Whether a mesh of this many vertices and triangle slots can be numbered.
constexpr bool ids_fit(std::int64_t vertices, std::int64_t triangles, IdLimits limits = {}) {
  return vertices <= limits.vertices && triangles <= limits.triangles;
}

// The limits check_capacity applies: the ids' own, unless a test lowers them to
// reach the guard on a small mesh (capacity_test.cpp).
IdLimits& id_limits();

// Throws CapacityError unless ids_fit(vertices, triangles, id_limits()); `steiner`
// (the points inserted so far) names the budget that stops the run before, with exit 3,
// or is kInputOnly before the input's triangulation (no budget helps then).
constexpr std::int64_t kInputOnly = -1;
void check_capacity(std::int64_t vertices, std::int64_t triangles, std::int64_t steiner);

}  // namespace lepp::fast
