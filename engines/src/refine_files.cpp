// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp refine`'s files: the input read and validated, the refined mesh (and trace) written.
#include "lepp/engines/refine_files.h"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <future>
#include <string>
#include <system_error>

#include "lepp/input.h"
#include "lepp/io.h"
#include "lepp/mesh_output.h"
#include "lepp/trace_io.h"
#include "lepp/validate.h"

namespace lepp::engines {
namespace {

// FILE:LINE of a region's line in the input (FILE when its line is unknown).
std::string detail_where(const Pslg& p, std::size_t region) {
  const int line = region < p.region_lines.size() ? p.region_lines[region] : 0;
  return line > 0 ? p.source + ":" + std::to_string(line) : p.source;
}

}  // namespace

RefineInput read_refine_input(const RefineRequest& request) {
  const auto start = std::chrono::steady_clock::now();
  RefineInput in;
  in.pslg = validate(read_input(request.input, in.warnings), request.domain, in.warnings);
  // One note for the first region with a bound: the user learns the flag, not a list.
  for (std::size_t r = 0; r < in.pslg.regions.size() && !request.region_areas; ++r)
    if (in.pslg.regions[r].max_area > 0) {
      in.unapplied_region_areas = detail_where(in.pslg, r) +
                                  ": regional area bounds are read but not applied; pass --region-areas to apply them "
                                  "(Triangle's -a with no number), or --max-area for one bound everywhere";
      break;
    }
  in.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return in;
}

void write_refine_outputs(const RefineRequest& request, const RefineResult& result, const MeshLabels& labels,
                          NodeTextStream* node_text) {
  // The names were checked by refine_request_error (msh2 with msh4) and the option parser.
  const MeshFormatChoice output = choose_mesh_formats(request.formats);
  MeshWriteOptions write_options;
  write_options.binary = request.binary;
  write_options.threads = output_threads(request);
  write_options.node_text = node_text;
  // A file that cannot be written is the user's to fix (exit 2 in lepp refine), as
  // Triangle's files already are (their InputError): the writers' std::system_error
  // (the other formats, the .unimprovable, the trace) names the file.
  try {
    write_refined_mesh(request.output, result.mesh, labels, result.unimprovable, output.formats, write_options);
    if (request.trace) write_trace(request.output + ".trace", trace_points(result.trace));
  } catch (const std::system_error& e) {
    throw InputError(request.output, 0, std::string("cannot write the output: ") + e.what());
  }
}

int output_threads(const RefineRequest& request) {
  return threads_or_cores(request.threads);
}

RefineWritten write_refine_files(const RefineRequest& request, RefineResult& result, const Pslg& input,
                                 NodeTextStream* node_text) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  const MeshLabels labels = label_refined_mesh(result.mesh, input, request.domain);
  // Both only read the labelled mesh. With more than one thread the statistics start
  // beside the writing, and this thread joins them once the files are written.
  MeshStatsJob statistics(result.mesh, input);
  Clock::time_point statistics_start = Clock::now();
  std::future<void> beside;
  if (output_threads(request) > 1) beside = std::async(std::launch::async, [&statistics] { statistics.work(); });
  write_refine_outputs(request, result, labels, node_text);
  RefineWritten written;
  written.write_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (!beside.valid()) statistics_start = Clock::now();
  statistics.work();
  if (beside.valid()) beside.get();
  written.stats = statistics.result();
  written.statistics_seconds = std::chrono::duration<double>(Clock::now() - statistics_start).count();
  return written;
}

std::unique_ptr<NodeTextStream> stream_node_text(const RefineRequest& request, RefineOptions& options) {
  if (output_threads(request) < 2 || options.order == QueueOrder::Batch) return nullptr;
  const MeshFormatChoice output = choose_mesh_formats(request.formats);
  if (std::find(output.formats.begin(), output.formats.end(), MeshFormat::Triangle) == output.formats.end())
    return nullptr;
  std::unique_ptr<NodeTextStream> stream = NodeTextStream::open(request.output);
  if (stream)
    options.on_vertices = [s = stream.get()](const std::vector<Point>& vertices, std::size_t input_vertices) {
      s->add(vertices, input_vertices);
    };
  return stream;
}

}  // namespace lepp::engines
