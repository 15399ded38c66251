// SPDX-License-Identifier: GPL-3.0-or-later
// The mesh file formats lepp writes: Triangle's .node/.ele/.poly, VTK's XML
// .vtu (for ParaView, with per-triangle quality) and Gmsh's .msh 2.2 and 4.1
// (for FEM codes, with physical groups). `lepp refine --format` and Python's
// Mesh.write call these through lepp/mesh_output.h. docs/FORMATS.md, "Other
// output formats", says what each file holds.
#pragma once
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "lepp/mesh.h"
#include "lepp/mesh_labels.h"

namespace lepp {

enum class MeshFormat {
  Triangle,  // PREFIX.node, PREFIX.ele, PREFIX.poly (lepp/io.h's write_mesh)
  Vtu,       // PREFIX.vtu: VTK XML UnstructuredGrid, appended raw binary
  Msh2,      // PREFIX.msh: Gmsh 2.2 (MFEM and others read only this version)
  Msh4,      // PREFIX.msh: Gmsh 4.1 (deal.II, libMesh, Gmsh's default)
};

class NodeTextStream;

struct MeshWriteOptions {
  bool binary = false;  // .msh only: Gmsh's binary variant instead of ASCII (.vtu is always binary)
  int threads = 1;      // Triangle's files: > 1 writes the .node beside the .ele (write_mesh in lepp/io.h)
  // Triangle's .node: its lines made beside the refinement (lepp/node_text_stream.h), or nullptr.
  NodeTextStream* node_text = nullptr;
};

// "triangle", "vtu", "msh2", "msh4": the names `lepp refine --format` takes.
const char* to_string(MeshFormat format);
std::optional<MeshFormat> parse_mesh_format(std::string_view name);
// The extension a format adds to PREFIX (".vtu", ".msh"; ".node" for Triangle's, which also writes .ele and .poly).
const char* file_extension(MeshFormat format);

// Writes the mesh in `format` to PREFIX + its extension (Triangle's format:
// the three files). `labels` (mesh_labels()) gives the boundary markers and
// regions: empty vectors write no groups from them. Throws std::system_error
// naming the file when it cannot be written, std::invalid_argument when the
// labels do not match the mesh.
void write_mesh(const std::string& prefix, const Mesh& mesh, MeshFormat format, const MeshLabels& labels,
                const MeshWriteOptions& options = {});

// The per-triangle measures the .vtu writes as cell data, in its order, each a
// function of the corners (lepp/stats.h). One list, so that other views of a
// mesh (Python's Mesh.to_meshio and lepp.plot) carry the same names and values.
struct TriangleMeasure {
  const char* name;  // the .vtu's array name: "min_angle", "max_angle", "area_quality", ...
  double (*of)(const Point& a, const Point& b, const Point& c);
};
const std::vector<TriangleMeasure>& triangle_measures();

// The writers themselves, to the path given (no extension added).
void write_vtu(const std::string& path, const Mesh& mesh, const MeshLabels& labels);
void write_msh2(const std::string& path, const Mesh& mesh, const MeshLabels& labels, bool binary = false);
void write_msh4(const std::string& path, const Mesh& mesh, const MeshLabels& labels, bool binary = false);

}  // namespace lepp
