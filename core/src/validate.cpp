// SPDX-License-Identifier: GPL-3.0-or-later
// validate(): the checks a parsed PSLG needs before an engine sees it. This
// file does the plain ones (finite numbers, ids in range, duplicate vertices,
// zero-length segments); validate_geometry.cpp the ones needing exact
// predicates and a triangulation.
#include "lepp/validate.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include <fmt/format.h>

#include "lepp/input.h"
#include "lepp/io.h"
#include "validate_geometry.h"

namespace lepp {
namespace detail {

std::string where(const std::string& file, int line) {
  std::string name = file.empty() ? std::string("<input>") : file;
  return line > 0 ? fmt::format("{}:{}", name, line) : name;
}

void WarningSink::add(std::string message) {
  if (count_++ < keep_) out_.push_back(std::move(message));
}

WarningSink::~WarningSink() {
  if (count_ > keep_) out_.push_back(fmt::format("... and {} more warnings of this kind ({})", count_ - keep_, kind_));
}

}  // namespace detail

namespace {

int line_at(const std::vector<int>& lines, std::size_t i) { return i < lines.size() ? lines[i] : 0; }

bool finite(const Point& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

Pslg validate(const Pslg& input, std::vector<std::string>& warnings) { return detail::validate(input, false, warnings); }

Pslg detail::validate(const Pslg& input, bool split, std::vector<std::string>& warnings) {
  const std::string& file = input.source;
  const std::size_t n = input.vertices.size();
  // Generated PSLGs skip the parser: check what it would have.
  for (std::size_t i = 0; i < n; ++i)
    if (!finite(input.vertices[i]))
      throw InputError(file, line_at(input.vertex_lines, i), fmt::format("vertex {} has a coordinate that is not finite (NaN or infinite)", i + 1));
  for (std::size_t h = 0; h < input.holes.size(); ++h)
    if (!finite(input.holes[h]))
      throw InputError(file, line_at(input.hole_lines, h), fmt::format("hole point {} has a coordinate that is not finite", h + 1));
  for (std::size_t r = 0; r < input.regions.size(); ++r)
    if (!finite(input.regions[r].at) || std::isnan(input.regions[r].max_area))
      throw InputError(file, line_at(input.region_lines, r), fmt::format("region {} has a coordinate that is not finite or an area bound that is NaN", r + 1));
  for (std::size_t s = 0; s < input.segments.size(); ++s) {
    const Segment& seg = input.segments[s];
    if (seg.a < 0 || seg.b < 0 || static_cast<std::size_t>(seg.a) >= n || static_cast<std::size_t>(seg.b) >= n)
      throw InputError(file, line_at(input.segment_lines, s),
                       fmt::format("segment {} has an endpoint out of range ({} vertices)", s + 1, n));
  }

  Pslg out;
  out.source = input.source;
  out.holes = input.holes;
  out.hole_lines = input.hole_lines;
  out.regions = input.regions;  // crossing_vertices: set by split_crossings() below
  out.region_lines = input.region_lines;

  // Duplicate vertices (exactly equal coordinates) merge into the first in file order.
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    const Point &p = input.vertices[i], &q = input.vertices[j];
    return p.x < q.x || (p.x == q.x && p.y < q.y);
  });
  std::vector<std::size_t> first_of(n);
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t i = order[k];
    first_of[i] = k > 0 && input.vertices[order[k - 1]] == input.vertices[i] ? first_of[order[k - 1]] : i;
  }
  std::vector<int> new_id(n, -1);
  {
    detail::WarningSink duplicates(warnings, "duplicate vertex");
    for (std::size_t i = 0; i < n; ++i) {
      if (first_of[i] != i) {
        new_id[i] = new_id[first_of[i]];
        duplicates.add(fmt::format("{}: vertex {} duplicates vertex {} (line {}); merged",
                                   detail::where(file, line_at(input.vertex_lines, i)), i + 1, first_of[i] + 1,
                                   line_at(input.vertex_lines, first_of[i])));
        continue;
      }
      new_id[i] = static_cast<int>(out.vertices.size());
      out.vertices.push_back(input.vertices[i]);
      if (i < input.vertex_markers.size()) out.vertex_markers.push_back(input.vertex_markers[i]);
      out.vertex_lines.push_back(line_at(input.vertex_lines, i));
    }
  }
  if (out.vertex_markers.size() != out.vertices.size()) out.vertex_markers.clear();

  // A zero-length segment (both endpoints one vertex, also after merging) is
  // dropped with a warning, as Triangle does ("Endpoints of segment N are
  // coincident"); the others keep their file numbers in segment_origin.
  {
    detail::WarningSink zero(warnings, "zero-length segment");
    for (std::size_t s = 0; s < input.segments.size(); ++s) {
      Segment seg = input.segments[s];
      const int a = seg.a, b = seg.b;
      seg.a = new_id[static_cast<std::size_t>(seg.a)];
      seg.b = new_id[static_cast<std::size_t>(seg.b)];
      if (seg.a == seg.b) {
        zero.add(fmt::format("{}: segment {} has zero length ({}); dropped", detail::where(file, line_at(input.segment_lines, s)),
                             s + 1,
                             a == b ? fmt::format("both endpoints are vertex {}", a + 1)
                                    : fmt::format("vertices {} and {} are the same point", a + 1, b + 1)));
        continue;
      }
      out.segments.push_back(seg);
      out.segment_lines.push_back(line_at(input.segment_lines, s));
      out.segment_origin.push_back(static_cast<int>(s));
    }
  }
  if (out.segment_origin.size() == input.segments.size()) out.segment_origin.clear();  // nothing dropped: as before

  if (split) split_crossings(out, warnings);
  // Splits at vertices, repeats and overlaps, crossings, collinear input, holes.
  detail::check_geometry(out, warnings);
  return out;
}

}  // namespace lepp
