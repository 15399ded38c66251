// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp certify IN.poly MESH_PREFIX`: the exact certificate of any mesher's
// Triangle-format output (docs/CERTIFIER.md): exit 0 certified, 1 violations, 2 bad input.
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "message.h"
#include "lepp/certify.h"
#include "lepp/certify_html.h"
#include "lepp/certify_json.h"
#include "lepp/certify_svg.h"
#include "lepp/engines/registry.h"
#include "lepp/input.h"
#include "lepp/io.h"
#include "lepp/mesh_read.h"
#include "lepp/validate.h"
#include "lepp/version.h"

namespace lepp::cli {
namespace {

struct CertifyArgs {
  std::string input, mesh;
  double min_angle = 0;
  bool conforming = false;
  bool no_theorem2 = false;
  bool json = false;
  bool exempt = false;
  bool exempt_precision = false;
  bool ties_by_ids = false;
  std::size_t tie_search_states = kTieSearchStates;
  double time_limit = 0;
  std::string method = to_string(Method::Centroid);
  double max_area = 0;
  bool region_areas = false;
  std::size_t max_listed = 50;
  int threads = 1;
  std::string svg, svg_zoom, html;
  DomainOptions domain;
};

// Writes the drawing; a message on stderr either way (the verdict is unchanged).
void write_svg(const std::string& path, const Mesh& mesh, const certify::Report& report, bool zoom, const std::string& title) {
  try {
    const std::string svg = certify::report_svg(mesh, report, zoom, title);
    std::ofstream out(path, std::ios::binary);
    out << svg;
    if (!out) throw std::runtime_error("cannot write " + path);
    message("lepp certify: wrote %s\n", path.c_str());
  } catch (const std::exception& e) {
    message("lepp certify: no drawing %s: %s\n", path.c_str(), e.what());
  }
}

// Writes the page; a message on stderr either way (the verdict is unchanged).
void write_html(const CertifyArgs& args, const Mesh& mesh, const certify::Report& report) {
  certify::HtmlOptions o;
  o.title = args.input + ", " + args.mesh;
  o.command = "lepp certify " + args.input + " " + args.mesh +
              (args.min_angle > 0 ? fmt::format(" --min-angle {:g}", args.min_angle) : std::string());
  std::ofstream out(args.html, std::ios::binary);
  out << certify::html_report(mesh, report, o);
  if (out.flush())
    message("lepp certify: wrote %s\n", args.html.c_str());
  else
    message("lepp certify: cannot write %s\n", args.html.c_str());
}

int run_certify(const CertifyArgs& args) {
  Pslg input;
  Mesh mesh;
  certify::Options options;
  std::vector<std::string> warnings;
  try {
    input = validate(read_input(args.input, warnings), args.domain, warnings);
    mesh = read_mesh(args.mesh, args.threads);
    options.unimprovable = read_unimprovable(args.mesh);
  } catch (const InputError& e) {
    message("lepp certify: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    message("lepp certify: cannot read input: %s\n", e.what());
    return 2;
  }
  for (const std::string& w : warnings) message("lepp certify: warning: %s\n", w.c_str());
  options.min_angle_deg = args.min_angle;
  options.conforming = args.conforming;
  options.theorem2 = !args.no_theorem2;
  options.max_listed_per_reason = args.max_listed;
  options.exempt_small_input_angles = args.exempt;
  options.exempt_precision_limited = args.exempt_precision;
  options.precision_ties_by_ids = args.ties_by_ids;
  options.tie_search_states = args.tie_search_states;
  options.time_limit_seconds = args.time_limit;
  options.precision_method = *engines::parse_method(args.method);  // the option admits only the registry's names
  options.max_area = args.max_area;
  options.region_area_bounds = args.region_areas;
  options.threads = args.threads;
  certify::Report report;
  try {
    report = certify::certify(input, mesh, options);
  } catch (const std::length_error& e) {  // a mesh past the index's 32-bit ids
    message("lepp certify: %s: %s\n", args.mesh.c_str(), e.what());
    return 2;
  }
  if (args.json) {
    nlohmann::json j = certify::json_report(report, args.max_listed);
    add_version(j);
    std::printf("%s\n", j.dump(2).c_str());
  } else {
    std::printf("%s", certify::format_report(report).c_str());
  }
  std::fflush(stdout);
  const std::string title = args.mesh + (report.certified() ? ": certified" : ": not certified");
  if (!args.svg.empty()) write_svg(args.svg, mesh, report, false, title);
  if (!args.svg_zoom.empty()) write_svg(args.svg_zoom, mesh, report, true, title);
  if (!args.html.empty()) write_html(args, mesh, report);
  return report.certified() ? 0 : 1;
}

}  // namespace

void add_certify_command(CLI::App& app, int& status) {
  auto args = std::make_shared<CertifyArgs>();
  auto* cmd = app.add_subcommand("certify", "Check a mesh of a .poly file exactly (topology, input, constraints, Delaunay, angles, Theorem 2, size bounds)");
  cmd->add_option("input", args->input, "Input PSLG in Triangle's .poly format, or a .node point set, or a bare prefix X (X.poly, else X.node)")->required();
  cmd->add_option("mesh", args->mesh, "Mesh prefix: reads PREFIX.node, PREFIX.ele, PREFIX.poly and PREFIX.unimprovable if present")
      ->required();
  cmd->add_option("--min-angle", args->min_angle, "Check every smallest angle >= this many degrees (0: no angle check)")
      ->default_val(0)
      ->check(CLI::Range(0.0, 60.0));
  cmd->add_flag("--conforming", args->conforming, "Every edge locally Delaunay, constrained ones too (conforming Delaunay)");
  cmd->add_flag("--no-theorem2", args->no_theorem2, "Skip the Theorem 2 check (largest angles of terminal pairs <= 120 degrees)");
  cmd->add_option("--max-listed", args->max_listed, "List at most this many violations of each kind (all are counted)")
      ->default_val(50);
  cmd->add_flag("--exempt-small-input-angles", args->exempt,
                "Triangles below --min-angle whose shortest edge lies near an input angle below 60 degrees are exempt, "
                "counted apart (docs/CERTIFIER.md: the rule depends only on the input and the mesh)");
  cmd->add_flag("--exempt-precision-limited", args->exempt_precision,
                "Triangles below --min-angle for which every point Select Point allows (--method), rounded to doubles in "
                "every way, cannot be inserted are exempt, counted apart (docs/CERTIFIER.md section 5c; input and mesh only)");
  cmd->add_flag("--precision-ties-by-ids", args->ties_by_ids,
                "With the precision-limit exemption (and for PREFIX.unimprovable's double-precision lines): equal edge "
                "lengths decided by vertex ids, as lepp's engines decide them; reads numbering, so only for lepp's own "
                "meshes, no certificate for another mesher (docs/CERTIFIER.md section 5c, Finding)");
  cmd->add_option("--tie-search-states", args->tie_search_states,
                  "The precision-limit search's bound: at most this many Lepp states per triangle (the engines' default); "
                  "beyond it no exemption, and a listed claim is undecided at this bound. 0: no bound, the search decides "
                  "(or stops at --time-limit) (docs/CERTIFIER.md section 5c)")
      ->default_val(args->tie_search_states);
  cmd->add_option("--time-limit", args->time_limit,
                  "Seconds for the precision-limit searches in all (0: none); a search still running then stops undecided")
      ->default_val(0)
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--method", args->method, "The Select Point of the precision-limit exemption: centroid or midpoint")
      ->default_val(args->method)
      ->check(CLI::IsMember(engines::method_names()));
  cmd->add_option("--max-area", args->max_area,
                  "Every triangle's area must be <= this (as refine --max-area, Triangle's -a X; exact)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--region-areas", args->region_areas,
                "Every triangle's area must be <= the bound of its region in the .poly (as refine --region-areas, "
                "Triangle's -a); with --max-area too, the smaller bound applies");
  cmd->add_flag("--convex-hull", args->domain.convex_hull,
                "The domain has the convex hull's edges as segments (as refine --convex-hull, Triangle's -c)");
  cmd->add_flag("--split-crossings", args->domain.split_crossings,
                "Crossing segments are split at their rounded intersection (as refine --split-crossings)");
  cmd->add_option("--threads", args->threads,
                  "Threads for reading the mesh and for the checks (0: the machine's cores); the report is the same for any count")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--json", args->json, "Print the report as JSON");
  cmd->add_option("--svg", args->svg, "Also draw the mesh with every listed violation in red to this SVG file");
  cmd->add_option("--svg-zoom", args->svg_zoom, "Also draw the window around the first listed violation to this SVG file");
  cmd->add_option("--html", args->html,
                  "Also write the report as one self-contained HTML page: counts, statistics, a histogram of the "
                  "smallest angles, the mesh and each violation as pictures that pan and zoom");
  cmd->footer("Exit status: 0 certified; 1 violations found (each listed); 2 unreadable input. docs/CERTIFIER.md says what each check tests.");
  cmd->callback([args, &status] { status = run_certify(*args); });
}

}  // namespace lepp::cli
