// SPDX-License-Identifier: GPL-3.0-or-later
// PREFIX.msh in Gmsh's format 4.1, ASCII or binary: the entities (curves per
// boundary marker, surfaces per region, msh_layout.h) with their physical
// groups, every node in one block on the first surface, and one element block
// per entity.
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

// Binary 4.1 writes counts and tags as size_t (the format line's data size), entity fields as int.
void count(BlockFile& out, bool binary, std::size_t value) {
  if (binary)
    out.raw(static_cast<std::uint64_t>(value));
  else
    out.print("{} ", value);
}

void entity(BlockFile& out, bool binary, const MshEntity& e) {
  if (binary) {
    out.raw(e.tag);
    out.bytes(e.box.data(), sizeof(double) * e.box.size());
    out.raw(static_cast<std::uint64_t>(e.physical ? 1 : 0));
    if (e.physical) out.raw(e.physical);
    out.raw(std::uint64_t{0});  // no bounding entities: the mesh is "discrete"
  } else {
    out.print("{} {} {} {} {} {} {} ", e.tag, e.box[0], e.box[1], e.box[2], e.box[3], e.box[4], e.box[5]);
    if (e.physical)
      out.print("1 {} 0\n", e.physical);
    else
      out.print("0 0\n");
  }
}

void block_header(BlockFile& out, bool binary, int dim, int tag, int type_or_parametric, std::size_t size) {
  if (binary) {
    const int head[3] = {dim, tag, type_or_parametric};
    out.bytes(head, sizeof head);
    out.raw(static_cast<std::uint64_t>(size));
  } else {
    out.print("{} {} {} {}\n", dim, tag, type_or_parametric, size);
  }
}

}  // namespace

void write_msh4(const std::string& path, const Mesh& mesh, const MeshLabels& labels, bool binary) {
  const detail::MshLayout layout = detail::msh_layout(mesh, labels);
  const std::size_t n = mesh.vertices.size(), m = layout.triangles;
  const char* nl = binary ? "\n" : "";  // binary sections end with a newline before $End
  BlockFile out(path);
  out.print("$MeshFormat\n4.1 {} {}\n", binary ? 1 : 0, sizeof(std::uint64_t));
  if (binary) {
    const int one = 1;  // tells the reader this machine's byte order
    out.raw(one);
    out.print("\n");
  }
  out.print("$EndMeshFormat\n");

  detail::write_physical_names(out, layout);

  out.print("$Entities\n");
  count(out, binary, 0);
  count(out, binary, layout.curves.size());
  count(out, binary, layout.surfaces.size());
  count(out, binary, 0);
  if (!binary) out.print("\n");
  for (const MshEntity& e : layout.curves) entity(out, binary, e);
  for (const MshEntity& e : layout.surfaces) entity(out, binary, e);
  out.print("{}$EndEntities\n", nl);

  // Nodes: one block, on the first surface (or surface 1 when there is none).
  out.print("$Nodes\n");
  const int node_surface = layout.surfaces.empty() ? 1 : layout.surfaces.front().tag;
  count(out, binary, n > 0 ? 1 : 0);
  count(out, binary, n);
  count(out, binary, n > 0 ? 1 : 0);
  count(out, binary, n);
  if (!binary) out.print("\n");
  if (n > 0) {
    block_header(out, binary, 2, node_surface, 0, n);
    for (std::size_t v = 0; v < n; ++v) {
      if (binary)
        out.raw(static_cast<std::uint64_t>(v + 1));
      else
        out.print(FMT_COMPILE("{}\n"), v + 1);
    }
    for (const Point& p : mesh.vertices) {
      if (binary) {
        const double xyz[3] = {p.x, p.y, 0.0};
        out.bytes(xyz, sizeof xyz);
      } else {
        out.print(FMT_COMPILE("{} {} 0\n"), p.x, p.y);
      }
    }
  }
  out.print("{}$EndNodes\n", nl);

  const std::size_t elements = m + layout.lines;
  out.print("$Elements\n");
  count(out, binary, layout.curves.size() + layout.surfaces.size());
  count(out, binary, elements);
  count(out, binary, elements > 0 ? 1 : 0);
  count(out, binary, elements);
  if (!binary) out.print("\n");
  for (const MshEntity& e : layout.curves) {
    block_header(out, binary, 1, e.tag, kLine, e.end - e.begin);
    for (std::size_t i = e.begin; i < e.end; ++i) {
      const auto c = static_cast<std::size_t>(layout.line_order[i]);
      const ConstrainedEdge& edge = mesh.constrained_edges[c];
      const std::uint64_t id = m + c + 1, a = static_cast<std::uint64_t>(edge.a) + 1, b = static_cast<std::uint64_t>(edge.b) + 1;
      if (binary) {
        const std::uint64_t record[3] = {id, a, b};
        out.bytes(record, sizeof record);
      } else {
        out.print(FMT_COMPILE("{} {} {}\n"), id, a, b);
      }
    }
  }
  for (const MshEntity& e : layout.surfaces) {
    block_header(out, binary, 2, e.tag, kTriangle, e.end - e.begin);
    for (std::size_t i = e.begin; i < e.end; ++i) {
      const auto t = static_cast<std::size_t>(layout.triangle_order[i]);
      const Tri& tri = mesh.triangles[t];
      const std::uint64_t record[4] = {t + 1, static_cast<std::uint64_t>(tri[0]) + 1, static_cast<std::uint64_t>(tri[1]) + 1,
                                       static_cast<std::uint64_t>(tri[2]) + 1};
      if (binary)
        out.bytes(record, sizeof record);
      else
        out.print(FMT_COMPILE("{} {} {} {}\n"), record[0], record[1], record[2], record[3]);
    }
  }
  out.print("{}$EndElements\n", nl);
  out.close();
}

}  // namespace lepp
