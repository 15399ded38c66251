// SPDX-License-Identifier: GPL-3.0-or-later
// Triangle's .poly and .node readers: syntax only (geometry is validate()'s job).
#include <algorithm>
#include <fstream>

#include <fmt/format.h>

#include "lepp/io.h"
#include "line_reader.h"

namespace lepp {

InputError::InputError(std::string file, int line, const std::string& what)
    : std::runtime_error(line > 0 ? fmt::format("{}:{}: {}", file, line, what) : fmt::format("{}: {}", file, what)),
      file_(std::move(file)),
      line_(line) {}

namespace {

using detail::LineReader;
using Tokens = std::vector<std::string_view>;

// A header count: non-negative and no larger than the lines left to hold it,
// so a lying header cannot make us allocate or loop.
std::size_t count(LineReader& in, std::string_view token, const char* what, std::size_t lines_per_item = 1) {
  std::int64_t n = in.integer(token, what);
  if (n < 0) in.fail(fmt::format("{} is negative ({})", what, n));
  if (n > 0 && static_cast<std::size_t>(n) > in.lines_left() / lines_per_item)
    in.fail(fmt::format("{} is {} but the file has only {} more lines", what, n, in.lines_left()));
  return static_cast<std::size_t>(n);
}

// Reads the vertex section: header already in `header`. Sets first index (0 or 1).
void read_vertices(LineReader& in, const Tokens& header, Pslg& pslg, int& first) {
  in.fields(header, 1, 4, "vertex header (count, dimension, attributes, markers)");
  std::size_t n = count(in, header[0], "vertex count");
  if (header.size() >= 2 && in.integer(header[1], "dimension") != 2) in.fail("dimension must be 2");
  std::int64_t attributes = header.size() >= 3 ? in.integer(header[2], "attribute count") : 0;
  if (attributes < 0 || attributes > 1000) in.fail(fmt::format("attribute count {} is out of range", attributes));
  std::int64_t markers = header.size() >= 4 ? in.integer(header[3], "boundary marker count") : 0;
  if (markers != 0 && markers != 1) in.fail("boundary marker count must be 0 or 1");
  const std::size_t fields = 3 + static_cast<std::size_t>(attributes) + static_cast<std::size_t>(markers);
  pslg.vertices.reserve(n);
  pslg.vertex_lines.reserve(n);
  if (markers) pslg.vertex_markers.reserve(n);
  Tokens t;
  for (std::size_t i = 0; i < n; ++i) {
    in.expect(t, fmt::format("vertex {} of {}", i + 1, n));
    in.fields(t, fields, fields, "vertex line (number, x, y, attributes, marker)");
    std::int64_t number = in.integer(t[0], "vertex number");
    if (i == 0) {
      if (number != 0 && number != 1) in.fail(fmt::format("first vertex is numbered {}; must be 0 or 1", number));
      first = static_cast<int>(number);
    } else if (number != first + static_cast<std::int64_t>(i)) {
      in.fail(fmt::format("vertex number {} out of order (expected {})", number, first + static_cast<std::int64_t>(i)));
    }
    pslg.vertices.push_back({in.real(t[1], "x coordinate"), in.real(t[2], "y coordinate")});
    for (std::size_t a = 3; a < 3 + static_cast<std::size_t>(attributes); ++a) in.real(t[a], "attribute");
    if (markers) pslg.vertex_markers.push_back(static_cast<int>(in.integer(t.back(), "boundary marker")));
    pslg.vertex_lines.push_back(in.line());
  }
}

std::string node_path_for(const std::string& poly_path) {
  std::string base = poly_path;
  if (base.size() > 5 && base.compare(base.size() - 5, 5, ".poly") == 0) base.resize(base.size() - 5);
  return base + ".node";
}

}  // namespace

Pslg read_node(const std::string& path) {
  LineReader in(path);
  Pslg pslg;
  pslg.source = path;
  Tokens t;
  in.expect(t, "vertex header");
  int first = 1;
  read_vertices(in, t, pslg, first);
  if (in.next(t)) in.fail("unexpected content after the last vertex");
  return pslg;
}

Pslg read_poly(const std::string& path) {
  LineReader in(path);
  Pslg pslg;
  pslg.source = path;
  Tokens t;
  int first = 1;
  in.expect(t, "vertex header (count, dimension, attributes, markers)");
  read_vertices(in, t, pslg, first);
  if (pslg.vertices.empty()) {
    // Triangle: a .poly with no vertices takes them from the .node beside it.
    std::string node = node_path_for(path);
    if (!std::ifstream(node)) in.fail(fmt::format("the .poly lists no vertices and {} cannot be opened", node));
    Pslg points = read_node(node);
    pslg.vertices = std::move(points.vertices);
    pslg.vertex_markers = std::move(points.vertex_markers);
    pslg.vertex_lines = std::move(points.vertex_lines);
    if (!pslg.vertices.empty()) {  // the .node's numbering (0 or 1) is the segments' too
      LineReader probe(node);
      Tokens h;
      probe.expect(h, "vertex header");
      probe.expect(h, "vertex 1");
      first = static_cast<int>(probe.integer(h[0], "vertex number"));
    }
  }
  const std::int64_t nv = static_cast<std::int64_t>(pslg.vertices.size());

  in.expect(t, "segment header (count, markers)");
  in.fields(t, 1, 2, "segment header (count, markers)");
  std::size_t ns = count(in, t[0], "segment count");
  std::int64_t markers = t.size() >= 2 ? in.integer(t[1], "boundary marker count") : 0;
  if (markers != 0 && markers != 1) in.fail("boundary marker count must be 0 or 1");
  pslg.segments.reserve(ns);
  pslg.segment_lines.reserve(ns);
  for (std::size_t i = 0; i < ns; ++i) {
    in.expect(t, fmt::format("segment {} of {}", i + 1, ns));
    in.fields(t, 3 + static_cast<std::size_t>(markers), 3 + static_cast<std::size_t>(markers),
              "segment line (number, endpoint, endpoint, marker)");
    std::int64_t number = in.integer(t[0], "segment number");
    if (number != first + static_cast<std::int64_t>(i))
      in.fail(fmt::format("segment number {} out of order (expected {})", number, first + static_cast<std::int64_t>(i)));
    Segment s;
    std::int64_t ends[2];
    for (int k = 0; k < 2; ++k) {
      ends[k] = in.integer(t[1 + static_cast<std::size_t>(k)], "segment endpoint");
      if (ends[k] < first || ends[k] >= first + nv)
        in.fail(fmt::format("segment endpoint {} out of range (vertices are numbered {} to {})", ends[k], first,
                            first + nv - 1));
    }
    if (ends[0] == ends[1]) in.fail(fmt::format("segment {} has both endpoints at vertex {} (zero length)", number, ends[0]));
    s.a = static_cast<int>(ends[0] - first);
    s.b = static_cast<int>(ends[1] - first);
    if (markers) s.marker = static_cast<int>(in.integer(t[3], "boundary marker"));
    pslg.segments.push_back(s);
    pslg.segment_lines.push_back(in.line());
  }

  // Triangle allows the hole section to be missing entirely.
  if (!in.next(t)) return pslg;
  in.fields(t, 1, 1, "hole header (count)");
  std::size_t nh = count(in, t[0], "hole count");
  for (std::size_t i = 0; i < nh; ++i) {
    in.expect(t, fmt::format("hole {} of {}", i + 1, nh));
    in.fields(t, 3, 3, "hole line (number, x, y)");
    in.integer(t[0], "hole number");
    pslg.holes.push_back({in.real(t[1], "hole x"), in.real(t[2], "hole y")});
    pslg.hole_lines.push_back(in.line());
  }

  // Optional regional attributes / area constraints: read, checked, not used.
  if (!in.next(t)) return pslg;
  in.fields(t, 1, 1, "region header (count)");
  std::size_t nr = count(in, t[0], "region count");
  for (std::size_t i = 0; i < nr; ++i) {
    in.expect(t, fmt::format("region {} of {}", i + 1, nr));
    in.fields(t, 4, 5, "region line (number, x, y, attribute, max area)");
    for (std::size_t k = 1; k < t.size(); ++k) in.real(t[k], "region field");
  }
  if (in.next(t)) in.fail("unexpected content after the last section");
  return pslg;
}

}  // namespace lepp
