// SPDX-License-Identifier: GPL-3.0-or-later
// The settings of the paper reproduction (`lepp paper`'s options).
#pragma once
#include <algorithm>
#include <cstdint>
#include <string>

namespace lepp::paper {

struct Options {
  std::string out = "docs";        // PAPER.md here, figures and results.json in OUT/paper/
  std::string work = "out/paper";  // meshes of every run (not committed)
  std::string root = ".";          // the source tree: corpus/, paper/, tools/triangle/
  std::string engine = "auto";     // auto (fast when it exists, else reference), fast, reference
  bool quick = false;              // lower limits, no angles above 36, no alternative readings
  bool no_plots = false;           // skip the matplotlib figures
  std::int64_t budget = 300000;           // Steiner points per run of ours or CGAL's before "did not finish"
  std::int64_t triangle_budget = 20000;   // Triangle's -S: the wasm build's 16 MB heap ends near 10^5 points
  double time_limit = 60;                 // seconds per run, same meaning
};

// --quick: at most 5000 points and 10 s per run (the other differences of a
// quick study are decided by `quick` itself).
inline void apply_quick_limits(Options& o) {
  if (!o.quick) return;
  o.budget = std::min<std::int64_t>(o.budget, 5000);
  o.triangle_budget = std::min<std::int64_t>(o.triangle_budget, 5000);
  o.time_limit = std::min(o.time_limit, 10.0);
}

}  // namespace lepp::paper
