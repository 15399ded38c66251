// SPDX-License-Identifier: GPL-3.0-or-later
// PREFIX.node/.ele/.poly (and .unimprovable) in and out, as Triangle writes them.
#include <algorithm>
#include <cstdio>
#include <exception>
#include <fstream>
#include <functional>
#include <future>
#include <limits>
#include <memory>
#include <optional>
#include <type_traits>

#include <fmt/format.h>
#include <fmt/os.h>

#include "lepp/io.h"
#include "lepp/mesh_read.h"
#include "block_file.h"
#include "double_text.h"
#include "lepp/node_text_stream.h"
#include "node_line.h"
#include "line_reader.h"
#include "node_reader.h"

namespace lepp {
namespace {

using detail::BlockFile;
using detail::LineReader;
using Tokens = std::vector<std::string_view>;

std::size_t header_count(LineReader& in, std::string_view token, const char* what) {
  std::int64_t n = in.integer(token, what);
  if (n < 0 || static_cast<std::size_t>(n) > in.lines_left())
    in.fail(LineReader::too_many(what, n, in.lines_left()));
  return static_cast<std::size_t>(n);
}

// header_count for a section of n item lines read one by one: checked against the lines
// left only if an error comes first (LineReader::count_later), with the same message.
std::size_t header_count_later(LineReader& in, std::string_view token, const char* what) {
  std::int64_t n = in.integer(token, what);
  if (n < 0) in.fail(LineReader::too_many(what, n, in.lines_left()));
  in.count_later(static_cast<std::size_t>(n), what);
  return static_cast<std::size_t>(n);
}

int vertex_id(LineReader& in, std::int64_t v, int first, std::size_t n) {
  if (v < first || v >= first + static_cast<std::int64_t>(n))
    in.fail(fmt::format("vertex id {} out of range ({} to {})", v, first, first + static_cast<std::int64_t>(n) - 1));
  return static_cast<int>(v - first);
}

}  // namespace

namespace {

// Vertex ids as the .ele and .poly give them, checked against the .node's count and
// numbering once the .node is read: the files read at once (read_mesh with threads).
// An id that does not fit an int is recorded as failed; the sequential read then names it.
struct DeferredIds {
  bool failed = false;
  int operator()(LineReader&, std::int64_t v) {
    if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) failed = true;
    return static_cast<int>(v);
  }
  // Shifts ids from the file's numbering to 0-based; false if one is out of range.
  template <class Item>
  static bool resolve(std::vector<Item>& items, int first, std::size_t n) {
    constexpr int ids = std::is_same_v<Item, Tri> ? 3 : 2;
    for (Item& item : items)
      for (int k = 0; k < ids; ++k) {
        int& id = item_id(item, k);
        const std::int64_t v = static_cast<std::int64_t>(id) - first;
        if (v < 0 || v >= static_cast<std::int64_t>(n)) return false;
        id = static_cast<int>(v);
      }
    return true;
  }
  static int& item_id(Tri& t, int k) { return t[static_cast<std::size_t>(k)]; }
  static int& item_id(ConstrainedEdge& e, int k) { return k == 0 ? e.a : e.b; }
};

template <class VertexId>
std::vector<Tri> read_ele(const std::string& path, VertexId&& vertex) {
  LineReader in(path);
  Tokens t;
  in.expect(t, "triangle header (count, nodes per triangle, attributes)");
  in.fields(t, 1, 3, "triangle header (count, nodes per triangle, attributes)");
  std::size_t nt = header_count_later(in, t[0], "triangle count");
  std::int64_t corners = t.size() >= 2 ? in.integer(t[1], "nodes per triangle") : 3;
  if (corners != 3 && corners != 6) in.fail("nodes per triangle must be 3 or 6");
  std::int64_t attributes = t.size() >= 3 ? in.integer(t[2], "attribute count") : 0;
  if (attributes < 0 || attributes > 1000) in.fail("attribute count out of range");
  const std::size_t fields = 1 + static_cast<std::size_t>(corners + attributes);
  // The plain line's kinds: the number and what follows the corners are not read.
  const std::string kinds = "-iii" + std::string(fields - 4, '-');
  std::int64_t corner[3];
  Tri tri;
  std::vector<Tri> triangles;
  triangles.reserve(std::min(nt, in.bytes_left() / 4 + 1));  // a line is 8 bytes at least: nt unless the count is wrong
  for (std::size_t i = 0; i < nt; ++i) {
    if (in.plain(kinds.c_str(), corner, nullptr)) {
      for (std::size_t k = 0; k < 3; ++k) tri[k] = vertex(in, corner[k]);
    } else {
      in.expect_item(t, "triangle", i + 1, nt);
      in.fields(t, fields, fields, "triangle line (number, corners, attributes)");
      // Each corner read, then checked, in order: the first wrong one is named.
      for (std::size_t k = 0; k < 3; ++k) tri[k] = vertex(in, in.integer(t[1 + k], "vertex id"));
    }
    triangles.push_back(tri);
  }
  in.count_kept();
  return triangles;
}

// The .poly beside a mesh: its segments, the mesh's constrained edges (none if there is no .poly).
template <class VertexId>
std::vector<ConstrainedEdge> read_poly_edges(const std::string& path, VertexId&& vertex) {
  std::vector<ConstrainedEdge> edges;
  if (!std::ifstream(path)) return edges;
  LineReader in(path);
  Tokens t;
  in.expect(t, "vertex header");
  if (in.integer(t[0], "vertex count") != 0) {
    // A full .poly: skip its vertex lines (the .node holds the same vertices).
    std::size_t nv = header_count(in, t[0], "vertex count");
    for (std::size_t i = 0; i < nv; ++i) in.expect(t, "vertex line");
  }
  in.expect(t, "segment header");
  in.fields(t, 1, 2, "segment header (count, markers)");
  std::size_t ns = header_count(in, t[0], "segment count");
  for (std::size_t i = 0; i < ns; ++i) {
    in.expect_item(t, "segment", i + 1, ns);
    in.fields(t, 3, 4, "segment line (number, endpoint, endpoint, marker)");
    // Markers are not trusted to be segment ids: the certifier finds the
    // input segment of each constrained edge by geometry.
    const int a = vertex(in, in.integer(t[1], "vertex id"));
    const int b = vertex(in, in.integer(t[2], "vertex id"));
    edges.push_back({a, b, -1});
  }
  return edges;
}

// The three files at once: the .ele on a second thread, the .node then the .poly on this
// one. nullopt if anything is wrong but the .node: read_mesh's sequential read then
// reports the first error as it always does (the .node's errors are thrown here, first).
std::optional<Mesh> read_mesh_at_once(const std::string& prefix) {
  DeferredIds ele_ids;
  auto ele = std::async(std::launch::async, [&] { return read_ele(prefix + ".ele", ele_ids); });
  Mesh mesh;
  int first = 1;
  std::vector<std::string> ignored;
  std::vector<ConstrainedEdge> edges;
  DeferredIds poly_ids;
  bool poly_ok = true;
  try {
    Pslg nodes = detail::read_node_numbered(prefix + ".node", ignored, first, true);
    mesh.vertices = std::move(nodes.vertices);
    try {
      edges = read_poly_edges(prefix + ".poly", poly_ids);
    } catch (const InputError&) {
      poly_ok = false;
    }
  } catch (...) {
    ele.wait();  // the thread reads this function's locals
    throw;
  }
  std::vector<Tri> triangles;
  try {
    triangles = ele.get();
  } catch (const InputError&) {
    return std::nullopt;
  }
  const std::size_t n = mesh.vertices.size();
  if (!poly_ok || ele_ids.failed || poly_ids.failed || !DeferredIds::resolve(triangles, first, n) ||
      !DeferredIds::resolve(edges, first, n))
    return std::nullopt;
  mesh.triangles = std::move(triangles);
  mesh.constrained_edges = std::move(edges);
  return mesh;
}

}  // namespace

Mesh read_mesh(const std::string& prefix) { return read_mesh(prefix, 1); }

Mesh read_mesh(const std::string& prefix, int threads) {
  if (threads != 1)
    if (std::optional<Mesh> mesh = read_mesh_at_once(prefix)) return std::move(*mesh);
  Mesh mesh;
  int first = 1;
  std::vector<std::string> ignored;
  mesh.vertices = detail::read_node_numbered(prefix + ".node", ignored, first, true).vertices;
  const std::size_t n = mesh.vertices.size();
  auto vertex = [&](LineReader& in, std::int64_t v) { return vertex_id(in, v, first, n); };
  mesh.triangles = read_ele(prefix + ".ele", vertex);
  mesh.constrained_edges = read_poly_edges(prefix + ".poly", vertex);
  return mesh;
}

namespace {

// `streamed`: lines made beside the refinement (node_text_stream.h), copied behind
// the header; the vertices past them formatted here.
void write_node_file(const std::string& prefix, const Mesh& mesh, NodeTextStream* streamed) {
  BlockFile out(prefix + ".node");
  out.print("# lepp mesh: marker 1 = input vertex, 0 = Steiner point\n");
  out.print("{} 2 0 1\n", mesh.vertices.size());
  std::size_t from = 0;
  if (streamed)
    if (const NodeTextStream::Made made = streamed->finish(mesh.input_vertices);
        made.lines > 0 && made.lines <= mesh.vertices.size()) {
      out.copy_from(streamed->fd(), made.bytes);
      from = made.lines;
    }
  for (std::size_t i = from; i < mesh.vertices.size(); ++i)
    out.line(detail::kNodeLine, [&](char* at) {
      return detail::write_node_line(at, i, mesh.vertices[i], i < mesh.input_vertices);
    });
  out.close();
}

void write_ele_and_poly_files(const std::string& prefix, const Mesh& mesh) {
  {
    BlockFile out(prefix + ".ele");
    out.print("{} 3 0\n", mesh.triangles.size());
    constexpr std::size_t kEleLine = 96;  // four numbers of at most 20 digits, 4 separators
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
      const Tri& t = mesh.triangles[i];
      out.line(kEleLine, [&](char* at) { return fmt::format_to(at, FMT_COMPILE("{} {} {} {}\n"), i + 1, t[0] + 1, t[1] + 1, t[2] + 1); });
    }
    out.close();
  }
  BlockFile out(prefix + ".poly");
  out.print("# lepp mesh: constrained edges; marker = input segment number (1-based), 0 if unknown\n");
  out.print("0 2 0 1\n{} 1\n", mesh.constrained_edges.size());
  for (std::size_t i = 0; i < mesh.constrained_edges.size(); ++i) {
    const ConstrainedEdge& e = mesh.constrained_edges[i];
    out.print(FMT_COMPILE("{} {} {} {}\n"), i + 1, e.a + 1, e.b + 1, e.segment + 1);
  }
  out.print("0\n");
  out.close();
}

}  // namespace

void write_mesh(const std::string& prefix, const Mesh& mesh, int threads, NodeTextStream* node_text) {
  try {
    if (threads > 1) {
      // Each file is written by one thread alone; the .node's error, if any, is
      // rethrown here after the others are written (get waits for it).
      std::future<void> node = std::async(std::launch::async, write_node_file, std::cref(prefix), std::cref(mesh), node_text);
      std::exception_ptr other;
      try {
        write_ele_and_poly_files(prefix, mesh);
      } catch (...) {
        other = std::current_exception();
      }
      node.get();
      if (other) std::rethrow_exception(other);
    } else {
      write_node_file(prefix, mesh, node_text);
      write_ele_and_poly_files(prefix, mesh);
    }
  } catch (const std::system_error& e) {
    throw InputError(prefix, 0, fmt::format("cannot write mesh: {}", e.what()));
  }
}

void write_poly(const std::string& path, const Pslg& pslg) {
  // A buffer of about the text's size, 32 KiB at most (fmt's default): the fuzzers write
  // thousands of small PSLGs, and a sanitizer maps each buffer apart.
  const std::size_t items = pslg.vertices.size() + pslg.segments.size() + pslg.holes.size() + 2 * pslg.regions.size();
  const std::size_t estimate = std::min<std::size_t>(64 * items + 256, std::size_t{1} << 15);
  auto out = fmt::output_file(path, fmt::buffer_size = estimate);
  const bool markers = pslg.vertex_markers.size() == pslg.vertices.size() && !pslg.vertices.empty();
  out.print("{} 2 0 {}\n", pslg.vertices.size(), markers ? 1 : 0);
  for (std::size_t i = 0; i < pslg.vertices.size(); ++i) {
    if (markers)
      out.print("{} {} {} {}\n", i + 1, pslg.vertices[i].x, pslg.vertices[i].y, pslg.vertex_markers[i]);
    else
      out.print("{} {} {}\n", i + 1, pslg.vertices[i].x, pslg.vertices[i].y);
  }
  out.print("{} 1\n", pslg.segments.size());
  for (std::size_t i = 0; i < pslg.segments.size(); ++i)
    out.print("{} {} {} {}\n", i + 1, pslg.segments[i].a + 1, pslg.segments[i].b + 1, pslg.segments[i].marker);
  out.print("{}\n", pslg.holes.size());
  for (std::size_t i = 0; i < pslg.holes.size(); ++i) out.print("{} {} {}\n", i + 1, pslg.holes[i].x, pslg.holes[i].y);
  if (pslg.regions.empty()) return;
  out.print("{}\n", pslg.regions.size());
  for (std::size_t i = 0; i < pslg.regions.size(); ++i) {
    const Region& r = pslg.regions[i];
    out.print("{} {} {} {} {}\n", i + 1, r.at.x, r.at.y, r.attribute, r.max_area);
  }
}

void write_unimprovable(const std::string& prefix, const std::vector<UnimprovableTriangle>& list) {
  const std::string path = prefix + ".unimprovable";
  if (list.empty()) {
    std::remove(path.c_str());
    return;
  }
  // BlockFile, not fmt::output_file: that one flushes in its destructor, where a
  // full disk's error would end the process instead of reaching the caller as the
  // std::system_error naming the file that write_refined_mesh promises.
  detail::BlockFile out(path);
  out.print("# triangles left bad: by the small-input-angle rule (section 8) or at double precision (section 8b,\n");
  out.print("# apex and segments 0) of docs/ALGORITHM.md\n");
  out.print("# v1 v2 v3 apex segment1 segment2 input_angle_deg reason (1-based ids)\n{}\n", list.size());
  for (const UnimprovableTriangle& u : list)
    out.print("{} {} {} {} {} {} {} {}\n", u.triangle[0] + 1, u.triangle[1] + 1, u.triangle[2] + 1, u.apex + 1,
              u.segment1 + 1, u.segment2 + 1, u.input_angle_deg, to_string(u.reason));
  out.close();
}

std::vector<UnimprovableTriangle> read_unimprovable(const std::string& prefix) {
  std::vector<UnimprovableTriangle> list;
  const std::string path = prefix + ".unimprovable";
  if (!std::ifstream(path)) return list;
  LineReader in(path);
  Tokens t;
  in.expect(t, "count");
  in.fields(t, 1, 1, "count");
  std::size_t n = header_count(in, t[0], "count");
  for (std::size_t i = 0; i < n; ++i) {
    in.expect(t, "unimprovable triangle");
    in.fields(t, 7, 8, "unimprovable line (v1 v2 v3 apex segment1 segment2 angle [reason])");
    UnimprovableTriangle u;
    if (t.size() == 8) {  // no reason: an older file, the small-input-angle rule
      if (t[7] == to_string(LeftReason::DoublePrecision)) u.reason = LeftReason::DoublePrecision;
      else if (t[7] != to_string(LeftReason::SmallInputAngle))
        in.fail(fmt::format("unknown reason '{}' (small-input-angle or double-precision)", t[7]));
    }
    const bool precision = u.reason == LeftReason::DoublePrecision;
    // 1-based ids; checked against the mesh and input by the certifier, here only for range.
    auto id = [&](std::string_view token, const char* what) {
      std::int64_t v = in.integer(token, what);
      if (precision && v == 0 && std::string_view(what) != "vertex id") return -1;  // none
      if (v < 1 || v > std::numeric_limits<int>::max()) in.fail(fmt::format("{} {} out of range", what, v));
      return static_cast<int>(v - 1);
    };
    for (int k = 0; k < 3; ++k) u.triangle[k] = id(t[k], "vertex id");
    u.apex = id(t[3], "apex");
    u.segment1 = id(t[4], "segment");
    u.segment2 = id(t[5], "segment");
    u.input_angle_deg = in.real(t[6], "angle");
    list.push_back(u);
  }
  return list;
}

}  // namespace lepp
