// SPDX-License-Identifier: GPL-3.0-or-later
// Loads the passes over triangles will need a few iterations ahead. A triangle's points
// lie far apart in the vertex array (a mesher numbers its Steiner points in insertion
// order), so at 10^7 triangles each one is a cache miss the loop would wait for; asked
// for early, the misses of several triangles overlap. Hints only: no result depends on them.
// Each function is always inlined: GCC finds a function whose only effect is a prefetch
// pure, and deletes calls to a pure function whose result is unused, prefetch and all
// (the case of prefetch_across_longest, out of line, in Theorem 2's and the mean Lepp
// size's passes: no prefetch instruction was left in their objects).
#pragma once
#include <cstddef>

#include "certification.h"

namespace lepp::certify {

// How many iterations ahead a pass asks for its triangles' points.
constexpr std::size_t kAhead = 16;

[[gnu::always_inline]] inline void prefetch(const void* p) { __builtin_prefetch(p); }
[[gnu::always_inline]] inline void prefetch_write(const void* p) { __builtin_prefetch(p, 1); }

// The points of triangle x (ids out of range skipped: the pass reports them).
[[gnu::always_inline]] inline void prefetch_points(const MeshIndex& ix, const Tri& x) {
  const std::size_t n = ix.mesh.vertices.size();
  for (int v : x)
    if (static_cast<std::size_t>(v) < n) prefetch(&ix.mesh.vertices[static_cast<std::size_t>(v)]);
}

// What a step of a Lepp from triangle t reads across its longest edge: the neighbour's
// longest edge and that edge's twin (Theorem 2's terminal pairs, the mean Lepp size).
[[gnu::always_inline]] inline void prefetch_across_longest(const MeshIndex& ix, std::size_t t) {
  if (!ix.tri_ok[t]) return;
  const int g = ix.twin[static_cast<std::size_t>(ix.longest_half(t))];
  if (g < 0) return;
  const std::size_t u = static_cast<std::size_t>(g / 3);
  prefetch(&ix.longest[u]);
  prefetch(&ix.twin[3 * u]);
}

}  // namespace lepp::certify
