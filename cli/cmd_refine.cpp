// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp refine IN.poly -o PREFIX`: options parsed, lepp::engines' refine request run (read, refine, write), its report printed.
#include <cstdio>
#include <exception>
#include <memory>
#include <string>

#include <unistd.h>

#include "commands.h"
#include "message.h"
#include "lepp/capacity_error.h"
#include "lepp/engines/refine_files.h"
#include "lepp/engines/refine_request.h"
#include "lepp/engines/refine_summary.h"
#include "lepp/io.h"

namespace lepp::cli {
namespace {

int run_refine(const engines::RefineRequest& args) {
  if (const std::string error = engines::refine_request_error(args); !error.empty()) {
    message("lepp refine: %s\n", error.c_str());
    return 2;
  }
  engines::RefineInput input;
  try {
    input = engines::read_refine_input(args);
  } catch (const InputError& e) {
    message("lepp refine: %s\n", e.what());
    return 2;
  }
  for (const std::string& w : input.warnings) message("lepp refine: warning: %s\n", w.c_str());
  if (!input.unapplied_region_areas.empty())
    message("lepp refine: warning: %s\n", input.unapplied_region_areas.c_str());

  RefineOptions options = engines::refine_options(args);
  // The progress line is rewritten in place (\r, ESC[K): on a terminal only, so that a
  // log file or a pipe gets no control characters (lepp audit does the same).
  if (!args.quiet && !args.json && isatty(STDERR_FILENO)) {
    options.on_progress = [](std::int64_t n) { message("\rlepp refine: %lld Steiner points", static_cast<long long>(n)); };
  }
  // The .node's lines made beside the refinement, where a thread is free for them.
  const std::unique_ptr<NodeTextStream> node_text = engines::stream_node_text(args, options);
  RefineResult result;
  try {
    result = engines::refine(engines::refine_engine(args), input.pslg, options);
  } catch (const CapacityError& e) {
    // A mesh larger than the engine can number: the request's to change (its size
    // bound or budget), like bad input; no file is written.
    if (options.on_progress) message("\r\033[K");
    message("lepp refine: %s\n", e.what());
    return 2;
  }
  if (options.on_progress) message("\r\033[K");
  engines::RefineWritten written;
  try {
    written = engines::write_refine_files(args, result, input.pslg, node_text.get());
  } catch (const InputError& e) {
    // An output that cannot be written (a directory in the way, a full disk, a
    // folder that does not exist) is the user's to fix: bad usage, naming the file.
    std::fprintf(stderr, "lepp refine: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    message("lepp refine: %s\n", e.what());
    return 1;
  }

  if (args.json)
    std::printf("%s\n", engines::refine_json_summary(args, input, result, written).dump(2).c_str());
  else
    std::printf("%s", engines::refine_text_summary(args, input, result, written).c_str());
  return exit_status(result.outcome);
}

}  // namespace

void add_refine_command(CLI::App& app, int& status) {
  auto args = std::make_shared<engines::RefineRequest>();
  auto* cmd = app.add_subcommand("refine", "Refine a .poly file into a quality mesh (writes PREFIX.node/.ele/.poly, or --format)");
  cmd->add_option("input", args->input, "Input PSLG in Triangle's .poly format, or a .node point set, or a bare prefix X (X.poly, else X.node)")->required();
  cmd->add_option("-o,--output", args->output,
                  "Output prefix: writes PREFIX.node, PREFIX.ele, PREFIX.poly (Triangle's formats; see --format)")
      ->required();
  cmd->add_option("--format", args->formats,
                  "Output format, repeatable: triangle (PREFIX.node/.ele/.poly, the default), vtu (PREFIX.vtu, VTK XML with "
                  "per-triangle quality), msh2 or msh4 (PREFIX.msh, Gmsh 2.2 or 4.1 with physical groups); "
                  "docs/FORMATS.md; also comma-separated (--format triangle,vtu)")
      ->allow_extra_args(false)
      ->delimiter(',')
      ->check(CLI::IsMember({"triangle", "vtu", "msh2", "msh4"}));
  cmd->add_flag("--binary", args->binary, "Write .msh in Gmsh's binary variant instead of ASCII (.vtu is always binary)");
  cmd->add_option("--min-angle", args->min_angle, "Smallest angle wanted, degrees (a triangle below it is bad)")
      ->default_val(30)
      ->check(CLI::Range(0.0, 60.0));
  cmd->add_option("--method", args->method, "Point selection: centroid (the paper's Lepp-centroid) or midpoint (Lepp-midpoint)")
      ->default_val(args->method)
      ->check(CLI::IsMember(engines::method_names()));
  cmd->add_option("--engine", args->engine, "fast (optimized) or reference (exact CGAL Epeck, slow)")
      ->default_val(args->engine)
      ->check(CLI::IsMember(engines::names(engines::lepp_engines())));
  cmd->add_option("--order", args->order,
                  "Processing order of bad triangles: fifo (default), lifo, flip (in the order the insertion's flips "
                  "create them), random (--order-seed), smallest-angle, or batch (rounds of independent insertions) "
                  "(docs/ALGORITHM.md section 7)")
      ->default_val(args->order)
      ->check(CLI::IsMember(engines::order_names()));
  cmd->add_option("--order-seed", args->order_seed, "Seed of --order random (SplitMix64, docs/ALGORITHM.md)")->default_val(0);
  cmd->add_option("--threads", args->threads,
                  "Threads for --order batch's selection (fast engine; 0: the machine's cores), and for the output: "
                  "the statistics beside the writing, Triangle's .node beside its .ele (its lines made during the "
                  "refinement, except with batch), the canonical sort; and the fast engine's memory made ready "
                  "beside its refinement. The mesh and files are the same for every number; the other orders refine on one")
      ->default_val(0)
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--max-steiner", args->max_steiner, "Steiner budget; default 100000 + 1000 x (vertices + segments)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--max-area", args->max_area, "Size bound: a triangle larger than this is bad too (Triangle's -a)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--region-areas", args->region_areas,
                "Apply the area bounds of the .poly's regions, each to the triangles of its region (Triangle's -a with "
                "no number); with --max-area too, the smaller bound applies");
  cmd->add_option("--time-limit", args->time_limit, "Stop after this many seconds (outcome time-limit, exit 3)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--tie-search-states", args->tie_search_states,
                  "At the precision limit, try other resolutions of exact length ties in at most this many Lepp states "
                  "per triangle before leaving it (0: no bound; docs/ALGORITHM.md section 8b)")
      ->default_val(args->tie_search_states);
  cmd->add_option("--edge-floor", args->edge_floor,
                  "Stop (outcome edge-floor, exit 3) when an edge shorter than this appears; default 2^-20 x the "
                  "input's smallest feature (docs/ALGORITHM.md)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--convex-hull", args->domain.convex_hull,
                "Add the convex hull's edges as segments, so open boundaries mesh (Triangle's -c); a point set (a .node, "
                "or a .poly with no segments) always meshes its convex hull");
  cmd->add_flag("--split-crossings", args->domain.split_crossings,
                "Split crossing segments at their exact intersection rounded to doubles (default: rejected); output "
                "markers are then the file's segment numbers");
  cmd->add_flag("--json", args->json, "Print the statistics as JSON");
  cmd->add_flag("--trace", args->trace, "Also write PREFIX.trace: the Steiner points in insertion order (docs/FORMATS.md)");
  cmd->add_flag("-q,--quiet", args->quiet, "No progress line on stderr (there is none when stderr is no terminal)");
  cmd->footer(
      "Exit status: 0 converged; 3 stopped by a guard (budget, edge floor, time limit) or triangles left\n"
      "unimprovable by small input angles or at double precision (the mesh is still written, a valid CDT);\n"
      "2 bad input, or a mesh past the fast engine's 2^29 vertices or triangles; 1 internal error.");
  cmd->callback([args, &status] { status = run_refine(*args); });
}

}  // namespace lepp::cli
