// SPDX-License-Identifier: GPL-3.0-or-later
// How a mesh maps onto Gmsh's model, for both .msh versions: the entities
// (one surface per group of triangles, one curve per boundary marker), their
// physical groups and names, and the elements grouped by entity.
// docs/FORMATS.md, "Gmsh .msh", states the numbering. Internal to lepp_core.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "lepp/mesh.h"
#include "lepp/mesh_labels.h"

namespace lepp::detail {

struct MshEntity {
  int tag = 0;       // the entity's tag (its dimension: 1 curve, 2 surface)
  int physical = 0;  // its physical group's tag (the writers give every entity one)
  std::string name;  // the physical group's name
  std::size_t begin = 0, end = 0;  // its elements: MshLayout's order[begin, end)
  std::array<double, 6> box{};     // min x y z, max x y z of its elements' vertices
};

struct MshLayout {
  std::vector<MshEntity> curves, surfaces;  // by increasing tag
  std::vector<int> line_order;              // constrained edge ids, grouped by curve
  std::vector<int> triangle_order;          // triangle ids, grouped by surface
  // Element tags: triangle t is t + 1, constrained edge e is triangles + e + 1.
  std::size_t triangles = 0, lines = 0;
  int physical_groups() const;
};

// Throws std::invalid_argument when the labels' sizes do not match the mesh.
MshLayout msh_layout(const Mesh& mesh, const MeshLabels& labels);

class BlockFile;
// The $PhysicalNames section, the same text in .msh 2.2 and 4.1 (ASCII and binary).
void write_physical_names(BlockFile& out, const MshLayout& layout);

}  // namespace lepp::detail
