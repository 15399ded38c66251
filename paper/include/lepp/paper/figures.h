// SPDX-License-Identifier: GPL-3.0-or-later
// The figures of PAPER.md: the matplotlib plots (ROOT/paper/plots.py on
// results.json) and Fig. 13's drawings of Circles240 at 32 degrees.
#pragma once
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "lepp/paper/run.h"

namespace lepp::paper {

// The plots plots.py makes, in the page's order: (file in FIGDIR, caption).
const std::vector<std::pair<std::string, std::string>>& plot_figures();

// Fig. 13's two drawings (draw_fig13's files in FIGDIR): centroid, then Triangle.
const std::vector<std::string>& fig13_files();

// Runs `/usr/bin/python3 ROOT/paper/plots.py FIGDIR/results.json FIGDIR`; true
// when it exits 0, else false with its output (stdout and stderr) in `output`.
bool make_plots(const std::string& root, const std::string& figdir, std::string& output);

// FIGDIR/fig13_circles240_{centroid,triangle}_32.svg from those runs' meshes
// (as `lepp render --color quality --highlight bad --min-angle 32 --width 700`
// draws them); a drawing whose run is missing or has no mesh is removed. Each
// failure is told to `note`.
void draw_fig13(const Results& res, const std::string& figdir, const std::function<void(const std::string&)>& note);

}  // namespace lepp::paper
