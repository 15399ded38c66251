// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp paper`: reproduces the paper's empirical study (Section 5 and 6: Table 1,
// Figs. 10 to 14) with Lepp-centroid, Lepp-midpoint, CGAL's mesher and Triangle,
// and writes docs/PAPER.md, docs/paper/results.json and the figures. The study
// is lepp::paper::reproduce (paper/); this file parses options and prints.
#include <cstdio>
#include <memory>
#include <string>

#include "commands.h"
#include "lepp/paper/reproduce.h"
#include "lepp/paper/summary_table.h"

namespace lepp::cli {
namespace {

// One line on stderr per run, as it ends.
void print_progress(const paper::Run& r) {
  std::fprintf(stderr, "  %-12s %-9s %-5s %5g°  %7lld points  %-16s %.2f s\n", r.reading.empty() ? r.problem.c_str() : r.reading.c_str(),
               r.method.c_str(), r.order.c_str(), r.theta, static_cast<long long>(r.steiner), r.outcome.c_str(), r.seconds);
}

int run_paper(const paper::Options& options) {
  paper::StudyEvents events;
  events.note = [](const std::string& line) { std::fprintf(stderr, "lepp paper: %s\n", line.c_str()); };
  events.run = print_progress;
  paper::Reproduction rep = paper::reproduce(options, events);
  if (rep.status != 0) {
    std::fprintf(stderr, "lepp paper: %s\n", rep.error.c_str());
    return rep.status;
  }
  std::fputs(paper::summary_table(rep.study.results, rep.study.angles).c_str(), stdout);
  std::fprintf(stderr, "lepp paper: wrote %s/PAPER.md and %s/ in %.0f s\n", options.out.c_str(), rep.figdir.c_str(), rep.seconds);
  return 0;
}

}  // namespace

void add_paper_command(CLI::App& app, int& status) {
  auto args = std::make_shared<paper::Options>();
  auto* cmd = app.add_subcommand("paper", "Reproduce the paper's Table 1 and Figs. 10-14 (writes OUT/PAPER.md and OUT/paper/)");
  cmd->add_option("--out", args->out, "Where PAPER.md goes; figures and results.json go to OUT/paper/")->default_val("docs");
  cmd->add_option("--work", args->work, "Where the meshes of every run go")->default_val("out/paper");
  cmd->add_option("--root", args->root, "The source tree (corpus/paper, paper/plots.py, tools/triangle)")->default_val(".");
  cmd->add_option("--engine", args->engine, "auto (fast if implemented, else reference), fast or reference")
      ->default_val("auto")
      ->check(CLI::IsMember({"auto", "fast", "reference"}));
  cmd->add_option("--budget", args->budget, "Steiner points per run (ours, CGAL) before it counts as not finished")
      ->default_val(300000)
      ->check(CLI::PositiveNumber);
  cmd->add_option("--triangle-budget", args->triangle_budget, "Triangle's -S: Steiner points before it counts as not finished")
      ->default_val(20000)
      ->check(CLI::PositiveNumber);
  cmd->add_option("--time-limit", args->time_limit, "Seconds per run before it counts as not finished")
      ->default_val(60)
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--quick", args->quick, "Budget 5000 and 10 s per run, no angles above 36, no alternative readings");
  cmd->add_flag("--no-plots", args->no_plots, "Skip the matplotlib figures");
  cmd->footer("Exit status: 0 page written (runs that did not finish are reported on it); 2 corpus not found.");
  cmd->callback([args, &status] {
    paper::apply_quick_limits(*args);
    status = run_paper(*args);
  });
}

}  // namespace lepp::cli
