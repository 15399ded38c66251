// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp refine IN.poly -o PREFIX`: read, validate, refine, write, report.
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include <unistd.h>

#include <nlohmann/json.hpp>

#include "commands.h"
#include "lepp/engines/registry.h"
#include "lepp/input.h"
#include "lepp/io.h"
#include "lepp/mesh_output.h"
#include "lepp/stats.h"
#include "lepp/trace_io.h"
#include "lepp/validate.h"
#include "lepp/version.h"

namespace lepp::cli {
namespace {

struct RefineArgs {
  std::string input, output;
  double min_angle = 30;
  std::string method = to_string(Method::Centroid);
  std::string engine = engines::to_string(engines::Engine::Fast);
  std::string order = to_string(QueueOrder::Fifo);
  std::uint64_t order_seed = 0;
  int threads = 0;
  std::int64_t max_steiner = -1;
  double max_area = 0;
  bool region_areas = false;
  double time_limit = 0;
  double edge_floor = -1;
  bool json = false;
  bool quiet = false;
  bool trace = false;
  std::vector<std::string> formats{"triangle"};  // --format replaces it
  bool binary = false;               // .msh in Gmsh's binary variant
  DomainOptions domain;
};

std::string detail_where(const Pslg& p, std::size_t region) {
  const int line = region < p.region_lines.size() ? p.region_lines[region] : 0;
  return line > 0 ? p.source + ":" + std::to_string(line) : p.source;
}

// The input file that an output file of prefix `output` would overwrite, or ""
// (`lepp refine X.poly -o X` would write X.poly over the file being read; the
// files read: the path, a bare prefix's X.poly and X.node, a .poly's X.node).
std::string input_overwritten(const std::string& input, const std::string& output) {
  namespace fs = std::filesystem;
  std::vector<std::string> read = {input, input + ".poly", input + ".node"};
  if (fs::path(input).extension() == ".poly") read.push_back(fs::path(input).replace_extension(".node").string());
  for (const std::string& r : read)
    for (const char* ext : {".node", ".ele", ".poly", ".vtu", ".msh", ".unimprovable", ".trace"}) {
      std::error_code ec;
      if (fs::equivalent(output + ext, r, ec)) return r;
    }
  return "";
}

int run_refine(const RefineArgs& args) {
  if (const std::string overwritten = input_overwritten(args.input, args.output); !overwritten.empty()) {
    std::fprintf(stderr,
                 "lepp refine: -o %s would write over the input %s; give another output prefix (Triangle writes %s.1.*)\n",
                 args.output.c_str(), overwritten.c_str(), args.output.c_str());
    return 2;
  }
  const MeshFormatChoice output = choose_mesh_formats(args.formats);  // CLI11 checked the names
  if (output.same_file) {
    std::fprintf(stderr, "lepp refine: --format msh2 and --format msh4 would both write %s.msh; ask for one per run\n",
                 args.output.c_str());
    return 2;
  }
  Pslg input;
  std::vector<std::string> warnings;
  try {
    input = validate(read_input(args.input, warnings), args.domain, warnings);
  } catch (const InputError& e) {
    std::fprintf(stderr, "lepp refine: %s\n", e.what());
    return 2;
  }
  for (const std::string& w : warnings) std::fprintf(stderr, "lepp refine: warning: %s\n", w.c_str());
  for (std::size_t r = 0; r < input.regions.size() && !args.region_areas; ++r)
    if (input.regions[r].max_area > 0) {
      std::fprintf(stderr,
                   "lepp refine: warning: %s: regional area bounds are read but not applied; pass --region-areas to "
                   "apply them (Triangle's -a with no number), or --max-area for one bound everywhere\n",
                   detail_where(input, r).c_str());
      break;
    }

  RefineOptions options;
  options.min_angle_deg = args.min_angle;
  // The options' checks admit only the registry's names.
  options.method = *engines::parse_method(args.method);
  options.order = *engines::parse_order(args.order);
  options.order_seed = args.order_seed;
  options.threads = args.threads;
  options.max_steiner = args.max_steiner;
  options.max_area = args.max_area;
  options.region_area_bounds = args.region_areas;
  options.time_limit_seconds = args.time_limit;
  options.edge_floor = args.edge_floor;
  options.trace = args.trace;
  // The progress line is rewritten in place (\r, ESC[K): on a terminal only, so that a
  // log file or a pipe gets no control characters (lepp audit does the same).
  if (!args.quiet && !args.json && isatty(STDERR_FILENO)) {
    options.on_progress = [](std::int64_t n) { std::fprintf(stderr, "\rlepp refine: %lld Steiner points", static_cast<long long>(n)); };
  }

  RefineResult result = engines::refine(*engines::parse_engine(args.engine, engines::lepp_engines()), input, options);
  if (options.on_progress) std::fprintf(stderr, "\r\033[K");
  const MeshLabels labels = label_refined_mesh(result.mesh, input, args.domain);
  try {
    MeshWriteOptions write_options;
    write_options.binary = args.binary;
    write_refined_mesh(args.output, result.mesh, labels, result.unimprovable, output.formats, write_options);
    if (args.trace) write_trace(args.output + ".trace", trace_points(result.trace));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "lepp refine: %s\n", e.what());
    return 1;
  }

  MeshStats s = mesh_stats(result.mesh, input);
  std::size_t at_precision = 0;
  for (const UnimprovableTriangle& u : result.unimprovable) at_precision += u.reason == LeftReason::DoublePrecision;
  const double avg_lepp = average_lepp_size(result);
  if (args.json) {
    nlohmann::json j = {
        {"input", args.input},
        {"output", args.output},
        {"engine", args.engine},
        {"method", to_string(options.method)},
        {"order", to_string(options.order)},
        {"order_seed", options.order == QueueOrder::Random ? nlohmann::json(options.order_seed) : nlohmann::json()},
        {"rounds", options.order == QueueOrder::Batch ? nlohmann::json(result.rounds) : nlohmann::json()},
        {"looks", options.order == QueueOrder::Batch ? nlohmann::json(result.looks) : nlohmann::json()},
        {"min_angle_target", args.min_angle},
        {"max_area", args.max_area},
        {"region_areas", args.region_areas},
        {"input_vertices", input.vertices.size()},
        {"steiner_points", result.steiner_points},
        {"vertices", s.vertices},
        {"triangles", s.triangles},
        {"min_angle", s.min_angle_deg},
        {"avg_min_angle", s.avg_min_angle_deg},
        {"min_area_quality", s.min_area_quality},
        {"shortest_edge_ratio", s.shortest_edge_ratio},
        {"avg_lepp_size", avg_lepp},
        {"cocircular_ties", result.cocircular_ties},
        {"area_refined", result.area_refined},
        {"unimprovable", result.unimprovable.size()},
        {"unimprovable_by_reason",
         {{to_string(LeftReason::SmallInputAngle), result.unimprovable.size() - at_precision},
          {to_string(LeftReason::DoublePrecision), at_precision}}},
        {"precision_stops", result.precision_stops},
        {"tie_resolutions", result.tie_resolutions},
        {"outcome", to_string(result.outcome)},
        {"stuck", result.stuck},
        {"seconds", result.seconds},
        {"warnings", warnings},
    };
    // The triangles left at double precision (1-based ids as in PREFIX.unimprovable), the first 50.
    nlohmann::json limited = nlohmann::json::array();
    for (const UnimprovableTriangle& u : result.unimprovable)
      if (u.reason == LeftReason::DoublePrecision && limited.size() < 50)
        limited.push_back({{"triangle", {u.triangle[0] + 1, u.triangle[1] + 1, u.triangle[2] + 1}},
                           {"reason", to_string(u.reason)},
                           {"rule", to_string(u.rule)},
                           {"point", {u.point.x, u.point.y}}});
    j["unimprovable_at_precision"] = limited;
    add_version(j);
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf("input vertices        %zu\n", input.vertices.size());
    std::printf("Steiner points added  %lld\n", static_cast<long long>(result.steiner_points));
    std::printf("triangles             %zu\n", s.triangles);
    std::printf("smallest angle        %.4f deg\n", s.min_angle_deg);
    std::printf("average smallest      %.4f deg\n", s.avg_min_angle_deg);
    std::printf("smallest area quality %.4f\n", s.min_area_quality);
    std::printf("shortest edge / input %.4f\n", s.shortest_edge_ratio);
    std::printf("average Lepp size     %.3f\n", avg_lepp);
    if (args.max_area > 0 || args.region_areas)
      std::printf("refined for area      %lld triangles (too big for their bound)\n", static_cast<long long>(result.area_refined));
    if (!result.unimprovable.empty())
      std::printf("unimprovable          %zu triangles (%zu by small input angles, %zu at double precision; listed in %s.unimprovable)\n",
                  result.unimprovable.size(), result.unimprovable.size() - at_precision, at_precision, args.output.c_str());
    if (options.order == QueueOrder::Random)
      std::printf("processing order      random (seed %llu)\n", static_cast<unsigned long long>(options.order_seed));
    else if (options.order == QueueOrder::Batch)
      std::printf("processing order      batch (%lld rounds)\n", static_cast<long long>(result.rounds));
    else
      std::printf("processing order      %s\n", to_string(options.order));
    std::printf("outcome               %s\n", to_string(result.outcome));
    if (!result.stuck.empty()) std::printf("stuck at              %s\n", result.stuck.c_str());
    std::printf("seconds               %.3f\n", result.seconds);
  }
  return exit_status(result.outcome);
}

}  // namespace

void add_refine_command(CLI::App& app, int& status) {
  auto args = std::make_shared<RefineArgs>();
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
                  "Threads for --order batch's selection (fast engine; 0: the machine's cores). The mesh is the same "
                  "for every number; the other orders run on one")
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
      "2 bad input; 1 internal error.");
  cmd->callback([args, &status] { status = run_refine(*args); });
}

}  // namespace lepp::cli
