// First pass of validation: duplicates, zero-length and repeated segments,
// collinear input. (Vertices on segments, crossings and hole checks: see
// validate_geometry.cpp once it lands.)
#include "lepp/validate.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>

#include <fmt/format.h>

#include "lepp/io.h"

namespace lepp {

Pslg validate(const Pslg& input, std::vector<std::string>& warnings) {
  auto line_of = [](const std::vector<int>& lines, std::size_t i) {
    return i < lines.size() ? lines[i] : 0;
  };
  Pslg out;
  out.source = input.source;
  out.holes = input.holes;
  out.hole_lines = input.hole_lines;
  // Duplicate vertices (exactly equal coordinates) merge into the first.
  std::vector<std::size_t> order(input.vertices.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    const Point &p = input.vertices[i], &q = input.vertices[j];
    return p.x < q.x || (p.x == q.x && p.y < q.y);
  });
  std::vector<int> first_of(input.vertices.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    std::size_t i = order[k];
    first_of[i] = static_cast<int>(i);
    if (k > 0 && input.vertices[order[k - 1]] == input.vertices[i]) first_of[i] = first_of[order[k - 1]];
  }
  std::vector<int> new_id(input.vertices.size(), -1);
  for (std::size_t i = 0; i < input.vertices.size(); ++i) {
    if (first_of[i] != static_cast<int>(i)) {
      new_id[i] = new_id[static_cast<std::size_t>(first_of[i])];
      warnings.push_back(fmt::format("{}:{}: vertex {} duplicates vertex at line {}; merged", input.source,
                                     line_of(input.vertex_lines, i), i + 1,
                                     line_of(input.vertex_lines, static_cast<std::size_t>(first_of[i]))));
      continue;
    }
    new_id[i] = static_cast<int>(out.vertices.size());
    out.vertices.push_back(input.vertices[i]);
    if (i < input.vertex_markers.size()) out.vertex_markers.push_back(input.vertex_markers[i]);
    out.vertex_lines.push_back(line_of(input.vertex_lines, i));
  }
  std::set<std::pair<int, int>> seen;
  for (std::size_t s = 0; s < input.segments.size(); ++s) {
    Segment seg = input.segments[s];
    seg.a = new_id[static_cast<std::size_t>(seg.a)];
    seg.b = new_id[static_cast<std::size_t>(seg.b)];
    int line = line_of(input.segment_lines, s);
    if (seg.a == seg.b)
      throw InputError(input.source, line, fmt::format("segment {} has zero length (its endpoints coincide)", s + 1));
    if (!seen.insert(std::minmax(seg.a, seg.b)).second) {
      warnings.push_back(fmt::format("{}:{}: segment {} repeats an earlier segment; dropped", input.source, line, s + 1));
      continue;
    }
    out.segments.push_back(seg);
    out.segment_lines.push_back(line);
  }
  // Fewer than three non-collinear vertices: nothing to triangulate.
  bool area = false;
  for (std::size_t i = 2; i < out.vertices.size() && !area; ++i) {
    const Point &a = out.vertices[0], &b = out.vertices[1], &c = out.vertices[i];
    area = (b.x - a.x) * (c.y - a.y) != (b.y - a.y) * (c.x - a.x);  // placeholder until exact orient lands
  }
  if (!area) throw InputError(input.source, 0, "fewer than three non-collinear vertices: nothing to triangulate");
  return out;
}

}  // namespace lepp
