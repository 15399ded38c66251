// SPDX-License-Identifier: GPL-3.0-or-later
// Format names and the one entry point that writes PREFIX in any format.
#include "lepp/mesh_formats.h"

#include "lepp/io.h"
#include "lepp/stats.h"

namespace lepp {

const char* to_string(MeshFormat format) {
  switch (format) {
    case MeshFormat::Triangle: return "triangle";
    case MeshFormat::Vtu: return "vtu";
    case MeshFormat::Msh2: return "msh2";
    case MeshFormat::Msh4: return "msh4";
  }
  return "?";
}

std::optional<MeshFormat> parse_mesh_format(std::string_view name) {
  for (MeshFormat f : {MeshFormat::Triangle, MeshFormat::Vtu, MeshFormat::Msh2, MeshFormat::Msh4})
    if (name == to_string(f)) return f;
  return std::nullopt;
}

const char* file_extension(MeshFormat format) {
  switch (format) {
    case MeshFormat::Triangle: return ".node";
    case MeshFormat::Vtu: return ".vtu";
    case MeshFormat::Msh2:
    case MeshFormat::Msh4: return ".msh";
  }
  return "";
}

const std::vector<TriangleMeasure>& triangle_measures() {
  static const std::vector<TriangleMeasure> measures = {{"min_angle", min_angle_deg},
                                                        {"max_angle", max_angle_deg},
                                                        {"area_quality", area_quality},
                                                        {"radius_ratio", radius_ratio},
                                                        {"edge_ratio", edge_ratio}};
  return measures;
}

void write_mesh(const std::string& prefix, const Mesh& mesh, MeshFormat format, const MeshLabels& labels,
                const MeshWriteOptions& options) {
  switch (format) {
    case MeshFormat::Triangle: write_mesh(prefix, mesh, options.threads, options.node_text); return;
    case MeshFormat::Vtu: write_vtu(prefix + ".vtu", mesh, labels); return;
    case MeshFormat::Msh2: write_msh2(prefix + ".msh", mesh, labels, options.binary); return;
    case MeshFormat::Msh4: write_msh4(prefix + ".msh", mesh, labels, options.binary); return;
  }
}

}  // namespace lepp
