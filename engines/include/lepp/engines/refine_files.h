// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp refine`'s files: the input read and validated, the refined mesh (and trace) written.
#pragma once
#include <string>
#include <vector>

#include "lepp/engines/refine_request.h"
#include "lepp/mesh_labels.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"

namespace lepp::engines {

struct RefineInput {
  Pslg pslg;                          // validated (validate.h), with the request's domain options
  std::vector<std::string> warnings;  // the reader's and the validation's, in order ("warnings" of the JSON)
  // A region's area bound read but not applied (no --region-areas), naming FILE:LINE, or "".
  // Kept apart from `warnings`: lepp refine prints it as a warning, its JSON never listed it.
  std::string unapplied_region_areas;
  double seconds = 0;  // wall seconds reading and validating
};

// request.input read (read_input) and validated. Throws InputError naming file and line.
RefineInput read_refine_input(const RefineRequest& request);

// PREFIX (request.output) in the formats asked for, PREFIX.unimprovable, and with
// request.trace PREFIX.trace. `labels`: label_refined_mesh of the result's mesh.
// Throws std::exception naming the file that cannot be written.
void write_refine_outputs(const RefineRequest& request, const RefineResult& result, const MeshLabels& labels);

// The result's mesh labelled (label_refined_mesh, with the request's domain options)
// and written (write_refine_outputs): the wall seconds it took (the summary's "write"
// phase). Throws as write_refine_outputs.
double label_and_write_refine_outputs(const RefineRequest& request, RefineResult& result, const Pslg& input);

}  // namespace lepp::engines
