// SPDX-License-Identifier: GPL-3.0-or-later
// The definitions behind lepp/paper/reproduce.h: the paper reproduction (`lepp paper`).
#include "lepp/paper/reproduce.h"

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "lepp/paper/figures.h"
#include "lepp/paper/orders.h"
#include "lepp/paper/html_page.h"
#include "lepp/paper/page.h"
#include "lepp/version.h"

namespace fs = std::filesystem;

namespace lepp::paper {

Reproduction reproduce(const Options& options, const StudyEvents& events) {
  auto t0 = std::chrono::steady_clock::now();
  auto note = [&](const std::string& line) {
    if (events.note) events.note(line);
  };
  Reproduction rep;
  fs::path corpus = fs::path(options.root) / "corpus" / "paper";
  if (!fs::is_directory(corpus)) {
    rep.status = 2;
    rep.error = fmt::format("{} not found; run from the source tree or pass --root", corpus.string());
    return rep;
  }
  fs::create_directories(fs::path(options.work) / "meshes");
  fs::path figdir = fs::path(options.out) / "paper";
  fs::create_directories(figdir);
  rep.figdir = figdir.string();

  rep.study = run_study(options, events);
  const Study& study = rep.study;

  // Raw results, then the plots and the drawings.
  nlohmann::json j = {{"engine", study.engine}, {"budget", options.budget}, {"time_limit", options.time_limit},
                      {"quick", options.quick}};
  add_version(j);
  j["runs"] = nlohmann::json::array();
  for (const Run& r : study.results.runs()) j["runs"].push_back(to_json(r));
  std::ofstream(figdir / "results.json") << j.dump(1) << "\n";

  bool plots_ok = false;
  if (!options.no_plots) {
    std::string output;
    plots_ok = make_plots(options.root, rep.figdir, output);
    if (!plots_ok) note("plots failed:\n" + output);
  }
  draw_fig13(study.results, rep.figdir, note);

  rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  fs::create_directories(options.out);
  // The processing-order section is `lepp paper --orders`'s (it takes longer): kept as it is.
  std::string kept;
  if (std::ifstream old(fs::path(options.out) / "PAPER.md"); old) {
    std::ostringstream s;
    s << old.rdbuf();
    kept = order_section_of(s.str());
  }
  std::string page = paper_page(options, study, plots_ok || options.no_plots, rep.seconds);
  if (!kept.empty()) page = splice_order_section(page, kept);
  std::ofstream(fs::path(options.out) / "PAPER.md") << page;
  // The same tables and the figures on one page to open in a browser.
  std::ofstream(figdir / "index.html") << paper_html(options, study, rep.figdir, rep.seconds);
  return rep;
}

}  // namespace lepp::paper
