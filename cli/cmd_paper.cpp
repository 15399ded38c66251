// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp paper`: reproduces the paper's empirical study (Section 5 and 6: Table 1,
// Figs. 10 to 14) with Lepp-centroid, Lepp-midpoint, CGAL's mesher and Triangle,
// and writes docs/PAPER.md, docs/paper/results.json and the figures. The study
// is lepp::paper::reproduce (paper/); this file parses options and prints.
#include <cstdio>
#include <exception>
#include <vector>
#include <memory>
#include <string>

#include "commands.h"
#include "message.h"
#include "lepp/engines/registry.h"
#include "lepp/paper/orders.h"
#include "lepp/paper/reproduce.h"
#include "lepp/paper/summary_table.h"

namespace lepp::cli {
namespace {

// One line on stderr per run, as it ends.
void print_progress(const paper::Run& r) {
  message("  %-12s %-9s %-5s %5g°  %7lld points  %-16s %.2f s\n", r.reading.empty() ? r.problem.c_str() : r.reading.c_str(),
               r.method.c_str(), r.order.c_str(), r.theta, static_cast<long long>(r.steiner), r.outcome.c_str(), r.seconds);
}

int run_paper(const paper::Options& options) {
  paper::StudyEvents events;
  events.note = [](const std::string& line) { message("lepp paper: %s\n", line.c_str()); };
  events.run = print_progress;
  paper::Reproduction rep = paper::reproduce(options, events);
  if (rep.status != 0) {
    message("lepp paper: %s\n", rep.error.c_str());
    return rep.status;
  }
  std::fputs(paper::summary_table(rep.study.results, rep.study.angles).c_str(), stdout);
  message("lepp paper: wrote %s/PAPER.md, %s/index.html and %s/ in %.0f s\n", options.out.c_str(), rep.figdir.c_str(),
          rep.figdir.c_str(), rep.seconds);
  return 0;
}

// `lepp paper --orders`: the processing-order study and its section of PAPER.md.
struct OrdersArgs {
  bool run = false;
  paper::OrderStudyOptions study;
  std::string angles = "28:38";
  std::string from_json;
};

int run_orders(const paper::Options& options, OrdersArgs& a, const std::string& command) {
  a.study.root = options.root;
  // auto: the fast engine.
  a.study.engine = engines::to_string(engines::parse_engine(options.engine, engines::lepp_engines()).value_or(engines::Engine::Fast));
  a.study.angles.clear();
  double lo = 0, hi = 0;
  if (std::sscanf(a.angles.c_str(), "%lf:%lf", &lo, &hi) == 2 && lo <= hi) {
    for (double t = lo; t <= hi + 1e-9; t += 1) a.study.angles.push_back(t);
  } else if (std::sscanf(a.angles.c_str(), "%lf", &lo) == 1) {
    a.study.angles.push_back(lo);
  } else {
    message("lepp paper: --orders-angles: expected LO:HI or one angle, got '%s'\n", a.angles.c_str());
    return 2;
  }
  try {
    paper::OrderStudy s = paper::reproduce_orders(
        a.study, options.out, command, options.no_plots, a.from_json,
        [](const paper::OrderRun& r) {
          if (r.order != "random" || r.seed == 1)
            message("  %-10s %-8s %4g°  %-14s %7lld points  %s\n", r.problem.c_str(), r.method.c_str(), r.theta,
                         r.order == "random" ? "random 1.." : r.order.c_str(), static_cast<long long>(r.steiner), r.outcome.c_str());
        },
        [](const std::string& line) { message("lepp paper: %s\n", line.c_str()); });
    message("lepp paper: %zu runs in %.0f s (%.0f CPU s); wrote %s/PAPER.md's order section and %s/paper/orders.json\n",
                 s.runs.size(), s.seconds, s.cpu_seconds, options.out.c_str(), options.out.c_str());
  } catch (const std::exception& e) {
    message("lepp paper: %s\n", e.what());
    return 2;
  }
  return 0;
}

// --engine: auto (the fast engine), or one of lepp's engines by name.
std::vector<std::string> engine_choices() {
  std::vector<std::string> choices = {"auto"};
  for (const std::string& name : engines::names(engines::lepp_engines())) choices.push_back(name);
  return choices;
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
      ->check(CLI::IsMember(engine_choices()));
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
  auto orders = std::make_shared<OrdersArgs>();
  cmd->add_flag("--orders", orders->run,
                "Instead: the processing-order study (issue 21): every paper problem, --orders-angles, centroid and "
                "midpoint, the named orders and --orders-random random ones; writes OUT/PAPER.md's order section, "
                "OUT/paper/orders.json and its figures");
  cmd->add_option("--orders-angles", orders->angles, "The order study's angles, LO:HI in steps of 1 degree, or one angle")
      ->default_val("28:38");
  cmd->add_option("--orders-random", orders->study.random_orders, "Random orders (seeds 1..N) per cell of the order study")
      ->default_val(100)
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--orders-budget-factor", orders->study.budget_factor,
                  "The order study's Steiner budget: this many times the paper's count (docs/PAPER.md)")
      ->default_val(20)
      ->check(CLI::PositiveNumber);
  cmd->add_option("--orders-methods", orders->study.methods, "The order study's methods")
      ->default_val(engines::method_names())
      ->check(CLI::IsMember(engines::method_names()));
  cmd->add_option("--orders-problems", orders->study.problems, "The order study's problems (corpus/paper keys; default all four)")
      ->check(CLI::IsMember({"square400", "circles240", "rect162", "A"}));
  cmd->add_option("--orders-from", orders->from_json, "Rewrite the order section from this orders.json instead of running");
  cmd->footer("Exit status: 0 page written (runs that did not finish are reported on it); 2 corpus not found.");
  cmd->callback([args, orders, &status, cmd] {
    paper::apply_quick_limits(*args);
    if (orders->run) {
      std::string command = "lepp paper --orders";
      for (const char* o : {"--orders-angles", "--orders-random", "--orders-budget-factor", "--orders-methods", "--orders-problems"})
        if (cmd->count(o) > 0) {
          command += std::string(" ") + o;
          for (const std::string& v : cmd->get_option(o)->results()) command += " " + v;
        }
      status = run_orders(*args, *orders, command);
    } else {
      status = run_paper(*args);
    }
  });
}

}  // namespace lepp::cli
