// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/paper/figures.h: the figures of PAPER.md.
#include "lepp/paper/figures.h"

#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>

#include "lepp/io.h"
#include "lepp/render.h"
#include "mesher_names.h"
#include "shell_command.h"

namespace fs = std::filesystem;

namespace lepp::paper {

const std::vector<std::pair<std::string, std::string>>& plot_figures() {
  static const std::vector<std::pair<std::string, std::string>> figures = {
      {"fig10_min_area_quality.png", "Fig. 10: minimum area quality vs number of vertices, centroid vs midpoint"},
      {"fig11_avg_min_angle.png", "Fig. 11: average smallest angle vs number of vertices, centroid vs midpoint"},
      {"fig12_quality_distribution.png", "Fig. 12: area-quality distribution, Square400 at 10° and 25°"},
      {"fig14_min_angle.png", "Fig. 14: minimum angle vs number of vertices, centroid vs Triangle (and CGAL)"},
      {"shortest_edge.png", "Normalized shortest edge (shortest mesh edge / shortest input segment) vs θ"},
      {"lepp_size.png", "Average Lepp size vs θ"},
  };
  return figures;
}

const std::vector<std::string>& fig13_files() {
  static const std::vector<std::string> files = {fmt::format("fig13_circles240_{}_32.svg", centroid_name()),
                                                 fmt::format("fig13_circles240_{}_32.svg", triangle_name())};
  return files;
}

bool make_plots(const std::string& root, const std::string& figdir, std::string& output) {
  std::string cmd = fmt::format("/usr/bin/python3 {} {} {} 2>&1", others::shell_quote(root + "/paper/plots.py"),
                                others::shell_quote((fs::path(figdir) / "results.json").string()), others::shell_quote(figdir));
  return others::run_shell(cmd, output) == 0;
}

void draw_fig13(const Results& res, const std::string& figdir, const std::function<void(const std::string&)>& note) {
  for (const std::string method : {centroid_name(), triangle_name()}) {
    const Run* r = res.find("circles240", method, 32);
    fs::path svg = fs::path(figdir) / fig13_files()[method == centroid_name() ? 0 : 1];
    if (!r || r->stats.triangles == 0) {
      fs::remove(svg);
      continue;
    }
    render::RenderOptions options;
    options.color = render::ColorBy::Quality;
    options.highlight_bad = true;
    options.min_angle_deg = 32;
    options.width = 700;
    options.title = fmt::format("Circles240, {}, 32°", method == centroid_name() ? "Lepp-centroid" : "Triangle");
    try {
      std::string drawing = render::render_svg(read_mesh(r->mesh_prefix), options);
      std::ofstream out(svg);
      out << drawing;
      if (!out) throw std::runtime_error("cannot write " + svg.string());
    } catch (const std::exception& e) {
      if (note) note(fmt::format("render failed:\n{}: {}\n", r->mesh_prefix, e.what()));
    }
  }
}

}  // namespace lepp::paper
