// SPDX-License-Identifier: GPL-3.0-or-later
// The files of a refined mesh: the formats chosen, the labels, the writing.
#include "lepp/mesh_output.h"

#include <algorithm>
#include <optional>

#include "lepp/io.h"

namespace lepp {
namespace {

bool has(const std::vector<MeshFormat>& formats, MeshFormat f) {
  return std::find(formats.begin(), formats.end(), f) != formats.end();
}

}  // namespace

MeshFormatChoice choose_mesh_formats(const std::vector<std::string>& names) {
  MeshFormatChoice choice;
  for (const std::string& name : names) {
    const std::optional<MeshFormat> f = parse_mesh_format(name);
    if (!f) {
      choice.formats.clear();
      choice.unknown = name;
      return choice;
    }
    if (!has(choice.formats, *f)) choice.formats.push_back(*f);
  }
  choice.same_file = has(choice.formats, MeshFormat::Msh2) && has(choice.formats, MeshFormat::Msh4);
  return choice;
}

MeshLabels label_refined_mesh(Mesh& mesh, const Pslg& input, const DomainOptions& domain) {
  MeshLabels labels = mesh_labels(mesh, input);
  if (domain.split_crossings)
    for (ConstrainedEdge& e : mesh.constrained_edges)
      if (e.segment >= 0 && static_cast<std::size_t>(e.segment) < input.segment_origin.size())
        e.segment = input.segment_origin[static_cast<std::size_t>(e.segment)];
  return labels;
}

void write_refined_mesh(const std::string& prefix, const Mesh& mesh, const MeshLabels& labels,
                        const std::vector<UnimprovableTriangle>& unimprovable, const std::vector<MeshFormat>& formats,
                        const MeshWriteOptions& options) {
  for (MeshFormat f : formats) write_mesh(prefix, mesh, f, labels, options);
  write_unimprovable(prefix, unimprovable);
}

}  // namespace lepp
