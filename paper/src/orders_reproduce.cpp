// SPDX-License-Identifier: GPL-3.0-or-later
// `lepp paper --orders`: the order study's runs, then its files.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "lepp/paper/orders.h"
#include "lepp/version.h"
#include "shell_command.h"

namespace fs = std::filesystem;

namespace lepp::paper {

OrderStudy reproduce_orders(const OrderStudyOptions& options, const std::string& out, const std::string& command,
                            bool no_plots, const std::string& from_json,
                            const std::function<void(const OrderRun&)>& progress,
                            const std::function<void(const std::string&)>& note) {
  OrderStudy study;
  if (!from_json.empty()) {
    std::ifstream in(from_json);
    if (!in) throw std::runtime_error("cannot read " + from_json);
    study = order_study_from_json(nlohmann::json::parse(in));
    if (study.command.empty()) study.command = command;
  } else {
    study = run_order_study(options, progress);
    study.command = command;
  }
  const fs::path figdir = fs::path(out) / "paper";
  fs::create_directories(figdir);
  const fs::path json = figdir / "orders.json";
  if (from_json.empty() || fs::absolute(from_json) != fs::absolute(json)) {
    nlohmann::json j = to_json(study);
    add_version(j);
    std::ofstream(json) << j.dump(1) << "\n";
  }
  if (!no_plots) {
    std::string output;
    const std::string cmd = fmt::format("/usr/bin/python3 {} {} {} 2>&1", others::shell_quote(options.root + "/paper/orders_plots.py"),
                                        others::shell_quote(json.string()), others::shell_quote(figdir.string()));
    if (others::run_shell(cmd, output) != 0 && note) note("plots failed:\n" + output);
  }
  const fs::path page = fs::path(out) / "PAPER.md";
  std::string text;
  if (std::ifstream in(page); in) {
    std::ostringstream s;
    s << in.rdbuf();
    text = s.str();
  }
  std::ofstream(page) << splice_order_section(text, order_section(study, study.command));
  return study;
}

}  // namespace lepp::paper
