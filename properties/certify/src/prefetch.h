// SPDX-License-Identifier: GPL-3.0-or-later
// Loads the passes over triangles will need a few iterations ahead. A triangle's points
// lie far apart in the vertex array (a mesher numbers its Steiner points in insertion
// order), so at 10^7 triangles each one is a cache miss the loop would wait for; asked
// for early, the misses of several triangles overlap. Hints only: no result depends on them.
#pragma once
#include <cstddef>

#include "certification.h"

namespace lepp::certify {

// How many iterations ahead a pass asks for its triangles' points.
constexpr std::size_t kAhead = 16;

inline void prefetch(const void* p) { __builtin_prefetch(p); }
inline void prefetch_write(const void* p) { __builtin_prefetch(p, 1); }

// The points of triangle x (ids out of range skipped: the pass reports them).
inline void prefetch_points(const MeshIndex& ix, const Tri& x) {
  const std::size_t n = ix.mesh.vertices.size();
  for (int v : x)
    if (static_cast<std::size_t>(v) < n) prefetch(&ix.mesh.vertices[static_cast<std::size_t>(v)]);
}

}  // namespace lepp::certify
