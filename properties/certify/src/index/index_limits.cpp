// SPDX-License-Identifier: GPL-3.0-or-later
// The mesh index's 32-bit limits, checked once (index_limits.h).
#include "index_limits.h"

#include <stdexcept>

#include <fmt/format.h>

namespace lepp::certify {

void check_index_limits(std::size_t vertices, std::size_t triangles, std::size_t max_ids) {
  if (vertices > max_ids)
    throw std::length_error(fmt::format("the mesh has {} vertices; the certifier numbers vertices in 32-bit ids, at most {}", vertices, max_ids));
  if (triangles > max_ids / 3)
    throw std::length_error(fmt::format("the mesh has {} triangles; the certifier numbers their half-edges (3 a triangle) in 32-bit ids, "
                                        "so at most {} triangles",
                                        triangles, max_ids / 3));
}

}  // namespace lepp::certify
