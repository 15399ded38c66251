// SPDX-License-Identifier: GPL-3.0-or-later
// What a refined mesh leaves beside PREFIX: the mesh in each format asked for
// (`lepp refine --format`, `--binary`) with the boundary markers and regions
// taken from the input, and PREFIX.unimprovable. `lepp refine -o PREFIX` and
// Python's Mesh.write both go through these, so that they write the same bytes.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "lepp/input.h"
#include "lepp/mesh.h"
#include "lepp/mesh_formats.h"
#include "lepp/mesh_labels.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp {

// The formats named ("triangle", "vtu", "msh2", "msh4": to_string's), each
// once, in the order first named.
struct MeshFormatChoice {
  std::vector<MeshFormat> formats;
  std::optional<std::string> unknown;  // the first name that is no format; formats is then empty
  bool same_file = false;              // msh2 and msh4 both named: each writes PREFIX.msh, so callers refuse the choice
};
MeshFormatChoice choose_mesh_formats(const std::vector<std::string>& names);

// The labels of `mesh`, refined from the validated `input` (mesh_labels), and
// its constrained edges numbered as lepp refine writes them: with
// domain.split_crossings both pieces of a split segment keep its identity, the
// file's segment number (docs/FORMATS.md). The labels are taken first: they
// read the markers by validated segment.
MeshLabels label_refined_mesh(Mesh& mesh, const Pslg& input, const DomainOptions& domain);

// Writes PREFIX in each of `formats` (write_mesh) and PREFIX.unimprovable
// (write_unimprovable: removed when `unimprovable` is empty). Throws
// std::system_error naming the file that cannot be written.
void write_refined_mesh(const std::string& prefix, const Mesh& mesh, const MeshLabels& labels,
                        const std::vector<UnimprovableTriangle>& unimprovable, const std::vector<MeshFormat>& formats,
                        const MeshWriteOptions& options = {});

}  // namespace lepp
