// SPDX-License-Identifier: GPL-3.0-or-later
// PREFIX.msh in Gmsh's format 2.2, ASCII or binary: nodes, then the triangles
// and the constrained edges (line elements), each with two tags, its physical
// group (0: none) and its elementary entity (msh_layout.h).
#include <cstdint>
#include <vector>

#include "block_file.h"
#include "lepp/mesh_formats.h"
#include "msh_layout.h"

namespace lepp {
namespace {

using detail::BlockFile;
using detail::MshEntity;

constexpr int kLine = 1, kTriangle = 2;  // Gmsh element types

}  // namespace

void write_msh2(const std::string& path, const Mesh& mesh, const MeshLabels& labels, bool binary) {
  const detail::MshLayout layout = detail::msh_layout(mesh, labels);
  const std::size_t n = mesh.vertices.size(), m = layout.triangles;
  BlockFile out(path);
  out.print("$MeshFormat\n2.2 {} {}\n", binary ? 1 : 0, sizeof(double));
  if (binary) {
    const int one = 1;  // tells the reader this machine's byte order
    out.raw(one);
    out.print("\n");
  }
  out.print("$EndMeshFormat\n");
  detail::write_physical_names(out, layout);

  out.print("$Nodes\n{}\n", n);
  for (std::size_t v = 0; v < n; ++v) {
    const Point& p = mesh.vertices[v];
    if (binary) {
      const int id = static_cast<int>(v + 1);
      const double xyz[3] = {p.x, p.y, 0.0};
      out.raw(id);
      out.bytes(xyz, sizeof xyz);
    } else {
      out.print(FMT_COMPILE("{} {} {} 0\n"), v + 1, p.x, p.y);
    }
  }
  out.print("{}$EndNodes\n", binary ? "\n" : "");

  out.print("$Elements\n{}\n", m + layout.lines);
  // Binary: one header (type, count, number of tags) per element type, then
  // the elements as ints: id, physical, elementary, vertices.
  auto element = [&](int id, int type, const MshEntity& e, const int* vertices, int count) {
    if (binary) {
      int record[2 + 3 + 1];
      record[0] = id;
      record[1] = e.physical;
      record[2] = e.tag;
      for (int k = 0; k < count; ++k) record[3 + k] = vertices[k] + 1;
      out.bytes(record, sizeof(int) * static_cast<std::size_t>(3 + count));
    } else if (count == 3) {
      out.print(FMT_COMPILE("{} {} 2 {} {} {} {} {}\n"), id, type, e.physical, e.tag, vertices[0] + 1, vertices[1] + 1, vertices[2] + 1);
    } else {
      out.print(FMT_COMPILE("{} {} 2 {} {} {} {}\n"), id, type, e.physical, e.tag, vertices[0] + 1, vertices[1] + 1);
    }
  };
  if (binary && m > 0) {
    const int header[3] = {kTriangle, static_cast<int>(m), 2};
    out.bytes(header, sizeof header);
  }
  for (const MshEntity& e : layout.surfaces)
    for (std::size_t i = e.begin; i < e.end; ++i) {
      const int t = layout.triangle_order[i];
      element(t + 1, kTriangle, e, mesh.triangles[static_cast<std::size_t>(t)].data(), 3);
    }
  if (binary && layout.lines > 0) {
    const int header[3] = {kLine, static_cast<int>(layout.lines), 2};
    out.bytes(header, sizeof header);
  }
  for (const MshEntity& e : layout.curves)
    for (std::size_t i = e.begin; i < e.end; ++i) {
      const int c = layout.line_order[i];
      const ConstrainedEdge& edge = mesh.constrained_edges[static_cast<std::size_t>(c)];
      const int ends[2] = {edge.a, edge.b};
      element(static_cast<int>(m) + c + 1, kLine, e, ends, 2);
    }
  out.print("{}$EndElements\n", binary ? "\n" : "");
  out.close();
}

}  // namespace lepp
