// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp render MESH_PREFIX -o out.svg`: draws a mesh as SVG, triangles coloured
// by quality or smallest angle, constrained edges bold, bad triangles marked. The
// drawing is lepp::render::render_svg (render/); this file parses options and writes.
#include <cstdio>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include "commands.h"
#include "message.h"
#include "lepp/io.h"
#include "lepp/render.h"

namespace lepp::cli {
namespace {

struct RenderArgs {
  std::string prefix, output;
  std::string color = "quality";
  std::string highlight = "none";
  double min_angle = 30;
  double width = 1000;
  std::string title;
};

int run_render(const RenderArgs& args) {
  Mesh mesh;
  try {
    mesh = read_mesh(args.prefix);
  } catch (const InputError& e) {
    message("lepp render: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    message("lepp render: %s\n", e.what());
    return 2;
  }
  if (mesh.triangles.empty()) {
    message("lepp render: %s has no triangles\n", args.prefix.c_str());
    return 2;
  }
  render::RenderOptions options;
  options.color = args.color == "angle" ? render::ColorBy::Angle : render::ColorBy::Quality;
  options.highlight_bad = args.highlight == "bad";
  options.min_angle_deg = args.min_angle;
  options.width = args.width;
  options.title = args.title;
  std::string svg;
  try {
    svg = render::render_svg(mesh, options);
  } catch (const std::invalid_argument& e) {
    message("lepp render: %s: %s\n", args.prefix.c_str(), e.what());
    return 2;
  }
  std::ofstream out(args.output);
  out << svg;
  if (!out) {
    message("lepp render: cannot write %s\n", args.output.c_str());
    return 1;
  }
  return 0;
}

}  // namespace

void add_render_command(CLI::App& app, int& status) {
  auto args = std::make_shared<RenderArgs>();
  auto* cmd = app.add_subcommand("render", "Draw a mesh (PREFIX.node/.ele/.poly) as SVG, coloured by quality");
  cmd->add_option("prefix", args->prefix, "Mesh prefix: reads PREFIX.node, PREFIX.ele and PREFIX.poly if present")
      ->required();
  cmd->add_option("-o,--output", args->output, "SVG file to write")->required();
  cmd->add_option("--color", args->color, "Colour triangles by area quality q (1 = equilateral) or smallest angle")
      ->default_val("quality")
      ->check(CLI::IsMember({"quality", "angle"}));
  cmd->add_option("--highlight", args->highlight, "bad: outline and ring the triangles with smallest angle below --min-angle")
      ->default_val("none")
      ->check(CLI::IsMember({"none", "bad"}));
  cmd->add_option("--min-angle", args->min_angle, "Angle below which a triangle is bad, degrees")
      ->default_val(30)
      ->check(CLI::Range(0.0, 60.0));
  cmd->add_option("--width", args->width, "Drawing width in pixels")->default_val(1000)->check(CLI::Range(100.0, 20000.0));
  cmd->add_option("--title", args->title, "Text put before the summary line under the drawing");
  cmd->footer("Exit status: 0 written; 2 the mesh cannot be read; 1 the SVG cannot be written.");
  cmd->callback([args, &status] { status = run_render(*args); });
}

}  // namespace lepp::cli
