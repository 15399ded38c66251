// SPDX-License-Identifier: GPL-3.0-or-later
// PREFIX.vtu: VTK's XML UnstructuredGrid with every array in one appended raw
// binary block (header_type UInt64, so arrays above 4 GiB are fine). Per
// triangle: the quality measures of lepp/stats.h and the region; per vertex:
// input or Steiner. docs/FORMATS.md lists the arrays.
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

#include "block_file.h"
#include "lepp/mesh_formats.h"

namespace lepp {
namespace {

using detail::BlockFile;

struct Array {
  const char* name;
  const char* type;
  int components;
  std::size_t count;  // values (tuples x components)
  std::size_t bytes_per_value;
};

// Writes `count` values made by value(i), in chunks (no whole-array copy).
template <class T, class F>
void write_values(BlockFile& out, std::size_t count, F value) {
  constexpr std::size_t kChunk = 1 << 16;
  std::vector<T> chunk;
  chunk.reserve(kChunk);
  const std::uint64_t nbytes = count * sizeof(T);
  out.raw(nbytes);
  for (std::size_t i = 0; i < count; i += kChunk) {
    chunk.clear();
    const std::size_t end = std::min(count, i + kChunk);
    for (std::size_t j = i; j < end; ++j) chunk.push_back(static_cast<T>(value(j)));
    out.bytes(chunk.data(), chunk.size() * sizeof(T));
  }
}

template <class F>
void write_measure(BlockFile& out, const Mesh& mesh, F measure) {
  write_values<double>(out, mesh.triangles.size(), [&](std::size_t t) {
    const Tri& tri = mesh.triangles[t];
    return measure(mesh.vertices[static_cast<std::size_t>(tri[0])], mesh.vertices[static_cast<std::size_t>(tri[1])],
                   mesh.vertices[static_cast<std::size_t>(tri[2])]);
  });
}

template <class Id>
void write_cells(BlockFile& out, const Mesh& mesh) {
  write_values<Id>(out, 3 * mesh.triangles.size(),
                   [&](std::size_t i) { return mesh.triangles[i / 3][i % 3]; });
  write_values<Id>(out, mesh.triangles.size(), [](std::size_t t) { return 3 * (t + 1); });
}

}  // namespace

void write_vtu(const std::string& path, const Mesh& mesh, const MeshLabels& labels) {
  const std::size_t n = mesh.vertices.size(), m = mesh.triangles.size();
  if (!labels.triangle_regions.empty() && labels.triangle_regions.size() != m)
    throw std::invalid_argument("write_vtu: one region per triangle expected");
  // 32-bit ids when they fit, as VTK itself writes them.
  const bool wide = 3 * m > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()) ||
                    n > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max());
  const char* id_type = wide ? "Int64" : "Int32";
  const std::size_t id_bytes = wide ? 8 : 4;

  const Array point_data[] = {{"input", "UInt8", 1, n, 1}};
  std::vector<Array> cell_data;
  for (const TriangleMeasure& measure : triangle_measures()) cell_data.push_back({measure.name, "Float64", 1, m, 8});
  cell_data.push_back({"region", "Int32", 1, m, 4});
  const Array points = {"Points", "Float64", 3, 3 * n, 8};
  const Array cells[] = {{"connectivity", id_type, 1, 3 * m, id_bytes},
                         {"offsets", id_type, 1, m, id_bytes},
                         {"types", "UInt8", 1, m, 1}};

  BlockFile out(path);
  std::uint64_t offset = 0;
  auto declare = [&](const Array& a) {
    out.print("        <DataArray type=\"{}\" Name=\"{}\"", a.type, a.name);
    if (a.components > 1) out.print(" NumberOfComponents=\"{}\"", a.components);
    out.print(" format=\"appended\" offset=\"{}\"/>\n", offset);
    offset += sizeof(std::uint64_t) + a.count * a.bytes_per_value;
  };
  out.print("<?xml version=\"1.0\"?>\n");
  out.print("<!-- lepp mesh: cell data = per-triangle quality (docs/FORMATS.md); point data input = 1 for an input "
            "vertex, 0 for a Steiner point -->\n");
  out.print("<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"{}\" header_type=\"UInt64\">\n",
            detail::little_endian() ? "LittleEndian" : "BigEndian");
  out.print("  <UnstructuredGrid>\n    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", n, m);
  out.print("      <PointData Scalars=\"input\">\n");
  for (const Array& a : point_data) declare(a);
  out.print("      </PointData>\n      <CellData Scalars=\"min_angle\">\n");
  for (const Array& a : cell_data) declare(a);
  out.print("      </CellData>\n      <Points>\n");
  declare(points);
  out.print("      </Points>\n      <Cells>\n");
  for (const Array& a : cells) declare(a);
  out.print("      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n  <AppendedData encoding=\"raw\">\n   _");

  // The data, in the order declared.
  write_values<std::uint8_t>(out, n, [&](std::size_t v) { return v < mesh.input_vertices ? 1 : 0; });
  for (const TriangleMeasure& measure : triangle_measures()) write_measure(out, mesh, measure.of);
  write_values<std::int32_t>(out, m, [&](std::size_t t) {
    return labels.triangle_regions.empty() ? 0 : labels.triangle_regions[t];
  });
  write_values<double>(out, 3 * n, [&](std::size_t i) {
    const Point& p = mesh.vertices[i / 3];
    return i % 3 == 0 ? p.x : i % 3 == 1 ? p.y : 0.0;
  });
  if (wide)
    write_cells<std::int64_t>(out, mesh);
  else
    write_cells<std::int32_t>(out, mesh);
  constexpr std::uint8_t kVtkTriangle = 5;
  write_values<std::uint8_t>(out, m, [](std::size_t) { return kVtkTriangle; });
  out.print("\n  </AppendedData>\n</VTKFile>\n");
  out.close();
}

}  // namespace lepp
