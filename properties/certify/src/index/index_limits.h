// SPDX-License-Identifier: GPL-3.0-or-later
// The mesh index's ids are 32-bit: vertex ids as the mesh gives them (int), half-edge
// 3 t + i of triangle t, and offsets into arrays of half-edges. A mesh with more
// vertices than INT_MAX or more half-edges (3 per triangle) is refused before anything
// is built, rather than numbered past the limit.
#pragma once
#include <climits>
#include <cstddef>

namespace lepp::certify {

constexpr std::size_t kMaxIndexIds = INT_MAX;

// Throws std::length_error naming the count and the limit when vertices > max_ids or
// 3 * triangles > max_ids. max_ids is kMaxIndexIds but for tests, which try the limit
// without a mesh of two billion half-edges.
void check_index_limits(std::size_t vertices, std::size_t triangles, std::size_t max_ids = kMaxIndexIds);

}  // namespace lepp::certify
