// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp refine`'s files: the input read and validated, the refined mesh (and trace) written.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "lepp/engines/refine_request.h"
#include "lepp/mesh_labels.h"
#include "lepp/node_text_stream.h"
#include "lepp/pslg.h"
#include "lepp/refine.h"
#include "lepp/stats.h"

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
void write_refine_outputs(const RefineRequest& request, const RefineResult& result, const MeshLabels& labels,
                          NodeTextStream* node_text = nullptr);

// What writing a run leaves for its summary (refine_summary.h): the statistics of
// the labelled mesh, and the wall seconds of the two phases.
struct RefineWritten {
  MeshStats stats;
  double write_seconds = 0;       // labelling and writing every file
  double statistics_seconds = 0;  // mesh_stats
};

// The threads the request's files and statistics may use: request.threads, 0 for
// the machine's cores.
int output_threads(const RefineRequest& request);

// The result's mesh labelled (label_refined_mesh, with the request's domain options)
// and written (write_refine_outputs), and its statistics computed (mesh_stats). With
// more than one output thread the statistics run beside the writing (this thread
// joins them when the files are written), and Triangle's .node is written beside its
// .ele: the same files and numbers. Throws as write_refine_outputs. `node_text`:
// stream_node_text's, for the .node.
RefineWritten write_refine_files(const RefineRequest& request, RefineResult& result, const Pslg& input,
                                 NodeTextStream* node_text = nullptr);

// The .node's lines made beside the refinement (lepp/node_text_stream.h), fed by
// options.on_vertices: with more than one output thread, Triangle's files among the
// formats and an order that refines on one thread (the batch order's selection takes
// the threads). nullptr otherwise, or where no temporary file can be made; the files
// are the same either way. Give it to write_refine_files.
std::unique_ptr<NodeTextStream> stream_node_text(const RefineRequest& request, RefineOptions& options);

}  // namespace lepp::engines
