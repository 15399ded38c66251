// SPDX-License-Identifier: GPL-3.0-or-later
// One vertex line of lepp's .node, "i x y marker": written by write_mesh and by the
// lines made beside the refinement (node_text_stream.h), so that the two give the
// same bytes. Internal to lepp_core.
#pragma once
#include <cstddef>

#include <fmt/compile.h>
#include <fmt/format.h>

#include "double_text.h"
#include "lepp/pslg.h"

namespace lepp::detail {

// A line's most bytes: a 20-digit number, two doubles of at most 24 characters, a
// digit, 4 separators.
constexpr std::size_t kNodeLine = 128;

// Vertex `index` (0-based; written 1-based) at `at`; its marker 1 for an input
// vertex, 0 for a Steiner point. Returns the end.
inline char* write_node_line(char* at, std::size_t index, const Point& p, bool input_vertex) {
  // The coordinates as fmt's "{}" writes them, by a cheaper layout (double_text.h).
  at = fmt::format_to(at, FMT_COMPILE("{} "), index + 1);
  at = write_double(at, p.x);
  *at++ = ' ';
  at = write_double(at, p.y);
  *at++ = ' ';
  *at++ = input_vertex ? '1' : '0';
  *at++ = '\n';
  return at;
}

}  // namespace lepp::detail
